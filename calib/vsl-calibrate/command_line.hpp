// vsl-calibrate's command line (usage text in command_line.cpp).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "chessboard.hpp"
#include "stereo_calibrator.hpp"
#include "view_sources.hpp"

namespace vsl::calibration {

enum class Mode { kHelp, kCalibrate, kCheck };

struct CalibrateCommand {
  Mode mode = Mode::kHelp;
  BoardSpec board;
  std::string images_directory;  // empty: live from STEREO_FRAME
  LiveOptions live;
  std::string output_path;             // calibrate
  std::string calibration_path;        // check
  std::optional<double> max_error_px;  // check: exit 1 above this epipolar RMS
  CalibrationOptions calibration;
};

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws UsageError with a one-line message.
CalibrateCommand parse_calibrate_command(int argc, const char* const* argv);
std::string calibrate_usage();

}  // namespace vsl::calibration
