// Tallies of a recognition evaluation (evaluation.hpp).
#include "evaluation.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vsl::tools {

int distance_band(double distance_m) {
  return std::clamp(static_cast<int>(std::floor(distance_m)), 0, kDistanceBands - 1);
}

int viewing_angle_band(double facing_cosine) {
  const double angle_deg =
      std::acos(std::clamp(facing_cosine, 0.0, 1.0)) * 180.0 / std::numbers::pi;
  int band = 0;
  while (band + 1 < kViewingAngleBands &&
         angle_deg >= kViewingAngleBandStartsDeg[static_cast<std::size_t>(band + 1)]) {
    ++band;
  }
  return band;
}

namespace {

// Counts a flat object in its viewing-angle band, and among the whole ones when it is whole.
void count_by_viewing_angle(const recognition::GroundTruthObject& object, bool whole,
                            std::array<int, kViewingAngleBands>& all,
                            std::array<int, kViewingAngleBands>& whole_only) {
  if (!object.flat) return;
  const auto band = static_cast<std::size_t>(viewing_angle_band(object.facing_cosine));
  ++all[band];
  if (whole) ++whole_only[band];
}

// Counts a false positive as misplaced, mistyped or neither (ClassTally).
void classify_false_positive(const std::vector<recognition::GroundTruthObject>& ground_truth,
                             const recognition::PerceptToMatch& percept, double max_error_m,
                             ClassTally& c) {
  bool mistyped = false;
  for (const recognition::GroundTruthObject& object : ground_truth) {
    const double distance_m = (object.ego_position_m - percept.ego_position_m).norm();
    if (object.type == c.type && distance_m <= kMisplacedDistanceM) {
      ++c.false_misplaced;
      return;
    }
    if (object.type != c.type && distance_m <= max_error_m) mistyped = true;
  }
  if (mistyped) ++c.false_mistyped;
}

}  // namespace

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double t = position - static_cast<double>(below);
  return values[below] + t * (values[above] - values[below]);
}

std::vector<recognition::PerceptMatch> tally_frame(
    const std::vector<recognition::GroundTruthObject>& ground_truth,
    const recognition::FrameResult& result, double frame_ms, double max_distance_m,
    double max_error_m, EvaluationTally& tally) {
  const Eigen::Vector3d ego_left_centre_m = result.ego_T_left_camera.translation();
  std::vector<recognition::PerceptToMatch> percepts;
  for (const recognition::FramePercept& p : result.percepts) {
    percepts.push_back({p.type, p.ego_position_m, p.confidence});
  }
  const std::vector<recognition::PerceptMatch> matches =
      recognition::match_percepts(percepts, ground_truth, max_error_m);
  // Objects outside the ground truth a percept was already left out for: one each, so a second
  // percept of one of them is a false positive, as a second percept of a ground-truth object is.
  std::vector<char> taken(ground_truth.size(), 0);
  for (ClassTally& c : tally.classes) {
    for (const recognition::GroundTruthObject& object : ground_truth) {
      if (!object.visible || object.type != c.type) continue;
      ++c.ground_truth;
      const bool whole = recognition::whole_in_both_images(object);
      if (whole) ++c.ground_truth_whole;
      count_by_viewing_angle(object, whole, c.flat_ground_truth, c.flat_ground_truth_whole);
    }
    for (std::size_t i = 0; i < percepts.size(); ++i) {
      if (percepts[i].type != c.type) continue;
      if (matches[i].ground_truth < 0 &&
          (percepts[i].ego_position_m - ego_left_centre_m).norm() > max_distance_m + max_error_m) {
        ++c.out_of_range;
        continue;
      }
      ++c.percepts;
      if (matches[i].ground_truth >= 0) {
        ++c.true_positives;
        const auto& object = ground_truth[static_cast<std::size_t>(matches[i].ground_truth)];
        const bool whole = recognition::whole_in_both_images(object);
        if (whole) ++c.true_positives_whole;
        count_by_viewing_angle(object, whole, c.flat_true_positives, c.flat_true_positives_whole);
        const auto band = static_cast<std::size_t>(distance_band(object.distance_m));
        c.errors_m[band].push_back(matches[i].error_m);
        const Eigen::Vector3d error = result.percepts[i].ego_position_m - object.ego_position_m;
        const Eigen::LDLT<Eigen::Matrix3d> covariance(result.percepts[i].ego_covariance_m2);
        if (covariance.info() == Eigen::Success && covariance.isPositive()) {
          c.mahalanobis2[band].push_back(error.dot(covariance.solve(error)));
        }
        continue;
      }
      bool on_other_object = false;
      for (std::size_t k = 0; k < ground_truth.size() && !on_other_object; ++k) {
        const recognition::GroundTruthObject& object = ground_truth[k];
        if (!taken[k] && !object.visible && object.type == c.type &&
            (object.ego_position_m - percepts[i].ego_position_m).norm() <= max_error_m) {
          ++c.false_positives_on_other_objects;
          taken[k] = 1;
          on_other_object = true;
        }
      }
      if (!on_other_object) classify_false_positive(ground_truth, percepts[i], max_error_m, c);
    }
  }
  ++tally.frames;
  tally.frame_ms.push_back(frame_ms);
  tally.segmentation_ms.push_back(result.segmentation_ms);
  tally.classification_ms.push_back(result.classification_ms);
  tally.stereo_ms.push_back(result.stereo_ms);
  return matches;
}

}  // namespace vsl::tools
