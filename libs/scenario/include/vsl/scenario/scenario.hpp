// Seeded localization scenarios: a robot standing somewhere in a world's free space, the fused
// percepts its scanning head would deliver there (paper §2.1.1: typed points in the ego frame,
// Eq. 7 noise, misses and false positives), and the ground truth pose world_T_ego.
//
// Scenario `index` of seed `seed` is the same whatever else is generated: every scenario and every
// part of it (pose, noise, misses, false positives, order) draws from its own stream.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/percept_file.hpp"
#include "vsl/scenario/collision_scene.hpp"
#include "vsl/scenario/free_space.hpp"
#include "vsl/scenario/head_scan.hpp"
#include "vsl/scenario/percept_errors.hpp"
#include "vsl/scenario/visibility.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::scenario {

struct ScenarioOptions {
  PoseSamplingOptions pose;
  HeadScanOptions scan;
  VisibilityOptions visibility;
  PerceptErrorOptions errors;
};

// Where a percept of a scenario came from.
enum class PerceptSource { object, wrong_type, spurious };
const char* to_string(PerceptSource source);

struct PerceptTruth {
  PerceptSource source = PerceptSource::object;
  std::optional<std::size_t> object_index;  // the object seen (object, wrong_type)
};

struct Scenario {
  std::uint64_t seed = 0;
  std::size_t index = 0;
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();  // ground truth
  std::vector<SeenObject> visible;  // everything the head could recognize, before misses
  std::vector<bool> missed;         // parallel to `visible`
  std::vector<localization::FusedPercept> percepts;  // what the file holds, shuffled
  std::vector<PerceptTruth> truth;                   // parallel to `percepts`

  // The percept file of this scenario: its percepts and the ground truth.
  localization::PerceptFile percept_file() const;
};

class ScenarioGenerator {
 public:
  // Noise (zeta, C_L) comes from the localizer's options, so that scenarios and the localizer
  // agree on Eq. 7; so do the recognizable types (the graph's node types) unless
  // options.visibility.types names others. Throws config::Error when the world has no usable
  // floor or the options are out of range. `world` must outlive the generator.
  ScenarioGenerator(const world::WorldModel& world, ScenarioOptions options,
                    const localization::LocalizerOptions& localizer);
  ~ScenarioGenerator();
  ScenarioGenerator(ScenarioGenerator&&) noexcept;
  ScenarioGenerator& operator=(ScenarioGenerator&&) noexcept;

  const ScenarioOptions& options() const;
  const localization::PerceptNoiseOptions& noise() const;
  double ego_height_m() const;  // ego origin above the floor
  const CollisionScene& scene() const;
  const FreeSpace& free_space() const;
  const HeadModel& head() const;

  Scenario generate(std::uint64_t seed, std::size_t index) const;

  // Active validation (paper §2.4.2): the head looks once at `ego_target_m` (one view centred on
  // it; no joint limits: the robot may turn for it). Returns the new percepts of objects recognized
  // in that view that `scenario` has no percept of yet (misses and Eq. 7 noise apply; drawn from
  // the scenario's `active` stream with `round` mixed in), with their truth.
  std::vector<std::pair<localization::FusedPercept, PerceptTruth>> look_at(
      const Scenario& scenario, const Eigen::Vector3d& ego_target_m, int round) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Throws config::Error (no location) for options out of range.
void validate(const ScenarioOptions& options);

}  // namespace vsl::scenario
