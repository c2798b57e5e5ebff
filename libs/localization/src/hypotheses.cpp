#include "vsl/localization/hypotheses.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vsl/localization/pose_uncertainty.hpp"

namespace vsl::localization {
namespace {

using world::NodeIndex;

// A fourth sphere that misses the other pair point by less than this (chi^2, i.e. 3 sigma of one
// radius) cannot tell the pair apart: that point keeps no descendant and stays a hypothesis.
constexpr double kUnresolvedChi2 = 9.0;
// Associations (the seed's and the first ones added) a new association is checked against.
constexpr std::size_t kPairwiseChecks = 8;
// Restriction spheres per location: the most precise associations of an interpretation.
constexpr std::size_t kMaxSpheres = 8;
// Regularizes the location's Fisher information (1 / m^2): a direction no sphere constrains is
// known to 1 km.
constexpr double kMinInformation = 1e-6;

double gate_sigmas(const LocalizerOptions& options) {
  return std::max(options.validation.gate_sigmas, options.pruning.tau_sigmas);
}

PoseUncertainty uncertainty_of(const LocalizationContext& context,
                               std::span<const NodeAssociation> associations) {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> sigmas;
  for (const NodeAssociation& a : associations) {
    points.push_back(context.percepts[a.percept].ego_position_m);
    sigmas.push_back(context.noise[a.percept].sigma_m);
  }
  return pose_uncertainty(points, sigmas);
}

// Tilt allowed for a pose known to sigma_rotation: the configured tilt plus three sigmas.
bool upright_enough(const Eigen::Isometry3d& pose, const PoseUncertainty& uncertainty,
                    const PruningOptions& options) {
  if (!options.use_gravity) return true;
  return tilt_rad(pose) <= options.max_tilt_rad + 3.0 * uncertainty.sigma_rotation_rad;
}

}  // namespace

double rotation_angle_rad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

bool same_hypothesis(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                     const HypothesisOptions& options) {
  return (a.translation() - b.translation()).norm() < options.same_position_m &&
         rotation_angle_rad(a, b) < options.same_angle_rad;
}

double tilt_rad(const Eigen::Isometry3d& world_T_ego) {
  const double cos_tilt = std::clamp(world_T_ego.linear()(2, 2), -1.0, 1.0);
  return std::acos(cos_tilt);
}

std::optional<SeedPose> seed_pose(const LocalizationContext& context, const PerceptTriple& seed,
                                  const ModelTriple& subgraph) {
  std::vector<PointCorrespondence> points;
  std::vector<NodeAssociation> associations;
  for (int s = 0; s < 3; ++s) {
    points.push_back(context.correspondence(seed.percepts[s], subgraph.nodes[s]));
    associations.push_back({seed.percepts[s], subgraph.nodes[s]});
  }
  const auto pose = estimate_pose(points, 1e-3);
  if (!pose) return std::nullopt;
  SeedPose out{*pose, uncertainty_of(context, associations)};
  if (!upright_enough(out.world_T_ego, out.uncertainty, context.options.pruning))
    return std::nullopt;
  return out;
}

std::optional<Interpretation> extend_interpretation(const LocalizationContext& context,
                                                    const PerceptTriple& seed,
                                                    const ModelTriple& subgraph, int min_count) {
  const auto start = seed_pose(context, seed, subgraph);
  if (!start) return std::nullopt;
  return extend_interpretation(context, seed, subgraph, *start, min_count);
}

namespace {

// The percepts an interpretation is extended with, most precise first (they decide early
// whether the seed is hopeless): every usable percept but the seed's.
std::vector<int> extension_order(const LocalizationContext& context, const PerceptTriple& seed) {
  std::vector<int> rest;
  for (std::size_t l = 0; l < context.percepts.size(); ++l) {
    const int p = static_cast<int>(l);
    if (p == seed.percepts[0] || p == seed.percepts[1] || p == seed.percepts[2]) continue;
    if (context.candidates.types[l]) rest.push_back(p);
  }
  std::sort(rest.begin(), rest.end(),
            [&](int a, int b) { return context.noise[a].sigma_m < context.noise[b].sigma_m; });
  return rest;
}

// The model object percept `l` is best associated with, given the associations so far and the
// pose they give: of its type, within the gate around where the pose puts it, every checked
// pairwise distance within its tolerance (Eq. 8), least squared normalized distance error.
std::optional<NodeIndex> best_object(const LocalizationContext& context,
                                     const ModelTriple& subgraph,
                                     const std::vector<NodeAssociation>& associations, int l,
                                     const Eigen::Isometry3d& pose,
                                     const PoseUncertainty& uncertainty) {
  const FusedPercept& percept = context.percepts[l];
  const world::TypeId type = *context.candidates.types[l];
  const double sigma_pose = uncertainty.sigma_at_m(percept.ego_position_m);
  const double radius_m =
      gate_sigmas(context.options) *
      std::sqrt(context.noise[l].sigma_m * context.noise[l].sigma_m + sigma_pose * sigma_pose);
  const Eigen::Vector3d predicted_m = pose * percept.ego_position_m;
  // Pairwise distance checks (Eq. 8 for each new pair) against the seed and the most precise
  // associations found since (the first ones added): a wrong object can match three distances
  // by chance, rarely eight.
  const std::size_t checked = std::min(associations.size(), kPairwiseChecks);
  std::array<PerceptPair, kPairwiseChecks> pairs;
  int anchor = -1;
  for (std::size_t s = 0; s < checked; ++s) {
    pairs[s] = context.pair(l, associations[s].percept);
    if (s < 3 && pairs[s].distance_m + pairs[s].tau_m < context.graph.link_threshold_m() &&
        (anchor < 0 || pairs[s].distance_m < pairs[anchor].distance_m)) {
      anchor = static_cast<int>(s);
    }
  }
  double best_cost = std::numeric_limits<double>::infinity();
  NodeIndex best_node = 0;
  const auto consider = [&](NodeIndex node) {
    for (const NodeAssociation& a : associations) {
      if (a.node == node) return;
    }
    const Eigen::Vector3d& x = context.graph.world_position_m(node);
    // Distances leave the mirror side of the associations' plane open; the pose picks.
    if ((x - predicted_m).squaredNorm() > radius_m * radius_m) return;
    double cost = 0.0;
    for (std::size_t s = 0; s < checked; ++s) {
      const double d = (x - context.graph.world_position_m(associations[s].node)).norm();
      const double r = (d - pairs[s].distance_m) / pairs[s].tau_m;
      if (std::abs(r) > 1.0) return;
      cost += r * r;
    }
    if (cost < best_cost) {
      best_cost = cost;
      best_node = node;
    }
  };
  if (anchor >= 0) {
    // The objects at the right distance from the nearest seed object: a graph lookup.
    const PerceptPair& p = pairs[anchor];
    for (const world::Neighbour& n : context.adjacency.within(
             subgraph.nodes[anchor], type, p.distance_m - p.tau_m, p.distance_m + p.tau_m)) {
      consider(n.node);
    }
  } else {
    // Farther than any link from the seed: look where the seed's pose puts it.
    context.grid.for_each_within(type, predicted_m, radius_m,
                                 [&](NodeIndex node, double) { consider(node); });
  }
  if (!std::isfinite(best_cost)) return std::nullopt;
  return best_node;
}

}  // namespace

std::optional<Interpretation> extend_interpretation(const LocalizationContext& context,
                                                    const PerceptTriple& seed,
                                                    const ModelTriple& subgraph,
                                                    const SeedPose& start, int min_count) {
  Interpretation out;
  std::vector<PointCorrespondence> points;
  for (int s = 0; s < 3; ++s) {
    out.associations.push_back({seed.percepts[s], subgraph.nodes[s]});
    points.push_back(context.correspondence(seed.percepts[s], subgraph.nodes[s]));
  }
  std::optional<Eigen::Isometry3d> pose = start.world_T_ego;
  PoseUncertainty uncertainty = start.uncertainty;
  const auto refit = [&]() {
    const auto estimate = estimate_pose(points, 1e-3);
    if (!estimate) return;
    pose = estimate;
    uncertainty = uncertainty_of(context, out.associations);
  };

  const std::vector<int> rest = extension_order(context, seed);
  const int max_misses = static_cast<int>(rest.size()) + 3 - min_count;
  if (max_misses < 0) return std::nullopt;
  int misses = 0;
  for (const int l : rest) {
    const std::optional<NodeIndex> node =
        best_object(context, subgraph, out.associations, l, *pose, uncertainty);
    if (!node) {
      if (++misses > max_misses) return std::nullopt;
      continue;
    }
    out.associations.push_back({l, *node});
    points.push_back(context.correspondence(l, *node));
    // A seed of three percepts fixes the pose only roughly (its rotation to sigma / altitude),
    // and far percepts sit on long lever arms; re-estimating as precise associations join (after
    // the 2nd and the 8th) keeps the prediction, and so the choice among same-type neighbours,
    // sharp.
    const std::size_t added = out.associations.size() - 3;
    if (added == 2 || added == 8) refit();
  }
  // Eq. 16 over everything found (unless the last association already triggered it).
  const std::size_t added = out.associations.size() - 3;
  if (added > 0 && added != 2 && added != 8) refit();
  out.world_T_ego = *pose;
  out.uncertainty = uncertainty;
  return out;
}

geometry::GaussianSphere restriction_sphere(const FusedPercept& percept, const PerceptNoise& noise,
                                            const Eigen::Vector3d& world_object_m) {
  const double radius_m = percept.ego_position_m.norm();
  const Eigen::Vector3d ray = radius_m > 0.0 ? Eigen::Vector3d(percept.ego_position_m / radius_m)
                                             : Eigen::Vector3d::UnitX();
  return {{world_object_m, radius_m}, noise.sigma_along_m(ray)};
}

std::vector<Eigen::Vector3d> location_hypotheses(
    std::span<const geometry::GaussianSphere> spheres) {
  std::vector<Eigen::Vector3d> out;
  if (spheres.size() < 3) return out;
  const geometry::DensityMaximum maximum = geometry::maximal_density(spheres);
  switch (maximum.locus) {
    case geometry::DensityLocus::kPointPair:
      // Phi2 (three spheres, or coplanar centres): the pair has no descendant, both points are
      // hypotheses.
      for (int p = 0; p < maximum.point_count(); ++p) out.push_back(maximum.points_m[p]);
      return out;
    case geometry::DensityLocus::kPoint:
      break;
    default:
      return out;  // collinear centres: a circle, no location
  }
  // Phi3: one point. Its mirror image through the centres' plane is the other point of the pair
  // it descends from; when the centres are nearly coplanar for the data (the mirror fits within
  // kUnresolvedChi2 of the optimum) the spheres did not really pick a side, and the mirror stays
  // a hypothesis too.
  const Eigen::Vector3d point = maximum.points_m[0];
  out.push_back(point);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const geometry::GaussianSphere& s : spheres) centroid += s.sphere.centre_m;
  centroid /= static_cast<double>(spheres.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const geometry::GaussianSphere& s : spheres) {
    const Eigen::Vector3d a = s.sphere.centre_m - centroid;
    scatter += a * a.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(scatter);
  const Eigen::Vector3d normal = eigen.eigenvectors().col(0);  // across the best-fit plane
  const Eigen::Vector3d mirror = point - 2.0 * normal.dot(point - centroid) * normal;
  if ((mirror - point).norm() > 1e-6 &&
      geometry::chi_square(spheres, mirror) <= maximum.cost + kUnresolvedChi2) {
    out.push_back(mirror);
  }
  return out;
}

std::vector<Eigen::Isometry3d> hypothesis_poses(const LocalizationContext& context,
                                                const Interpretation& interpretation) {
  const LocalizerOptions& options = context.options;
  const auto& associations = interpretation.associations;
  std::vector<Eigen::Isometry3d> out;
  if (associations.size() < 3) return out;

  // Eq. 16 over the whole subgraph (the interpretation search ends with it).
  const std::optional<Eigen::Isometry3d> pose = interpretation.world_T_ego;
  const PoseUncertainty& uncertainty = interpretation.uncertainty;
  if (!upright_enough(*pose, uncertainty, options.pruning)) return out;
  const double pose_sigma_m = uncertainty.sigma_at_m(Eigen::Vector3d::Zero());
  const double gate = gate_sigmas(options);

  // Phi0: restriction spheres of the subgraph's most precise associations that agree with the
  // Eq. 16 pose (a false positive matched to some object would otherwise bend the location; far
  // percepts add little but cost Gauss-Newton work).
  std::vector<NodeAssociation> generating;
  const Eigen::Isometry3d ego_T_world = pose->inverse();
  for (const NodeAssociation& a : associations) {
    const Eigen::Vector3d& x = context.percepts[a.percept].ego_position_m;
    const Eigen::Vector3d ego_error = ego_T_world * context.graph.world_position_m(a.node) - x;
    const double extra = std::pow(uncertainty.sigma_at_m(x), 2);
    if (context.noise[a.percept].mahalanobis_sq(ego_error, extra) <= gate * gate) {
      generating.push_back(a);
    }
  }
  if (generating.size() < 3) return out;
  std::stable_sort(generating.begin(), generating.end(),
                   [&](const NodeAssociation& a, const NodeAssociation& b) {
                     return context.noise[a.percept].sigma_m < context.noise[b.percept].sigma_m;
                   });
  if (generating.size() > kMaxSpheres) generating.resize(kMaxSpheres);
  std::vector<geometry::GaussianSphere> spheres;
  for (const NodeAssociation& a : generating) {
    spheres.push_back(restriction_sphere(context.percepts[a.percept], context.noise[a.percept],
                                         context.graph.world_position_m(a.node)));
  }

  // The subgraph stands when one of its location hypotheses (Eq. 15) is where Eq. 16 puts the ego
  // centre, within both uncertainties. The location's covariance is the inverse Fisher
  // information of the Gaussian spheres, sum_i u_i u_i^T / sigma_i^2 (u_i the unit vector from
  // centre i): ranges from nearly coplanar objects fix the ego centre well across their plane and
  // poorly along it, and only across it does the mirror location differ.
  //
  // That test linearizes the spheres' chi^2 at the location. Where the centres are nearly
  // coplanar, chi^2 is a flat valley across their plane and its maximal density may lie anywhere
  // along it, between the mirror pair (in the bundled kitchen, eight objects of one wall put it
  // 70 cm from the Eq. 16 centre, whose chi^2 was within a few units of it): the linearization at
  // that point then refuses a centre the spheres fit almost as well. So the same test is also
  // taken exactly, as a likelihood ratio: the Eq. 16 centre stands when its chi^2 is within
  // gate^2 of the best location's (to second order these are the same test), each sphere's
  // sigma widened by the Eq. 16 centre's as the covariance above is.
  const std::vector<Eigen::Vector3d> locations = location_hypotheses(spheres);
  std::vector<geometry::GaussianSphere> widened = spheres;
  for (geometry::GaussianSphere& sphere : widened) {
    sphere.sigma_m = std::hypot(sphere.sigma_m, pose_sigma_m);
  }
  double best_chi2 = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& location : locations) {
    Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
    for (const geometry::GaussianSphere& sphere : spheres) {
      const Eigen::Vector3d d = location - sphere.sphere.centre_m;
      const double n = d.norm();
      if (n == 0.0) continue;
      const Eigen::Vector3d u = d / n;
      information += u * u.transpose() / (sphere.sigma_m * sphere.sigma_m);
    }
    const Eigen::Matrix3d covariance =
        (information + Eigen::Matrix3d::Identity() * kMinInformation).inverse() +
        Eigen::Matrix3d::Identity() * (pose_sigma_m * pose_sigma_m);
    const Eigen::Vector3d error = pose->translation() - location;
    if (error.dot(covariance.ldlt().solve(error)) <= gate * gate) {
      out.push_back(*pose);
      return out;
    }
    best_chi2 = std::min(best_chi2, geometry::chi_square(widened, location));
  }
  if (!locations.empty() &&
      geometry::chi_square(widened, pose->translation()) <= best_chi2 + gate * gate) {
    out.push_back(*pose);
  }
  return out;
}

}  // namespace vsl::localization
