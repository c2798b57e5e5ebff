#include "upright_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsl::world_import {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// Andrew's monotone chain; counter-clockwise, no repeated end point.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const Eigen::Vector2d& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

FrameExtents extents_in(const std::vector<Eigen::Vector3d>& world_points_m,
                        const Eigen::Matrix3d& world_R_frame) {
  FrameExtents out;
  if (world_points_m.empty()) return out;
  out.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  out.hi = -out.lo;
  for (const Eigen::Vector3d& p : world_points_m) {
    const Eigen::Vector3d q = world_R_frame.transpose() * p;
    out.lo = out.lo.cwiseMin(q);
    out.hi = out.hi.cwiseMax(q);
  }
  return out;
}

UprightBox upright_box(const std::vector<Eigen::Vector3d>& world_points_m) {
  UprightBox box;
  if (world_points_m.empty()) return box;
  std::vector<Eigen::Vector2d> footprint;
  footprint.reserve(world_points_m.size());
  for (const Eigen::Vector3d& p : world_points_m) footprint.emplace_back(p.x(), p.y());
  const std::vector<Eigen::Vector2d> hull = convex_hull(std::move(footprint));
  // The minimum-area rectangle has a side on a hull edge (Freeman and Shapira): try each.
  Eigen::Vector2d best_axis = Eigen::Vector2d::UnitX();
  double best_area = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d edge = hull[(i + 1) % hull.size()] - hull[i];
    if (edge.norm() < 1e-12) continue;
    const Eigen::Vector2d u = edge.normalized(), v(-u.y(), u.x());
    double u_lo = 1e300, u_hi = -1e300, v_lo = 1e300, v_hi = -1e300;
    for (const Eigen::Vector2d& p : hull) {
      u_lo = std::min(u_lo, p.dot(u));
      u_hi = std::max(u_hi, p.dot(u));
      v_lo = std::min(v_lo, p.dot(v));
      v_hi = std::max(v_hi, p.dot(v));
    }
    const double area = (u_hi - u_lo) * (v_hi - v_lo);
    if (area < best_area - 1e-12) {
      best_area = area;
      best_axis = (u_hi - u_lo) >= (v_hi - v_lo) ? u : v;
    }
  }
  // A canonical sign, so that equal shapes get equal frames: x points to +x (or +y).
  if (best_axis.x() < -1e-9 || (std::abs(best_axis.x()) <= 1e-9 && best_axis.y() < 0)) {
    best_axis = -best_axis;
  }
  box.axis_x = Eigen::Vector3d(best_axis.x(), best_axis.y(), 0.0);
  box.axis_y = Eigen::Vector3d(-best_axis.y(), best_axis.x(), 0.0);
  Eigen::Matrix3d world_R_box;
  world_R_box << box.axis_x, box.axis_y, Eigen::Vector3d::UnitZ();
  const FrameExtents extents = extents_in(world_points_m, world_R_box);
  box.extents_m = extents.size();
  box.centre_m = world_R_box * extents.mid();
  return box;
}

}  // namespace vsl::world_import
