#include <gtest/gtest.h>

#include "vsl/worldgen/geometry.hpp"

namespace vsl::worldgen {
namespace {

TEST(WorldgenGeometry, PrismIsClosedAndOutwardForEitherWinding) {
  const std::vector<Eigen::Vector2d> profile = {
      {0, 0}, {0.1, 0}, {0.1, 0.02}, {0.01, 0.03}, {0, 0.02}};
  EXPECT_EQ(check_polyhedron(prism_x(profile, 1.0)), "");
  std::vector<Eigen::Vector2d> reversed(profile.rbegin(), profile.rend());
  EXPECT_EQ(check_polyhedron(prism_x(reversed, 1.0)), "");
}

TEST(WorldgenGeometry, FrustumAndVerticalPrismAreClosedAndOutward) {
  EXPECT_EQ(check_polyhedron(frustum(rectangle(0.6, 0.5), rectangle(0.3, 0.26, {0, 0.12}), 0.2)),
            "");
  EXPECT_EQ(check_polyhedron(frustum(regular_polygon(8, 0.2), regular_polygon(8, 0.07), 0.2)), "");
  const std::vector<Eigen::Vector2d> clockwise = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  EXPECT_EQ(check_polyhedron(frustum(clockwise, clockwise, 0.1)), "");
}

TEST(WorldgenGeometry, BasinIsClosedAndOutward) {
  EXPECT_EQ(check_polyhedron(basin({0.44, 0.42}, 0.18, 0.015, 0.008, 0.012)), "");
}

TEST(WorldgenGeometry, CheckRejectsInwardFaces) {
  world::Polyhedron p = frustum(rectangle(1, 1), rectangle(1, 1), 1);
  for (auto& face : p.faces) std::reverse(face.begin(), face.end());
  EXPECT_NE(check_polyhedron(p), "");
  p.faces.pop_back();
  EXPECT_NE(check_polyhedron(p), "");
}

TEST(WorldgenGeometry, CylinderAxes) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_TRUE((cylinder("m", Eigen::Vector3d::Zero(), 0.1, 1, Axis::x).object_orientation * z)
                  .isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE((cylinder("m", Eigen::Vector3d::Zero(), 0.1, 1, Axis::y).object_orientation * z)
                  .isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(
      (cylinder("m", Eigen::Vector3d::Zero(), 0.1, 1, Axis::z).object_orientation * z).isApprox(z));
}

TEST(WorldgenGeometry, BoxBetween) {
  const world::Primitive p = box_between("m", {1, 2, 3}, {0, 0, 0});
  EXPECT_TRUE(p.object_position_m.isApprox(Eigen::Vector3d(0.5, 1, 1.5)));
  EXPECT_TRUE(std::get<world::Box>(p.shape).size_m.isApprox(Eigen::Vector3d(1, 2, 3)));
}

}  // namespace
}  // namespace vsl::worldgen
