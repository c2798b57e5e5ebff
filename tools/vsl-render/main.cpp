// vsl-render: render one stereo pair of a world model as the simulated head sees it, into PNGs.
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "id_colours.hpp"
#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_io.hpp"

namespace {

constexpr const char* kUsage =
    R"(usage: vsl-render --world FILE --pose X,Y,Z,YAW_DEG -o PREFIX [options]

Renders one stereo pair of a world model as the simulated head sees it from a robot pose, into
PREFIX_left.png and PREFIX_right.png (docs/rendering.md).
  --world FILE          world model (docs/world-model.md), e.g. config/worlds/kitchen.yaml
  --pose X,Y,Z,YAW_DEG  the robot's ego frame in the world: position (m) and heading (degrees,
                        counter-clockwise from world +x; ego x is forward, z up)
  -o, --output PREFIX   output path prefix (its directory must exist)
options:
  --head FILE           head kinematics (default config/heads/armar3.yaml; docs/head.md)
  --calib FILE          stereo calibration to use instead of the head file's own
  --joints N=RAD,...    joint positions in radians; joints not named stay at their rest angle
  --look-at X,Y,Z       turn the head to look at this world point (the head's gaze solver,
                        starting from --joints)
  --ids                 also write PREFIX_ids.png: the left camera's object ids in false colour
                        (one colour per object, black where nothing)
  --depth               also write PREFIX_depth.png: the left camera's depth, 16-bit, millimetres
                        along the optical axis (0 where nothing)
  --seed N              sensor noise seed of the left image (the right one uses N + 1); default 0
  --clean               no sensor noise and no exposure variation (at realism full no shot
                        or read noise and no white-balance error)
  --realism LEVEL       off (default: flat colours), materials (textures, lamps, window light,
                        shadows, highlights) or full (materials and the camera's effects:
                        auto-exposure, vignetting, defocus, sensor noise, white balance, MJPEG)
  --exposure-ev EV      exposure compensation in EV, [-8, 8], at realism full; default 0
exit codes: 0 ok, 1 a file could not be written, 2 bad usage or input file
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-render: " << what << " (see vsl-render --help)\n";
  std::exit(2);
}

double parse_number(const std::string& text, const std::string& what) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  usage_error(what + ": '" + text + "' is not a finite number");
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, separator);) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& option) {
  const std::vector<std::string> parts = split(text, ',');
  if (parts.size() != count) {
    usage_error(option + " needs " + std::to_string(count) + " comma-separated numbers, got '" +
                text + "'");
  }
  std::vector<double> values;
  for (const std::string& part : parts) values.push_back(parse_number(part, option));
  return values;
}

struct Options {
  std::string world_file;
  std::vector<double> pose;  // x, y, z (m), yaw (deg)
  std::string prefix;
  std::string head_file = "config/heads/armar3.yaml";
  std::optional<std::string> calibration_file;
  std::vector<std::pair<std::string, double>> joints;
  std::optional<Eigen::Vector3d> look_at_world_m;
  bool ids = false;
  bool depth = false;
  std::uint64_t seed = 0;
  bool clean = false;
  vsl::render::RealismLevel realism = vsl::render::RealismLevel::off;
  std::optional<double> exposure_ev;
};

vsl::render::RealismLevel parse_realism(const std::string& text) {
  for (const auto level : {vsl::render::RealismLevel::off, vsl::render::RealismLevel::materials,
                           vsl::render::RealismLevel::full}) {
    if (text == vsl::render::realism_level_name(level)) return level;
  }
  usage_error("--realism wants off, materials or full, got '" + text + "'");
}

Options parse(int argc, char** argv) {
  Options options;
  auto value_of = [&](int& i, const std::string& arg) -> std::string {
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--world") {
      options.world_file = value_of(i, arg);
    } else if (arg == "--pose") {
      options.pose = parse_numbers(value_of(i, arg), 4, arg);
    } else if (arg == "-o" || arg == "--output") {
      options.prefix = value_of(i, arg);
    } else if (arg == "--head") {
      options.head_file = value_of(i, arg);
    } else if (arg == "--calib") {
      options.calibration_file = value_of(i, arg);
    } else if (arg == "--joints") {
      for (const std::string& item : split(value_of(i, arg), ',')) {
        const std::size_t equals = item.find('=');
        if (equals == std::string::npos || equals == 0) {
          usage_error("--joints wants NAME=RADIANS items, got '" + item + "'");
        }
        options.joints.emplace_back(item.substr(0, equals),
                                    parse_number(item.substr(equals + 1), "--joints " + item));
      }
    } else if (arg == "--look-at") {
      const std::vector<double> p = parse_numbers(value_of(i, arg), 3, arg);
      options.look_at_world_m = Eigen::Vector3d(p[0], p[1], p[2]);
    } else if (arg == "--ids") {
      options.ids = true;
    } else if (arg == "--depth") {
      options.depth = true;
    } else if (arg == "--clean") {
      options.clean = true;
    } else if (arg == "--realism") {
      options.realism = parse_realism(value_of(i, arg));
    } else if (arg == "--exposure-ev") {
      const double ev = parse_number(value_of(i, arg), arg);
      if (ev < -8.0 || ev > 8.0)
        usage_error("--exposure-ev must be in [-8, 8], got " + std::string(argv[i]));
      options.exposure_ev = ev;
    } else if (arg == "--seed") {
      const std::string text = value_of(i, arg);
      try {
        std::size_t used = 0;
        options.seed = std::stoull(text, &used);
        if (used != text.size() || text[0] == '-') throw std::invalid_argument(text);
      } catch (const std::exception&) {
        usage_error("--seed wants a non-negative integer, got '" + text + "'");
      }
    } else {
      usage_error("unknown argument " + arg);
    }
  }
  if (options.world_file.empty()) usage_error("--world is required");
  if (options.pose.empty()) usage_error("--pose is required");
  if (options.prefix.empty()) usage_error("-o PREFIX is required");
  return options;
}

// The joint state: rest angles, then --joints, then the gaze solver for --look-at.
vsl::head::JointState joint_state(const vsl::head::HeadKinematics& head, const Options& options,
                                  const Eigen::Isometry3d& world_T_ego) {
  vsl::head::JointState state = head.rest_state();
  for (const auto& [name, radians] : options.joints) {
    const std::optional<std::size_t> index = head.joint_index(name);
    if (!index) {
      std::string known;
      for (const std::string& joint : head.joint_names())
        known += (known.empty() ? "" : ", ") + joint;
      usage_error("--joints: head '" + head.name() + "' has no joint '" + name + "' (it has " +
                  known + ")");
    }
    state.positions_rad[*index] = radians;
  }
  state.positions_rad = head.clamp(state.positions_rad);
  if (options.look_at_world_m) {
    const Eigen::Vector3d ego_target_m = world_T_ego.inverse() * *options.look_at_world_m;
    const vsl::head::GazeSolution gaze = head.gaze_joint_targets(ego_target_m, state);
    if (gaze.clamped) {
      std::cerr << "vsl-render: warning: --look-at is beyond the joint limits; the cameras miss it "
                   "by "
                << gaze.max_axis_error_rad * 180.0 / std::numbers::pi << " deg\n";
    }
    state.positions_rad = gaze.targets.positions_rad;
  }
  return state;
}

vsl::render::RenderOptions render_options(const Options& options) {
  vsl::render::RenderOptions out;
  out.realism.level = options.realism;
  if (options.exposure_ev) {
    if (options.realism != vsl::render::RealismLevel::full) {
      std::cerr << "vsl-render: warning: --exposure-ev acts only at --realism full\n";
    }
    out.realism.exposure_compensation_ev = *options.exposure_ev;
  }
  if (options.clean) {
    // Nothing random: the same image for every seed.
    out.noise_sigma_grey = 0.0;
    out.exposure_variation = 0.0;
    out.realism.full_well_electrons = 0.0;  // no shot and no read noise
    out.realism.white_balance_error = 0.0;
  }
  return out;
}

void write_png(const std::string& path, const cv::Mat& image) {
  bool written = false;
  try {
    written = cv::imwrite(path, image);
  } catch (const cv::Exception&) {
  }
  if (!written) {
    std::cerr << "vsl-render: cannot write " << path << "\n";
    std::exit(1);
  }
}

// "door 5, handle 6, ..." for the objects that cover at least one pixel.
std::string visible_summary(const vsl::world::WorldModel& world, const cv::Mat& object_ids) {
  std::vector<bool> seen(world.objects.size(), false);
  for (int v = 0; v < object_ids.rows; ++v) {
    for (int u = 0; u < object_ids.cols; ++u) {
      const std::int32_t id = object_ids.at<std::int32_t>(v, u);
      if (id >= 0) seen[static_cast<std::size_t>(id)] = true;
    }
  }
  std::map<std::string, int> by_type;
  int total = 0;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (!seen[i]) continue;
    ++by_type[world.objects[i].type];
    ++total;
  }
  std::string text = std::to_string(total) + " objects";
  std::string separator = " (";
  for (const auto& [type, count] : by_type) {
    text += separator + type + " " + std::to_string(count);
    separator = ", ";
  }
  return text + (by_type.empty() ? "" : ")");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse(argc, argv);
    const vsl::world::WorldModel world = vsl::world::load_world(options.world_file);
    const vsl::head::HeadKinematics head =
        vsl::head::HeadKinematics::load(options.head_file, options.calibration_file);

    Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
    world_T_ego.translation() = Eigen::Vector3d(options.pose[0], options.pose[1], options.pose[2]);
    world_T_ego.linear() =
        Eigen::AngleAxisd(options.pose[3] * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ())
            .matrix();
    const vsl::head::JointState state = joint_state(head, options, world_T_ego);
    Eigen::Isometry3d ego_T_left, ego_T_right;
    head.ego_T_cameras(state.positions_rad, ego_T_left, ego_T_right);

    const vsl::render::Renderer renderer(world, render_options(options));
    const vsl::head::StereoCalibration& calibration = head.calibration();
    const vsl::render::RenderedImage left =
        renderer.render(calibration.left, world_T_ego * ego_T_left, options.seed);
    const vsl::render::RenderedImage right =
        renderer.render(calibration.right, world_T_ego * ego_T_right, options.seed + 1);

    std::vector<std::string> written;
    auto write = [&](const std::string& suffix, const cv::Mat& image) {
      write_png(options.prefix + suffix, image);
      written.push_back(options.prefix + suffix);
    };
    write("_left.png", left.image);
    write("_right.png", right.image);
    if (options.ids) write("_ids.png", vsl::tools::false_colour_ids(left.object_ids));
    if (options.depth) write("_depth.png", vsl::tools::depth_millimetres(left.depth_m));

    std::string joints;
    for (std::size_t i = 0; i < state.positions_rad.size(); ++i) {
      char item[96];
      std::snprintf(item, sizeof item, "%s%s=%.3f", i == 0 ? "" : ",",
                    head.joint_names()[i].c_str(), state.positions_rad[i]);
      joints += item;
    }
    const Eigen::Vector3d world_left_m = (world_T_ego * ego_T_left).translation();
    std::printf("joints: %s\n", joints.c_str());
    std::printf("left camera at (%.3f, %.3f, %.3f) m in world; sees %s\n", world_left_m.x(),
                world_left_m.y(), world_left_m.z(),
                visible_summary(world, left.object_ids).c_str());
    for (const std::string& path : written) std::printf("wrote %s\n", path.c_str());
  } catch (const vsl::config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "vsl-render: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
