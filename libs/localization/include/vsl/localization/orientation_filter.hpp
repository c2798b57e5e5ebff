// Orientation filtering (paper §2.3.2, Eq. 10): which model triples can a triple of percepts be?
//
// Three non-collinear percepts i, j, k span a reference frame S_percept^{i,j,k} = [R, X_i]; the
// relative displacement V_{i,jk} = R^T (X_j - X_k) of Eq. 10 does not depend on where the robot
// stands. A model triple u, v, w (candidates of i, j, k after proximity filtering, linked in the
// world graph) gives the same vector in its own frame S_model^{u,v,w} when it is what was seen;
// subgraphs whose vectors differ by more than mu in length or kappa in angle are rejected.
// Candidate neighbours are only visited when their link lengths fall in |V| +- mu (the world
// graph's adjacency rows carry the distances).
//
// What a triple frame can tell. The paper's frame, delta1 = X_j - X_i, delta2 = delta1 x
// (X_k - X_i), delta3 = delta1 x delta2, puts the triangle in its own plane: V_{i,jk} has no
// component along delta2 and the component along delta3 always has the same sign. It therefore
// encodes exactly the triangle's shape, which the three lengths of proximity filtering already
// fixed; in particular a triangle and its mirror image are congruent under a proper rotation (the
// half-turn about an in-plane axis), so the frame cannot tell them apart, and a match may turn the
// robot upside down or put it behind the wall it looks at.
//
// Gravity. The ego frame's z axis is up and the robot stands upright (world_R_ego = Rz(yaw) up to
// a small tilt), so the vertical is shared by both frames. With use_gravity the frame is
// e3 = z (up), e1 = the horizontal direction of delta1, e2 = e3 x e1: a frame that only the yaw
// can turn. In it, V_{i,j} = R^T delta1 = (|delta1_h|, 0, delta1_z) compares the heights of the
// pair, and V_{i,jk} is a full 3-D vector whose e2 component has a sign: the triangle's handedness
// seen from above. Mirror images, upside-down matches and triangles tilted differently are all
// rejected, which is most of what the paper's frame lets through in a kitchen full of congruent
// handle-door triangles. A tilt up to max_tilt_rad is allowed by widening mu by |V| tilt.
//
// Tolerances. The paper's mu_max and kappa_max are fixed; a far percept (Eq. 7: 12 cm at 4 m)
// would then reject its own true subgraph, so both are widened to the noise: mu = max(mu_max,
// tau_sigmas * s) with s the standard deviation of the compared vector (its two end points plus
// the frame's rotation error, sigma / |delta1_h|, acting on its length), and kappa =
// max(kappa_max, asin(mu / |V|)) (a short vector's direction is only known to mu / |V|).
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

#include "vsl/localization/localizer.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/proximity_filter.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::localization {

// Three percepts (i, j, k): the frame's origin is i, its first axis points towards j.
struct PerceptTriple {
  std::array<int, 3> percepts{-1, -1, -1};
};

// A model subgraph u, v, w matched to a percept triple (u for i, v for j, w for k).
struct ModelTriple {
  std::array<world::NodeIndex, 3> nodes{};
};

// R = [e1 e2 e3] of S^{i,j,k} (columns, frame of the inputs), or nullopt when the points are
// collinear within `min_extent_m` (with gravity: when delta1 has no horizontal extent).
std::optional<Eigen::Matrix3d> triple_frame(const Eigen::Vector3d& x_i, const Eigen::Vector3d& x_j,
                                            const Eigen::Vector3d& x_k, bool use_gravity,
                                            double min_extent_m = 1e-6);

struct OrientationFilterResult {
  std::vector<ModelTriple> subgraphs;  // consistent model triples, in graph order
  std::size_t examined = 0;            // triples whose frames were compared
  bool truncated = false;              // stopped at max_subgraphs
  // Candidates of i, j, k that belong to at least one consistent subgraph (the pruned psi_act).
  std::array<std::vector<world::NodeIndex>, 3> nodes;
};

OrientationFilterResult orientation_filter(
    const world::WorldGraph& graph, const TypedAdjacency& adjacency,
    const std::vector<FusedPercept>& percepts, const std::vector<PerceptNoise>& noise,
    const CandidateSets& candidates, const PerceptTriple& triple, const PruningOptions& options,
    std::size_t max_subgraphs);

}  // namespace vsl::localization
