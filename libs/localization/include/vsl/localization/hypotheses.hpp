// Hypothesis generation (paper §2.4.1, Eqs. 11-16).
//
// 1. Interpretation search. A seed subgraph from orientation filtering (three percepts and the
//    model triple they may be) is extended percept by percept, most precise first, as in an
//    interpretation tree: a percept joins with a model object of its type whose distances to the
//    objects already associated (the seed's and the first five added) match the percept's
//    distances to their percepts (the pairwise checks of Eq. 8, with tau). Candidates come from
//    the typed adjacency of the nearest seed object (objects at the right distance from it: a
//    graph lookup), or from the spatial grid where the pose puts the percept when it is farther
//    than any link. Distances fix a point up to its mirror image through the associated objects'
//    plane; the current Eq. 16 pose picks the side, so at most one object per percept remains and
//    the tree does not branch below the seed. The pose is re-estimated (Eq. 16 over all
//    associations) after the 2nd and 8th additions and at the end. A percept that matches nothing
//    is left out (a false positive or a bad measurement); an interpretation that can no longer
//    reach `min_count` associations is abandoned.
// 2. Restriction spheres. Each association <O_i^pf, O_j^m> confines the ego centre to the sphere
//    about X_j^m of radius ||X_i^pf|| (Fig. 4a), with the radial standard deviation of the percept
//    (Eq. 7) as a Gaussian sphere. Phi0 holds the spheres of the interpretation's (at most 8) most
//    precise associations that agree with its Eq. 16 pose; Gaussian spheres (maximal density,
//    libs/geometry) make their meets exist under noise. Three spheres meet in a point pair (Phi2,
//    Eq. 12 via the circles of Eq. 11): both points are hypotheses. More spheres meet in a point
//    (Phi3, Eq. 13): it is a hypothesis, and so is its mirror image through the centres' plane
//    when the spheres fit it almost as well (the pair point then keeps no real descendant: nearly
//    coplanar objects, all on one wall, cannot pick the side by their distances alone).
// 3. Orientation and acceptance (Eq. 16). The 6-DoF pose of an interpretation is Eq. 16 over all
//    its associations (estimate_pose: it uses the full 3-D percepts, so it is more precise than
//    the spheres' location, which only uses their ranges). The interpretation stands as a
//    hypothesis when one of its location hypotheses is where that pose puts the ego centre,
//    within both uncertainties (the location's from the spheres' Fisher information: ranges from
//    objects on one wall fix the ego centre well across the wall and poorly along it, and only
//    across it does the mirror location differ), or when the spheres fit that centre within
//    gate^2 of their chi^2 at the best location (the same test as a likelihood ratio, exact where
//    the spheres' chi^2 is a flat valley and the linearization at its minimum is not). With
//    gravity a tilted pose is dropped.
// 4. Duplicates (within same_position_m and same_angle_rad, or indistinguishable by their
//    uncertainty) are merged by the caller.
#pragma once

#include <Eigen/Geometry>

#include <optional>
#include <span>
#include <vector>

#include "vsl/geometry/gaussian_spheres.hpp"
#include "vsl/localization/localization_context.hpp"
#include "vsl/localization/orientation_filter.hpp"
#include "vsl/localization/pose_uncertainty.hpp"

namespace vsl::localization {

// A consistent association set: the seed's three first, then the extension in percept order.
struct Interpretation {
  std::vector<NodeAssociation> associations;
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();  // Eq. 16 over all of them
  PoseUncertainty uncertainty;                                    // of world_T_ego
};

// Eq. 16 over a seed subgraph: S_ego = S_model [S_percept]^-1 (as the least-squares rigid
// transform of the three pairs), with how well three percepts fix it. nullopt when degenerate, or
// tilted beyond max_tilt_rad (plus its own uncertainty) with gravity.
struct SeedPose {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  PoseUncertainty uncertainty;
};
std::optional<SeedPose> seed_pose(const LocalizationContext& context, const PerceptTriple& seed,
                                  const ModelTriple& subgraph);

// Extends one seed subgraph from its seed pose (see 1. above). nullopt when fewer than
// `min_count` associations remain reachable. The returned world_T_ego is Eq. 16 over all the
// associations found.
std::optional<Interpretation> extend_interpretation(const LocalizationContext& context,
                                                    const PerceptTriple& seed,
                                                    const ModelTriple& subgraph,
                                                    const SeedPose& start, int min_count);
// seed_pose() and the above in one.
std::optional<Interpretation> extend_interpretation(const LocalizationContext& context,
                                                    const PerceptTriple& seed,
                                                    const ModelTriple& subgraph, int min_count);

// Omega<O_i^pf, O_j^m>: centre X_j^m (world), radius ||X_i^pf||, sigma the percept's standard
// deviation along its ray from the ego centre.
geometry::GaussianSphere restriction_sphere(const FusedPercept& percept, const PerceptNoise& noise,
                                            const Eigen::Vector3d& world_object_m);

// Location hypotheses (Eq. 15) of three or four restriction spheres, the first three being the
// seed's: see 2. above. Empty when the centres are collinear.
std::vector<Eigen::Vector3d> location_hypotheses(std::span<const geometry::GaussianSphere> spheres);

// The hypotheses of one interpretation (see 2. and 3. above): its Eq. 16 pose when a location
// hypothesis of its restriction spheres agrees with it, else none.
std::vector<Eigen::Isometry3d> hypothesis_poses(const LocalizationContext& context,
                                                const Interpretation& interpretation);

// Rotation angle of a^-1 b.
double rotation_angle_rad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
// Within same_position_m and same_angle_rad of each other.
bool same_hypothesis(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                     const HypothesisOptions& options);
// Angle between the ego z axis carried into the world and the world's z axis.
double tilt_rad(const Eigen::Isometry3d& world_T_ego);

}  // namespace vsl::localization
