// Scoring localization results against the ground truth of scenarios (issue 3): correct,
// ambiguous (with or without the truth among the hypotheses), failed, wrong-confident, and the
// distributions of errors and times.
#pragma once

#include <Eigen/Geometry>

#include <cstddef>
#include <numbers>
#include <optional>
#include <vector>

#include "vsl/localization/types.hpp"

namespace vsl::scenario {

struct Thresholds {
  double position_m = 0.05;                             // 5 cm
  double heading_rad = 2.0 * std::numbers::pi / 180.0;  // 2 deg
};

struct PoseError {
  double position_m = 0.0;    // |t_estimate - t_truth|
  double heading_rad = 0.0;   // |yaw difference| of the ego x axes in the world's xy plane, wrapped
  double rotation_rad = 0.0;  // angle of the whole relative rotation (tilt included)
};

PoseError pose_error(const Eigen::Isometry3d& world_T_ego_estimate,
                     const Eigen::Isometry3d& world_T_ego_truth);
bool within(const PoseError& error, const Thresholds& thresholds);

// One scenario's result, judged.
struct Outcome {
  localization::Status status = localization::Status::kFailed;
  std::optional<PoseError> error;  // of the reported pose; none when failed
  bool correct = false;            // localized and within the thresholds
  bool truth_among_hypotheses = false;
  std::size_t hypotheses = 0;
  std::size_t percepts = 0;
  localization::StageTimes timing;  // the localizer's own stage times
  double wall_ms = 0.0;             // measured around localize() by the caller
};

Outcome assess(const localization::LocalizationResult& result,
               const Eigen::Isometry3d& world_T_ego_truth, const Thresholds& thresholds,
               std::size_t percepts, double wall_ms);

struct Distribution {
  std::size_t count = 0;
  double median = 0.0;
  double p95 = 0.0;
  double max = 0.0;
};
// Linear-interpolated percentiles (numpy's default); all zero for an empty sample.
Distribution distribution(std::vector<double> values);

struct Summary {
  std::size_t scenarios = 0;
  std::size_t localized = 0, correct = 0, wrong_confident = 0;
  std::size_t ambiguous = 0, ambiguous_with_truth = 0;
  std::size_t failed = 0;
  Distribution position_error_m;             // over localized results
  Distribution heading_error_deg;            // over localized results
  Distribution total_ms;                     // the localizer's total, all scenarios
  Distribution wall_ms;                      // around localize(), all scenarios
  localization::StageTimes median_stage_ms;  // per stage, all scenarios
  Distribution percepts;                     // per scenario

  double rate(std::size_t n) const { return scenarios ? static_cast<double>(n) / scenarios : 0.0; }
};

Summary summarize(const std::vector<Outcome>& outcomes);

}  // namespace vsl::scenario
