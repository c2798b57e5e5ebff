// vsl-localize: localize once from a percept file against a world model (paper §2.3-2.4), and
// print the pose, its covariance, the ranked hypotheses and the time of each stage.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "json_writer.hpp"
#include "vsl/config/node.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/localization/percept_file.hpp"
#include "vsl/localization/truth_check.hpp"
#include "vsl/world/world_io.hpp"

namespace {

using vsl::localization::LocalizationResult;
using vsl::localization::PerceptTruth;

constexpr const char* kUsage =
    R"(usage: vsl-localize --world WORLD.yaml --percepts PERCEPTS.yaml [--config FILE] [--json]

Localizes the robot from fused percepts in its ego frame against a world model: proximity and
orientation filtering of the world graph, hypotheses from restriction spheres, validation, and a
Ceres-refined 6-DoF pose world_T_ego with its covariance. Formats: docs/localize.md.
  --world FILE     world model (docs/world-model.md)
  --percepts FILE  percepts: [{type, position: [x, y, z], covariance?, support?}], ego frame, m
  --config FILE    localizer configuration (default: built-in defaults, as config/localizer.yaml)
  --json           print one JSON object instead of text
With a ground truth in the percept file it also prints, per percept, the object of its type it
lies nearest under the truth and how many sigmas off (a failure with too few percepts near their
objects is the recognizer's, not the localizer's).
exit codes: 0 localized or ambiguous, 1 failed, 2 bad input or usage
)";

struct Options {
  std::string world, percepts, config;
  bool json = false;
};

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-localize: " << what << " (see vsl-localize --help)\n";
  std::exit(2);
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
    } else if (arg == "--world") {
      options.world = value();
    } else if (arg == "--percepts") {
      options.percepts = value();
    } else if (arg == "--config") {
      options.config = value();
    } else if (arg == "--json") {
      options.json = true;
    } else {
      usage_error("unknown argument " + arg);
    }
  }
  if (options.world.empty()) usage_error("--world is required");
  if (options.percepts.empty()) usage_error("--percepts is required");
  return options;
}

Eigen::Quaterniond quaternion(const Eigen::Isometry3d& pose) {
  Eigen::Quaterniond q(pose.rotation());
  if (q.w() < 0) q.coeffs() *= -1.0;
  return q.normalized();
}

void write_pose(vsl::tools::JsonWriter& json, const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q = quaternion(pose);
  json.begin_object();
  json.key("position")
      .numbers({pose.translation().x(), pose.translation().y(), pose.translation().z()});
  json.key("quaternion").numbers({q.w(), q.x(), q.y(), q.z()});
  json.end_object();
}

void write_associations(vsl::tools::JsonWriter& json,
                        const std::vector<vsl::localization::Association>& associations) {
  json.begin_array();
  for (const auto& a : associations) {
    json.begin_object();
    json.key("percept").number(a.percept_index);
    json.key("object").string(a.object_id);
    json.end_object();
  }
  json.end_array();
}

// The id of the world object behind graph node `node`.
const std::string& object_id(const vsl::localization::Localizer& localizer,
                             vsl::world::NodeIndex node) {
  return localizer.world().objects[localizer.graph().object_index(node)].id;
}

void write_truth(vsl::tools::JsonWriter& json, const vsl::localization::Localizer& localizer,
                 const std::vector<PerceptTruth>& truth) {
  json.begin_array();
  for (std::size_t i = 0; i < truth.size(); ++i) {
    json.begin_object();
    json.key("percept").number(static_cast<double>(i));
    if (truth[i].nearest) {
      json.key("object").string(object_id(localizer, *truth[i].nearest));
      json.key("distance_m").number(truth[i].distance_m);
      json.key("sigmas").number(truth[i].sigmas);
      json.key("bar_object").string(object_id(localizer, *truth[i].nearest_bar));
      json.key("bar_sigmas").number(truth[i].bar_sigmas);
    }
    json.end_object();
  }
  json.end_array();
}

void print_json(const LocalizationResult& result, const vsl::localization::Localizer& localizer,
                const std::optional<std::vector<PerceptTruth>>& truth) {
  vsl::tools::JsonWriter json(std::cout);
  json.begin_object();
  json.key("status").string(vsl::localization::to_string(result.status));
  json.key("pose");
  write_pose(json, result.world_T_ego);
  json.key("covariance").begin_array();
  for (int r = 0; r < 6; ++r) {
    json.numbers({result.covariance(r, 0), result.covariance(r, 1), result.covariance(r, 2),
                  result.covariance(r, 3), result.covariance(r, 4), result.covariance(r, 5)});
  }
  json.end_array();
  json.key("hypotheses").begin_array();
  for (const auto& h : result.hypotheses) {
    json.begin_object();
    json.key("pose");
    write_pose(json, h.world_T_ego);
    json.key("score").number(h.score);
    json.key("associations");
    write_associations(json, h.associations);
    json.end_object();
  }
  json.end_array();
  json.key("associations");
  write_associations(json, result.associations);
  const auto& t = result.timing;
  json.key("timing_ms").begin_object();
  json.key("proximity_filter").number(t.proximity_filter_ms);
  json.key("orientation_filter").number(t.orientation_filter_ms);
  json.key("hypothesis_generation").number(t.hypothesis_generation_ms);
  json.key("validation").number(t.validation_ms);
  json.key("refinement").number(t.refinement_ms);
  json.key("total").number(t.total_ms);
  json.end_object();
  if (truth) {
    json.key("truth");
    write_truth(json, localizer, *truth);
  }
  json.end_object();
  std::cout << "\n";
}

double yaw_deg(const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d x = pose.rotation() * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x()) * 180.0 / M_PI;
}

void print_pose_line(const char* label, const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q = quaternion(pose);
  std::printf(
      "%s position [%.4f, %.4f, %.4f] m, quaternion [%.6f, %.6f, %.6f, %.6f] (yaw %.2f deg)\n",
      label, pose.translation().x(), pose.translation().y(), pose.translation().z(), q.w(), q.x(),
      q.y(), q.z(), yaw_deg(pose));
}

// Each percept against the ground truth (truth_check.hpp), and how many lie within the validation
// gate of an object of their type.
void print_truth(const vsl::localization::Localizer& localizer,
                 const vsl::localization::PerceptFile& file,
                 const std::vector<PerceptTruth>& truth) {
  const vsl::localization::ValidationOptions& v = localizer.options().validation;
  std::printf(
      "percepts under the ground truth (the nearest object of their type; gate %.1f sigmas):\n",
      v.gate_sigmas);
  std::size_t near = 0, on_bar = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const PerceptTruth& t = truth[i];
    const std::string& type = file.percepts[i].type;
    if (!t.nearest) {
      std::printf("  %3zu %-16s no object of this type\n", i, type.c_str());
      continue;
    }
    const bool in_gate = t.sigmas <= v.gate_sigmas;
    const bool piece = !in_gate && t.bar_sigmas <= v.gate_sigmas;
    near += in_gate;
    on_bar += piece;
    std::printf("  %3zu %-16s %-36s %6.1f cm %6.1f sigmas", i, type.c_str(),
                object_id(localizer, *t.nearest).c_str(), 100.0 * t.distance_m, t.sigmas);
    if (piece) {
      std::printf(", %.1f from the bar of %s", t.bar_sigmas,
                  object_id(localizer, *t.nearest_bar).c_str());
    }
    std::printf("\n");
  }
  std::printf(
      "within the gate: %zu of %zu percepts (%zu more on a bar); validation needs %.0f %%\n", near,
      truth.size(), on_bar, 100.0 * v.min_explained_fraction);
}

void print_text(const LocalizationResult& result, const vsl::localization::PerceptFile& file,
                const vsl::localization::Localizer& localizer,
                const std::optional<std::vector<PerceptTruth>>& truth) {
  std::printf("status: %s%s%s\n", vsl::localization::to_string(result.status),
              result.message.empty() ? "" : " - ", result.message.c_str());
  if (result.status == vsl::localization::Status::kLocalized) {
    print_pose_line("pose world_T_ego:", result.world_T_ego);
    const auto& c = result.covariance;
    std::printf("  1-sigma: x %.4f y %.4f z %.4f m, rx %.3f ry %.3f rz %.3f deg\n",
                std::sqrt(c(0, 0)), std::sqrt(c(1, 1)), std::sqrt(c(2, 2)),
                std::sqrt(c(3, 3)) * 180 / M_PI, std::sqrt(c(4, 4)) * 180 / M_PI,
                std::sqrt(c(5, 5)) * 180 / M_PI);
    std::printf("associations:");
    for (const auto& a : result.associations)
      std::printf(" %d->%s", a.percept_index, a.object_id.c_str());
    std::printf("\n");
  }
  std::printf("hypotheses: %zu\n", result.hypotheses.size());
  for (std::size_t i = 0; i < result.hypotheses.size() && i < 10; ++i) {
    const auto& h = result.hypotheses[i];
    char label[64];
    std::snprintf(label, sizeof label, "  #%zu score %.2f, %zu assoc.:", i + 1, h.score,
                  h.associations.size());
    print_pose_line(label, h.world_T_ego);
  }
  if (file.ground_truth_world_T_ego) {
    print_pose_line("ground truth:    ", *file.ground_truth_world_T_ego);
    if (result.status == vsl::localization::Status::kLocalized) {
      const Eigen::Isometry3d error = file.ground_truth_world_T_ego->inverse() * result.world_T_ego;
      std::printf("error: %.4f m, %.3f deg\n", error.translation().norm(),
                  Eigen::AngleAxisd(error.rotation()).angle() * 180 / M_PI);
    }
  }
  if (truth) print_truth(localizer, file, *truth);
  const auto& t = result.timing;
  std::printf(
      "time (ms): proximity %.3f, orientation %.3f, hypotheses %.3f, validation %.3f, "
      "refinement %.3f, total %.3f\n",
      t.proximity_filter_ms, t.orientation_filter_ms, t.hypothesis_generation_ms, t.validation_ms,
      t.refinement_ms, t.total_ms);
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    vsl::localization::LocalizerOptions localizer_options;
    if (!options.config.empty()) {
      localizer_options =
          vsl::localization::localizer_options_from(vsl::config::Node::load_file(options.config));
    }
    const vsl::world::WorldModel world = vsl::world::load_world(options.world);
    const vsl::localization::PerceptFile file =
        vsl::localization::load_percept_file(options.percepts);
    const vsl::localization::Localizer localizer(world, localizer_options);
    const LocalizationResult result = localizer.localize(file.percepts);
    std::optional<std::vector<PerceptTruth>> truth;
    if (file.ground_truth_world_T_ego) {
      truth = vsl::localization::check_against_truth(localizer, file.percepts,
                                                     *file.ground_truth_world_T_ego);
    }
    if (options.json) {
      print_json(result, localizer, truth);
    } else {
      print_text(result, file, localizer, truth);
    }
    return result.status == vsl::localization::Status::kFailed ? 1 : 0;
  } catch (const vsl::config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
