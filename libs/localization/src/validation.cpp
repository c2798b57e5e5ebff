#include "vsl/localization/validation.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "vsl/localization/hypotheses.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/segment_nodes.hpp"

#include "one_to_one.hpp"

namespace vsl::localization {
namespace {

using world::NodeIndex;

PoseUncertainty uncertainty_of(const LocalizationContext& context,
                               const std::vector<NodeAssociation>& associations) {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> sigmas;
  for (const NodeAssociation& a : associations) {
    points.push_back(context.percepts[a.percept].ego_position_m);
    sigmas.push_back(context.noise[a.percept].sigma_m);
  }
  return pose_uncertainty(points, sigmas);
}

}  // namespace

Explanation explain(const LocalizationContext& context, const Eigen::Isometry3d& world_T_ego,
                    const PoseUncertainty& uncertainty) {
  const double gate = context.options.validation.gate_sigmas;
  const double gate_sq = gate * gate;
  const Eigen::Isometry3d ego_T_world = world_T_ego.inverse();
  struct Pairing {
    double d2;
    int percept;
    NodeIndex node;
    double log_normaliser;  // log N(0; 0, Sigma') + log(1 / clutter density)
  };
  const double log_clutter = -std::log(context.options.validation.clutter_density_per_m3);
  std::vector<Pairing> pairings;
  for (std::size_t l = 0; l < context.percepts.size(); ++l) {
    const auto& type = context.candidates.types[l];
    if (!type) continue;
    const Eigen::Vector3d& x = context.percepts[l].ego_position_m;
    const PerceptNoise& noise = context.noise[l];
    const double extra_m2 = std::pow(uncertainty.sigma_at_m(x), 2);
    const double radius_m = gate * std::sqrt(noise.variances_m2.maxCoeff() + extra_m2);
    const double log_normaliser =
        -0.5 * (2.0 * std::numbers::pi * (noise.variances_m2.array() + extra_m2)).log().sum() +
        log_clutter;
    context.grid.for_each_within(*type, world_T_ego * x, radius_m, [&](NodeIndex node, double) {
      const double d2 =
          noise.mahalanobis_sq(ego_T_world * context.graph.world_position_m(node) - x, extra_m2);
      if (d2 <= gate_sq) pairings.push_back({d2, static_cast<int>(l), node, log_normaliser});
    });
  }
  // One object per percept and one percept per object, closest pairs first.
  Explanation out;
  std::vector<bool> percept_used(context.percepts.size(), false);
  std::vector<NodeIndex> nodes_used;
  for (const Pairing& p : internal::one_to_one(std::move(pairings), percept_used, nodes_used)) {
    out.associations.push_back({p.percept, p.node});
    out.chi2 += p.d2;
    out.log_likelihood_ratio += std::max(0.0, p.log_normaliser - 0.5 * p.d2);
  }
  std::sort(
      out.associations.begin(), out.associations.end(),
      [](const NodeAssociation& a, const NodeAssociation& b) { return a.percept < b.percept; });
  out.bar_pieces = bar_pieces(context, world_T_ego, uncertainty, out.associations);
  return out;
}

bool ValidatedHypothesis::explains(int percept) const {
  return std::any_of(explanation.associations.begin(), explanation.associations.end(),
                     [&](const NodeAssociation& a) { return a.percept == percept; });
}

std::optional<ValidatedHypothesis> validate_hypothesis(
    const LocalizationContext& context, const Eigen::Isometry3d& world_T_ego,
    const std::vector<NodeAssociation>& generating, int max_rounds) {
  ValidatedHypothesis out;
  out.world_T_ego = world_T_ego;
  out.explanation = explain(context, world_T_ego, uncertainty_of(context, generating));
  std::vector<NodeAssociation> by_percept = generating;
  std::sort(
      by_percept.begin(), by_percept.end(),
      [](const NodeAssociation& a, const NodeAssociation& b) { return a.percept < b.percept; });
  for (int round = 0; round < max_rounds; ++round) {
    const std::vector<NodeAssociation>& current = out.explanation.associations;
    if (current.size() < 3) break;
    // A pose estimated from exactly what it explains is already the re-estimate.
    if (round == 0 && current == by_percept) break;
    std::vector<PointCorrespondence> points;
    for (const NodeAssociation& a : current)
      points.push_back(context.correspondence(a.percept, a.node));
    const auto refit = estimate_pose(points, 1e-3);
    if (!refit) break;
    Explanation next = explain(context, *refit, uncertainty_of(context, current));
    // Keep the re-estimate unless it explains less (a wrong association can pull it off).
    if (next.log_likelihood_ratio < out.explanation.log_likelihood_ratio) break;
    const bool stable = next.associations == current;
    out.world_T_ego = *refit;
    out.explanation = std::move(next);
    if (stable) break;
  }
  if (out.explanation.associations.size() < 3) return std::nullopt;
  out.score = out.explanation.log_likelihood_ratio;
  out.uncertainty = uncertainty_of(context, out.explanation.associations);
  // The re-estimate may have tilted a pose that was upright enough when generated from three
  // percepts; with gravity (ego z up) a robot standing on a tilted pose is not a hypothesis.
  const PruningOptions& pruning = context.options.pruning;
  if (pruning.use_gravity &&
      tilt_rad(out.world_T_ego) > pruning.max_tilt_rad + 3.0 * out.uncertainty.sigma_rotation_rad) {
    return std::nullopt;
  }
  return out;
}

constexpr double kMaxMergeSigmaM = 0.1;
constexpr double kMaxMergeSigmaRad = 0.05;

bool indistinguishable(const ValidatedHypothesis& a, const ValidatedHypothesis& b,
                       const HypothesisOptions& options) {
  if (same_hypothesis(a.world_T_ego, b.world_T_ego, options)) return true;
  // Two sigmas of each, the sigmas capped: a pose known only to decimetres is not merged with
  // everything within a metre of it.
  constexpr double kSigmas = 2.0;
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  const double sa = std::min(a.uncertainty.sigma_at_m(origin), kMaxMergeSigmaM);
  const double sb = std::min(b.uncertainty.sigma_at_m(origin), kMaxMergeSigmaM);
  const double ra = std::min(a.uncertainty.sigma_rotation_rad, kMaxMergeSigmaRad);
  const double rb = std::min(b.uncertainty.sigma_rotation_rad, kMaxMergeSigmaRad);
  return (a.world_T_ego.translation() - b.world_T_ego.translation()).norm() <
             kSigmas * std::sqrt(sa * sa + sb * sb) &&
         rotation_angle_rad(a.world_T_ego, b.world_T_ego) < kSigmas * std::sqrt(ra * ra + rb * rb);
}

bool ranks_before(const ValidatedHypothesis& a, const ValidatedHypothesis& b) {
  if (a.score != b.score) return a.score > b.score;
  return a.explanation.chi2 < b.explanation.chi2;
}

std::string pieces_note(std::size_t pieces) {
  return pieces > 0 ? " (" + std::to_string(pieces) + " more, pieces of bars, set aside)" : "";
}

Decision decide(const std::vector<ValidatedHypothesis>& ranked, std::size_t usable_percepts,
                const ValidationOptions& validation, const HypothesisOptions& hypotheses) {
  Decision out;
  if (ranked.empty()) {
    out.message = "no hypothesis is consistent with the percepts";
    return out;
  }
  const double best = ranked.front().score;
  const std::size_t explained = ranked.front().explained();
  // Pieces of bars are set aside (segment_nodes.hpp): the share is of the rest.
  const std::size_t pieces = ranked.front().explanation.bar_pieces.size();
  const std::size_t judged = usable_percepts - std::min(pieces, usable_percepts);
  const double needed = std::max(static_cast<double>(hypotheses.min_associations),
                                 validation.min_explained_fraction * static_cast<double>(judged));
  if (static_cast<double>(explained) < needed) {
    out.message = "the best hypothesis explains " + std::to_string(explained) + " of " +
                  std::to_string(judged) + " percepts" + pieces_note(pieces) +
                  ", fewer than needed";
    return out;
  }
  out.contenders = 1;
  while (out.contenders < ranked.size() &&
         ranked[out.contenders].score > best - validation.ambiguity_margin) {
    ++out.contenders;
  }
  if (out.contenders > 1) {
    out.status = Status::kAmbiguous;
    out.message =
        std::to_string(out.contenders) +
        " hypotheses explain the percepts equally well (best: " + std::to_string(explained) +
        " of " + std::to_string(usable_percepts) + ")";
    return out;
  }
  out.status = Status::kLocalized;
  return out;
}

namespace {

// One discriminating object under one hypothesis (see choose_discriminator).
struct LookCandidate {
  NodeIndex node;
  std::size_t hypothesis;
  Eigen::Vector3d ego_target_m;
  Eigen::Vector3d camera_ray;  // unit vector, camera -> target, ego frame
  double range_m;
  double discrimination_m;
};

// Whether the head can usefully look at `ego_target` (validation.hpp: choose_discriminator).
bool within_limits(const Eigen::Vector3d& ego_target, const Eigen::Vector3d& camera,
                   const LookLimits& limits, const std::vector<Eigen::Vector3d>& looked_at_ego_m) {
  const Eigen::Vector3d ray = ego_target - camera;
  const double range = ray.norm();
  if (range < limits.min_range_m || range > limits.max_range_m) return false;
  if (std::abs(std::atan2(ego_target.y(), ego_target.x())) > limits.max_azimuth_rad) return false;
  if (std::abs(std::atan2(ray.z(), ray.head<2>().norm())) > limits.max_elevation_rad) return false;
  return std::none_of(
      looked_at_ego_m.begin(), looked_at_ego_m.end(),
      [&](const Eigen::Vector3d& looked) { return (looked - ego_target).norm() < 0.3; });
}

// Whether a look may count the objects of graph type `type` (LookLimits::types).
bool looked_for(const world::WorldGraph& graph, std::size_t type, const LookLimits& limits) {
  if (limits.types.empty()) return true;
  const std::string& name = graph.type_name(static_cast<world::TypeId>(type));
  return std::find(limits.types.begin(), limits.types.end(), name) != limits.types.end();
}

}  // namespace

std::optional<ActiveValidationTarget> choose_discriminator(
    const world::WorldModel& world, const world::WorldGraph& graph, const NodeGrid& grid,
    const std::vector<Eigen::Isometry3d>& hypotheses, const LocalizerOptions& options,
    const LookLimits& limits, const std::vector<Eigen::Vector3d>& looked_at_ego_m) {
  if (hypotheses.size() < 2) return std::nullopt;
  const Eigen::Vector3d& camera = options.noise.ego_camera_position_m;
  std::vector<LookCandidate> candidates;
  for (std::size_t h = 0; h < hypotheses.size(); ++h) {
    const Eigen::Isometry3d ego_T_world = hypotheses[h].inverse();
    for (std::size_t t = 0; t < graph.type_count(); ++t) {
      if (!looked_for(graph, t, limits)) continue;
      const auto type = static_cast<world::TypeId>(t);
      grid.for_each_within(
          type, hypotheses[h] * camera, limits.max_range_m, [&](NodeIndex node, double) {
            const Eigen::Vector3d ego_target = ego_T_world * graph.world_position_m(node);
            if (!within_limits(ego_target, camera, limits, looked_at_ego_m)) return;
            // What another hypothesis expects at that ego point: the nearest object of the type.
            double discrimination = limits.cap_m;
            for (std::size_t other = 0; other < hypotheses.size() && discrimination > 0.0;
                 ++other) {
              if (other == h) continue;
              const auto nearest = grid.nearest(type, hypotheses[other] * ego_target, limits.cap_m);
              if (nearest) discrimination = std::min(discrimination, nearest->distance_m);
            }
            // A percept at the target would be explained under the others too within its gate.
            const double gate_m = options.validation.gate_sigmas *
                                  eq7_sigma_m(ego_target, options.noise) * std::sqrt(3.0);
            if (discrimination <= gate_m) return;
            const Eigen::Vector3d ray = ego_target - camera;
            candidates.push_back(
                {node, h, ego_target, ray.normalized(), ray.norm(), discrimination});
          });
    }
  }
  // Rate each look by everything discriminating in view around its target (same hypothesis).
  const double cos_view = std::cos(limits.view_half_angle_rad);
  std::optional<ActiveValidationTarget> best;
  double best_range_cost = 0.0;
  for (const LookCandidate& c : candidates) {
    double in_view = 0.0;
    for (const LookCandidate& o : candidates) {
      if (o.hypothesis == c.hypothesis && o.camera_ray.dot(c.camera_ray) >= cos_view) {
        in_view += o.discrimination_m;
      }
    }
    const double range_cost = std::abs(c.range_m - limits.preferred_range_m);
    if (!best || in_view > best->view_discrimination_m + 1e-9 ||
        (in_view > best->view_discrimination_m - 1e-9 && range_cost < best_range_cost)) {
      best = ActiveValidationTarget{world.objects[graph.object_index(c.node)].id, c.hypothesis,
                                    c.ego_target_m, c.discrimination_m, in_view};
      best_range_cost = range_cost;
    }
  }
  return best;
}

// The rating of a precision look (validation.hpp). State: the pose parameters the refinement
// estimated, those of `covariance` with a positive variance (world translation x, y, z and the
// small rotation r about the world axes, PoseCovariance's order; the planar prior leaves out
// roll and pitch). A percept of an object at world point X, seen from the pose (R, t), is
// X = R e + t; under the perturbation (exp([r]x) R, t + dt) it moves by dt + r x d with
// d = R e = X - t, so its Jacobian is J = [I | -[d]x] (3 x 6) and, with the isotropic Eq. 7
// sigma(e), it adds the information J^T J / sigma^2. The pose's information now is
// covariance^-1 (on the state); after a look it is that plus the sum over the objects in view
// (the paper's percept model: each object recognized, with its Eq. 7 error).
namespace {

using PoseMatrix = Eigen::Matrix<double, 6, 6>;

PoseMatrix object_information(const Eigen::Vector3d& d_world_m, double sigma_m) {
  Eigen::Matrix<double, 3, 6> jacobian;
  jacobian.leftCols<3>().setIdentity();
  jacobian.rightCols<3>() << 0.0, d_world_m.z(), -d_world_m.y(),  //
      -d_world_m.z(), 0.0, d_world_m.x(),                         //
      d_world_m.y(), -d_world_m.x(), 0.0;
  return jacobian.transpose() * jacobian / (sigma_m * sigma_m);
}

// The inverse of `m` on the parameters `free` (zero elsewhere): covariance <-> information on
// the state the refinement estimated.
PoseMatrix inverse_on(const PoseMatrix& m, const std::vector<int>& free) {
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd reduced(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) reduced(i, j) = m(free[i], free[j]);
  }
  const Eigen::MatrixXd inverse = reduced.ldlt().solve(Eigen::MatrixXd::Identity(n, n));
  PoseMatrix out = PoseMatrix::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) out(free[i], free[j]) = inverse(i, j);
  }
  return out;
}

// The worst-axis standard deviations of position and angle under `information` (on the state
// `free`), each over its requirement: the look that makes the larger of the two smallest is the one
// that brings the pose nearest the precision bound.
double precision_ratio(const PoseMatrix& information, const std::vector<int>& free,
                       const ValidationOptions& v) {
  const PoseMatrix covariance = inverse_on(information, free);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(covariance.topLeftCorner<3, 3>(), Eigen::EigenvaluesOnly);
  const double position_m = std::sqrt(std::max(0.0, eigen.eigenvalues()[2]));
  eigen.computeDirect(covariance.bottomRightCorner<3, 3>(), Eigen::EigenvaluesOnly);
  const double angle_rad = std::sqrt(std::max(0.0, eigen.eigenvalues()[2]));
  return std::max(position_m / v.required_position_m, angle_rad / v.required_angle_rad);
}

}  // namespace

std::optional<ActiveValidationTarget> choose_precision_look(
    const world::WorldModel& world, const world::WorldGraph& graph, const NodeGrid& grid,
    const Eigen::Isometry3d& world_T_ego, const PoseCovariance& covariance,
    const LocalizerOptions& options, const LookLimits& limits,
    const std::vector<Eigen::Vector3d>& looked_at_ego_m) {
  std::vector<int> free;
  for (int i = 0; i < 6; ++i) {
    if (covariance(i, i) > 0.0 && std::isfinite(covariance(i, i))) free.push_back(i);
  }
  if (free.empty()) return std::nullopt;
  const PoseMatrix information_now = inverse_on(covariance, free);
  const Eigen::Vector3d& camera = options.noise.ego_camera_position_m;
  const double cos_view = std::cos(limits.view_half_angle_rad);
  // The gaze rays of the earlier looks (ego frame, unit vectors from the camera).
  std::vector<Eigen::Vector3d> looked_rays;
  for (const Eigen::Vector3d& looked : looked_at_ego_m) {
    const Eigen::Vector3d ray = looked - camera;
    if (ray.norm() > 0.0) looked_rays.push_back(ray.normalized());
  }
  struct Candidate {
    NodeIndex node;
    Eigen::Vector3d ego_target_m;
    Eigen::Vector3d camera_ray;  // unit, ego frame
    double range_m;
    double information_per_m2;  // 1 / sigma^2, Eq. 7
    PoseMatrix pose_information;
  };
  std::vector<Candidate> candidates;
  const Eigen::Isometry3d ego_T_world = world_T_ego.inverse();
  for (std::size_t t = 0; t < graph.type_count(); ++t) {
    if (!looked_for(graph, t, limits)) continue;
    grid.for_each_within(
        static_cast<world::TypeId>(t), world_T_ego * camera, limits.max_range_m,
        [&](NodeIndex node, double) {
          const Eigen::Vector3d ego_target = ego_T_world * graph.world_position_m(node);
          if (!within_limits(ego_target, camera, limits, {})) return;
          const Eigen::Vector3d ray = (ego_target - camera).normalized();
          for (const Eigen::Vector3d& looked : looked_rays) {
            if (looked.dot(ray) >= cos_view) return;  // in an earlier view
          }
          const double sigma = eq7_sigma_m(ego_target, options.noise);
          candidates.push_back({node, ego_target, ray, (ego_target - camera).norm(),
                                1.0 / (sigma * sigma),
                                object_information(world_T_ego.linear() * ego_target, sigma)});
        });
  }
  std::optional<ActiveValidationTarget> best;
  double best_ratio = 0.0, best_range_cost = 0.0;
  for (const Candidate& c : candidates) {
    double in_view = 0.0;
    PoseMatrix information = information_now;
    for (const Candidate& o : candidates) {
      if (o.camera_ray.dot(c.camera_ray) < cos_view) continue;
      in_view += o.information_per_m2;
      information += o.pose_information;
    }
    const double ratio = precision_ratio(information, free, options.validation);
    const double range_cost = std::abs(c.range_m - limits.preferred_range_m);
    const double tie = 1e-9 * std::max(1.0, ratio);
    if (!best || ratio < best_ratio - tie ||
        (ratio < best_ratio + tie && range_cost < best_range_cost)) {
      best = ActiveValidationTarget{
          world.objects[graph.object_index(c.node)].id, 0, c.ego_target_m, 0.0, 0.0, in_view};
      best->predicted_precision_ratio = ratio;
      best_ratio = ratio;
      best_range_cost = range_cost;
    }
  }
  return best;
}

}  // namespace vsl::localization
