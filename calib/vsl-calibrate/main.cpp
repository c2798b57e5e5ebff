// vsl-calibrate: stereo calibration of the real cameras from chessboard views, and a check of a
// calibration file against views (usage: command_line.cpp, docs/cameras.md).
#include <cstdio>
#include <exception>
#include <string>

#include "calibration_writer.hpp"
#include "command_line.hpp"
#include "epipolar_check.hpp"
#include "vsl/config/node.hpp"

namespace {

using namespace vsl::calibration;

void line(const std::string& text) {
  std::fputs((text + "\n").c_str(), stdout);
  std::fflush(stdout);
}

std::string fixed(double value, int decimals = 3) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

struct Views {
  std::vector<StereoView> views;
  cv::Size image_size;
};

Views collect(const CalibrateCommand& command) {
  if (!command.images_directory.empty()) {
    FileViews files = views_from_files(command.images_directory, command.board);
    return {std::move(files.views), files.image_size};
  }
  line("collecting " + std::to_string(command.live.views) + " views from " + command.live.channel +
       " (move the board between views)");
  LiveViews live = views_from_channel(command.board, command.live, line);
  if (live.frames_seen == 0) {
    throw std::runtime_error("no stereo frame on " + command.live.channel + " at " +
                             command.live.lcm_url + " within " + fixed(command.live.timeout_s, 0) +
                             " s (is a driver running?)");
  }
  return {std::move(live.views), live.image_size};
}

int calibrate(const CalibrateCommand& command) {
  const Views views = collect(command);
  const CalibrationResult result =
      calibrate_stereo(views.views, command.board, views.image_size, command.calibration);
  for (const ViewError& view : result.views) {
    std::string text = "view " + view.name + ": ";
    if (view.left_rms_px > 0.0 || view.right_rms_px > 0.0) {
      text += "left " + fixed(view.left_rms_px) + " px, right " + fixed(view.right_rms_px) + " px";
    }
    if (view.rejected)
      text += (text.back() == ' ' ? "" : ", ") + std::string("rejected: ") + view.reason;
    line(text);
  }
  const vsl::head::StereoCalibration& c = result.calibration;
  line("RMS reprojection error " + fixed(result.rms_px) + " px over " +
       std::to_string(result.views_used) + " of " + std::to_string(result.views.size()) + " views");
  line("left fx " + fixed(c.left.fx_px, 2) + " fy " + fixed(c.left.fy_px, 2) + " cx " +
       fixed(c.left.cx_px, 2) + " cy " + fixed(c.left.cy_px, 2) + " px; right fx " +
       fixed(c.right.fx_px, 2) + " fy " + fixed(c.right.fy_px, 2) + " cx " +
       fixed(c.right.cx_px, 2) + " cy " + fixed(c.right.cy_px, 2) + " px; baseline " +
       fixed(c.baseline_m() * 1000.0, 2) + " mm");
  write_text_file(command.output_path,
                  calibration_yaml(c, calibration_header(result, command.board)));
  // Read back through the loader every program uses: what was written is what they will get.
  vsl::head::load_stereo_calibration(command.output_path);
  line("wrote " + command.output_path);
  return 0;
}

int check(const CalibrateCommand& command) {
  const vsl::head::StereoCalibration calibration =
      vsl::head::load_stereo_calibration(command.calibration_path);
  const Views views = collect(command);
  if (views.image_size.width != calibration.left.width_px ||
      views.image_size.height != calibration.left.height_px) {
    throw std::runtime_error("the views are " + std::to_string(views.image_size.width) + "x" +
                             std::to_string(views.image_size.height) + ", " +
                             command.calibration_path + " is for " +
                             std::to_string(calibration.left.width_px) + "x" +
                             std::to_string(calibration.left.height_px));
  }
  const EpipolarReport report = epipolar_errors(calibration, views.views);
  for (const StereoView& view : views.views) {
    if (view.left.empty()) line("view " + view.name + ": board not found in both images");
  }
  for (const ViewEpipolarError& view : report.views) {
    line("view " + view.name + ": epipolar error mean " + fixed(view.mean_px) + " px, max " +
         fixed(view.max_px) + " px (" + std::to_string(view.corners) + " corners)");
  }
  if (report.views.empty()) throw std::runtime_error("the board was not found in any view");
  line("epipolar error RMS " + fixed(report.rms_px) + " px, max " + fixed(report.max_px) +
       " px over " + std::to_string(report.views.size()) + " views");
  if (command.max_error_px && report.rms_px > *command.max_error_px) {
    std::fprintf(stderr, "vsl-calibrate: epipolar error RMS %.3f px exceeds %.3f px\n",
                 report.rms_px, *command.max_error_px);
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CalibrateCommand command;
  try {
    command = parse_calibrate_command(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "vsl-calibrate: %s (try --help)\n", e.what());
    return 2;
  }
  if (command.mode == Mode::kHelp) {
    std::fputs(calibrate_usage().c_str(), stdout);
    return 0;
  }
  try {
    return command.mode == Mode::kCalibrate ? calibrate(command) : check(command);
  } catch (const vsl::config::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vsl-calibrate: %s\n", e.what());
    return 1;
  }
}
