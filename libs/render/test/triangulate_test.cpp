// Triangulated primitives are closed, outward-facing and of the right size.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "triangulate.hpp"

namespace vsl::render {
namespace {

// Volume by the divergence theorem (positive only when every triangle faces outward) and area.
struct Measures {
  double volume = 0.0;
  double area = 0.0;
};

Measures measure(const Mesh& mesh) {
  Measures m;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices_m[t[0]];
    const Eigen::Vector3d& b = mesh.vertices_m[t[1]];
    const Eigen::Vector3d& c = mesh.vertices_m[t[2]];
    m.volume += a.dot(b.cross(c)) / 6.0;
    m.area += 0.5 * (b - a).cross(c - a).norm();
  }
  return m;
}

TEST(Triangulate, Box) {
  const Mesh mesh = triangulate(world::Box{Eigen::Vector3d(0.6, 0.5, 0.7)});
  EXPECT_EQ(mesh.vertices_m.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  const Measures m = measure(mesh);
  EXPECT_NEAR(m.volume, 0.6 * 0.5 * 0.7, 1e-12);
  EXPECT_NEAR(m.area, 2 * (0.6 * 0.5 + 0.5 * 0.7 + 0.6 * 0.7), 1e-12);
}

TEST(Triangulate, CylinderIsAPrism) {
  const int n = 24;
  const Mesh mesh = triangulate(world::Cylinder{0.1, 0.5}, n);
  EXPECT_EQ(mesh.vertices_m.size(), 48u);
  EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(2 * n + 2 * (n - 2)));
  // Inscribed regular n-gon of radius r: area n/2 r^2 sin(2 pi / n).
  const double polygon_area = 0.5 * n * 0.01 * std::sin(2 * std::numbers::pi / n);
  EXPECT_NEAR(measure(mesh).volume, polygon_area * 0.5, 1e-12);
}

TEST(Triangulate, NonConvexFaceByEarClipping) {
  // An L-shaped prism (a 2 x 2 square missing its 1 x 1 corner), 0.5 high: a fan from the first
  // vertex of the L would cover the missing corner.
  world::Polyhedron l_shape;
  const std::vector<Eigen::Vector2d> outline{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (const auto& p : outline) l_shape.vertices_m.emplace_back(p.x(), p.y(), 0.0);
  for (const auto& p : outline) l_shape.vertices_m.emplace_back(p.x(), p.y(), 0.5);
  l_shape.faces.push_back({5, 4, 3, 2, 1, 0});    // bottom: clockwise from above, CCW from below
  l_shape.faces.push_back({6, 7, 8, 9, 10, 11});  // top
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    l_shape.faces.push_back({i, j, j + 6, i + 6});
  }
  const Mesh mesh = triangulate(l_shape);
  EXPECT_EQ(mesh.triangles.size(), 4u + 4u + 12u);
  const Measures m = measure(mesh);
  EXPECT_NEAR(m.volume, 3.0 * 0.5, 1e-12);
  EXPECT_NEAR(m.area, 2 * 3.0 + 8.0 * 0.5, 1e-12);
}

}  // namespace
}  // namespace vsl::render
