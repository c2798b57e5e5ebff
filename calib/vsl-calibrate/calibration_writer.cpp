#include "calibration_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace vsl::calibration {
namespace {

// Enough digits that a value reads back to within 1e-10 of itself.
std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.12g", value == 0.0 ? 0.0 : value);  // no "-0"
  std::string out = text;
  if (out.find_first_of(".eEn") == std::string::npos) out += ".0";
  return out;
}

template <class Matrix>
std::string rows(const Matrix& m, const std::string& indent) {
  std::string out = "[";
  for (int r = 0; r < m.rows(); ++r) {
    out += r == 0 ? "[" : ",\n" + indent + " [";
    for (int c = 0; c < m.cols(); ++c) out += (c == 0 ? "" : ", ") + number(m(r, c));
    out += "]";
  }
  return out + "]";
}

std::string camera(const char* name, const head::CameraIntrinsics& in) {
  std::string out = std::string(name) + ":\n";
  out += "  width_px: " + std::to_string(in.width_px) + "\n";
  out += "  height_px: " + std::to_string(in.height_px) + "\n";
  out += "  fx_px: " + number(in.fx_px) + "\n";
  out += "  fy_px: " + number(in.fy_px) + "\n";
  out += "  cx_px: " + number(in.cx_px) + "\n";
  out += "  cy_px: " + number(in.cy_px) + "\n";
  out += "  distortion: [";
  for (std::size_t i = 0; i < in.distortion.size(); ++i) {
    out += (i == 0 ? "" : ", ") + number(in.distortion[i]);
  }
  return out + "]   # k1, k2, p1, p2, k3\n";
}

std::string fixed(double value, int decimals) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

std::string calibration_yaml(const head::StereoCalibration& c,
                             const std::vector<std::string>& header) {
  std::string out;
  for (const std::string& line : header) out += "#" + (line.empty() ? "" : " " + line) + "\n";
  out += camera("left", c.left);
  out += camera("right", c.right);
  out += "# X_right = R * X_left + T (camera frames: x right, y down, z forward), T in metres.\n";
  out += "stereo:\n";
  out += "  R: " + rows(c.right_R_left, "    ") + "\n";
  out += "  T_m: [" + number(c.right_t_left_m.x()) + ", " + number(c.right_t_left_m.y()) + ", " +
         number(c.right_t_left_m.z()) + "]\n";
  if (c.rms_reprojection_error_px) {
    out += "rms_reprojection_error_px: " + number(*c.rms_reprojection_error_px) + "\n";
  }
  if (c.rectification) {
    const head::StereoRectification& r = *c.rectification;
    out +=
        "# cv::stereoRectify (alpha 0): rectified <- raw rotations, rectified projections (px),\n";
    out += "# disparity-to-depth Q.\n";
    out += "rectification:\n";
    out += "  R1: " + rows(r.left_rect_R_left, "     ") + "\n";
    out += "  R2: " + rows(r.right_rect_R_right, "     ") + "\n";
    out += "  P1: " + rows(r.left_projection, "     ") + "\n";
    out += "  P2: " + rows(r.right_projection, "     ") + "\n";
    out += "  Q: " + rows(r.disparity_to_depth, "    ") + "\n";
  }
  return out;
}

std::vector<std::string> calibration_header(const CalibrationResult& result,
                                            const BoardSpec& board) {
  std::vector<std::string> out;
  out.push_back(
      "Stereo calibration made by vsl-calibrate (format: docs/head.md). Keys map 1:1 onto");
  out.push_back("cv::stereoCalibrate's K1 D1 K2 D2 R T; left = camera 1.");
  out.push_back("Board: " + std::to_string(board.columns) + "x" + std::to_string(board.rows) +
                " inner corners, " + fixed(board.square_m * 1000.0, 2) + " mm squares. " +
                std::to_string(result.views_used) + " of " + std::to_string(result.views.size()) +
                " views used, RMS reprojection error " + fixed(result.rms_px, 3) + " px.");
  out.push_back("Per view: RMS error left, right (px) from the last calibration that used it:");
  for (const ViewError& view : result.views) {
    std::string line = "  " + view.name + ": ";
    if (view.left_rms_px > 0.0 || view.right_rms_px > 0.0) {
      line += fixed(view.left_rms_px, 3) + ", " + fixed(view.right_rms_px, 3);
    }
    if (view.rejected) line += "  rejected: " + view.reason;
    out.push_back(line);
  }
  return out;
}

void write_text_file(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file << text;
    if (!file.flush()) throw std::runtime_error("cannot write " + temporary);
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw std::runtime_error("cannot write " + path + ": " + error.message());
}

}  // namespace vsl::calibration
