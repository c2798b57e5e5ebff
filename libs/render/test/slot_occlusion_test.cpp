// Light lost in narrow slots (slot_occlusion.hpp): the edges of two doors facing each other across
// a 4 mm gap darken; a large facet facing another across a small gap (a wall behind a carcass)
// does not; facets in the open keep all their light.
#include "slot_occlusion.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace vsl::render {
namespace {

struct Facets {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Eigen::Vector4d> planes;

  // A rectangle in the plane x = x0 (y in [0, width], z in [0, height]) facing +x or -x, as two
  // triangles wound so that their normal is `normal_x` * x.
  void rectangle(double x0, double width_m, double height_m, double normal_x) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    vertices.push_back({x0, 0, 0});
    vertices.push_back({x0, width_m, 0});
    vertices.push_back({x0, width_m, height_m});
    vertices.push_back({x0, 0, height_m});
    if (normal_x > 0) {
      triangles.push_back({base, base + 1, base + 2});
      triangles.push_back({base, base + 2, base + 3});
    } else {
      triangles.push_back({base, base + 2, base + 1});
      triangles.push_back({base, base + 3, base + 2});
    }
    for (int i = 0; i < 2; ++i) planes.push_back({normal_x, 0, 0, normal_x * x0});
  }
};

TEST(SlotOcclusion, DoorEdgesAcrossAFourMillimetreGapDarken) {
  Facets f;
  f.rectangle(0.0, 0.018, 0.7, +1.0);    // right edge of door A (18 mm thick), facing +x
  f.rectangle(0.004, 0.018, 0.7, -1.0);  // left edge of door B, 4 mm away, facing -x
  const std::vector<float> factors = slot_light_factors(f.vertices, f.triangles, f.planes, 0.02);
  ASSERT_EQ(factors.size(), 4u);
  // w / (w + depth) = 0.004 / (0.004 + 0.018)
  for (float factor : factors) EXPECT_NEAR(factor, 0.004 / 0.022, 1e-3);
}

TEST(SlotOcclusion, LargeFacetsAndOpenFacetsKeepTheirLight) {
  Facets f;
  f.rectangle(0.0, 2.0, 2.6, +1.0);    // a wall
  f.rectangle(0.01, 0.6, 0.8, -1.0);   // a carcass back 1 cm in front of it
  f.rectangle(3.0, 0.018, 0.7, +1.0);  // a door edge with nothing in front
  const std::vector<float> factors = slot_light_factors(f.vertices, f.triangles, f.planes, 0.02);
  for (float factor : factors) EXPECT_EQ(factor, 1.0f);
}

TEST(SlotOcclusion, TwoSidedMeshTrianglesTakeNoPart) {
  // A small facet and its reverse (how a mesh triangle is drawn), then a door edge facing it
  // across 4 mm: the mesh's own triangles are no slot walls, so nothing darkens.
  Facets f;
  f.rectangle(0.0, 0.018, 0.7, +1.0);
  f.rectangle(0.0, 0.018, 0.7, -1.0);
  f.rectangle(0.004, 0.018, 0.7, -1.0);
  const std::vector<bool> two_sided{true, true, true, true, false, false};
  const std::vector<float> factors =
      slot_light_factors(f.vertices, f.triangles, f.planes, 0.02, two_sided);
  for (float factor : factors) EXPECT_EQ(factor, 1.0f);
  // Unmarked, the same facets darken each other.
  const std::vector<float> unmarked = slot_light_factors(f.vertices, f.triangles, f.planes, 0.02);
  EXPECT_LT(unmarked[0], 0.5f);
}

TEST(SlotOcclusion, OffKeepsEverything) {
  Facets f;
  f.rectangle(0.0, 0.018, 0.7, +1.0);
  f.rectangle(0.004, 0.018, 0.7, -1.0);
  for (float factor : slot_light_factors(f.vertices, f.triangles, f.planes, 0.0)) {
    EXPECT_EQ(factor, 1.0f);
  }
}

}  // namespace
}  // namespace vsl::render
