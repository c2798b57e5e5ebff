// Imported triangle meshes render like the solids they describe, and from both sides.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <cmath>
#include <cstdlib>

#include "test_scenes.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

// The box of `size_m` as a triangle soup, deliberately with half of its triangles wound inward:
// an imported mesh need not be consistently oriented.
world::TriangleMesh box_mesh(const Eigen::Vector3d& size_m) {
  world::TriangleMesh mesh;
  const Eigen::Vector3f half = (0.5 * size_m).cast<float>();
  for (int i = 0; i < 8; ++i) {  // bit 0: +x, bit 1: +y, bit 2: +z
    mesh.vertices_m.emplace_back(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(),
                                 i & 4 ? half.z() : -half.z());
  }
  const std::uint32_t quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[3], q[2]});  // the other winding of the same quad
  }
  return mesh;
}

world::ObjectModel as_mesh(world::ObjectModel object) {
  const auto box = std::get<world::Box>(object.primitives[0].shape);
  object.primitives[0].shape = box_mesh(box.size_m);
  return object;
}

// True when pixel (u, v) of `ids` has a neighbour (3 x 3) showing another id: an edge pixel.
bool at_edge(const cv::Mat& ids, int u, int v) {
  const std::int32_t id = ids.at<std::int32_t>(v, u);
  for (int dv = -1; dv <= 1; ++dv) {
    for (int du = -1; du <= 1; ++du) {
      const int x = u + du, y = v + dv;
      if (x < 0 || y < 0 || x >= ids.cols || y >= ids.rows) continue;
      if (ids.at<std::int32_t>(y, x) != id) return true;
    }
  }
  return false;
}

TEST(MeshRender, ClosedMeshCubeRendersAsTheBox) {
  // A cupboard-sized box on a floor, seen from above a corner so that three faces show; a second
  // box behind it to check ids.
  const std::vector<world::ObjectModel> boxes{
      box_object("floor", "floor", {0, 0, -0.05}, {6, 6, 0.1}, {150, 150, 150}),
      box_object("cube", "cupboard", {0.2, 1.5, 0.4}, {0.6, 0.5, 0.8}, {40, 90, 160}, 0.4),
      box_object("back", "wall", {0, 3, 1.0}, {4, 0.2, 2.0}, {200, 180, 150})};
  std::vector<world::ObjectModel> meshes = boxes;
  meshes[1] = as_mesh(meshes[1]);
  meshes[2] = as_mesh(meshes[2]);
  const RenderOptions options = test::clean_options();
  const Renderer box_renderer(test::world_of(boxes), options);
  const Renderer mesh_renderer(test::world_of(meshes), options);
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera =
      camera_pose({-0.8, 0.2, 1.5}, Eigen::Vector3d(1.0, 1.3, -1.0));
  const RenderedImage box = box_renderer.render(intrinsics, world_T_camera, 0);
  const RenderedImage mesh = mesh_renderer.render(intrinsics, world_T_camera, 0);

  int cube_pixels = 0, differing_ids = 0, differing_inside = 0;
  double worst_depth_m = 0.0;
  int worst_grey = 0;
  for (int v = 0; v < box.object_ids.rows; ++v) {
    for (int u = 0; u < box.object_ids.cols; ++u) {
      const std::int32_t id = box.object_ids.at<std::int32_t>(v, u);
      cube_pixels += id == 1;
      const bool edge = at_edge(box.object_ids, u, v);
      if (id != mesh.object_ids.at<std::int32_t>(v, u)) {
        ++differing_ids;
        differing_inside += !edge;
        continue;
      }
      if (edge) continue;
      worst_depth_m = std::max<double>(
          worst_depth_m, std::abs(box.depth_m.at<float>(v, u) - mesh.depth_m.at<float>(v, u)));
      const cv::Vec3b a = box.image.at<cv::Vec3b>(v, u), b = mesh.image.at<cv::Vec3b>(v, u);
      for (int k = 0; k < 3; ++k) worst_grey = std::max(worst_grey, std::abs(a[k] - b[k]));
    }
  }
  EXPECT_GT(cube_pixels, 5000);    // the cube is well in view
  EXPECT_EQ(differing_inside, 0);  // ids differ, if at all, only within a pixel of an edge
  EXPECT_LT(differing_ids, 100);   // and only on a few of them
  EXPECT_LT(worst_depth_m, 1e-4);  // same surfaces: float precision
  EXPECT_LE(worst_grey, 1);        // the face seen is shaded with its outward normal
}

TEST(MeshRender, SmallMeshIsNotDarkenedAsASlot) {
  // Facets under 0.1 m facing another across no gap are slot walls (slot_occlusion.hpp); a mesh
  // triangle and its reverse must not count as such, or every small part would render black.
  const std::vector<world::ObjectModel> boxes{
      box_object("knob", "handle", {0, 0.5, 1.0}, {0.05, 0.04, 0.06}, {180, 150, 60}, 0.5)};
  const std::vector<world::ObjectModel> meshes{as_mesh(boxes[0])};
  const RenderOptions options = test::clean_options();
  ASSERT_GT(options.slot_occlusion_max_width_m, 0.0);
  const Renderer box_renderer(test::world_of(boxes), options);
  const Renderer mesh_renderer(test::world_of(meshes), options);
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera =
      camera_pose({-0.1, 0.2, 1.15}, Eigen::Vector3d(0.1, 0.3, -0.15));
  const RenderedImage box = box_renderer.render(intrinsics, world_T_camera, 0);
  const RenderedImage mesh = mesh_renderer.render(intrinsics, world_T_camera, 0);
  const cv::Mat knob_mask = box.object_ids == 0;
  ASSERT_GT(cv::countNonZero(knob_mask), 1000);
  const cv::Scalar box_mean = cv::mean(box.image, knob_mask);
  const cv::Scalar mesh_mean = cv::mean(mesh.image, knob_mask);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(mesh_mean[k], box_mean[k], 1.0) << "channel " << k;
}

TEST(MeshRender, BigFlatMeshBuildsAndRendersQuickly) {
  // 45k coplanar 1 cm triangles (a scanned floor): the scene is built in linear time, however
  // many triangles share a plane, and seen from 1 m above the floor covers the view.
  constexpr std::uint32_t kSide = 151;
  world::TriangleMesh floor;
  for (std::uint32_t y = 0; y < kSide; ++y) {
    for (std::uint32_t x = 0; x < kSide; ++x)
      floor.vertices_m.emplace_back(0.01f * x, 0.01f * y, 0);
  }
  for (std::uint32_t y = 0; y + 1 < kSide; ++y) {
    for (std::uint32_t x = 0; x + 1 < kSide; ++x) {
      const std::uint32_t a = y * kSide + x;
      floor.triangles.push_back({a, a + 1, a + kSide + 1});
      floor.triangles.push_back({a, a + kSide + 1, a + kSide});
    }
  }
  world::ObjectModel object;
  object.id = "floor";
  object.type = "floor";
  object.primitives.emplace_back().shape = floor;
  const Renderer renderer(test::world_of({object}), test::clean_options());
  const head::CameraIntrinsics intrinsics;
  const RenderedImage rendered = renderer.render(
      intrinsics,
      camera_pose({0.75, 0.75, 1.0}, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY()), 0);
  EXPECT_EQ(cv::countNonZero(rendered.object_ids == 0), 640 * 480);
  EXPECT_NEAR(rendered.depth_m.at<float>(240, 320), 1.0, 1e-4);
}

TEST(MeshRender, OpenMeshIsSeenFromBothSides) {
  // One square of two triangles in the plane y = 0 (normals along +y), viewed from -y and +y.
  world::TriangleMesh square;
  square.vertices_m = {{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {0.5f, 0, 0.5f}, {-0.5f, 0, 0.5f}};
  square.triangles = {{0, 2, 1}, {0, 3, 2}, {1, 1, 2}};  // the last one degenerate: ignored
  world::ObjectModel sheet;
  sheet.id = "sheet";
  sheet.type = "clutter";
  sheet.world_position_m = {0, 0, 1};
  sheet.primitives.emplace_back().shape = square;
  const Renderer renderer(test::world_of({sheet}), test::clean_options());
  const head::CameraIntrinsics intrinsics;
  for (const double side : {-1.0, 1.0}) {
    const Eigen::Isometry3d world_T_camera =
        camera_pose({0, 2.0 * side, 1}, Eigen::Vector3d(0, -side, 0));
    const RenderedImage rendered = renderer.render(intrinsics, world_T_camera, 0);
    const int centre_id = rendered.object_ids.at<std::int32_t>(240, 320);
    EXPECT_EQ(centre_id, 0) << "seen from y = " << 2.0 * side;
    EXPECT_NEAR(rendered.depth_m.at<float>(240, 320), 2.0, 1e-4);
  }
}

TEST(MeshRender, RealisticMaterialsShadeAMeshLikeTheBox) {
  // The realistic path (textures, light map, shadows) takes the mesh too; a matte mesh cube
  // looks like the matte box up to the light map's texels along its different diagonals.
  const std::vector<world::ObjectModel> boxes{
      box_object("floor", "floor", {0, 0, -0.05}, {4, 4, 0.1}, {150, 150, 150}),
      box_object("cube", "cupboard", {0, 1.2, 0.4}, {0.6, 0.5, 0.8}, {40, 90, 160})};
  std::vector<world::ObjectModel> meshes = boxes;
  meshes[1] = as_mesh(meshes[1]);
  RenderOptions options = test::clean_options();
  options.realism.level = RealismLevel::materials;
  options.realism.shadow_map_px = 128;
  options.realism.light_map_texel_m = 0.1;
  const Renderer box_renderer(test::world_of(boxes), options);
  const Renderer mesh_renderer(test::world_of(meshes), options);
  head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d world_T_camera =
      camera_pose({-0.6, -0.2, 1.4}, Eigen::Vector3d(0.6, 1.4, -1.0));
  const RenderedImage box = box_renderer.render(intrinsics, world_T_camera, 0);
  const RenderedImage mesh = mesh_renderer.render(intrinsics, world_T_camera, 0);
  const cv::Mat cube_mask = box.object_ids == 1;
  ASSERT_GT(cv::countNonZero(cube_mask), 2000);
  const cv::Scalar box_mean = cv::mean(box.image, cube_mask);
  const cv::Scalar mesh_mean = cv::mean(mesh.image, cube_mask);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(mesh_mean[k], box_mean[k], 4.0) << "channel " << k;
  EXPECT_GT(mesh_mean[0], 10.0);  // lit, not black from a slot or a shadow of its own
}

}  // namespace
}  // namespace vsl::render
