#include "shared_noise_fit.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

namespace vsl::scan_noise {
namespace {

// One matched percept, in the terms of the model (shared_noise_fit.hpp).
struct Matched {
  Eigen::Vector3d error_m;    // e_i, ego frame
  Eigen::Vector3d ray;        // r_i: camera to the object, unit
  double range_m = 0.0;       // z_i
  double disparity_px = 0.0;  // delta_i
  Eigen::Matrix3d covariance_m2;
  double shared_sigma_m = 0.0;
  double shared_ray_sigma_m = 0.0;
};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

// e^T C^-1 e, or nullopt when C is not positive definite.
std::optional<double> squared_mahalanobis(const Eigen::Vector3d& e, const Eigen::Matrix3d& c) {
  const Eigen::LLT<Eigen::Matrix3d> llt(c);
  if (llt.info() != Eigen::Success) return std::nullopt;
  return e.dot(llt.solve(e));
}

struct ClassTally {
  ClassFit fit;
  std::vector<double> across_terms, along_means_px2, within_along_px2, ranges_m;
  std::vector<double> across_mean_norms, within_across, along_mean_abs;
  std::vector<double> claimed_floor, claimed_disparity, own_d2, whole_d2;
};

// The group's share of the estimators (shared_noise_fit.hpp) and the honesty figures.
void add_group(const std::vector<Matched>& group, const FitOptions& o, ClassTally& t) {
  const double n = static_cast<double>(group.size());
  Eigen::Vector3d mean_error = Eigen::Vector3d::Zero(), mean_across = Eigen::Vector3d::Zero();
  double mean_delta = 0.0, mean_range = 0.0;
  std::vector<Eigen::Vector3d> across;
  for (const Matched& m : group) {
    across.push_back(m.error_m - m.ray * m.ray.dot(m.error_m));
    mean_error += m.error_m / n;
    mean_across += across.back() / n;
    mean_delta += m.disparity_px / n;
    mean_range += m.range_m / n;
  }
  double w = 0.0, v = 0.0;
  for (std::size_t i = 0; i < group.size(); ++i) {
    w += (across[i] - mean_across).squaredNorm() / (n - 1.0);
    v += (group[i].disparity_px - mean_delta) * (group[i].disparity_px - mean_delta) / (n - 1.0);
  }
  t.across_terms.push_back((mean_across.squaredNorm() - w / n) / 2.0);
  t.along_means_px2.push_back(mean_delta * mean_delta - v / n);
  t.within_along_px2.push_back(v / n);
  t.ranges_m.push_back(mean_range);
  t.across_mean_norms.push_back(mean_across.norm());
  t.within_across.push_back(w / n);
  t.along_mean_abs.push_back(std::abs(mean_delta));
  const double fb = o.focal_px * o.baseline_m;
  for (const Matched& m : group) {
    t.claimed_floor.push_back(m.shared_sigma_m);
    t.claimed_disparity.push_back(m.shared_ray_sigma_m * fb / (m.range_m * m.range_m));
    const Eigen::Matrix3d shared =
        m.shared_sigma_m * m.shared_sigma_m * Eigen::Matrix3d::Identity() +
        m.shared_ray_sigma_m * m.shared_ray_sigma_m * m.ray * m.ray.transpose();
    if (const auto d2 = squared_mahalanobis(m.error_m - mean_error,
                                            (m.covariance_m2 - shared) * (n - 1.0) / n)) {
      t.own_d2.push_back(*d2);
    }
    if (const auto d2 = squared_mahalanobis(m.error_m, m.covariance_m2)) t.whole_d2.push_back(*d2);
  }
  ++t.fit.groups;
  t.fit.percepts += static_cast<int>(group.size());
}

void finish(const FitOptions& o, ClassTally& t) {
  ClassFit& f = t.fit;
  const double fb = o.focal_px * o.baseline_m;
  f.floor_m = std::sqrt(std::max(0.0, mean(t.across_terms)));
  double along = 0.0;
  for (std::size_t g = 0; g < t.along_means_px2.size(); ++g) {
    const double floor_px = fb * f.floor_m / (t.ranges_m[g] * t.ranges_m[g]);
    along += (t.along_means_px2[g] - floor_px * floor_px) /
             static_cast<double>(t.along_means_px2.size());
  }
  f.shared_disparity_px = std::sqrt(std::max(0.0, along));
  const double floor_robust2 =
      std::pow(median(t.across_mean_norms) / 1.1774, 2) - median(t.within_across) / 2.0;
  f.floor_robust_m = std::sqrt(std::max(0.0, floor_robust2));
  const double along_robust2 =
      std::pow(median(t.along_mean_abs) / 0.6745, 2) - median(t.within_along_px2);
  f.shared_disparity_robust_px = std::sqrt(std::max(0.0, along_robust2));
  f.claimed_floor_m = median(t.claimed_floor);
  f.claimed_shared_disparity_px = median(t.claimed_disparity);
  f.own_median_d2 = median(t.own_d2);
  f.whole_median_d2 = median(t.whole_d2);
  const auto within =
      std::count_if(t.whole_d2.begin(), t.whole_d2.end(), [](double d2) { return d2 <= 9.0; });
  f.whole_within_3_sigma =
      t.whole_d2.empty() ? 0.0
                         : static_cast<double>(within) / static_cast<double>(t.whole_d2.size());
}

// Matches each scan's percepts to the set's world and adds its groups.
void tally_scans(const ScanSet& set, const FitOptions& o, double fb,
                 std::map<std::string, ClassTally>& tallies) {
  const world::WorldModel& world = *set.world;
  for (const ScanFrames& scan : set.scans) {
    const Eigen::Isometry3d ego_T_world = scan.world_T_ego.inverse();
    std::map<std::pair<std::string, std::size_t>, std::vector<Matched>> groups;
    for (const FramePerceptRecord& p : scan.percepts) {
      // The gate (shared_noise_fit.hpp), in the ego frame along the ray from the camera.
      std::size_t nearest = world.objects.size();
      double nearest_gate = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < world.objects.size(); ++k) {
        if (world.objects[k].type != p.type) continue;
        const Eigen::Vector3d object_m = ego_T_world * world.objects[k].world_position_m;
        const Eigen::Vector3d ray = (object_m - p.ego_camera_position_m).normalized();
        const Eigen::Vector3d error_m = p.ego_position_m - object_m;
        const double along_m = error_m.dot(ray);
        const double across_m = (error_m - along_m * ray).norm();
        const double gate =
            std::pow(across_m / o.match_across_m, 2) + std::pow(along_m / o.match_along_m, 2);
        if (gate < nearest_gate) nearest_gate = gate, nearest = k;
      }
      if (nearest_gate > 1.0) {
        ++tallies[p.type].fit.unmatched;
        continue;
      }
      const Eigen::Vector3d object_m = ego_T_world * world.objects[nearest].world_position_m;
      Matched m;
      m.error_m = p.ego_position_m - object_m;
      const Eigen::Vector3d to_object = object_m - p.ego_camera_position_m;
      m.range_m = to_object.norm();
      if (!(m.range_m > 1e-3)) continue;
      m.ray = to_object / m.range_m;
      const double measured_m = std::max(m.range_m + m.error_m.dot(m.ray), 1e-3);
      m.disparity_px = fb * (1.0 / measured_m - 1.0 / m.range_m);
      m.covariance_m2 = p.ego_covariance_m2;
      m.shared_sigma_m = p.shared_sigma_m;
      m.shared_ray_sigma_m = p.shared_ray_sigma_m;
      groups[{p.type, nearest}].push_back(m);
    }
    std::map<std::string, bool> seen;
    for (const auto& [key, group] : groups) {
      if (static_cast<int>(group.size()) < o.min_percepts) continue;
      add_group(group, o, tallies[key.first]);
      seen[key.first] = true;
    }
    for (const auto& [type, unused] : seen) ++tallies[type].fit.scans;
  }
}

}  // namespace

std::map<std::string, ClassFit> fit_shared_noise(const std::vector<ScanSet>& sets,
                                                 const FitOptions& o) {
  if (!(o.focal_px > 0.0) || !(o.baseline_m > 0.0) || !(o.match_across_m > 0.0) ||
      !(o.match_along_m > 0.0) || o.min_percepts < 2) {
    throw std::invalid_argument(
        "fit_shared_noise: focal length, baseline and match gate must be positive and "
        "min_percepts at least 2");
  }
  const double fb = o.focal_px * o.baseline_m;
  std::map<std::string, ClassTally> tallies;
  for (const ScanSet& set : sets) {
    if (!set.world) throw std::invalid_argument("fit_shared_noise: a scan set without a world");
    tally_scans(set, o, fb, tallies);
  }
  std::map<std::string, ClassFit> fits;
  for (auto& [type, tally] : tallies) {
    finish(o, tally);
    fits[type] = tally.fit;
  }
  return fits;
}

void print_fits(const std::map<std::string, ClassFit>& fits, std::ostream& out) {
  char line[512];
  for (const auto& [type, f] : fits) {
    std::snprintf(line, sizeof line,
                  "%s: %d groups (object x scan) in %d scans, %d percepts; %d outside every "
                  "object's gate\n",
                  type.c_str(), f.groups, f.scans, f.percepts, f.unmatched);
    out << line;
    if (f.groups == 0) continue;
    std::snprintf(line, sizeof line,
                  "  floor_m             %.4f m  (robust %.4f; claimed %.4f)\n"
                  "  shared_disparity_px %.3f px (robust %.3f; claimed %.3f)\n"
                  "  own part about the object's mean: median d2 %.2f (2.37 when honest)\n"
                  "  whole covariance: median d2 %.2f (2.37), %.0f %% within 3 sigma (97 %%)\n",
                  f.floor_m, f.floor_robust_m, f.claimed_floor_m, f.shared_disparity_px,
                  f.shared_disparity_robust_px, f.claimed_shared_disparity_px, f.own_median_d2,
                  f.whole_median_d2, 100.0 * f.whole_within_3_sigma);
    out << line;
  }
}

}  // namespace vsl::scan_noise
