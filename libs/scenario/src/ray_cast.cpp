#include "vsl/scenario/ray_cast.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vsl::scenario {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Below this a direction component counts as parallel to a slab or the cylinder axis.
constexpr double kParallel = 1e-12;

// Clips `span` to the slab |coordinate| <= half along one axis; false when empty.
bool clip_slab(double origin, double direction, double half, Span& span) {
  if (std::abs(direction) < kParallel) return std::abs(origin) <= half;
  double t0 = (-half - origin) / direction;
  double t1 = (half - origin) / direction;
  if (t0 > t1) std::swap(t0, t1);
  span.enter_m = std::max(span.enter_m, t0);
  span.exit_m = std::min(span.exit_m, t1);
  return span.enter_m <= span.exit_m;
}

// Crossing-number test of q against the face polygon projected onto the plane that drops
// `drop_axis` (the dominant axis of the face normal, so the projection is never degenerate).
bool inside_polygon(const world::Polyhedron& polyhedron, const std::vector<std::uint32_t>& face,
                    const Eigen::Vector3d& q, int drop_axis) {
  const int u = (drop_axis + 1) % 3;
  const int v = (drop_axis + 2) % 3;
  bool inside = false;
  for (std::size_t i = 0, j = face.size() - 1; i < face.size(); j = i++) {
    const Eigen::Vector3d& a = polyhedron.vertices_m[face[i]];
    const Eigen::Vector3d& b = polyhedron.vertices_m[face[j]];
    if ((a[v] > q[v]) != (b[v] > q[v])) {
      const double cross_u = a[u] + (q[v] - a[v]) / (b[v] - a[v]) * (b[u] - a[u]);
      if (q[u] < cross_u) inside = !inside;
    }
  }
  return inside;
}

std::optional<double> first_in_span(const std::optional<Span>& span, double t_min, double t_max) {
  if (!span) return std::nullopt;
  const double t = std::max(span->enter_m, t_min);
  if (t > std::min(span->exit_m, t_max)) return std::nullopt;
  return t;
}

// Möller–Trumbore: t at which the line meets triangle abc (edges included), or nullopt for a miss
// or a line parallel to the triangle's plane. Degenerate triangles are never met.
std::optional<double> line_meets_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c, const Ray& ray) {
  const Eigen::Vector3d ab = b - a, ac = c - a;
  const Eigen::Vector3d p = ray.direction.cross(ac);
  const double determinant = ab.dot(p);
  // Relative to the edges' lengths, so that millimetre facets and metre walls are judged alike.
  if (!(std::abs(determinant) > kParallel * ab.norm() * ac.norm())) return std::nullopt;
  const double inverse = 1.0 / determinant;
  const Eigen::Vector3d to_origin = ray.origin_m - a;
  const double u = to_origin.dot(p) * inverse;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Eigen::Vector3d q = to_origin.cross(ab);
  const double v = ray.direction.dot(q) * inverse;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  return ac.dot(q) * inverse;
}

// Where the line meets triangle `triangle` of the mesh, if it does.
std::optional<double> line_meets_mesh_triangle(const world::TriangleMesh& mesh,
                                               const std::array<std::uint32_t, 3>& triangle,
                                               const Ray& ray) {
  const std::size_t count = mesh.vertices_m.size();
  if (triangle[0] >= count || triangle[1] >= count || triangle[2] >= count) {
    return std::nullopt;  // the loader rejects these; a hand-made model must not crash us
  }
  return line_meets_triangle(mesh.vertices_m[triangle[0]].cast<double>(),
                             mesh.vertices_m[triangle[1]].cast<double>(),
                             mesh.vertices_m[triangle[2]].cast<double>(), ray);
}

// Calls visit(t) for every t at which the line crosses a triangle of the mesh.
template <typename Visit>
void for_each_mesh_crossing(const world::TriangleMesh& mesh, const Ray& ray, Visit&& visit) {
  for (const auto& triangle : mesh.triangles) {
    if (const std::optional<double> t = line_meets_mesh_triangle(mesh, triangle, ray)) visit(*t);
  }
}

}  // namespace

std::optional<Span> line_through_box(const world::Box& box, const Ray& ray) {
  Span span{-kInfinity, kInfinity};
  for (int axis = 0; axis < 3; ++axis) {
    if (!clip_slab(ray.origin_m[axis], ray.direction[axis], box.size_m[axis] / 2, span)) {
      return std::nullopt;
    }
  }
  return span;
}

std::optional<Span> line_through_cylinder(const world::Cylinder& cylinder, const Ray& ray) {
  Span span{-kInfinity, kInfinity};
  if (!clip_slab(ray.origin_m.z(), ray.direction.z(), cylinder.height_m / 2, span)) {
    return std::nullopt;
  }
  // |o_xy + t d_xy|^2 = r^2  ->  a t^2 + 2 b t + c = 0.
  const double a = ray.direction.head<2>().squaredNorm();
  const double b = ray.origin_m.head<2>().dot(ray.direction.head<2>());
  const double c = ray.origin_m.head<2>().squaredNorm() - cylinder.radius_m * cylinder.radius_m;
  if (a < kParallel) {
    if (c > 0) return std::nullopt;  // parallel to the axis, outside the mantle
    return span;
  }
  const double discriminant = b * b - a * c;
  if (discriminant < 0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  span.enter_m = std::max(span.enter_m, (-b - root) / a);
  span.exit_m = std::min(span.exit_m, (-b + root) / a);
  if (span.enter_m > span.exit_m) return std::nullopt;
  return span;
}

std::vector<double> polyhedron_crossings(const world::Polyhedron& polyhedron, const Ray& ray) {
  std::vector<double> crossings;
  for (const auto& face : polyhedron.faces) {
    if (face.size() < 3) continue;
    // Newell's normal: robust for any planar polygon, convex or not.
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (std::size_t i = 0, j = face.size() - 1; i < face.size(); j = i++) {
      const Eigen::Vector3d& a = polyhedron.vertices_m[face[j]];
      const Eigen::Vector3d& b = polyhedron.vertices_m[face[i]];
      normal +=
          Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                          (a.x() - b.x()) * (a.y() + b.y()));
    }
    const double denominator = normal.dot(ray.direction);
    if (std::abs(denominator) < kParallel * std::max(1.0, normal.norm())) continue;
    const double t = normal.dot(polyhedron.vertices_m[face[0]] - ray.origin_m) / denominator;
    int drop_axis = 0;
    normal.cwiseAbs().maxCoeff(&drop_axis);
    if (inside_polygon(polyhedron, face, ray.origin_m + t * ray.direction, drop_axis)) {
      crossings.push_back(t);
    }
  }
  std::sort(crossings.begin(), crossings.end());
  return crossings;
}

std::vector<double> mesh_crossings(const world::TriangleMesh& mesh, const Ray& ray) {
  std::vector<double> crossings;
  for_each_mesh_crossing(mesh, ray, [&](double t) { crossings.push_back(t); });
  std::sort(crossings.begin(), crossings.end());
  return crossings;
}

std::optional<double> first_hit(const world::Shape& shape, const Ray& ray, double t_min_m,
                                double t_max_m) {
  if (t_min_m > t_max_m) return std::nullopt;
  if (const auto* box = std::get_if<world::Box>(&shape)) {
    return first_in_span(line_through_box(*box, ray), t_min_m, t_max_m);
  }
  if (const auto* cylinder = std::get_if<world::Cylinder>(&shape)) {
    return first_in_span(line_through_cylinder(*cylinder, ray), t_min_m, t_max_m);
  }
  if (const auto* mesh = std::get_if<world::TriangleMesh>(&shape)) {
    // A surface without an inside: the nearest crossing in range, found without sorting them all.
    std::optional<double> nearest;
    for_each_mesh_crossing(*mesh, ray, [&](double t) {
      if (t >= t_min_m && t <= t_max_m && (!nearest || t < *nearest)) nearest = t;
    });
    return nearest;
  }
  const std::vector<double> crossings =
      polyhedron_crossings(std::get<world::Polyhedron>(shape), ray);
  const auto after = std::lower_bound(crossings.begin(), crossings.end(), t_min_m);
  if ((after - crossings.begin()) % 2 == 1) return t_min_m;  // odd crossings before: inside
  if (after != crossings.end() && *after <= t_max_m) return *after;
  return std::nullopt;
}

}  // namespace vsl::scenario
