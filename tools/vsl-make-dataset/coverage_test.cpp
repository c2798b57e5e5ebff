// render::ObjectCoverage against the renderer's id buffer: a door with its handle that nothing
// hides covers exactly its id-buffer pixels (point and area sampling), an occluder hides some of
// them, the image border cuts it.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <string>

#include "vsl/render/object_coverage.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::render {
namespace {

// The shipped kitchen's sink-unit door and its handle, alone (indices 0 and 1).
world::WorldModel door_world() {
  const world::WorldModel kitchen = world::load_world("config/worlds/kitchen.yaml");
  world::WorldModel w;
  w.materials = kitchen.materials;
  for (const char* id : {"north.base3.door1", "north.base3.door1.handle"}) {
    w.objects.push_back(kitchen.objects.at(*kitchen.find(id)));
  }
  w.objects[0].parent_id.clear();
  w.index_ids();
  return w;
}

// A camera `distance_m` in front of the door (the door's -y side), looking at its centre, moved
// `right_m` along the door's x and turned `yaw_rad` about its vertical.
Eigen::Isometry3d facing(const world::ObjectModel& door, double distance_m, double right_m = 0.0,
                         double yaw_rad = 0.0) {
  const Eigen::Matrix3d r = door.world_orientation.toRotationMatrix();
  Eigen::Isometry3d world_T_camera = Eigen::Isometry3d::Identity();
  world_T_camera.linear().col(0) = r.col(0);   // x right
  world_T_camera.linear().col(1) = -r.col(2);  // y down
  world_T_camera.linear().col(2) = r.col(1);   // z forward, into the door
  world_T_camera.linear() =
      world_T_camera.linear() * Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitY()).matrix();
  world_T_camera.translation() = door.world_position_m - distance_m * r.col(1) + right_m * r.col(0);
  return world_T_camera;
}

RenderOptions clean(int samples) {
  RenderOptions options;
  options.noise_sigma_grey = 0.0;
  options.exposure_variation = 0.0;
  options.samples = samples;
  return options;
}

int pixels_of(const cv::Mat& ids, std::initializer_list<std::int32_t> objects) {
  int pixels = 0;
  for (const std::int32_t object : objects) pixels += cv::countNonZero(ids == object);
  return pixels;
}

TEST(ObjectCoverage, AnUnhiddenGroupCoversExactlyItsIdBufferPixels) {
  const world::WorldModel w = door_world();
  const head::CameraIntrinsics camera;
  for (const int samples : {1, 2}) {
    const Renderer renderer(w, clean(samples));
    const ObjectCoverage coverage(w, {{0, 1}, {1}}, clean(samples));
    for (const double distance_m : {1.3, 1.9, 3.1}) {
      const Eigen::Isometry3d pose = facing(w.objects[0], distance_m, 0.13, 0.2);
      const cv::Mat ids = renderer.render(camera, pose, 0).object_ids;
      const Coverage door = coverage.cover(0, camera, pose);
      EXPECT_EQ(door.in_image_px, pixels_of(ids, {0, 1})) << samples << " " << distance_m;
      EXPECT_EQ(door.beyond_border_px, 0);
      EXPECT_EQ(coverage.cover(1, camera, pose).in_image_px, pixels_of(ids, {1}));
      EXPECT_GT(door.in_image_px, 1000);
    }
  }
}

TEST(ObjectCoverage, AnOccluderHidesPixelsButNotCoverage) {
  world::WorldModel w = door_world();
  const Eigen::Isometry3d pose = facing(w.objects[0], 1.5);
  // A 20 cm box 0.5 m in front of the door, on the camera's axis.
  world::ObjectModel box;
  box.id = "box";
  box.type = "clutter";
  box.world_position_m = pose * Eigen::Vector3d(0, 0, 1.0);
  box.primitives.emplace_back().shape = world::Box{Eigen::Vector3d::Constant(0.2)};
  w.objects.push_back(box);
  w.index_ids();
  const head::CameraIntrinsics camera;
  const cv::Mat ids = Renderer(w, clean(2)).render(camera, pose, 0).object_ids;
  const Coverage door = ObjectCoverage(w, {{0, 1}}, clean(2)).cover(0, camera, pose);
  const int visible = pixels_of(ids, {0, 1});
  const int hidden = cv::countNonZero(ids == 2);
  EXPECT_GT(hidden, 1000);
  EXPECT_EQ(door.in_image_px, visible + hidden);  // the box lies wholly in front of the door
}

TEST(ObjectCoverage, TheImageBorderCutsAGroup) {
  const world::WorldModel w = door_world();
  const head::CameraIntrinsics camera;
  // Seen from 0.6 m the door fills more than the image.
  const Eigen::Isometry3d pose = facing(w.objects[0], 0.6, 0.2);
  const cv::Mat ids = Renderer(w, clean(1)).render(camera, pose, 0).object_ids;
  const Coverage door = ObjectCoverage(w, {{0, 1}}, clean(1)).cover(0, camera, pose, 4);
  EXPECT_EQ(door.in_image_px, pixels_of(ids, {0, 1}));
  EXPECT_GT(door.beyond_border_px, 0);
  // Behind the camera: nothing.
  const Eigen::Isometry3d away = pose * Eigen::AngleAxisd(3.14159, Eigen::Vector3d::UnitY());
  EXPECT_EQ(ObjectCoverage(w, {{0, 1}}).cover(0, camera, away).in_image_px, 0);
  EXPECT_THROW(ObjectCoverage(w, {{0, 1}}).cover(1, camera, pose), std::out_of_range);
}

}  // namespace
}  // namespace vsl::render
