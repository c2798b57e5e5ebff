#include "command_line.hpp"

#include <cmath>
#include <string_view>
#include <vector>

#include "vsl/runtime/config.hpp"

namespace vsl::calibration {
namespace {

double positive_number(const std::string& option, const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value) && value > 0.0) return value;
  } catch (const std::exception&) {
  }
  throw UsageError("option " + option + ": expected a positive number, got '" + text + "'");
}

}  // namespace

std::string calibrate_usage() {
  return R"(Usage:
  vsl-calibrate calibrate --board COLSxROWS --square-mm S (--images DIR | --live) -o FILE
  vsl-calibrate check --calibration FILE --board COLSxROWS --square-mm S (--images DIR | --live)

Stereo calibration of the head's cameras from chessboard views (OpenCV: findChessboardCorners,
cornerSubPix, calibrateCamera per camera, stereoCalibrate, stereoRectify). Prints the RMS
reprojection error and every view's error, rejects bad views (error above 3x the median and
0.5 px), and writes the calibration file calib/*.yaml (docs/head.md) with the rectification.
`check` reports the epipolar error (row difference of the rectified corners) of views against a
calibration file.

Board:
  --board COLSxROWS      inner corners per row and column, e.g. 9x6 (one odd, one even)
  --square-mm S          square size in millimetres (the calibration's T comes out in metres)
Views:
  --images DIR           pairs left<name> / right<name> in DIR (e.g. left_003.png, right_003.png)
  --live                 from the STEREO_FRAME channel of a running driver
  --lcm-url URL          live: LCM URL (default: the daemons' default)
  --channel NAME         live: channel (default STEREO_FRAME)
  --views N              live: views to collect (default 20 for calibrate, 10 for check)
  --timeout-s S          live: give up collecting after S seconds (default 300)
  --min-motion-px P      live: a new view's corners must move P px on average (default 20 for
                         calibrate, 0 for check): move the board between views
  --save-views DIR       live: also write the accepted pairs as PNGs (re-run with --images DIR)
calibrate:
  -o, --output FILE      the calibration file to write
  --estimate-k3          estimate k3 too (wide-angle lenses); default: k1 k2 p1 p2, k3 = 0
check:
  --calibration FILE     the calibration file to check
  --max-error-px E       exit 1 when the epipolar RMS error exceeds E

Exit codes: 0 done, 1 failed (no views, too few usable views, check above --max-error-px),
2 bad command line.
)";
}

CalibrateCommand parse_calibrate_command(int argc, const char* const* argv) {
  CalibrateCommand out;
  out.live.lcm_url = runtime::kDefaultLcmUrl;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) throw UsageError("expected a command: calibrate or check");
  std::size_t i = 0;
  if (args[0] == "--help" || args[0] == "-h") return out;
  if (args[0] == "calibrate") {
    out.mode = Mode::kCalibrate;
  } else if (args[0] == "check") {
    out.mode = Mode::kCheck;
  } else {
    throw UsageError("unknown command '" + args[0] + "' (expected calibrate or check)");
  }
  std::string board_text;
  std::optional<double> square_mm;
  bool live = false;
  std::optional<int> views;
  std::optional<double> min_motion;
  for (i = 1; i < args.size(); ++i) {
    std::string option = args[i];
    std::optional<std::string> inline_value;
    if (const std::size_t eq = option.find('=');
        option.rfind("--", 0) == 0 && eq != std::string::npos) {
      inline_value = option.substr(eq + 1);
      option = option.substr(0, eq);
    }
    auto value = [&]() -> std::string {
      if (inline_value) return *inline_value;
      if (i + 1 >= args.size()) throw UsageError("option " + option + " needs a value");
      return args[++i];
    };
    if (option == "--help" || option == "-h") {
      out.mode = Mode::kHelp;
      return out;
    } else if (option == "--board") {
      board_text = value();
    } else if (option == "--square-mm") {
      square_mm = positive_number(option, value());
    } else if (option == "--images") {
      out.images_directory = value();
    } else if (option == "--live") {
      live = true;
    } else if (option == "--lcm-url") {
      out.live.lcm_url = value();
    } else if (option == "--channel") {
      out.live.channel = value();
    } else if (option == "--views") {
      const double n = positive_number(option, value());
      if (n != std::floor(n) || n > 10000) throw UsageError("option --views: expected a count");
      views = static_cast<int>(n);
    } else if (option == "--timeout-s") {
      out.live.timeout_s = positive_number(option, value());
    } else if (option == "--min-motion-px") {
      const std::string text = value();
      min_motion = text == "0" ? 0.0 : positive_number(option, text);
    } else if (option == "--save-views") {
      out.live.save_directory = value();
    } else if (option == "-o" || option == "--output") {
      out.output_path = value();
    } else if (option == "--estimate-k3") {
      out.calibration.estimate_k3 = true;
    } else if (option == "--calibration") {
      out.calibration_path = value();
    } else if (option == "--max-error-px") {
      out.max_error_px = positive_number(option, value());
    } else {
      throw UsageError("unknown option '" + args[i] + "'");
    }
  }
  if (board_text.empty()) throw UsageError("option --board COLSxROWS is required");
  if (!square_mm) throw UsageError("option --square-mm S is required");
  const auto board = parse_board(board_text, *square_mm / 1000.0);
  if (!board) {
    throw UsageError("option --board: expected COLSxROWS inner corners (e.g. 9x6), got '" +
                     board_text + "'");
  }
  out.board = *board;
  if (live == !out.images_directory.empty()) {
    throw UsageError("give exactly one of --images DIR and --live");
  }
  if (out.mode == Mode::kCalibrate && out.output_path.empty()) {
    throw UsageError("option -o FILE is required");
  }
  if (out.mode == Mode::kCheck && out.calibration_path.empty()) {
    throw UsageError("option --calibration FILE is required");
  }
  out.live.views = views.value_or(out.mode == Mode::kCalibrate ? 20 : 10);
  out.live.min_motion_px = min_motion.value_or(out.mode == Mode::kCalibrate ? 20.0 : 0.0);
  return out;
}

}  // namespace vsl::calibration
