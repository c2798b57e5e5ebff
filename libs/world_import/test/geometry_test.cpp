// The geometry under import: upright boxes and mesh simplification.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../src/simplify.hpp"
#include "../src/upright_box.hpp"

namespace vsl::world_import {
namespace {

std::vector<Eigen::Vector3d> box_corners(const Eigen::Vector3d& size, double yaw,
                                         const Eigen::Vector3d& centre) {
  std::vector<Eigen::Vector3d> out;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (int k = 0; k < 8; ++k) {
    out.push_back(centre + R * Eigen::Vector3d((k & 1 ? 0.5 : -0.5) * size.x(),
                                               (k & 2 ? 0.5 : -0.5) * size.y(),
                                               (k & 4 ? 0.5 : -0.5) * size.z()));
  }
  return out;
}

TEST(UprightBox, FindsATurnedBoxFromItsCorners) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> yaw(-3.0, 3.0);
  for (int trial = 0; trial < 20; ++trial) {
    const double turned = yaw(random);
    const UprightBox box = upright_box(box_corners({0.6, 0.02, 0.7}, turned, {1, 2, 0.5}));
    EXPECT_NEAR(box.extents_m.x(), 0.6, 1e-9);
    EXPECT_NEAR(box.extents_m.y(), 0.02, 1e-9);
    EXPECT_NEAR(box.extents_m.z(), 0.7, 1e-9);
    EXPECT_LT((box.centre_m - Eigen::Vector3d(1, 2, 0.5)).norm(), 1e-9);
    // x along the long side, either way round.
    EXPECT_NEAR(std::abs(box.axis_x.dot(Eigen::Vector3d(std::cos(turned), std::sin(turned), 0))),
                1.0, 1e-9);
  }
}

TEST(UprightBox, NoPointsIsAnEmptyBox) {
  EXPECT_EQ(upright_box({}).extents_m, Eigen::Vector3d::Zero());
}

// A finely tessellated flat square: n x n cells, two triangles each.
TriangleSoup grid(int n) {
  TriangleSoup soup;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) soup.vertices_m.emplace_back(float(i) / n, float(j) / n, 0.f);
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const auto v = [&](int a, int b) { return static_cast<std::uint32_t>(a * (n + 1) + b); };
      soup.triangles.push_back({v(i, j), v(i + 1, j), v(i, j + 1)});
      soup.triangles.push_back({v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  }
  return soup;
}

TEST(Simplify, LeavesASmallMeshAlone) {
  const SimplifyResult result = simplify(grid(10), 1000);
  EXPECT_EQ(result.cell_m, 0.0);
  EXPECT_EQ(result.soup.triangles.size(), 200u);
}

TEST(Simplify, BringsAHugeMeshUnderBudgetKeepingItsOutline) {
  const SimplifyResult result = simplify(grid(300), 5000);  // 180,000 triangles
  EXPECT_GT(result.cell_m, 0.0);
  EXPECT_LE(result.soup.triangles.size(), 5000u);
  EXPECT_GT(result.soup.triangles.size(), 500u);
  Eigen::AlignedBox3f bounds;
  for (const Eigen::Vector3f& v : result.soup.vertices_m) bounds.extend(v);
  // Corners move by at most a cell.
  EXPECT_LT(bounds.min().head<2>().norm(), result.cell_m * 1.5);
  EXPECT_GT(bounds.max().x(), 1.0 - result.cell_m * 1.5);
}

TEST(Simplify, DropsDegenerateTrianglesAndUnusedVertices) {
  TriangleSoup soup;
  soup.vertices_m = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  soup.triangles = {{0, 1, 2}, {0, 0, 1}};
  const SimplifyResult result = simplify(soup, 100);
  EXPECT_EQ(result.soup.triangles.size(), 1u);
  EXPECT_EQ(result.soup.vertices_m.size(), 3u);
}

}  // namespace
}  // namespace vsl::world_import
