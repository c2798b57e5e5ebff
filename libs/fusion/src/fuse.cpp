#include "vsl/fusion/fuse.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "vsl/fusion/isolation_filter.hpp"
#include "vsl/fusion/mean_shift.hpp"

namespace vsl::fusion {
namespace {

struct Member {
  std::size_t frame;
  const Percept* percept;
};

// E_i = Sigma_i - B of fuse.hpp as its eigen-decomposition, so that (E_i + tau2 I)^-1 is
// axes diag(1 / (variances + tau2)) axes^T for any tau2. Its eigenvalues are kept at or above a
// floor: a recognizer whose covariance is no wider than the shared part in some direction leaves
// its own part tiny there.
struct OwnPart {
  Eigen::Matrix3d axes;
  Eigen::Vector3d variances_m2;
};

OwnPart own_part(const Eigen::Matrix3d& covariance_m2, const Eigen::Matrix3d& shared_m2) {
  constexpr double kMinOwnVarianceM2 = 1e-8;
  const Eigen::Matrix3d own = covariance_m2 - shared_m2;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(0.5 * (own + own.transpose()));
  return {eigen.eigenvectors(), eigen.eigenvalues().cwiseMax(kMinOwnVarianceM2)};
}

// B_i of fuse.hpp: s^2 I + s_ray^2 r r^T, r the unit ray from the frame's left camera to the
// percept.
Eigen::Matrix3d shared_part(const Percept& percept, const Eigen::Vector3d& ego_camera_m) {
  Eigen::Matrix3d shared =
      percept.shared_sigma_m * percept.shared_sigma_m * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d ray = percept.ego_position_m - ego_camera_m;
  if (percept.shared_ray_sigma_m > 0.0 && ray.norm() > 0.0) {
    const Eigen::Vector3d r = ray.normalized();
    shared += percept.shared_ray_sigma_m * percept.shared_ray_sigma_m * r * r.transpose();
  }
  return shared;
}

// The members' mean weighted by W_i = (E_i + tau2 I)^-1, its covariance (sum_i W_i)^-1 and the
// chi-square of the members about it (fuse.hpp).
struct WeightedMean {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance_m2 = Eigen::Matrix3d::Zero();
  double chi2 = 0.0;
};

WeightedMean weighted_mean(const std::vector<OwnPart>& own,
                           const std::vector<Eigen::Vector3d>& positions_m, double tau2_m2) {
  std::vector<Eigen::Matrix3d> weights;
  weights.reserve(own.size());
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  Eigen::Vector3d information_position = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < own.size(); ++i) {
    const Eigen::Vector3d inverse = (own[i].variances_m2.array() + tau2_m2).inverse().matrix();
    weights.push_back(own[i].axes * inverse.asDiagonal() * own[i].axes.transpose());
    information += weights.back();
    information_position += weights.back() * positions_m[i];
  }
  WeightedMean out;
  out.covariance_m2 = information.llt().solve(Eigen::Matrix3d::Identity());
  out.position_m = out.covariance_m2 * information_position;
  for (std::size_t i = 0; i < own.size(); ++i) {
    const Eigen::Vector3d r = positions_m[i] - out.position_m;
    out.chi2 += r.dot(weights[i] * r);
  }
  return out;
}

// The Paule-Mandel excess variance of fuse.hpp: tau2 = 0 when chi2(0) <= 3 (n - 1), else the
// root of chi2(tau2) = 3 (n - 1). chi2 falls monotonically in tau2 (its derivative is
// -sum r_i^T W_i^2 r_i at the minimizing mean), and at tau2 = S / (3 (n - 1)), S the members'
// squared distances from their plain mean, it is at most 3 (n - 1) (W_i <= I / tau2): bisection
// between 0 and that bound.
WeightedMean random_effects_mean(const std::vector<OwnPart>& own,
                                 const std::vector<Eigen::Vector3d>& positions_m) {
  WeightedMean fixed = weighted_mean(own, positions_m, 0.0);
  const double dof = 3.0 * static_cast<double>(positions_m.size() - 1);
  if (positions_m.size() < 2 || fixed.chi2 <= dof) return fixed;
  Eigen::Vector3d plain = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : positions_m) plain += x;
  plain /= static_cast<double>(positions_m.size());
  double scatter_m2 = 0.0;
  for (const Eigen::Vector3d& x : positions_m) scatter_m2 += (x - plain).squaredNorm();
  double low = 0.0, high = scatter_m2 / dof;
  constexpr int kBisections = 40;  // tau2 to 1e-12 of its bound
  for (int k = 0; k < kBisections; ++k) {
    const double middle = 0.5 * (low + high);
    (weighted_mean(own, positions_m, middle).chi2 > dof ? low : high) = middle;
  }
  return weighted_mean(own, positions_m, high);
}

// The fused percept of one cluster (formula in fuse.hpp), and whether it passes Eq. 4 in some
// view.
struct FusedCluster {
  FusedPercept percept;
  bool passes = false;
};

FusedCluster fuse_cluster(const std::string& type, const std::vector<Member>& members,
                          const std::vector<Frame>& frames, const FieldOfView& field_of_view,
                          const FusionOptions& options) {
  FusedPercept out;
  out.type = type;
  out.num_percepts = static_cast<int>(members.size());
  // B: the part every member shares is at most the smallest any of them claims (least trace).
  Eigen::Matrix3d shared_m2 = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < members.size(); ++i) {
    const Eigen::Matrix3d b =
        shared_part(*members[i].percept, frames[members[i].frame].ego_T_left_camera.translation());
    if (i == 0 || b.trace() < shared_m2.trace()) shared_m2 = b;
  }
  std::vector<OwnPart> own;
  std::vector<Eigen::Vector3d> positions_m;
  std::set<std::size_t> supporting;
  for (const Member& m : members) {
    own.push_back(own_part(m.percept->ego_covariance_m2, shared_m2));
    positions_m.push_back(m.percept->ego_position_m);
    supporting.insert(m.frame);
  }
  const WeightedMean mean = random_effects_mean(own, positions_m);
  out.ego_position_m = mean.position_m;
  Eigen::Matrix3d covariance = mean.covariance_m2;
  covariance += shared_m2;
  out.ego_covariance_m2 = 0.5 * (covariance + covariance.transpose());
  // C: frames, not percepts, so that C <= T_s (a frame sees an object once).
  out.support = static_cast<int>(supporting.size());
  for (const std::size_t f : supporting) {
    out.ego_camera_position_m += frames[f].ego_T_left_camera.translation();
  }
  out.ego_camera_position_m /= static_cast<double>(supporting.size());
  // C_v and T_v per view. T_v: frames of view v whose left camera should have seen the fused
  // location; a frame that did see it counts even when the location falls just outside the
  // margin, so that C_v <= T_v.
  std::map<int, std::pair<int, int>> by_view;  // view -> (C_v, T_v)
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const bool saw = supporting.count(f) != 0;
    if (saw || field_of_view.sees(frames[f].ego_T_left_camera, out.ego_position_m)) {
      auto& [support, expected] = by_view[frames[f].view];
      support += saw ? 1 : 0;
      ++expected;
    }
  }
  FusedCluster result;
  for (const auto& [view, counts] : by_view) {
    out.expected += counts.second;
    if (counts.first == 0) continue;
    result.passes = result.passes || passes_confidence(counts.first, counts.second, options);
    out.confidence = std::max(out.confidence, static_cast<double>(counts.first) / counts.second);
  }
  result.percept = std::move(out);
  return result;
}

bool ordered(const FusedPercept& a, const FusedPercept& b) {
  return std::make_tuple(a.type, -a.support, a.ego_position_m.x(), a.ego_position_m.y(),
                         a.ego_position_m.z()) <
         std::make_tuple(b.type, -b.support, b.ego_position_m.x(), b.ego_position_m.y(),
                         b.ego_position_m.z());
}

}  // namespace

bool passes_confidence(int support, int expected, const FusionOptions& options) {
  // Eq. 4, T_s relaxed by iota frames (never below one frame).
  const int relaxed = std::max(expected - options.iota_frames, 1);
  return static_cast<double>(support) / static_cast<double>(relaxed) > options.e_min;
}

FusionResult fuse(const std::vector<Frame>& frames, const FieldOfView& field_of_view,
                  const FusionOptions& options) {
  FusionResult result;
  result.num_frames = frames.size();
  const std::vector<std::vector<bool>> keep = non_isolated(frames, options.isolation_distance_m);
  // Kept percepts per type alpha, in frame order (deterministic).
  std::map<std::string, std::vector<Member>> by_type;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    for (std::size_t i = 0; i < frames[f].percepts.size(); ++i) {
      ++result.num_percepts;
      if (!keep[f][i]) {
        ++result.num_isolated;
        continue;
      }
      by_type[frames[f].percepts[i].type].push_back({f, &frames[f].percepts[i]});
    }
  }
  for (const auto& [type, members] : by_type) {
    std::vector<Eigen::Vector3d> points;
    points.reserve(members.size());
    for (const Member& m : members) points.push_back(m.percept->ego_position_m);
    const MeanShiftResult modes =
        mean_shift(points, options.bandwidth_m, options.mode_merge_distance_m,
                   options.max_mean_shift_iterations);
    std::vector<std::vector<Member>> clusters(modes.modes.size());
    for (std::size_t i = 0; i < members.size(); ++i) {
      clusters[static_cast<std::size_t>(modes.cluster[i])].push_back(members[i]);
    }
    for (const std::vector<Member>& cluster : clusters) {
      FusedCluster fused = fuse_cluster(type, cluster, frames, field_of_view, options);
      if (fused.passes) {
        result.fused.push_back(std::move(fused.percept));
      } else {
        result.rejected.push_back(std::move(fused.percept));
      }
    }
  }
  std::sort(result.fused.begin(), result.fused.end(), ordered);
  std::sort(result.rejected.begin(), result.rejected.end(), ordered);
  return result;
}

}  // namespace vsl::fusion
