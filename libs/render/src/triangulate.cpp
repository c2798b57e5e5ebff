#include "triangulate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsl::render {
namespace {

// Newell's method: the normal of a polygon loop, robust for non-convex and slightly non-planar
// loops; its length is twice the loop's area.
Eigen::Vector3d newell_normal(const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<std::uint32_t>& loop) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d& a = vertices[loop[i]];
    const Eigen::Vector3d& b = vertices[loop[(i + 1) % loop.size()]];
    normal += Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                              (a.x() - b.x()) * (a.y() + b.y()));
  }
  return normal;
}

// Adds a loop of a convex solid centred on the origin, turning it so that it faces outward:
// the generators below then need not get every winding right by hand.
void add_outward_loop(Mesh& mesh, std::vector<std::uint32_t> loop) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const std::uint32_t index : loop) centroid += mesh.vertices_m[index];
  Eigen::Vector3d normal = newell_normal(mesh.vertices_m, loop);
  if (normal.dot(centroid) < 0.0) {
    std::reverse(loop.begin(), loop.end());
    normal = -normal;
  }
  triangulate_polygon(mesh.vertices_m, loop, normal, mesh.triangles);
}

double cross_2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool inside_triangle_2d(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return cross_2d(a, b, p) >= 0.0 && cross_2d(b, c, p) >= 0.0 && cross_2d(c, a, p) >= 0.0;
}

}  // namespace

void triangulate_polygon(const std::vector<Eigen::Vector3d>& vertices,
                         const std::vector<std::uint32_t>& loop, const Eigen::Vector3d& normal,
                         std::vector<std::array<std::uint32_t, 3>>& out) {
  if (loop.size() < 3) return;
  if (loop.size() == 3) {
    out.push_back({loop[0], loop[1], loop[2]});
    return;
  }
  // Project onto the plane of the two axes other than the normal's dominant one, keeping the
  // orientation CCW in 2D.
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  const int u_axis = (drop + 1) % 3;
  const int v_axis = (drop + 2) % 3;
  const bool flip = normal[drop] < 0.0;
  std::vector<Eigen::Vector2d> points;
  points.reserve(loop.size());
  for (const std::uint32_t index : loop) {
    const Eigen::Vector3d& p = vertices[index];
    points.emplace_back(flip ? p[v_axis] : p[u_axis], flip ? p[u_axis] : p[v_axis]);
  }

  std::vector<std::size_t> remaining(loop.size());
  for (std::size_t i = 0; i < remaining.size(); ++i) remaining[i] = i;
  std::vector<std::array<std::uint32_t, 3>> ears;
  std::size_t guard = remaining.size() * remaining.size();
  while (remaining.size() > 3 && guard-- > 0) {
    bool clipped = false;
    for (std::size_t i = 0; i < remaining.size(); ++i) {
      const std::size_t ia = remaining[(i + remaining.size() - 1) % remaining.size()];
      const std::size_t ib = remaining[i];
      const std::size_t ic = remaining[(i + 1) % remaining.size()];
      if (cross_2d(points[ia], points[ib], points[ic]) <= 0.0) continue;  // reflex or collinear
      bool empty = true;
      for (const std::size_t other : remaining) {
        if (other == ia || other == ib || other == ic) continue;
        if (inside_triangle_2d(points[other], points[ia], points[ib], points[ic])) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      ears.push_back({loop[ia], loop[ib], loop[ic]});
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
      break;
    }
    if (!clipped) break;
  }
  if (remaining.size() != 3) {
    // Not a simple polygon (or numerically degenerate): a fan still covers a convex-ish face.
    for (std::size_t i = 1; i + 1 < loop.size(); ++i)
      out.push_back({loop[0], loop[i], loop[i + 1]});
    return;
  }
  out.insert(out.end(), ears.begin(), ears.end());
  out.push_back({loop[remaining[0]], loop[remaining[1]], loop[remaining[2]]});
}

Mesh triangulate(const world::Box& box) {
  Mesh mesh;
  const Eigen::Vector3d half = 0.5 * box.size_m;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices_m.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                                 (i & 4) ? half.z() : -half.z());
  }
  // Faces as corner-index loops (bit 0: +x, bit 1: +y, bit 2: +z); add_outward_loop orients them.
  add_outward_loop(mesh, {0, 2, 6, 4});  // -x
  add_outward_loop(mesh, {1, 3, 7, 5});  // +x
  add_outward_loop(mesh, {0, 1, 5, 4});  // -y
  add_outward_loop(mesh, {2, 3, 7, 6});  // +y
  add_outward_loop(mesh, {0, 1, 3, 2});  // -z
  add_outward_loop(mesh, {4, 5, 7, 6});  // +z
  return mesh;
}

Mesh triangulate(const world::Cylinder& cylinder, int segments) {
  Mesh mesh;
  const auto n = static_cast<std::uint32_t>(std::max(segments, 3));
  const double half_height = 0.5 * cylinder.height_m;
  for (std::uint32_t k = 0; k < n; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / n;
    const double x = cylinder.radius_m * std::cos(angle);
    const double y = cylinder.radius_m * std::sin(angle);
    // Vertices alternate: bottom ring k is 2k, top ring k is 2k + 1.
    mesh.vertices_m.emplace_back(x, y, -half_height);
    mesh.vertices_m.emplace_back(x, y, half_height);
  }
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t next = (k + 1) % n;
    add_outward_loop(mesh, {2 * k, 2 * next, 2 * next + 1, 2 * k + 1});
    bottom.push_back(2 * k);
    top.push_back(2 * k + 1);
  }
  add_outward_loop(mesh, bottom);
  add_outward_loop(mesh, top);
  return mesh;
}

Mesh triangulate(const world::Polyhedron& polyhedron) {
  Mesh mesh;
  mesh.vertices_m = polyhedron.vertices_m;
  for (const auto& face : polyhedron.faces) {
    bool valid = face.size() >= 3;
    for (const std::uint32_t index : face) valid = valid && index < mesh.vertices_m.size();
    if (!valid) continue;  // the loader rejects these; a hand-made model must not crash us
    triangulate_polygon(mesh.vertices_m, face, newell_normal(mesh.vertices_m, face),
                        mesh.triangles);
  }
  return mesh;
}

Mesh triangulate(const world::TriangleMesh& mesh) {
  Mesh out;
  out.vertices_m.reserve(mesh.vertices_m.size());
  for (const Eigen::Vector3f& v : mesh.vertices_m) out.vertices_m.push_back(v.cast<double>());
  out.triangles.reserve(2 * mesh.triangles.size());
  for (const auto& [a, b, c] : mesh.triangles) {
    if (a >= out.vertices_m.size() || b >= out.vertices_m.size() || c >= out.vertices_m.size()) {
      continue;  // the loader rejects these; a hand-made model must not crash us
    }
    const Eigen::Vector3d& pa = out.vertices_m[a];
    if (a == b || b == c || c == a ||
        !((out.vertices_m[b] - pa).cross(out.vertices_m[c] - pa).squaredNorm() > 0.0)) {
      continue;
    }
    // The rasterizer culls faces turned away from the camera; an open or inconsistently wound
    // mesh has no outside, so both faces of each triangle are drawn.
    out.triangles.push_back({a, b, c});
    out.triangles.push_back({a, c, b});
  }
  return out;
}

}  // namespace vsl::render
