#include "vsl/scenario/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "vsl/config/node.hpp"

namespace vsl::scenario {

const char* to_string(PerceptSource source) {
  switch (source) {
    case PerceptSource::object:
      return "object";
    case PerceptSource::wrong_type:
      return "wrong_type";
    case PerceptSource::spurious:
      return "spurious";
  }
  return "?";
}

localization::PerceptFile Scenario::percept_file() const {
  localization::PerceptFile file;
  file.percepts = percepts;
  file.ground_truth_world_T_ego = world_T_ego;
  return file;
}

void validate(const ScenarioOptions& o) {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw config::Error("scenario options: " + what);
  };
  const double pi = std::numbers::pi;
  require(o.pose.footprint_radius_m > 0 && o.pose.footprint_radius_m < 10,
          "footprint_radius_m must be in (0, 10)");
  require(o.pose.floor_clearance_m >= 0, "floor_clearance_m must be >= 0");
  require(o.pose.camera_height_m > 0, "camera_height_m must be > 0");
  require(!o.pose.ego_height_m || *o.pose.ego_height_m >= 0, "ego_height_m must be >= 0");
  require(o.pose.yaw_spread_rad >= 0 && o.pose.yaw_spread_rad <= pi,
          "yaw spread must be in [0, 180] deg");
  require(o.pose.max_attempts >= 1, "max_attempts must be >= 1");
  require(!o.pose.floor_types.empty(), "floor_types must not be empty");
  require(!o.scan.pan_rad.empty() && !o.scan.tilt_rad.empty(),
          "the scan needs at least one pan and one tilt angle");
  for (const double tilt : o.scan.tilt_rad) {
    require(std::abs(tilt) < pi / 2, "tilt angles must be within (-90, 90) deg");
  }
  require(o.scan.horizontal_fov_rad > 0 && o.scan.horizontal_fov_rad < pi &&
              o.scan.vertical_fov_rad > 0 && o.scan.vertical_fov_rad < pi,
          "fields of view must be in (0, 180) deg");
  require(o.visibility.min_range_m >= 0 && o.visibility.max_range_m > o.visibility.min_range_m,
          "the range must satisfy 0 <= min_range_m < max_range_m");
  require(o.visibility.max_view_angle_rad > 0 && o.visibility.max_view_angle_rad <= pi,
          "max_view_angle must be in (0, 180] deg");
  require(o.visibility.occlusion_epsilon_m >= 0, "occlusion_epsilon_m must be >= 0");
  require(o.errors.false_positive_rate >= 0 && o.errors.false_positive_rate <= 0.9,
          "false-positive rate must be in [0, 0.9]");
  require(o.errors.wrong_type_fraction >= 0 && o.errors.wrong_type_fraction <= 1,
          "wrong_type_fraction must be in [0, 1]");
  require(o.errors.miss_rate >= 0 && o.errors.miss_rate <= 1, "miss rate must be in [0, 1]");
}

struct ScenarioGenerator::State {
  ScenarioOptions options;
  localization::PerceptNoiseOptions noise;
  double ego_height_m;
  std::unique_ptr<CollisionScene> scene;  // heap: the models below keep its address
  std::unique_ptr<FreeSpace> free_space;
  std::unique_ptr<HeadModel> head;

  localization::FusedPercept percept(const std::string& type, const Eigen::Vector3d& ego_point,
                                     int views) const {
    localization::FusedPercept p;
    p.type = type;
    p.ego_position_m = ego_point;
    p.support = std::max(views, 1);
    if (options.errors.write_covariance) {
      // The deviation at the reported point: what the recognizer would compute from its data.
      const double sigma = eq7_sigma_m(ego_point, noise);
      p.ego_covariance_m2 = Eigen::Matrix3d::Identity() * sigma * sigma;
    }
    return p;
  }
};

ScenarioGenerator::ScenarioGenerator(const world::WorldModel& world, ScenarioOptions options,
                                     const localization::LocalizerOptions& localizer)
    : state_(std::make_unique<State>()) {
  validate(options);
  State& s = *state_;
  s.options = std::move(options);
  s.noise = localizer.noise;
  const double camera_z = s.noise.ego_camera_position_m.z();
  s.ego_height_m = s.options.pose.ego_height_m.value_or(s.options.pose.camera_height_m - camera_z);
  const double camera_height_m = s.ego_height_m + camera_z;
  if (s.ego_height_m < 0 || camera_height_m <= s.options.pose.floor_clearance_m) {
    throw config::Error("scenario options: the camera (C_L at ego z " + std::to_string(camera_z) +
                        " m) and the ego origin (" + std::to_string(s.ego_height_m) +
                        " m) must both stand above the floor");
  }
  s.scene = std::make_unique<CollisionScene>(world);
  // The body reaches the camera at least: anything below the eyes blocks the robot.
  s.free_space = std::make_unique<FreeSpace>(*s.scene, s.options.pose,
                                             std::max(camera_height_m, s.ego_height_m));
  s.head = std::make_unique<HeadModel>(*s.scene, s.options.scan, s.options.visibility,
                                       s.noise.ego_camera_position_m, localizer.graph.node_types);
  if (s.head->types().empty()) {
    throw config::Error("world '" + world.name + "' has no object of a recognizable type");
  }
}

ScenarioGenerator::~ScenarioGenerator() = default;
ScenarioGenerator::ScenarioGenerator(ScenarioGenerator&&) noexcept = default;
ScenarioGenerator& ScenarioGenerator::operator=(ScenarioGenerator&&) noexcept = default;

const ScenarioOptions& ScenarioGenerator::options() const {
  return state_->options;
}
const localization::PerceptNoiseOptions& ScenarioGenerator::noise() const {
  return state_->noise;
}
double ScenarioGenerator::ego_height_m() const {
  return state_->ego_height_m;
}
const CollisionScene& ScenarioGenerator::scene() const {
  return *state_->scene;
}
const FreeSpace& ScenarioGenerator::free_space() const {
  return *state_->free_space;
}
const HeadModel& ScenarioGenerator::head() const {
  return *state_->head;
}

Scenario ScenarioGenerator::generate(std::uint64_t seed, std::size_t index) const {
  const State& s = *state_;
  const auto& objects = s.scene->world().objects;
  const PerceptErrorOptions& errors = s.options.errors;
  Scenario out;
  out.seed = seed;
  out.index = index;

  Rng pose_rng = Rng::for_scenario(seed, index, Stream::pose);
  out.world_T_ego =
      s.free_space->sample(pose_rng, s.ego_height_m, scan_centre_pan_rad(s.options.scan));
  out.visible = s.head->visible_objects(out.world_T_ego);

  // Noise for every visible object and a miss draw for each, whatever the rates: the streams are
  // used the same way, so the miss rate does not change the noise of the objects kept.
  Rng noise_rng = Rng::for_scenario(seed, index, Stream::noise);
  Rng miss_rng = Rng::for_scenario(seed, index, Stream::misses);
  Rng fp_rng = Rng::for_scenario(seed, index, Stream::false_positives);
  const std::vector<std::uint32_t> nearby = s.head->primitives_near(out.world_T_ego);
  out.missed.resize(out.visible.size());
  for (std::size_t k = 0; k < out.visible.size(); ++k) {
    const SeenObject& seen = out.visible[k];
    const Eigen::Vector3d noisy = with_eq7_noise(seen.ego_position_m, s.noise, noise_rng);
    out.missed[k] = miss_rng.chance(errors.miss_rate);
    if (out.missed[k]) continue;
    out.percepts.push_back(s.percept(objects[seen.object_index].type, noisy, seen.views));
    out.truth.push_back({PerceptSource::object, seen.object_index});
    // Each written percept is false with probability r: after each true one, false ones follow
    // while a draw says so (a geometric count of mean r / (1 - r)), so a fraction r of all
    // percepts are false.
    while (fp_rng.chance(errors.false_positive_rate)) {
      const std::vector<std::string>& types = s.head->types();
      const bool wrong_type = fp_rng.chance(errors.wrong_type_fraction) && types.size() > 1;
      if (wrong_type) {
        // A seen object (missed or not) recognized as another type.
        const SeenObject& object = out.visible[fp_rng.below(out.visible.size())];
        const std::string& true_type = objects[object.object_index].type;
        std::string type = true_type;
        while (type == true_type) type = types[fp_rng.below(types.size())];
        const Eigen::Vector3d point = with_eq7_noise(object.ego_position_m, s.noise, fp_rng);
        out.percepts.push_back(s.percept(type, point, object.views));
        out.truth.push_back({PerceptSource::wrong_type, object.object_index});
      } else {
        const std::string& type = types[fp_rng.below(types.size())];
        const Eigen::Vector3d point = spurious_ego_point(*s.head, out.world_T_ego, nearby, fp_rng);
        const int views = views_containing(s.options.scan, s.noise.ego_camera_position_m, point);
        out.percepts.push_back(s.percept(type, point, views));
        out.truth.push_back({PerceptSource::spurious, std::nullopt});
      }
    }
  }

  // Shuffle (Fisher-Yates on our own stream): the order of a file must not tell true percepts
  // (in object order) from false ones (right after a true one).
  Rng order_rng = Rng::for_scenario(seed, index, Stream::order);
  for (std::size_t k = out.percepts.size(); k > 1; --k) {
    const std::size_t j = order_rng.below(k);
    std::swap(out.percepts[k - 1], out.percepts[j]);
    std::swap(out.truth[k - 1], out.truth[j]);
  }
  return out;
}

std::vector<std::pair<localization::FusedPercept, PerceptTruth>> ScenarioGenerator::look_at(
    const Scenario& scenario, const Eigen::Vector3d& ego_target_m, int round) const {
  const State& s = *state_;
  const Eigen::Vector3d gaze = ego_target_m - s.noise.ego_camera_position_m;
  HeadScanOptions view = s.options.scan;
  view.pan_rad = {std::atan2(gaze.y(), gaze.x())};
  view.tilt_rad = {std::atan2(gaze.z(), gaze.head<2>().norm())};
  Rng rng = Rng::for_scenario(scenario.seed ^ (static_cast<std::uint64_t>(round) << 48),
                              scenario.index, Stream::active);
  std::vector<std::pair<localization::FusedPercept, PerceptTruth>> out;
  for (const SeenObject& seen : s.head->visible_objects(scenario.world_T_ego, view)) {
    const Eigen::Vector3d noisy = with_eq7_noise(seen.ego_position_m, s.noise, rng);
    if (rng.chance(s.options.errors.miss_rate)) continue;
    const bool known =
        std::any_of(scenario.truth.begin(), scenario.truth.end(), [&](const auto& t) {
          return t.source == PerceptSource::object && t.object_index == seen.object_index;
        });
    if (known) continue;
    out.emplace_back(s.percept(s.scene->world().objects[seen.object_index].type, noisy, seen.views),
                     PerceptTruth{PerceptSource::object, seen.object_index});
  }
  return out;
}

}  // namespace vsl::scenario
