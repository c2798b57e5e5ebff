#include "vsl/scenario/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsl::scenario {
namespace {

double heading_of(const Eigen::Isometry3d& world_T_ego) {
  const Eigen::Vector3d forward = world_T_ego.linear().col(0);  // ego x in the world
  return std::atan2(forward.y(), forward.x());
}

}  // namespace

PoseError pose_error(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth) {
  PoseError e;
  e.position_m = (estimate.translation() - truth.translation()).norm();
  e.heading_rad =
      std::abs(std::remainder(heading_of(estimate) - heading_of(truth), 2 * std::numbers::pi));
  e.rotation_rad = Eigen::AngleAxisd(estimate.linear().transpose() * truth.linear()).angle();
  return e;
}

bool within(const PoseError& error, const Thresholds& t) {
  return error.position_m < t.position_m && error.heading_rad < t.heading_rad;
}

Outcome assess(const localization::LocalizationResult& result, const Eigen::Isometry3d& truth,
               const Thresholds& thresholds, std::size_t percepts, double wall_ms) {
  Outcome o;
  o.status = result.status;
  o.hypotheses = result.hypotheses.size();
  o.percepts = percepts;
  o.timing = result.timing;
  o.wall_ms = wall_ms;
  if (result.status != localization::Status::kFailed) {
    o.error = pose_error(result.world_T_ego, truth);
  }
  o.correct = result.status == localization::Status::kLocalized && within(*o.error, thresholds);
  o.truth_among_hypotheses =
      (o.error && within(*o.error, thresholds)) ||
      std::any_of(result.hypotheses.begin(), result.hypotheses.end(), [&](const auto& h) {
        return within(pose_error(h.world_T_ego, truth), thresholds);
      });
  return o;
}

Distribution distribution(std::vector<double> values) {
  Distribution d;
  d.count = values.size();
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  const auto at = [&](double q) {
    const double position = q * static_cast<double>(values.size() - 1);
    const std::size_t lo = static_cast<std::size_t>(std::floor(position));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (position - static_cast<double>(lo)) * (values[hi] - values[lo]);
  };
  d.median = at(0.5);
  d.p95 = at(0.95);
  d.max = values.back();
  return d;
}

Summary summarize(const std::vector<Outcome>& outcomes) {
  Summary s;
  s.scenarios = outcomes.size();
  std::vector<double> position, heading, total, wall, percepts;
  std::vector<double> proximity, orientation, generation, validation, refinement;
  for (const Outcome& o : outcomes) {
    total.push_back(o.timing.total_ms);
    proximity.push_back(o.timing.proximity_filter_ms);
    orientation.push_back(o.timing.orientation_filter_ms);
    generation.push_back(o.timing.hypothesis_generation_ms);
    validation.push_back(o.timing.validation_ms);
    refinement.push_back(o.timing.refinement_ms);
    wall.push_back(o.wall_ms);
    percepts.push_back(static_cast<double>(o.percepts));
    switch (o.status) {
      case localization::Status::kLocalized:
        ++s.localized;
        if (o.correct) {
          ++s.correct;
        } else {
          ++s.wrong_confident;
        }
        position.push_back(o.error->position_m);
        heading.push_back(o.error->heading_rad * 180.0 / std::numbers::pi);
        break;
      case localization::Status::kAmbiguous:
        ++s.ambiguous;
        if (o.truth_among_hypotheses) ++s.ambiguous_with_truth;
        break;
      case localization::Status::kFailed:
        ++s.failed;
        break;
    }
  }
  s.position_error_m = distribution(position);
  s.heading_error_deg = distribution(heading);
  s.total_ms = distribution(total);
  s.wall_ms = distribution(wall);
  s.median_stage_ms.proximity_filter_ms = distribution(proximity).median;
  s.median_stage_ms.orientation_filter_ms = distribution(orientation).median;
  s.median_stage_ms.hypothesis_generation_ms = distribution(generation).median;
  s.median_stage_ms.validation_ms = distribution(validation).median;
  s.median_stage_ms.refinement_ms = distribution(refinement).median;
  s.median_stage_ms.total_ms = s.total_ms.median;
  s.percepts = distribution(percepts);
  return s;
}

}  // namespace vsl::scenario
