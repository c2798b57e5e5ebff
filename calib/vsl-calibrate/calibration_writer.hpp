// A calibration as the YAML file calib/*.yaml (docs/head.md) that head kinematics, the simulator
// and recognition read back with vsl::head::load_stereo_calibration: K1 D1 K2 D2 R T as
// cv::stereoCalibrate gives them, the RMS error and the rectification, with a comment header
// saying how it was made (views used, per-view errors).
#pragma once

#include <string>
#include <vector>

#include "stereo_calibrator.hpp"

namespace vsl::calibration {

// `header`: comment lines (without '#') to put first.
std::string calibration_yaml(const head::StereoCalibration& calibration,
                             const std::vector<std::string>& header);

// The header describing a calibration run: board, views used and rejected, per-view errors.
std::vector<std::string> calibration_header(const CalibrationResult& result,
                                            const BoardSpec& board);

// Writes text to path (through a temporary file and a rename, so that a reader never sees half a
// file). Throws std::runtime_error naming the path.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace vsl::calibration
