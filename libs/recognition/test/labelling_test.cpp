// Labels from id buffers: majority object, purity, coverage, sample roles, ground-truth
// visibility and the matching of percepts to ground truth; and the labels of a rendered kitchen.
#include "vsl/recognition/labelling.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "vsl/head/head_kinematics.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::recognition {
namespace {

// A blob of the pixels of `rect` in a grey image of the id buffer's size.
Blob blob_of(const cv::Rect& rect, const cv::Size& size) {
  cv::Mat mask(size, CV_8U, cv::Scalar(0));
  mask(rect).setTo(1);
  return make_blob(runs_from_mask(mask), cv::Mat(size, CV_8UC3, cv::Scalar(128, 128, 128)));
}

// Ids: object 0 (a door) at u 10..49, v 10..59 (2000 px); object 1 (its handle) inside it at
// u 40..43, v 20..39 (80 px); object 2 (a wall) elsewhere on the left half; -1 on the right.
cv::Mat door_scene() {
  cv::Mat ids(80, 120, CV_32S, cv::Scalar(-1));
  ids(cv::Rect(0, 0, 60, 80)).setTo(2);
  ids(cv::Rect(10, 10, 40, 50)).setTo(0);
  ids(cv::Rect(40, 20, 4, 20)).setTo(1);
  return ids;
}

const std::vector<std::string> kTypes{"door", "handle", "wall"};

TEST(Labelling, PixelCountsPerObject) {
  const std::vector<int> counts = object_pixel_counts(door_scene(), 3);
  EXPECT_EQ(counts, (std::vector<int>{2000 - 80, 80, 60 * 80 - 2000}));
  EXPECT_THROW(object_pixel_counts(door_scene(), 2), std::invalid_argument);  // id 2 too big
  EXPECT_THROW(object_pixel_counts(cv::Mat(4, 4, CV_8U), 3), std::invalid_argument);
}

TEST(Labelling, WholeDoorIsPurePositiveWholeHandleToo) {
  const cv::Mat ids = door_scene();
  const std::vector<int> visible = object_pixel_counts(ids, 3);
  // The door panel without the handle pixels: a blob of the door's own colour.
  cv::Mat door_mask(ids.size(), CV_8U, cv::Scalar(0));
  door_mask.setTo(1, ids == 0);
  const Blob door =
      make_blob(runs_from_mask(door_mask), cv::Mat(ids.size(), CV_8UC3, cv::Scalar(0, 0, 0)));
  const BlobLabel label = label_blob(door, ids, visible);
  EXPECT_EQ(label.object_index, 0);
  EXPECT_DOUBLE_EQ(label.purity, 1.0);
  EXPECT_DOUBLE_EQ(label.coverage, 1.0);
  EXPECT_EQ(sample_role(door, ids, visible, kTypes, "door"), SampleRole::positive);
  // A door is a negative handle sample; the handle a negative door sample.
  EXPECT_EQ(sample_role(door, ids, visible, kTypes, "handle"), SampleRole::negative);
  const Blob handle = blob_of(cv::Rect(40, 20, 4, 20), ids.size());
  EXPECT_EQ(sample_role(handle, ids, visible, kTypes, "handle"), SampleRole::positive);
  EXPECT_EQ(sample_role(handle, ids, visible, kTypes, "door"), SampleRole::negative);
}

TEST(Labelling, FragmentsAndMixturesAreNotUsed) {
  const cv::Mat ids = door_scene();
  const std::vector<int> visible = object_pixel_counts(ids, 3);
  // A third of the door: pure but low coverage -> neither a door nor a non-door.
  const Blob fragment = blob_of(cv::Rect(10, 10, 20, 30), ids.size());
  const BlobLabel label = label_blob(fragment, ids, visible);
  EXPECT_EQ(label.object_index, 0);
  EXPECT_DOUBLE_EQ(label.purity, 1.0);
  EXPECT_NEAR(label.coverage, 600.0 / 1920.0, 1e-12);
  EXPECT_EQ(sample_role(fragment, ids, visible, kTypes, "door"), SampleRole::unused);
  // Door plus a band of wall (and the handle): coverage 1 but purity 1920 / 2500 < 0.9.
  const Blob mixed = blob_of(cv::Rect(0, 10, 50, 50), ids.size());
  const BlobLabel mixed_label = label_blob(mixed, ids, visible);
  EXPECT_EQ(mixed_label.object_index, 0);
  EXPECT_NEAR(mixed_label.purity, 1920.0 / 2500.0, 1e-12);
  EXPECT_EQ(sample_role(mixed, ids, visible, kTypes, "door"), SampleRole::unused);
  // Wall with a sliver of door (5%): a negative door sample.
  const Blob wall = blob_of(cv::Rect(0, 0, 12, 80), ids.size());
  EXPECT_NEAR(fraction_on_type(wall, ids, kTypes, "door"), 100.0 / 960.0, 1e-12);
  EXPECT_EQ(sample_role(wall, ids, visible, kTypes, "door"), SampleRole::unused);  // 10.4%
  const Blob wall2 = blob_of(cv::Rect(0, 0, 11, 80), ids.size());                  // 50 / 880
  EXPECT_EQ(sample_role(wall2, ids, visible, kTypes, "door"), SampleRole::negative);
  // Background is no object at all.
  const Blob sky = blob_of(cv::Rect(70, 0, 30, 30), ids.size());
  EXPECT_EQ(label_blob(sky, ids, visible).object_index, -1);
  EXPECT_EQ(sample_role(sky, ids, visible, kTypes, "door"), SampleRole::negative);
}

TEST(Labelling, BlobOutsideTheBufferThrows) {
  const Blob big = blob_of(cv::Rect(0, 0, 120, 80), {120, 80});
  EXPECT_THROW(label_blob(big, cv::Mat(40, 40, CV_32S, cv::Scalar(-1)), std::vector<int>{}),
               std::invalid_argument);
}

GroundTruthObject object(const std::string& type, Eigen::Vector3d p, double distance_m, int left,
                         int left_free, int right, int right_free) {
  GroundTruthObject o;
  o.type = type;
  o.ego_position_m = p;
  o.distance_m = distance_m;
  o.left_visible_px = left;
  o.left_unoccluded_px = left_free;
  o.right_visible_px = right;
  o.right_unoccluded_px = right_free;
  return o;
}

TEST(Labelling, GroundTruthNeedsHalfVisibleInBothImagesWithinFourMetres) {
  std::vector<GroundTruthObject> objects{
      object("door", {1, 0, 1}, 2.0, 600, 1000, 500, 1000),  // visible
      object("door", {2, 0, 1}, 2.0, 600, 1000, 400, 1000),  // right image: 40%
      object("door", {3, 0, 1}, 4.5, 900, 1000, 900, 1000),  // too far
      object("handle", {4, 0, 1}, 3.0, 0, 0, 0, 0),          // nowhere in view
      object("handle", {5, 0, 1}, 3.0, 52, 50, 50, 50),      // rounding: capped at 1
  };
  mark_ground_truth_visible(objects);
  EXPECT_TRUE(objects[0].visible);
  EXPECT_FALSE(objects[1].visible);
  EXPECT_FALSE(objects[2].visible);
  EXPECT_FALSE(objects[3].visible);
  EXPECT_TRUE(objects[4].visible);
  EXPECT_DOUBLE_EQ(visible_fraction(52, 50), 1.0);
  EXPECT_DOUBLE_EQ(visible_fraction(5, 0), 0.0);
}

TEST(Labelling, WholeInBothImagesWhenNoUnoccludedPixelLiesBeyondABorder) {
  GroundTruthObject o = object("door", {1, 0, 1}, 2.0, 300, 1000, 300, 1000);
  o.left_in_image_px = 1000;
  o.right_in_image_px = 1000;
  EXPECT_TRUE(whole_in_both_images(o));  // occluded, but not cut by the border
  o.right_in_image_px = 990;
  EXPECT_FALSE(whole_in_both_images(o));
  EXPECT_FALSE(whole_in_both_images(object("door", {1, 0, 1}, 2.0, 0, 0, 0, 0)));
}

TEST(Labelling, PerceptsMatchTheNearestFreeObjectOfTheirTypeMostConfidentFirst) {
  std::vector<GroundTruthObject> truth{
      object("door", {1.0, 0, 1}, 1.0, 1, 1, 1, 1), object("door", {1.15, 0, 1}, 1.0, 1, 1, 1, 1),
      object("handle", {1.0, 0.05, 1}, 1.0, 1, 1, 1, 1),
      object("door", {3.0, 0, 1}, 1.0, 0, 1, 0, 1),  // not visible: never matched
  };
  mark_ground_truth_visible(truth);
  const std::vector<PerceptToMatch> percepts{
      {"door", {1.06, 0, 1}, 0.5f},   // nearer door 0 (6 cm) but less confident
      {"door", {1.04, 0, 1}, 0.9f},   // takes door 0 (4 cm)
      {"door", {1.04, 0, 1}, 0.1f},   // both doors within 10 cm taken: false positive
      {"handle", {1.0, 0, 1}, 0.5f},  // 5 cm from the handle
      {"door", {3.0, 0, 1}, 0.9f},    // on the invisible door: false positive
      {"window", {1.0, 0, 1}, 0.9f},  // no window in the ground truth
  };
  const std::vector<PerceptMatch> matches = match_percepts(percepts, truth);
  ASSERT_EQ(matches.size(), percepts.size());
  EXPECT_EQ(matches[1].ground_truth, 0);
  EXPECT_NEAR(matches[1].error_m, 0.04, 1e-12);
  EXPECT_EQ(matches[0].ground_truth, 1);  // door 1 is 9 cm away
  EXPECT_NEAR(matches[0].error_m, 0.09, 1e-12);
  EXPECT_EQ(matches[2].ground_truth, -1);
  EXPECT_EQ(matches[3].ground_truth, 2);
  EXPECT_EQ(matches[4].ground_truth, -1);
  EXPECT_EQ(matches[5].ground_truth, -1);
}

// The simulator's labels on the typical view of config/sim_head.yaml: the id mask of every door
// seen whole is a positive door sample of itself, and a negative handle sample.
TEST(Labelling, RenderedKitchenDoorsLabelThemselves) {
  const world::WorldModel world = world::load_world("config/worlds/kitchen.yaml");
  const head::HeadKinematics head = head::HeadKinematics::load("config/heads/armar3.yaml");
  head::JointState joints = head.rest_state();
  joints.positions_rad[*head.joint_index("neck_pitch")] = 0.15;
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  world_T_ego.translation() = Eigen::Vector3d(4.4, 1.0, 0.0);
  world_T_ego.linear() =
      Eigen::AngleAxisd(135.0 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).matrix();
  render::RenderOptions clean;
  clean.noise_sigma_grey = 0.0;
  clean.exposure_variation = 0.0;
  const render::Renderer renderer(world, clean);
  const render::RenderedImage left =
      renderer.render(head.calibration().left, world_T_ego * head.ego_T_left_camera(joints), 0);
  std::vector<std::string> types;
  for (const world::ObjectModel& o : world.objects) types.push_back(o.type);
  const std::vector<int> visible = object_pixel_counts(left.object_ids, world.objects.size());
  int doors = 0;
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    if (types[i] != "door" || visible[i] < 200) continue;
    const cv::Mat mask = left.object_ids == static_cast<int>(i);
    const Blob blob = make_blob(runs_from_mask(mask), left.image);
    const BlobLabel label = label_blob(blob, left.object_ids, visible);
    EXPECT_EQ(label.object_index, static_cast<int>(i));
    EXPECT_DOUBLE_EQ(label.purity, 1.0);
    EXPECT_DOUBLE_EQ(label.coverage, 1.0);
    EXPECT_EQ(sample_role(blob, left.object_ids, visible, types, "door"), SampleRole::positive);
    EXPECT_EQ(sample_role(blob, left.object_ids, visible, types, "handle"), SampleRole::negative);
    ++doors;
  }
  EXPECT_GE(doors, 5);
}

}  // namespace
}  // namespace vsl::recognition
