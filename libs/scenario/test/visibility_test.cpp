// What the scanning head sees: field of view, range, facing, occlusion (and what does not occlude).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_worlds.hpp"
#include "vsl/scenario/free_space.hpp"
#include "vsl/scenario/head_scan.hpp"
#include "vsl/scenario/visibility.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::scenario {
namespace {

using testing::add_box;
using testing::add_object;

constexpr double kDeg = std::numbers::pi / 180;
const Eigen::Vector3d kEgoCamera(0, 0, 1.5);  // the robot stands at the world origin, facing +x

// Front (-y) towards -x, i.e. towards a robot at the origin looking along +x.
constexpr double kFacingRobot = -std::numbers::pi / 2;

Visibility check(const world::WorldModel& world, const std::string& id) {
  const CollisionScene scene(world);
  const HeadModel head(scene, HeadScanOptions{}, VisibilityOptions{}, kEgoCamera);
  return head.check(*world.find(id), Eigen::Isometry3d::Identity());
}

TEST(HeadScan, CameraAxesFollowPanAndTilt) {
  const Eigen::Matrix3d straight = ego_R_camera(0, 0);
  EXPECT_TRUE((straight * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX()));   // fwd
  EXPECT_TRUE((straight * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitY()));  // right
  EXPECT_TRUE((straight * Eigen::Vector3d::UnitY()).isApprox(-Eigen::Vector3d::UnitZ()));  // down
  const Eigen::Matrix3d turned = ego_R_camera(90 * kDeg, 30 * kDeg);
  EXPECT_TRUE((turned * Eigen::Vector3d::UnitZ())
                  .isApprox(Eigen::Vector3d(0, std::cos(30 * kDeg), std::sin(30 * kDeg))));
  EXPECT_NEAR(turned.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((turned.transpose() * turned).isIdentity(1e-12));
  // 60 deg horizontal: 29 deg off-axis is in, 31 deg is out.
  EXPECT_TRUE(in_field_of_view({std::tan(29 * kDeg), 0, 1}, 60 * kDeg, 45 * kDeg));
  EXPECT_FALSE(in_field_of_view({std::tan(31 * kDeg), 0, 1}, 60 * kDeg, 45 * kDeg));
  EXPECT_FALSE(in_field_of_view({0, 0, -1}, 60 * kDeg, 45 * kDeg));
}

TEST(HeadScan, CountsTheViewsThatContainAPoint) {
  HeadScanOptions scan;
  scan.pan_rad = {-20 * kDeg, 0.0, 20 * kDeg};
  scan.tilt_rad = {0.0};
  // Straight ahead: within +-30 deg of all three pans.
  EXPECT_EQ(views_containing(scan, kEgoCamera, {3, 0, 1.5}), 3);
  // 40 deg to the left: only the pan at +20 (off by 20 < 30).
  EXPECT_EQ(
      views_containing(scan, kEgoCamera, {3 * std::cos(40 * kDeg), 3 * std::sin(40 * kDeg), 1.5}),
      1);
  EXPECT_EQ(views_containing(scan, kEgoCamera, {-3, 0, 1.5}), 0);
  EXPECT_DOUBLE_EQ(scan_centre_pan_rad(scan), 0.0);
}

TEST(Visibility, AheadInRangeIsSeenBehindOrOutOfRangeIsNot) {
  world::WorldModel world;
  add_object(world, "ahead", "door", {3, 0, 1.5});
  add_object(world, "behind", "door", {-3, 0, 1.5});
  add_object(world, "far", "door", {6, 0, 1.5});
  add_object(world, "too_close", "door", {0.3, 0, 1.5});
  add_object(world, "left", "door", {2 * std::cos(80 * kDeg), 2 * std::sin(80 * kDeg), 1.5});
  add_object(world, "far_left", "door", {2 * std::cos(95 * kDeg), 2 * std::sin(95 * kDeg), 1.5});
  add_object(world, "at_feet", "door", {0.6, 0, 0.2});     // 65 deg down: lowest tilt reaches 68
  add_object(world, "under_feet", "door", {0.4, 0, 0.2});  // 73 deg down
  EXPECT_EQ(check(world, "ahead"), Visibility::visible);
  EXPECT_EQ(check(world, "behind"), Visibility::out_of_view);
  EXPECT_EQ(check(world, "far"), Visibility::out_of_range);
  EXPECT_EQ(check(world, "too_close"), Visibility::out_of_range);
  EXPECT_EQ(check(world, "left"), Visibility::visible);
  EXPECT_EQ(check(world, "far_left"), Visibility::out_of_view);
  EXPECT_EQ(check(world, "at_feet"), Visibility::visible);
  EXPECT_EQ(check(world, "under_feet"), Visibility::out_of_view);
}

TEST(Visibility, FollowsTheRobotsPose) {
  world::WorldModel world;
  add_object(world, "d", "door", {10, 5, 1.5});
  const CollisionScene scene(world);
  const HeadModel head(scene, HeadScanOptions{}, VisibilityOptions{}, kEgoCamera);
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.translation() = Eigen::Vector3d(10, 2, 0);
  world_T_ego.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).matrix();
  EXPECT_EQ(head.check(0, world_T_ego), Visibility::visible);  // 3 m ahead of a robot facing +y
  world_T_ego.linear() =
      Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).matrix();
  EXPECT_EQ(head.check(0, world_T_ego), Visibility::out_of_view);
  const auto seen = HeadModel(scene, HeadScanOptions{}, VisibilityOptions{}, kEgoCamera)
                        .visible_objects(Eigen::Isometry3d(Eigen::Translation3d(7, 5, 0)));
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_TRUE(seen[0].ego_position_m.isApprox(Eigen::Vector3d(3, 0, 1.5)));
  EXPECT_GE(seen[0].views, 1);
}

TEST(Visibility, AnObjectBehindAWallIsOccluded) {
  world::WorldModel world;
  auto& wall = add_object(world, "wall", "wall", {1.5, 1.5, 1.5});
  add_box(wall, {0.1, 1.0, 3.0});  // x in [1.45, 1.55], y in [1, 2]
  add_object(world, "handle", "handle", {3, 3, 1.5});
  add_object(world, "beside", "handle", {3, 1.5, 1.5});
  EXPECT_EQ(check(world, "handle"), Visibility::occluded);
  EXPECT_EQ(check(world, "beside"), Visibility::visible);
}

// A cupboard with a closed door facing the robot: a handle on its front, one on its far side (on
// the inside of the door), and an object behind the cupboard.
world::WorldModel cupboard_world() {
  world::WorldModel world;
  auto& cupboard = add_object(world, "cab", "cupboard", {3.3, -1, 1.0}, kFacingRobot);
  add_box(cupboard, {0.5, 0.56, 0.7});  // x in [3.02, 3.58] once turned
  auto& door = add_object(world, "cab.door", "door", {3.0, -1, 1.0}, kFacingRobot, "cab");
  add_box(door, {0.5, 0.02, 0.7}, {0, 0.01, 0});  // x in [3.0, 3.02]: its front is the point
  // On the line of sight from the camera to the door's centre, 3 cm in front of the door.
  const Eigen::Vector3d camera = kEgoCamera;
  const Eigen::Vector3d on_line = camera + 0.99 * (Eigen::Vector3d(3.0, -1, 1.0) - camera);
  auto& front = add_object(world, "cab.door.handle", "handle", on_line, kFacingRobot, "cab.door");
  add_box(front, {0.16, 0.02, 0.02});
  auto& inner =
      add_object(world, "cab.door.inner", "handle", {3.05, -1, 1.0}, kFacingRobot, "cab.door");
  add_box(inner, {0.16, 0.02, 0.02});
  add_object(world, "behind_cab", "window", {3.9, -1.3, 0.9});
  return world;
}

TEST(Visibility, AHandleOnTheFarSideOfItsClosedDoorIsOccludedByIt) {
  EXPECT_EQ(check(cupboard_world(), "cab.door.inner"), Visibility::occluded);
  // With nothing else around (a room door, no cupboard), only the parent can hide it: parents
  // must count as occluders.
  world::WorldModel world;
  auto& door = add_object(world, "room_door", "door", {3.0, 0, 1.0}, kFacingRobot);
  add_box(door, {0.9, 0.04, 2.0}, {0, 0.02, 0});  // x in [3.0, 3.04]
  // Turned towards the robot (a real one faces away) so that only occlusion can hide it.
  auto& handle = add_object(world, "room_door.far_handle", "handle", {3.07, 0, 1.0}, kFacingRobot,
                            "room_door");
  add_box(handle, {0.13, 0.02, 0.02});
  EXPECT_EQ(check(world, "room_door.far_handle"), Visibility::occluded);
  EXPECT_EQ(check(world, "room_door"), Visibility::visible);
}

TEST(Visibility, AnObjectBehindACupboardIsOccluded) {
  EXPECT_EQ(check(cupboard_world(), "behind_cab"), Visibility::occluded);
}

TEST(Visibility, ADoorIsSeenThroughItsOwnHandleAndInFrontOfItsCupboard) {
  const world::WorldModel world = cupboard_world();
  // The handle in front lies on the line of sight to the door's centre: the door's own parts do
  // not hide it, and its cupboard is behind the point.
  EXPECT_EQ(check(world, "cab.door"), Visibility::visible);
  EXPECT_EQ(check(world, "cab.door.handle"), Visibility::visible);
}

TEST(Visibility, ObjectsSeenFromBehindOrEdgeOnAreNot) {
  world::WorldModel world;
  auto& away = add_object(world, "away", "door", {3, 1.5, 1.5}, std::numbers::pi / 2);
  add_box(away, {0.5, 0.02, 0.7}, {0, 0.01, 0});
  auto& edge_on = add_object(world, "edge_on", "door", {3, 0.2, 1.5}, 0.0);  // front faces -y
  add_box(edge_on, {0.5, 0.02, 0.7}, {0, 0.01, 0});
  auto& oblique = add_object(world, "oblique", "door", {3, -1.5, 1.5}, kFacingRobot + 0.5);
  add_box(oblique, {0.5, 0.02, 0.7}, {0, 0.01, 0});
  EXPECT_EQ(check(world, "away"), Visibility::facing_away);
  EXPECT_EQ(check(world, "edge_on"), Visibility::facing_away);  // seen 86 deg off its normal
  EXPECT_EQ(check(world, "oblique"), Visibility::visible);      // seen 55 deg off its normal
}

TEST(Visibility, OnlyRecognizableTypesAreReported) {
  world::WorldModel world;
  add_object(world, "d", "door", {3, 0, 1.5});
  add_object(world, "c", "chair", {3, 0.5, 1.5});
  const CollisionScene scene(world);
  const HeadModel by_graph(scene, HeadScanOptions{}, VisibilityOptions{}, kEgoCamera,
                           {"door", "handle"});
  EXPECT_EQ(by_graph.visible_objects(Eigen::Isometry3d::Identity()).size(), 1u);
  EXPECT_EQ(by_graph.types(), std::vector<std::string>{"door"});
  VisibilityOptions chairs;
  chairs.types = {"chair"};
  const HeadModel by_option(scene, HeadScanOptions{}, chairs, kEgoCamera, {"door"});
  const auto seen = by_option.visible_objects(Eigen::Isometry3d::Identity());
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].object_index, 1u);
}

TEST(Visibility, KitchenFromTheMiddleSeesTheNorthRun) {
  const world::WorldModel kitchen = world::load_world("config/worlds/kitchen.yaml");
  const CollisionScene scene(kitchen);
  const HeadModel head(scene, HeadScanOptions{}, VisibilityOptions{}, {0, 0, 0.6},
                       {"door", "handle", "drawer_front", "window"});
  // West of the table (its lamp hangs at eye height over its middle), facing north.
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.translation() = Eigen::Vector3d(1.0, 1.0, 1.0);
  world_T_ego.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).matrix();
  const FreeSpace space(scene, PoseSamplingOptions{}, 1.6);
  ASSERT_TRUE(space.is_free(space.floors()[0], {1.0, 1.0}));
  const auto seen = head.visible_objects(world_T_ego);
  EXPECT_GE(seen.size(), 15u);
  for (const SeenObject& s : seen) {
    const world::ObjectModel& object = kitchen.objects[s.object_index];
    // Nothing behind the robot: the scan covers +-90 deg of azimuth (a little more in the corners
    // of the tilted views, so allow a few degrees).
    EXPECT_GT(object.world_position_m.y(), 0.8) << object.id << " is behind the robot";
    EXPECT_LE((s.ego_position_m - Eigen::Vector3d(0, 0, 0.6)).norm(), 4.5) << object.id;
  }
}

}  // namespace
}  // namespace vsl::scenario
