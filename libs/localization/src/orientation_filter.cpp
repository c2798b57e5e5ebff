#include "vsl/localization/orientation_filter.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsl::localization {
namespace {

using world::NodeIndex;

// Angle between two vectors (rad); 0 when either is zero.
double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double na = a.norm();
  const double nb = b.norm();
  if (na == 0.0 || nb == 0.0) return 0.0;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// One displacement vector of the percept triple in its frame, with the noise-widened region Sigma
// of §2.3.2 around it: |V_pf - V_m| < mu and angle(V_pf, V_m) < kappa.
struct Displacement {
  Eigen::Vector3d frame_vector;
  double mu_m;
  double kappa_rad;

  bool accepts(const Eigen::Vector3d& model) const {
    if ((frame_vector - model).norm() >= mu_m) return false;
    return angle_between(frame_vector, model) < kappa_rad;
  }
};

Displacement displacement(const Eigen::Vector3d& frame_vector, double sigma_m,
                          const PruningOptions& options) {
  const double length = frame_vector.norm();
  double mu = std::max(options.mu_max_m, options.tau_sigmas * sigma_m);
  if (options.use_gravity) mu += length * std::sin(options.max_tilt_rad);
  const double kappa =
      length > mu ? std::max(options.kappa_max_rad, std::asin(mu / length)) : std::numbers::pi;
  return {frame_vector, mu, kappa};
}

// Distance of c from the line through a and b.
double altitude(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a;
  const double n = ab.norm();
  if (n == 0.0) return (c - a).norm();
  return ab.cross(c - a).norm() / n;
}

double horizontal_extent(const Eigen::Vector3d& d) {
  return std::sqrt(d.x() * d.x() + d.y() * d.y());
}

}  // namespace

std::optional<Eigen::Matrix3d> triple_frame(const Eigen::Vector3d& x_i, const Eigen::Vector3d& x_j,
                                            const Eigen::Vector3d& x_k, bool use_gravity,
                                            double min_extent_m) {
  const Eigen::Vector3d delta1 = x_j - x_i;
  Eigen::Matrix3d r;
  if (use_gravity) {
    // e3 = up, e1 = horizontal part of delta1, e2 = e3 x e1.
    const Eigen::Vector3d horizontal(delta1.x(), delta1.y(), 0.0);
    const double h = horizontal.norm();
    if (!(h > min_extent_m) || !(altitude(x_i, x_j, x_k) > min_extent_m)) return std::nullopt;
    const Eigen::Vector3d e1 = horizontal / h;
    const Eigen::Vector3d e3 = Eigen::Vector3d::UnitZ();
    r.col(0) = e1;
    r.col(1) = e3.cross(e1);
    r.col(2) = e3;
    return r;
  }
  // The paper's frame: delta2 = delta1 x (X_k - X_i), delta3 = delta1 x delta2, normalized.
  const Eigen::Vector3d delta2 = delta1.cross(x_k - x_i);
  const Eigen::Vector3d delta3 = delta1.cross(delta2);
  if (!(delta1.norm() > min_extent_m) || !(delta2.norm() > min_extent_m * delta1.norm())) {
    return std::nullopt;
  }
  r.col(0) = delta1.normalized();
  r.col(1) = delta2.normalized();
  r.col(2) = delta3.normalized();
  return r;
}

OrientationFilterResult orientation_filter(
    const world::WorldGraph& graph, const TypedAdjacency& adjacency,
    const std::vector<FusedPercept>& percepts, const std::vector<PerceptNoise>& noise,
    const CandidateSets& candidates, const PerceptTriple& triple, const PruningOptions& options,
    std::size_t max_subgraphs) {
  OrientationFilterResult result;
  const auto [i, j, k] = triple.percepts;
  if (!candidates.types[i] || !candidates.types[j] || !candidates.types[k]) return result;
  const Eigen::Vector3d& x_i = percepts[i].ego_position_m;
  const Eigen::Vector3d& x_j = percepts[j].ego_position_m;
  const Eigen::Vector3d& x_k = percepts[k].ego_position_m;
  const auto percept_frame = triple_frame(x_i, x_j, x_k, options.use_gravity);
  if (!percept_frame) return result;
  const double s_i = noise[i].sigma_m, s_j = noise[j].sigma_m, s_k = noise[k].sigma_m;

  // Side lengths with their tolerances: only links in |V| +- mu are ever looked at.
  const auto side = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double sa, double sb) {
    return std::make_pair((b - a).norm(),
                          std::max(options.mu_max_m, options.tau_sigmas * std::hypot(sa, sb)));
  };
  const auto [phi_ij, mu_ij] = side(x_i, x_j, s_i, s_j);
  const auto [phi_ik, mu_ik] = side(x_i, x_k, s_i, s_k);
  const auto [phi_jk, mu_jk] = side(x_j, x_k, s_j, s_k);

  // The two vectors of Eq. 10 in S_percept: V_{i,j} (the frame's own first edge: with gravity its
  // height and horizontal length) and V_{i,jk}. The frame's rotation error, about sigma / |e1
  // edge|, moves V_{i,jk} by its length times that angle.
  const Eigen::Matrix3d& r_p = *percept_frame;
  const Eigen::Vector3d delta1 = x_j - x_i;
  const double edge_m = options.use_gravity ? horizontal_extent(delta1) : delta1.norm();
  const double frame_sigma_rad = std::hypot(s_i, s_j) / edge_m;
  const Eigen::Vector3d v_ij = r_p.transpose() * delta1;
  const Eigen::Vector3d v_ijk = r_p.transpose() * (x_j - x_k);
  const Displacement d_ij = displacement(v_ij, std::hypot(s_i, s_j), options);
  const Displacement d_ijk = displacement(
      v_ijk, std::sqrt(s_j * s_j + s_k * s_k + std::pow(v_ijk.norm() * frame_sigma_rad, 2)),
      options);

  const world::TypeId type_i = *candidates.types[i];
  const world::TypeId type_j = *candidates.types[j];
  const world::TypeId type_k = *candidates.types[k];
  const auto is_candidate = [&](int percept, world::TypeId type, NodeIndex node) {
    if (graph.type(node) != type) return false;
    return !candidates.constrained[percept] || candidates.is_candidate(percept, node);
  };
  std::vector<NodeIndex> origins;
  if (candidates.constrained[i]) {
    origins = candidates.nodes[i];
  } else {
    for (std::size_t n = 0; n < graph.node_count(); ++n) {
      if (graph.type(static_cast<NodeIndex>(n)) == type_i)
        origins.push_back(static_cast<NodeIndex>(n));
    }
  }

  std::array<std::vector<NodeIndex>, 3> used;
  std::vector<NodeIndex> vs, ws;
  for (const NodeIndex u : origins) {
    vs.clear();
    ws.clear();
    for (const world::Neighbour& n : adjacency.within(u, type_j, phi_ij - mu_ij, phi_ij + mu_ij)) {
      if (is_candidate(j, type_j, n.node)) vs.push_back(n.node);
    }
    for (const world::Neighbour& n : adjacency.within(u, type_k, phi_ik - mu_ik, phi_ik + mu_ik)) {
      if (is_candidate(k, type_k, n.node)) ws.push_back(n.node);
    }
    const Eigen::Vector3d& m_u = graph.world_position_m(u);
    for (const NodeIndex v : vs) {
      const Eigen::Vector3d& m_v = graph.world_position_m(v);
      for (const NodeIndex w : ws) {
        if (w == v) continue;
        const Eigen::Vector3d& m_w = graph.world_position_m(w);
        if (std::abs((m_w - m_v).norm() - phi_jk) >= mu_jk) continue;
        ++result.examined;
        const auto model_frame = triple_frame(m_u, m_v, m_w, options.use_gravity);
        if (!model_frame) continue;
        const Eigen::Matrix3d& r_m = *model_frame;
        if (!d_ij.accepts(r_m.transpose() * (m_v - m_u))) continue;
        if (!d_ijk.accepts(r_m.transpose() * (m_v - m_w))) continue;
        if (result.subgraphs.size() >= max_subgraphs) {
          result.truncated = true;
          break;
        }
        result.subgraphs.push_back({{u, v, w}});
        used[0].push_back(u);
        used[1].push_back(v);
        used[2].push_back(w);
      }
      if (result.truncated) break;
    }
    if (result.truncated) break;
  }
  for (int s = 0; s < 3; ++s) {
    std::sort(used[s].begin(), used[s].end());
    used[s].erase(std::unique(used[s].begin(), used[s].end()), used[s].end());
    result.nodes[s] = std::move(used[s]);
  }
  return result;
}

}  // namespace vsl::localization
