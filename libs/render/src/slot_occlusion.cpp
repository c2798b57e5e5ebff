#include "slot_occlusion.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include <cmath>
#include <map>
#include <tuple>

namespace vsl::render {
namespace {

// Normals that agree to about 0.6 degrees share a key (box faces of one orientation).
using NormalKey = std::tuple<int, int, int>;
NormalKey key_of(const Eigen::Vector3d& unit_normal) {
  return {static_cast<int>(std::lround(unit_normal.x() * 100.0)),
          static_cast<int>(std::lround(unit_normal.y() * 100.0)),
          static_cast<int>(std::lround(unit_normal.z() * 100.0))};
}

// True when p (on the triangle's plane, up to rounding) lies inside triangle abc, edges included
// with a tolerance of tolerance_m.
bool inside(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
            const Eigen::Vector3d& c, const Eigen::Vector3d& unit_normal, double tolerance_m) {
  const Eigen::Vector3d* corners[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& from = *corners[k];
    const Eigen::Vector3d edge = *corners[(k + 1) % 3] - from;
    const double length = edge.norm();
    if (length <= 0.0) return false;
    // Signed distance of p from the edge line, positive inside (CCW seen from the normal).
    if (unit_normal.cross(edge).dot(p - from) / length < -tolerance_m) return false;
  }
  return true;
}

}  // namespace

// Slot walls deeper than this (m) are not darkened; see the use below.
constexpr double kMaxSlotDepth_m = 0.1;

std::vector<float> slot_light_factors(const std::vector<Eigen::Vector3d>& world_vertices_m,
                                      const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                      const std::vector<Eigen::Vector4d>& world_planes,
                                      double max_width_m, const std::vector<bool>& two_sided) {
  std::vector<float> factors(triangles.size(), 1.0f);
  if (!(max_width_m > 0.0)) return factors;
  const auto takes_part = [&](std::uint32_t t) { return two_sided.empty() || !two_sided[t]; };

  // Triangles by orientation, each group sorted by plane offset d, so that the facets facing a
  // given one within max_width are one binary search away.
  std::map<NormalKey, std::vector<std::pair<double, std::uint32_t>>> by_normal;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    if (!takes_part(t)) continue;
    by_normal[key_of(world_planes[t].head<3>())].emplace_back(world_planes[t].w(), t);
  }
  for (auto& [key, group] : by_normal) std::sort(group.begin(), group.end());

  constexpr double kTolerance_m = 1e-4;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    if (!takes_part(t)) continue;
    const Eigen::Vector3d n = world_planes[t].head<3>();
    const auto found = by_normal.find(key_of(-n));
    if (found == by_normal.end()) continue;
    const Eigen::Vector3d& a = world_vertices_m[triangles[t][0]];
    const Eigen::Vector3d& b = world_vertices_m[triangles[t][1]];
    const Eigen::Vector3d& c = world_vertices_m[triangles[t][2]];
    const Eigen::Vector3d centroid = (a + b + c) / 3.0;
    // A facet u with normal m = -n and offset d_u lies at distance w = m . centroid - d_u in
    // front of the centroid along n: m . (centroid + w n) = m . centroid - w = d_u.
    const double key = -n.dot(centroid);
    const auto& group = found->second;
    auto it = std::lower_bound(group.begin(), group.end(),
                               std::make_pair(key - max_width_m - kTolerance_m, std::uint32_t{0}));
    double width_m = -1.0;
    for (; it != group.end() && it->first <= key + kTolerance_m; ++it) {
      const std::uint32_t u = it->second;
      const Eigen::Vector3d m = world_planes[u].head<3>();
      const double denominator = -m.dot(n);  // ~1 for opposite normals
      if (denominator < 0.999) continue;
      const double w = (m.dot(centroid) - world_planes[u].w()) / denominator;
      if (w < -kTolerance_m || w > max_width_m) continue;
      if (width_m >= 0.0 && w >= width_m) continue;
      const Eigen::Vector3d p = centroid + w * n;
      if (!inside(p, world_vertices_m[triangles[u][0]], world_vertices_m[triangles[u][1]],
                  world_vertices_m[triangles[u][2]], m, kTolerance_m)) {
        continue;
      }
      width_m = std::max(w, 0.0);
    }
    if (width_m < 0.0) continue;
    const double depth_m = std::min({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    // Only narrow facets are walls of a slot (the edges of doors, panels and carcasses). A large
    // facet that happens to face another across a small gap (a wall behind a carcass) is mostly
    // open to the room: darkening it whole would paint the wall black.
    if (depth_m > kMaxSlotDepth_m) continue;
    // A facet flush against another (w = 0) is never seen; keep a trace of light so that a
    // sub-pixel glimpse of it is dark, not an artefact of exactly zero.
    factors[t] = static_cast<float>(std::max(width_m / (width_m + depth_m), 0.02));
  }
  return factors;
}

}  // namespace vsl::render
