#include "vsl/worldgen/geometry.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace vsl::worldgen {
namespace {

double signed_area(const std::vector<Eigen::Vector2d>& polygon) {
  double area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * area;
}

std::vector<Eigen::Vector2d> counter_clockwise(std::vector<Eigen::Vector2d> polygon) {
  if (polygon.size() < 3) throw std::invalid_argument("worldgen: a polygon needs 3 points");
  if (signed_area(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

std::uint32_t u32(std::size_t i) {
  return static_cast<std::uint32_t>(i);
}

}  // namespace

world::Primitive box(const std::string& material, const Eigen::Vector3d& centre_m,
                     const Eigen::Vector3d& size_m) {
  world::Primitive p;
  p.shape = world::Box{size_m};
  p.object_position_m = centre_m;
  p.material = material;
  return p;
}

world::Primitive box_between(const std::string& material, const Eigen::Vector3d& lo_m,
                             const Eigen::Vector3d& hi_m) {
  return box(material, 0.5 * (lo_m + hi_m), (hi_m - lo_m).cwiseAbs());
}

world::Primitive cylinder(const std::string& material, const Eigen::Vector3d& centre_m,
                          double radius_m, double length_m, Axis axis) {
  world::Primitive p;
  p.shape = world::Cylinder{radius_m, length_m};
  p.object_position_m = centre_m;
  p.material = material;
  constexpr double kQuarter = std::numbers::pi / 2.0;
  if (axis == Axis::x) {  // the cylinder's z onto x: +90 deg about y
    p.object_orientation =
        Eigen::Quaterniond(Eigen::AngleAxisd(kQuarter, Eigen::Vector3d::UnitY()));
  } else if (axis == Axis::y) {  // z onto y: -90 deg about x
    p.object_orientation =
        Eigen::Quaterniond(Eigen::AngleAxisd(-kQuarter, Eigen::Vector3d::UnitX()));
  }
  return p;
}

world::Primitive polyhedron(const std::string& material, const Eigen::Vector3d& origin_m,
                            world::Polyhedron shape) {
  world::Primitive p;
  p.shape = std::move(shape);
  p.object_position_m = origin_m;
  p.material = material;
  return p;
}

world::Polyhedron prism_x(const std::vector<Eigen::Vector2d>& profile_yz, double length_m) {
  // Counter-clockwise in (y, z) means the right-hand normal of the +x cap points along +x.
  const std::vector<Eigen::Vector2d> profile = counter_clockwise(profile_yz);
  const std::size_t m = profile.size();
  world::Polyhedron out;
  for (double x : {-0.5 * length_m, 0.5 * length_m}) {
    for (const Eigen::Vector2d& p : profile) out.vertices_m.emplace_back(x, p.x(), p.y());
  }
  std::vector<std::uint32_t> left, right;
  for (std::size_t k = 0; k < m; ++k) {
    right.push_back(u32(m + k));
    left.push_back(u32(m - 1 - k));
  }
  out.faces.push_back(std::move(left));
  out.faces.push_back(std::move(right));
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t j = (k + 1) % m;
    out.faces.push_back({u32(k), u32(j), u32(j + m), u32(k + m)});
  }
  return out;
}

world::Polyhedron frustum(const std::vector<Eigen::Vector2d>& bottom_xy,
                          const std::vector<Eigen::Vector2d>& top_xy, double height_m) {
  if (bottom_xy.size() != top_xy.size()) {
    throw std::invalid_argument("worldgen: frustum outlines differ in size");
  }
  const bool flip = signed_area(bottom_xy) < 0.0;
  std::vector<Eigen::Vector2d> bottom = bottom_xy, top = top_xy;
  if (flip) {
    std::reverse(bottom.begin(), bottom.end());
    std::reverse(top.begin(), top.end());
  }
  const std::size_t n = bottom.size();
  world::Polyhedron out;
  for (const Eigen::Vector2d& p : bottom) out.vertices_m.emplace_back(p.x(), p.y(), 0.0);
  for (const Eigen::Vector2d& p : top) out.vertices_m.emplace_back(p.x(), p.y(), height_m);
  std::vector<std::uint32_t> down, up;
  for (std::size_t k = 0; k < n; ++k) {
    down.push_back(u32(n - 1 - k));
    up.push_back(u32(n + k));
  }
  out.faces.push_back(std::move(down));
  out.faces.push_back(std::move(up));
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = (k + 1) % n;
    out.faces.push_back({u32(k), u32(j), u32(j + n), u32(k + n)});
  }
  return out;
}

world::Polyhedron basin(const Eigen::Vector2d& top_size_xy, double depth_m, double taper_m,
                        double wall_m, double rim_m) {
  const double x = 0.5 * top_size_xy.x(), y = 0.5 * top_size_xy.y();
  auto ring = [](double hx, double hy, double z) {
    return std::vector<Eigen::Vector3d>{{-hx, -hy, z}, {hx, -hy, z}, {hx, hy, z}, {-hx, hy, z}};
  };
  world::Polyhedron out;
  for (const auto& r :
       {ring(x, y, 0.0), ring(x - taper_m, y - taper_m, -depth_m), ring(x - rim_m, y - rim_m, 0.0),
        ring(x - rim_m - taper_m, y - rim_m - taper_m, -depth_m + wall_m)}) {
    out.vertices_m.insert(out.vertices_m.end(), r.begin(), r.end());
  }
  // 0-3 outer rim, 4-7 outer bottom, 8-11 opening, 12-15 inner bottom; each ring ccw from +z.
  out.faces.push_back({7, 6, 5, 4});      // outer bottom, facing down
  out.faces.push_back({12, 13, 14, 15});  // inner bottom, facing up into the bowl
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t j = (i + 1) % 4;
    out.faces.push_back({i, i + 4, j + 4, j});            // outer side, facing out
    out.faces.push_back({i, j, j + 8, i + 8});            // flat rim, facing up
    out.faces.push_back({j + 8, j + 12, i + 12, i + 8});  // inner side, facing the bowl
  }
  return out;
}

std::vector<Eigen::Vector2d> rectangle(double size_x, double size_y,
                                       const Eigen::Vector2d& centre) {
  const double x = 0.5 * size_x, y = 0.5 * size_y;
  return {centre + Eigen::Vector2d(-x, -y), centre + Eigen::Vector2d(x, -y),
          centre + Eigen::Vector2d(x, y), centre + Eigen::Vector2d(-x, y)};
}

std::vector<Eigen::Vector2d> regular_polygon(int sides, double radius) {
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    out.emplace_back(radius * std::cos(a), radius * std::sin(a));
  }
  return out;
}

std::string check_polyhedron(const world::Polyhedron& shape) {
  if (shape.vertices_m.size() < 4 || shape.faces.size() < 4)
    return "fewer than 4 vertices or faces";
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& face : shape.faces) {
    if (face.size() < 3) return "a face with fewer than 3 vertices";
    for (std::size_t k = 0; k < face.size(); ++k) {
      if (face[k] >= shape.vertices_m.size()) return "vertex index out of range";
      if (++edges[{face[k], face[(k + 1) % face.size()]}] > 1) return "edge used twice";
    }
  }
  for (const auto& [edge, count] : edges) {
    if (!edges.count({edge.second, edge.first})) return "not closed";
  }
  double volume = 0.0;
  for (const auto& face : shape.faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      volume += shape.vertices_m[face[0]].dot(
          shape.vertices_m[face[k]].cross(shape.vertices_m[face[k + 1]]));
    }
  }
  if (!(volume > 0.0)) return "not of positive volume (faces clockwise?)";
  return "";
}

Eigen::Isometry3d pose_yaw(const Eigen::Vector3d& position_m, double yaw_rad) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = position_m;
  return pose;
}

Eigen::Isometry3d offset(const Eigen::Isometry3d& frame, const Eigen::Vector3d& offset_m) {
  return frame * Eigen::Translation3d(offset_m);
}

}  // namespace vsl::worldgen
