// vsl-view: subscribes to the pipeline's channels and draws what it knows: a top-down map of the
// world model with the fused percepts, hypotheses, gaze target, pose estimate and ground truth,
// and the left camera image with the objects recognized in it. A window when a display exists,
// PNG files otherwise (docs/view.md). Drawing is in map_drawing / camera_drawing (no LCM); this
// file only keeps the newest of each message and decides when to draw.
#include <opencv2/highgui.hpp>
#include <opencv2/imgcodecs.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "camera_drawing.hpp"
#include "image_conversion.hpp"
#include "map_drawing.hpp"
#include "view_messages.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/image_t.hpp"
#include "vsl/runtime/config.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"
#include "vsl/stereo_frame_t.hpp"
#include "vsl/world/world_io.hpp"

namespace {

constexpr const char* kUsage = R"(usage: vsl-view [options]

Shows what the vsl pipeline knows: a top-down map of the world model with the fused percepts
(FUSED_PERCEPTS), the hypotheses and pose estimate with its 3-sigma covariance (POSE_ESTIMATE),
the gaze target (GAZE_COMMAND), the ground truth (GROUND_TRUTH_POSE, simulation) and the
localizer's state (LOCALIZER_STATUS); and the newest left camera image (STEREO_FRAME) with the
objects recognized in it (PERCEPTS), or recognition's RECOGNITION_DEBUG image when published.
A window when a display exists; PNG files (map.png, camera.png, final.png) otherwise.
options:
  --lcm-url URL   LCM URL (default udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304)
  --world FILE    world model (default config/worlds/kitchen.yaml)
  --head FILE     head kinematics with the calibration (default config/heads/armar3.yaml)
  --output DIR    write PNG files into DIR (created) instead of showing a window: map.png and
                  camera.png at most every --period seconds, final.png (map and camera side by
                  side) whenever a POSE_ESTIMATE arrives. Without a display: DIR = vsl-view-out
  --period S      seconds between rewrites of map.png and camera.png (default 1)
  --scale PX      map pixels per metre (default 120)
  --once          exit after the first POSE_ESTIMATE (after writing final.png)
  -h, --help      this text
exit codes: 0 done (--once) or window closed, 1 bus failure, 2 bad arguments or files
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-view: " << what << " (see vsl-view --help)\n";
  std::exit(2);
}

struct Options {
  std::string lcm_url = vsl::runtime::kDefaultLcmUrl;
  std::string world = "config/worlds/kitchen.yaml";
  std::string head = "config/heads/armar3.yaml";
  std::optional<std::string> output;
  double period_s = 1.0;
  double px_per_m = 120.0;
  bool once = false;
};

double positive_number(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || value <= 0) {
    usage_error(option + ": '" + text + "' is not a positive number");
  }
  return value;
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--lcm-url") {
      options.lcm_url = value();
    } else if (arg == "--world") {
      options.world = value();
    } else if (arg == "--head") {
      options.head = value();
    } else if (arg == "--output") {
      options.output = value();
    } else if (arg == "--period") {
      options.period_s = positive_number(arg, value());
    } else if (arg == "--scale") {
      options.px_per_m = positive_number(arg, value());
      if (options.px_per_m > 1000) usage_error("--scale: at most 1000 pixels per metre");
    } else if (arg == "--once") {
      options.once = true;
    } else {
      usage_error("unknown argument '" + arg + "'");
    }
  }
  return options;
}

// A window when a display exists and highgui can open one there.
bool open_windows() {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') return false;
  try {
    cv::namedWindow("vsl-view: map", cv::WINDOW_AUTOSIZE);
    cv::namedWindow("vsl-view: camera", cv::WINDOW_AUTOSIZE);
    return true;
  } catch (const cv::Exception&) {
    return false;
  }
}

// Written beside and renamed over, so that a reader never sees half a PNG.
bool write_png(const std::filesystem::path& path, const cv::Mat& image, vsl::runtime::Logger& log) {
  const std::filesystem::path partial = path.string() + ".partial.png";
  try {
    if (cv::imwrite(partial.string(), image)) {
      std::filesystem::rename(partial, path);
      return true;
    }
  } catch (const std::exception& error) {
    log.error("cannot write ", path.string(), ": ", error.what());
    return false;
  }
  log.error("cannot write ", path.string());
  return false;
}

// Stereo frames kept for pairing with their percepts, which arrive a recognition time later.
constexpr std::size_t kFramesKept = 8;

struct Frame {
  std::int64_t frame_id = -1;
  cv::Mat left_bgr;  // owned copy
};

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  vsl::runtime::Logger log("vsl-view", vsl::runtime::Level::kWarn);

  // Files first: a bad one is one line and exit code 2, before anything else happens.
  vsl::world::WorldModel world;
  vsl::head::CameraIntrinsics intrinsics;
  try {
    world = vsl::world::load_world(options.world);
  } catch (const std::exception& error) {
    std::cerr << "vsl-view: " << error.what() << "\n";
    return 2;
  }
  try {
    intrinsics = vsl::head::HeadKinematics::load(options.head).calibration().left;
  } catch (const std::exception& error) {
    std::cerr << "vsl-view: " << error.what() << "\n";
    return 2;
  }
  const bool windows = !options.output && open_windows();
  const std::filesystem::path output_dir = options.output.value_or("vsl-view-out");
  if (!windows) {
    std::error_code error;
    std::filesystem::create_directories(output_dir, error);
    if (error || !std::filesystem::is_directory(output_dir)) {
      std::cerr << "vsl-view: cannot create output directory '" << output_dir.string()
                << "': " << (error ? error.message() : "not a directory") << "\n";
      return 2;
    }
  }
  std::optional<vsl::runtime::LcmBus> bus_storage;
  try {
    bus_storage.emplace(options.lcm_url, log);
  } catch (const std::exception& error) {
    std::cerr << "vsl-view: " << error.what() << "\n";
    return 2;
  }
  vsl::runtime::Bus& bus = *bus_storage;

  const vsl::view::MapFrame map_frame = vsl::view::map_frame_for(world, options.px_per_m);
  const cv::Mat world_picture = vsl::view::draw_world(world, map_frame);

  // The newest of everything.
  std::optional<vsl::localizer_status_t> status;
  std::optional<vsl::pose_estimate_t> estimate;
  std::optional<Eigen::Isometry3d> truth;
  std::vector<vsl::view::FusedPercept> fused;
  std::int64_t fused_request_id = -1;
  std::optional<Eigen::Vector3d> gaze_target;
  std::deque<Frame> frames;
  vsl::view::CameraView camera;  // newest frame, with its percepts once they arrived
  std::optional<std::int64_t> camera_percepts_frame;  // frame_id whose percepts `camera` shows
  cv::Mat debug_image;
  bool dirty = true;
  // A POSE_ESTIMATE asks for final.png a moment later: the localizer's closing status follows
  // it, and the simulator's ground truth comes with its next frame.
  using Clock = std::chrono::steady_clock;
  std::optional<Clock::time_point> final_at;

  vsl::runtime::subscribe<vsl::localizer_status_t>(
      bus, "LOCALIZER_STATUS", [&](const vsl::localizer_status_t& m, std::int64_t) {
        // A new request: what belonged to the previous one is no longer current.
        if (estimate && m.request_id >= 0 && m.request_id != estimate->request_id &&
            m.state != vsl::localizer_status_t::IDLE) {
          estimate.reset();
          fused.clear();
        }
        status = m;
        dirty = true;
      });
  vsl::runtime::subscribe<vsl::pose_estimate_t>(
      bus, "POSE_ESTIMATE", [&](const vsl::pose_estimate_t& m, std::int64_t) {
        estimate = m;
        dirty = true;
        // Not postponed by further estimates, so that a stream of them still gets pictures.
        if (!final_at) final_at = Clock::now() + std::chrono::milliseconds(300);
      });
  vsl::runtime::subscribe<vsl::ground_truth_pose_t>(
      bus, "GROUND_TRUTH_POSE", [&](const vsl::ground_truth_pose_t& m, std::int64_t) {
        truth = vsl::view::isometry_of(m.world_T_ego);
        dirty = true;
      });
  vsl::runtime::subscribe<vsl::fused_percept_list_t>(
      bus, "FUSED_PERCEPTS", [&](const vsl::fused_percept_list_t& m, std::int64_t) {
        fused = vsl::view::fused_percepts_of(m);
        fused_request_id = m.request_id;
        dirty = true;
      });
  vsl::runtime::subscribe<vsl::gaze_command_t>(
      bus, "GAZE_COMMAND", [&](const vsl::gaze_command_t& m, std::int64_t) {
        const Eigen::Vector3d target(m.ego_target_m[0], m.ego_target_m[1], m.ego_target_m[2]);
        if (m.mode == vsl::gaze_command_t::TARGET_POINT && target.allFinite()) {
          gaze_target = target;
        } else {
          gaze_target.reset();  // joint targets: no point to show
        }
        dirty = true;
      });
  // Images: a few queued at most; a viewer wants the newest, not a backlog.
  vsl::runtime::subscribe<vsl::stereo_frame_t>(
      bus, "STEREO_FRAME",
      [&](const vsl::stereo_frame_t& m, std::int64_t) {
        const std::string problem = vsl::recognition_daemon::image_problem(
            m.left, intrinsics.width_px, intrinsics.height_px);
        if (!problem.empty()) {
          log.warn("STEREO_FRAME ", m.frame_id, ": left image: ", problem);
          return;
        }
        Frame frame{m.frame_id, {}};
        cv::Mat view;
        vsl::recognition_daemon::image_to_bgr(m.left, view);
        frame.left_bgr = view.clone();  // `view` may share the message's bytes
        frames.push_back(frame);
        if (frames.size() > kFramesKept) frames.pop_front();
        // Shown bare until its percepts arrive, unless the shown frame's percepts are recent.
        if (!camera_percepts_frame || m.frame_id > *camera_percepts_frame + 3 ||
            m.frame_id < *camera_percepts_frame) {
          camera = {frame.left_bgr,
                    Eigen::Isometry3d::Identity(),
                    {},
                    "frame " + std::to_string(m.frame_id) + " (no percepts yet)"};
          camera_percepts_frame.reset();
        }
        dirty = true;
      },
      4);
  vsl::runtime::subscribe<vsl::percept_list_t>(
      bus, "PERCEPTS", [&](const vsl::percept_list_t& m, std::int64_t) {
        const auto pose = vsl::view::isometry_of(m.ego_T_left_camera);
        if (!pose) return;
        for (const Frame& frame : frames) {
          if (frame.frame_id != m.frame_id) continue;
          camera = {frame.left_bgr, *pose, vsl::view::camera_percepts_of(m),
                    "left camera, frame " + std::to_string(m.frame_id) + ": " +
                        std::to_string(m.percepts.size()) + " percepts"};
          camera_percepts_frame = m.frame_id;
          dirty = true;
        }
      });
  vsl::runtime::subscribe<vsl::image_t>(
      bus, "RECOGNITION_DEBUG",
      [&](const vsl::image_t& m, std::int64_t) {
        if (!vsl::recognition_daemon::image_problem(m, m.width, m.height).empty()) return;
        cv::Mat view;
        vsl::recognition_daemon::image_to_bgr(m, view);
        debug_image = view.clone();
        dirty = true;
      },
      4);

  auto render = [&] {
    vsl::view::MapOverlay overlay;
    overlay.world_T_ego_truth = truth;
    overlay.fused_percepts = fused;
    overlay.ego_gaze_target_m = gaze_target;
    if (estimate) {
      overlay.hypotheses = vsl::view::hypotheses_of(*estimate);
      if (estimate->request_id == fused_request_id) {
        vsl::view::mark_matches(*estimate, overlay.fused_percepts);
      }
      if (estimate->status != vsl::pose_estimate_t::FAILED) {
        overlay.world_T_ego_estimate = vsl::view::isometry_of(estimate->world_T_ego);
        overlay.estimate_covariance = vsl::view::covariance_of(*estimate);
      }
    }
    overlay.caption = vsl::view::map_caption(status, estimate, overlay);
    const cv::Mat map = vsl::view::draw_map(world_picture, map_frame, overlay);
    const cv::Mat camera_picture =
        debug_image.empty() ? vsl::view::draw_camera(camera, intrinsics)
                            : vsl::view::draw_captioned(debug_image, "RECOGNITION_DEBUG");
    return std::pair{map, camera_picture};
  };

  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.period_s));
  Clock::time_point next_write = Clock::now();
  for (;;) {
    vsl::runtime::HandleResult result = vsl::runtime::HandleResult::kError;
    try {
      result = bus.handle(std::chrono::milliseconds(windows ? 30 : 100));
    } catch (const std::exception& error) {
      log.error("bus: ", error.what());
      return 1;
    }
    if (result == vsl::runtime::HandleResult::kError) {
      std::cerr << "vsl-view: the LCM bus failed\n";
      return 1;
    }
    const bool end_of_log = result == vsl::runtime::HandleResult::kEndOfLog;
    const bool final_due = final_at && (Clock::now() >= *final_at || end_of_log);
    const bool due = final_due || end_of_log || (dirty && Clock::now() >= next_write);
    if (due) {
      const auto [map, camera_picture] = render();
      if (windows) {
        cv::imshow("vsl-view: map", map);
        cv::imshow("vsl-view: camera", camera_picture);
      } else {
        write_png(output_dir / "map.png", map, log);
        write_png(output_dir / "camera.png", camera_picture, log);
        if (final_due) {
          write_png(output_dir / "final.png", vsl::view::side_by_side(map, camera_picture), log);
        }
      }
      dirty = false;
      next_write = Clock::now() + period;
      if (final_due && options.once) return 0;
      if (final_due) final_at.reset();
    }
    if (end_of_log) return 0;
    if (windows) {
      const int key = cv::waitKey(1);
      if (key == 'q' || key == 27) return 0;
    }
  }
}
