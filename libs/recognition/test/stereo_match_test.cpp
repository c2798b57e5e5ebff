// Cross match (paper §2.1): the gates (epipolar distance, disparity range, size, orientation),
// the one-to-one assignment, verging eyes, and the `stereo:` config section.
#include <gtest/gtest.h>

#include <algorithm>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "support/projection.hpp"
#include "vsl/config/node.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {
namespace {

// The simulated head's calibration: ideal 640x480 pinholes, parallel, 90 mm apart.
head::StereoCalibration sim_calibration() {
  return head::load_stereo_calibration("calib/armar3_sim.yaml");
}

using test::project;

// A vertical handle-like detection (elongated along v) at a pixel.
Detection detection(const std::string& type, const Eigen::Vector2d& px, double area_px = 120.0,
                    double angle_rad = M_PI / 2, float confidence = 0.9f) {
  Detection d;
  d.type = type;
  d.reference_px = px;
  d.area_px = area_px;
  d.major_axis_angle_rad = angle_rad;
  d.major_extent_px = 44.0;
  d.minor_extent_px = 4.0;
  d.confidence = confidence;
  return d;
}

struct Pair {
  Detection left, right;
};

class StereoMatchTest : public ::testing::Test {
 protected:
  Pair pair_of(const Eigen::Vector3d& left_point_m, const std::string& type = "handle") const {
    return {
        detection(type, project(left_point_m, calibration_.left, Eigen::Isometry3d::Identity())),
        detection(type, project(left_point_m, calibration_.right, left_T_right_))};
  }
  std::vector<StereoPercept> match(const std::vector<Detection>& left,
                                   const std::vector<Detection>& right) const {
    return match_and_triangulate(left, right, calibration_.left, calibration_.right, left_T_right_,
                                 options_);
  }
  // With the up direction (left camera frame) and, optionally, the pairs' trace.
  std::vector<StereoPercept> match(const std::vector<Detection>& left,
                                   const std::vector<Detection>& right, const Eigen::Vector3d& up,
                                   std::vector<StereoPairTrace>* trace = nullptr) const {
    return match_and_triangulate(left, right, calibration_.left, calibration_.right, left_T_right_,
                                 options_, up, trace);
  }

  // The door class's sizes (StereoMatchOptions::DoorClass): door pairs are placed by the
  // door's fit (partly_seen_door.hpp).
  void add_door_class() {
    StereoMatchOptions::DoorClass door;
    door.type = "door";
    door.typical_heights_m = {0.7};
    door.height_sigma_m = 0.12;
    door.min_width_m = 0.3;
    door.max_width_m = 1.0;
    door.typical_width_m = 0.5;
    door.width_sigma_m = 0.1;
    options_.door_classes.push_back(door);
  }

  head::StereoCalibration calibration_ = sim_calibration();
  Eigen::Isometry3d left_T_right_ = calibration_.left_T_right();
  StereoMatchOptions options_;
};

TEST_F(StereoMatchTest, EpipolarGateRejectsOffLineAndAcceptsOnIt) {
  const Pair p = pair_of({0.2, 0.1, 2.0});
  EXPECT_EQ(match({p.left}, {p.right}).size(), 1u);
  // Parallel cameras: the epipolar line is the row, so a shift in v is the distance to it.
  Detection off = p.right;
  off.reference_px.y() += 4.0;  // > max_epipolar_distance_px = 3
  EXPECT_TRUE(match({p.left}, {off}).empty());
  off.reference_px.y() = p.right.reference_px.y() - 2.5;
  EXPECT_EQ(match({p.left}, {off}).size(), 1u);
  // Along the line is a change of depth, not an epipolar violation.
  Detection along = p.right;
  along.reference_px.x() += 5.0;
  EXPECT_EQ(match({p.left}, {along}).size(), 1u);
}

// A door's front face 0.5 x 0.7 m, turned 40 deg about the vertical, its centre at `centre_m`:
// both outlines with corners clockwise from the top left.
// `down`: the door's vertical (the gravity direction) in the left camera frame.
Pair door_pair(const Eigen::Vector3d& centre_m, const head::StereoCalibration& calibration,
               const Eigen::Isometry3d& left_T_right,
               const Eigen::Vector3d& down = Eigen::Vector3d(0.0, 1.0, 0.0)) {
  const Eigen::Vector3d turned(std::cos(0.7), 0.0, std::sin(0.7));  // x right, z forward
  const Eigen::Vector3d across = (turned - turned.dot(down) * down).normalized();
  const std::array<Eigen::Vector3d, 4> corners{
      centre_m - 0.25 * across - 0.35 * down, centre_m + 0.25 * across - 0.35 * down,
      centre_m + 0.25 * across + 0.35 * down, centre_m - 0.25 * across + 0.35 * down};
  Pair p;
  for (Detection* d : {&p.left, &p.right}) {
    const bool left = d == &p.left;
    const Eigen::Isometry3d pose = left ? Eigen::Isometry3d::Identity() : left_T_right;
    const head::CameraIntrinsics& camera = left ? calibration.left : calibration.right;
    *d = detection("door", project(centre_m, camera, pose), 9000.0, M_PI / 2);
    for (const Eigen::Vector3d& c : corners) d->corners_px.push_back(project(c, camera, pose));
    d->height_px = 0.5 * ((d->corners_px[3] - d->corners_px[0]).norm() +
                          (d->corners_px[2] - d->corners_px[1]).norm());
  }
  return p;
}

TEST_F(StereoMatchTest, DoorFittedToBothOutlines) {
  const Eigen::Vector3d centre(0.1, 0.3, 2.5);
  const Eigen::Vector3d up(0.0, -1.0, 0.0);
  const Pair p = door_pair(centre, calibration_, left_T_right_);
  add_door_class();
  const auto exact = match({p.left}, {p.right}, up);
  ASSERT_EQ(exact.size(), 1u);
  EXPECT_LT((exact[0].left_camera_position_m - centre).norm(), 1e-3);
  // The fit's covariance: without the images to correlate the sides, the right outline's are
  // known to the position gate's tolerance, and the depth's sigma is about what that gives two
  // sides' disparities, z^2 / (f b) sigma / sqrt(2).
  const double f = calibration_.left.fx_px, b = calibration_.baseline_m();
  const double expected_m =
      2.5 * 2.5 / (f * b) * options_.max_epipolar_distance_px / std::sqrt(2.0);
  const double depth_sigma_m = std::sqrt(exact[0].left_camera_covariance_m2(2, 2));
  EXPECT_GT(depth_sigma_m, 0.5 * expected_m);
  EXPECT_LT(depth_sigma_m, 2.0 * expected_m);
  // Segmentation adds a 6 px strip along the bottom of the right outline only: its reference
  // point moves down 3 px (past the 3 px gate, within 5% of the height) and its bottom corners
  // 6 px. The right image says where the vertical sides are, the left where they end: the door
  // stays.
  Detection strip = p.right;
  strip.reference_px.y() += 3.5;
  strip.corners_px[2].y() += 6.0;
  strip.corners_px[3].y() += 6.0;
  const auto moved = match({p.left}, {strip}, up);
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_LT((moved[0].left_camera_position_m - centre).norm(), 0.01);
  // The same shift from the reference points alone is a depth error of decimetres.
  Detection shifted = p.right;
  shifted.corners_px.clear();
  Detection left_only = p.left;
  left_only.corners_px.clear();
  left_only.reference_px.x() += 1.5;  // what a strip along one side does to a centroid
  const auto from_points = match({left_only}, {shifted});
  ASSERT_EQ(from_points.size(), 1u);
  EXPECT_GT((from_points[0].left_camera_position_m - centre).norm(), 0.1);
}

TEST_F(StereoMatchTest, DoorOutlinesArePlacedByTheirSidesAndTheLeftImagesEnds) {
  // The camera pitched 0.4 rad up, the door above the eyes (the door's fit needs the up
  // direction). Stereo compares where the vertical sides are; where a side ends only the left
  // image says.
  const Eigen::Vector3d down(0.0, std::cos(0.4), -std::sin(0.4));
  const Eigen::Vector3d centre(0.1, 0.3, 2.5);
  const Pair p = door_pair(centre, calibration_, left_T_right_, down);
  add_door_class();
  const double height_px = p.right.height_px;
  const auto placed_at_centre = [&](const Detection& right) {
    const auto out = match({p.left}, {right}, -down);
    return out.size() == 1u && (out[0].left_camera_position_m - centre).norm() < 5e-3;
  };
  // A strip of 12% of the height along the top of the right outline, segmentation's, or the
  // whole right outline 40% longer at the bottom (a drawer merged below the door in one image).
  Detection strip = p.right;
  strip.corners_px[0] += 0.12 * (p.right.corners_px[0] - p.right.corners_px[3]);
  strip.corners_px[1] += 0.12 * (p.right.corners_px[1] - p.right.corners_px[2]);
  EXPECT_TRUE(placed_at_centre(strip));
  Detection merged = p.right;
  merged.corners_px[2] += 0.4 * (p.right.corners_px[2] - p.right.corners_px[1]);
  merged.corners_px[3] += 0.4 * (p.right.corners_px[3] - p.right.corners_px[0]);
  EXPECT_TRUE(placed_at_centre(merged));
  // Both outlines numbered from another corner (the segmenter starts at the corner of least
  // u + v, a side's end for a narrow outline at a grazing angle): the same door, and two handles
  // at one height 0.3 m apart are not one above another.
  Pair rotated = p;
  for (Detection* d : {&rotated.left, &rotated.right}) {
    std::rotate(d->corners_px.begin(), d->corners_px.begin() + 1, d->corners_px.end());
  }
  options_.bar_types = {"handle"};
  options_.max_bar_height_spread = 0.3;
  const Eigen::Vector3d turned(std::cos(0.7), 0.0, std::sin(0.7));  // door_pair's
  const Eigen::Vector3d along_face = (turned - turned.dot(down) * down).normalized();
  const Pair handle = pair_of(centre - 0.15 * along_face);
  const Pair beside = pair_of(centre + 0.15 * along_face);
  const auto placed = match({rotated.left, handle.left, beside.left},
                            {rotated.right, handle.right, beside.right}, -down);
  const auto door_percept = std::find_if(
      placed.begin(), placed.end(), [](const StereoPercept& q) { return q.left_detection == 0; });
  ASSERT_NE(door_percept, placed.end());
  EXPECT_LT((door_percept->left_camera_position_m - centre).norm(), 5e-3);
  // Sides 6% of the height to the right in the right image: another depth, another door.
  Detection moved = p.right;
  for (Eigen::Vector2d& c : moved.corners_px) c.x() += 0.06 * height_px;
  EXPECT_FALSE(placed_at_centre(moved));
}

TEST_F(StereoMatchTest, HeightRangeGate) {
  const Pair p = door_pair({0.1, 0.3, 2.5}, calibration_, left_T_right_);
  options_.height_range_m.push_back({"door", 0.5, 2.5});
  EXPECT_EQ(match({p.left}, {p.right}).size(), 1u);  // 0.7 m tall
  options_.height_range_m.back().min_m = 0.8;
  EXPECT_TRUE(match({p.left}, {p.right}).empty());
  // Not checked for other classes, nor without a height.
  options_.height_range_m.back().type = "window";
  EXPECT_EQ(match({p.left}, {p.right}).size(), 1u);
}

TEST_F(StereoMatchTest, DoorSidesMustBeVerticalIn3D) {
  // The camera pitched 0.4 rad up: the door's vertical sides converge in the image, but each
  // spans a plane holding the up direction.
  const Eigen::Vector3d down(0.0, std::cos(0.4), -std::sin(0.4));
  const Eigen::Vector3d up = -down;
  const Eigen::Vector3d centre(0.1, 0.3, 2.5);
  Pair p = door_pair(centre, calibration_, left_T_right_, down);
  // The reference points 3 px off (a strip of the blob): only the door's fit to the outlines'
  // corners places the door to the millimetre.
  p.left.reference_px.x() += 3.0;
  options_.max_side_tilt_rad = 0.03;
  add_door_class();
  EXPECT_EQ(match({p.left}, {p.right}, up).size(), 1u);
  // An occluder cut a bottom corner off one outline (a chair's contour became its side): 8 px
  // off the door's edge, a side some 0.05 rad from vertical. That side's corners are merged in
  // that image; the other image's and the other side's place the door. Either side, either image.
  std::vector<StereoPairTrace> trace;
  for (const std::size_t corner : {std::size_t{3}, std::size_t{2}}) {
    for (const bool in_left : {true, false}) {
      Pair cut = p;
      (in_left ? cut.left : cut.right).corners_px[corner].x() += corner == 3 ? 8.0 : -8.0;
      const auto placed = match({cut.left}, {cut.right}, up, &trace);
      ASSERT_EQ(placed.size(), 1u) << corner << " " << in_left;
      EXPECT_LT((placed[0].left_camera_position_m - centre).norm(), 1e-3) << corner << in_left;
    }
  }
  Pair cut = p;
  cut.left.corners_px[3].x() += 8.0;
  // The right image's left side is cut too (the occluder in both views): the side gate refuses
  // the pair, and the fit places it with that corner hidden in both images.
  Pair both = cut;
  both.right.corners_px[3].x() += 8.0;
  const auto hidden = match({both.left}, {both.right}, up, &trace);
  ASSERT_EQ(hidden.size(), 1u);
  EXPECT_LT((hidden[0].left_camera_position_m - centre).norm(), 0.02);
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_TRUE(trace[0].occluded_corner);
  // An outline with both sides tilted in one image: refused.
  Pair two = cut;
  two.left.corners_px[2].x() -= 8.0;
  EXPECT_TRUE(match({two.left}, {two.right}, up).empty());
  // Without the up direction or with the gate off, the sides are not checked.
  EXPECT_EQ(match({both.left}, {both.right}).size(), 1u);
  options_.max_side_tilt_rad = 0.0;
  EXPECT_EQ(match({both.left}, {both.right}, up).size(), 1u);
}

TEST_F(StereoMatchTest, DoorWithOneCornerHiddenByAnOccluderFromTheOtherThree) {
  // The camera pitched 0.4 rad up, the door (0.5 m x 0.7 m, turned 0.7 rad) 2.5 m away. A
  // chair's back half-way to the door hides its bottom-left corner in both images: the
  // outline's corner there is a point of the chair's contour, in the left image where the door's
  // face shows at 35% of the width and 25% of the height in from that corner, in the right image
  // at the chair's depth, half the face point's distance (some 21 px further left).
  const Eigen::Vector3d down(0.0, std::cos(0.4), -std::sin(0.4));
  const Eigen::Vector3d up = -down;
  const Eigen::Vector3d centre(0.1, 0.3, 2.5);
  const Pair p = door_pair(centre, calibration_, left_T_right_, down);
  options_.max_side_tilt_rad = 0.03;
  options_.height_range_m.push_back({"door", 0.5, 2.5});
  StereoMatchOptions::DoorClass door;
  door.type = "door";
  door.typical_heights_m = {0.7};
  door.min_width_m = 0.3;
  door.max_width_m = 1.0;
  options_.door_classes.push_back(door);
  const Eigen::Vector3d turned(std::cos(0.7), 0.0, std::sin(0.7));
  const Eigen::Vector3d across = (turned - turned.dot(down) * down).normalized();
  const Eigen::Vector3d bottom_left = centre - 0.25 * across + 0.35 * down;
  const auto hide_bottom_left = [&](const Eigen::Vector3d& face_point_m, double nearer) {
    Pair out = p;
    out.left.corners_px[3] =
        project(face_point_m, calibration_.left, Eigen::Isometry3d::Identity());
    out.right.corners_px[3] = project(nearer * face_point_m, calibration_.right, left_T_right_);
    return out;
  };
  const Pair hidden = hide_bottom_left(bottom_left + 0.35 * 0.5 * across - 0.25 * 0.7 * down, 0.5);
  std::vector<StereoPairTrace> trace;
  const auto placed = match({hidden.left}, {hidden.right}, up, &trace);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_LT((placed[0].left_camera_position_m - centre).norm(), 1e-3);
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kNone);
  EXPECT_TRUE(trace[0].occluded_corner);  // the trace says how it was placed
  {
    std::vector<StereoPairTrace> whole_trace;  // the whole door: an ordinary pair
    ASSERT_EQ(match({p.left}, {p.right}, up, &whole_trace).size(), 1u);
    ASSERT_EQ(whole_trace.size(), 1u);
    EXPECT_FALSE(whole_trace[0].occluded_corner);
  }
  const auto refused_by = [&](const Pair& pair) {
    const auto out = match({pair.left}, {pair.right}, up, &trace);
    EXPECT_TRUE(out.empty());
    return trace.at(0).refused_by;
  };
  // The right image's contour corner at another point of the occluder's contour (45% of the
  // height up, not 25%): the side gate refuses the pair as before; the three corners still place
  // the door.
  Pair elsewhere = hidden;
  elsewhere.right.corners_px[3] =
      project(0.5 * Eigen::Vector3d(bottom_left + 0.35 * 0.5 * across - 0.45 * 0.7 * down),
              calibration_.right, left_T_right_);
  const auto placed_elsewhere = match({elsewhere.left}, {elsewhere.right}, up, &trace);
  ASSERT_EQ(placed_elsewhere.size(), 1u);
  EXPECT_LT((placed_elsewhere[0].left_camera_position_m - centre).norm(), 1e-3);
  EXPECT_TRUE(trace.at(0).occluded_corner);
  // The contour's point outside the door (below it): an object added to the outline, no door
  // corner hidden.
  EXPECT_NE(refused_by(hide_bottom_left(bottom_left + 0.1 * down, 0.6)), StereoGate::kNone);
  // Both bottom corners hidden: no vertical side is whole, nothing fixes the door's height.
  Pair both = hidden;
  const Eigen::Vector3d bottom_right = centre + 0.25 * across + 0.35 * down;
  const Eigen::Vector3d face = bottom_right - 0.1 * across - 0.2 * down;
  both.left.corners_px[2] = project(face, calibration_.left, Eigen::Isometry3d::Identity());
  both.right.corners_px[2] = project(0.6 * face, calibration_.right, left_T_right_);
  EXPECT_NE(refused_by(both), StereoGate::kNone);
  // Too narrow for a door (the width bound of the class): refused.
  options_.door_classes[0].min_width_m = 0.6;
  EXPECT_NE(refused_by(hidden), StereoGate::kNone);
}

TEST_F(StereoMatchTest, ADoorOutlineWithHandlesOneAboveAnotherIsRefused) {
  // The door of door_pair: 0.5 m wide (along `across`), 0.7 m tall, turned 40 deg.
  const Eigen::Vector3d centre(0.1, 0.3, 2.5);
  const Eigen::Vector3d turned(std::cos(0.7), 0.0, std::sin(0.7));
  const Eigen::Vector3d across = turned.normalized(), down(0.0, 1.0, 0.0);
  const Pair door = door_pair(centre, calibration_, left_T_right_);
  options_.bar_types = {"handle"};
  options_.max_bar_height_spread = 0.3;
  std::vector<Detection> left{door.left}, right{door.right};
  const auto add_handle = [&](const Eigen::Vector3d& point) {
    const Pair h = pair_of(point);
    left.push_back(h.left);
    right.push_back(h.right);
  };
  std::vector<StereoPairTrace> trace;
  const auto door_trace = [&]() -> const StereoPairTrace& {
    match(left, right, Eigen::Vector3d::Zero(), &trace);
    for (const StereoPairTrace& t : trace) {
      if (t.left_detection == 0 && t.right_detection == 0) return t;
    }
    ADD_FAILURE() << "no trace of the door pair";
    return trace.at(0);
  };
  // The door's own handle, and a double door's neighbour's just beyond the shared edge at the
  // same height: a door.
  add_handle(centre + 0.2 * across);
  add_handle(centre + 0.29 * across);
  EXPECT_EQ(door_trace().refused_by, StereoGate::kNone);
  // A handle 0.3 m lower (0.43 of the door's height): two fronts one above another.
  add_handle(centre + 0.2 * across + 0.3 * down);
  EXPECT_EQ(door_trace().refused_by, StereoGate::kStackedBars);
  EXPECT_NEAR(door_trace().value, 0.3 / 0.7, 0.05);
  EXPECT_EQ(door_trace().limit, 0.3);
  EXPECT_STREQ(stereo_gate_name(StereoGate::kStackedBars), "stacked_bars");
  options_.max_bar_height_spread = 0.0;  // off
  EXPECT_EQ(door_trace().refused_by, StereoGate::kNone);
  // Handles on the outline's edge (a drawer's, seen at a grazing angle) count.
  options_.max_bar_height_spread = 0.3;
  left.resize(1);
  right.resize(1);
  add_handle(centre - 0.25 * across - 0.25 * down);
  add_handle(centre - 0.25 * across + 0.25 * down);
  EXPECT_EQ(door_trace().refused_by, StereoGate::kStackedBars);
}

TEST_F(StereoMatchTest, HandlesAreJudgedWhenOnlyOneImageHasAnOutline) {
  // The right image's blob of the door has no outline (its corners not found): the handles one
  // above another on the left outline still refuse the pair.
  const Eigen::Vector3d centre(0.1, 0.3, 2.5);
  Pair door = door_pair(centre, calibration_, left_T_right_);
  door.right.corners_px.clear();
  options_.bar_types = {"handle"};
  options_.max_bar_height_spread = 0.3;
  std::vector<Detection> left{door.left}, right{door.right};
  for (const double dy_m : {-0.2, 0.0, 0.2}) {
    const Pair h = pair_of(centre + Eigen::Vector3d(0.0, dy_m, 0.0));
    left.push_back(h.left);
    right.push_back(h.right);
  }
  std::vector<StereoPairTrace> trace;
  match(left, right, Eigen::Vector3d::Zero(), &trace);
  bool refused = false;
  for (const StereoPairTrace& t : trace) {
    if (t.left_detection == 0 && t.right_detection == 0) {
      refused = t.refused_by == StereoGate::kStackedBars;
    }
  }
  EXPECT_TRUE(refused);
}

TEST_F(StereoMatchTest, OutlinesThatNoDoorFitsAreRefused) {
  // The camera pitched 0.4 rad up, the door above the eyes: the door fits exact outlines.
  const Eigen::Vector3d down(0.0, std::cos(0.4), -std::sin(0.4));
  const Eigen::Vector3d up = -down;
  const Pair p = door_pair({0.1, 0.6, 2.5}, calibration_, left_T_right_, down);
  add_door_class();
  std::vector<StereoPairTrace> trace;
  EXPECT_EQ(match({p.left}, {p.right}, up, &trace).size(), 1u);
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kNone);
  // The bottom right corner 30 px up the door's right side in the left image, and 30 px up and
  // out of the door in the right: a door's two sides are equally tall, so no door fits that
  // corner, and an occluder that hid it would not add to the door in the right image.
  Pair occluded = p;
  occluded.left.corners_px[2].y() -= 30.0;
  occluded.right.corners_px[2].y() -= 30.0;
  occluded.right.corners_px[2].x() += 30.0;
  EXPECT_TRUE(match({occluded.left}, {occluded.right}, up, &trace).empty());
  ASSERT_EQ(trace.size(), 1u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kRectangleFit);
  EXPECT_GT(trace[0].value, trace[0].limit);
  EXPECT_STREQ(stereo_gate_name(trace[0].refused_by), "rectangle_fit");
}

TEST_F(StereoMatchTest, UntriangulablePairIsRefusedBeforeTheAssignment) {
  // Two left detections of one door compete for its right detection. The cheaper pair (its
  // reference points exactly on one epipolar line) has a left reference point 60 px to the left:
  // the rays through the reference points diverge (negative disparity), so it has no covariance
  // and cannot be triangulated, although its outline's centre can. It must be refused as a
  // candidate, leaving the right detection to the other pair, not assigned and then dropped.
  const Pair p = door_pair({0.1, 0.3, 2.5}, calibration_, left_T_right_);
  Detection behind = p.left;
  behind.reference_px.x() -= 60.0;
  Detection other = p.left;
  other.reference_px.y() += 2.0;
  std::vector<StereoPairTrace> trace;
  const auto percepts =
      match_and_triangulate({behind, other}, {p.right}, calibration_.left, calibration_.right,
                            left_T_right_, options_, Eigen::Vector3d(0.0, -1.0, 0.0), &trace);
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_EQ(percepts[0].left_detection, 1);
  // (Placed by its reference points, one 2 px off.)
  EXPECT_LT((percepts[0].left_camera_position_m - Eigen::Vector3d(0.1, 0.3, 2.5)).norm(), 0.05);
  ASSERT_EQ(trace.size(), 2u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kTriangulation);
  EXPECT_FALSE(trace[0].assigned);
  EXPECT_EQ(trace[1].refused_by, StereoGate::kNone);
  EXPECT_TRUE(trace[1].assigned);
  EXPECT_STREQ(stereo_gate_name(trace[0].refused_by), "triangulation");
}

TEST_F(StereoMatchTest, PairTraceNamesTheRefusingGate) {
  const Pair a = pair_of({0.2, 0.1, 2.0});
  const Pair b = pair_of({-0.3, 0.4, 2.0});  // another row: off a's epipolar line
  Detection small = b.right;
  small.area_px = 20.0;  // area ratio 6 against a's left
  std::vector<StereoPairTrace> trace;
  match_and_triangulate({a.left}, {a.right, small}, calibration_.left, calibration_.right,
                        left_T_right_, options_, Eigen::Vector3d::Zero(), &trace);
  ASSERT_EQ(trace.size(), 2u);
  EXPECT_EQ(trace[0].refused_by, StereoGate::kNone);
  EXPECT_TRUE(trace[0].assigned);
  EXPECT_EQ(trace[1].refused_by, StereoGate::kEpipolar);
  EXPECT_GT(trace[1].value, trace[1].limit);
  // Pairs of different types are not traced; an empty side clears the trace.
  Detection door = a.right;
  door.type = "door";
  match_and_triangulate({a.left}, {door}, calibration_.left, calibration_.right, left_T_right_,
                        options_, Eigen::Vector3d::Zero(), &trace);
  EXPECT_TRUE(trace.empty());
  trace.resize(3);
  match_and_triangulate({}, {a.right}, calibration_.left, calibration_.right, left_T_right_,
                        options_, Eigen::Vector3d::Zero(), &trace);
  EXPECT_TRUE(trace.empty());
}

TEST_F(StereoMatchTest, DisparityRangeAsDepth) {
  options_.min_depth_m = 0.5;
  options_.max_depth_m = 6.0;
  for (const double z : {0.55, 1.0, 3.0, 5.9}) {
    const Pair p = pair_of({0.05, -0.1, z});
    EXPECT_EQ(match({p.left}, {p.right}).size(), 1u) << z;
  }
  for (const double z : {0.35, 6.5, 20.0}) {
    const Pair p = pair_of({0.05, -0.1, z});
    EXPECT_TRUE(match({p.left}, {p.right}).empty()) << z;
  }
  // Negative disparity: the point would be behind the cameras.
  const Pair p = pair_of({0.05, -0.1, 2.0});
  Detection swapped = p.right;
  swapped.reference_px.x() = 2 * p.left.reference_px.x() - p.right.reference_px.x();
  EXPECT_TRUE(match({p.left}, {swapped}).empty());
}

TEST_F(StereoMatchTest, SizeOrientationAndTypeGates) {
  const Pair p = pair_of({-0.3, 0.2, 2.5});
  Detection bigger = p.right;
  bigger.area_px = p.left.area_px * 1.5;
  EXPECT_EQ(match({p.left}, {bigger}).size(), 1u);
  bigger.area_px = p.left.area_px * 1.7;  // > max_area_ratio = 1.6
  EXPECT_TRUE(match({p.left}, {bigger}).empty());

  Detection turned = p.right;
  turned.major_axis_angle_rad = M_PI / 2 + 0.5;  // > 0.35 rad from the left one
  EXPECT_TRUE(match({p.left}, {turned}).empty());
  // Axes are undirected: 0.05 and pi - 0.05 differ by 0.1 rad.
  Detection a = p.left, b = p.right;
  a.major_axis_angle_rad = 0.05;
  b.major_axis_angle_rad = M_PI - 0.05;
  EXPECT_EQ(match({a}, {b}).size(), 1u);
  // A near-round blob's axis is noise: not compared.
  turned.major_extent_px = turned.minor_extent_px = 20.0;
  EXPECT_EQ(match({p.left}, {turned}).size(), 1u);

  const Pair door = pair_of({-0.3, 0.2, 2.5}, "door");
  EXPECT_TRUE(match({p.left}, {door.right}).empty());
  EXPECT_EQ(match({p.left, door.left}, {door.right, p.right}).size(), 2u);
}

TEST_F(StereoMatchTest, OneToOne) {
  const Pair p = pair_of({0.1, 0.0, 2.0});
  // Two left detections compete for one right one: one match, the better one.
  Detection worse = p.left;
  worse.reference_px.y() += 2.0;
  auto percepts = match({worse, p.left}, {p.right});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_EQ(percepts[0].left_detection, 1);
  EXPECT_EQ(percepts[0].right_detection, 0);
  percepts = match({p.left}, {p.right, p.right});
  ASSERT_EQ(percepts.size(), 1u);
}

// The two handles of a double door, 7.4 cm apart at 2 m: the disparity (25 px) exceeds their
// spacing in the image (20 px), so the left image's right handle also fits the right image's left
// handle (at 1.1 m). The assignment must still pair each handle with itself.
TEST_F(StereoMatchTest, RepeatedObjectsPairWithThemselves) {
  const Eigen::Vector3d a{-0.037, 0.2, 2.0}, b{0.037, 0.2, 2.0};
  const Pair pa = pair_of(a), pb = pair_of(b);
  Detection pb_left = pb.left;
  pb_left.reference_px.y() += 0.3;  // the wrong pair is no worse than the true ones
  Detection pa_right = pa.right;
  pa_right.reference_px.y() += 0.3;
  for (int order = 0; order < 2; ++order) {
    const std::vector<Detection> left =
        order ? std::vector{pb_left, pa.left} : std::vector{pa.left, pb_left};
    const auto percepts = match(left, {pb.right, pa_right});
    ASSERT_EQ(percepts.size(), 2u);
    for (const StereoPercept& s : percepts) {
      const bool is_a = (left[s.left_detection].reference_px - pa.left.reference_px).norm() < 1.0;
      EXPECT_EQ(s.right_detection, is_a ? 1 : 0);
      EXPECT_NEAR(s.left_camera_position_m.z(), 2.0, 0.05);
    }
  }
}

TEST_F(StereoMatchTest, VergedEyesStillMatch) {
  // Each eye panned 6 degrees inward (about the camera y axis, down): the right camera turned
  // by 12 degrees against the left one. Epipolar lines are no longer rows.
  const double pan = 6.0 * M_PI / 180.0;
  Eigen::Isometry3d left_T_right = Eigen::Isometry3d::Identity();
  left_T_right.translation() = Eigen::Vector3d(0.09, 0.0, 0.0);
  left_T_right.linear() = Eigen::AngleAxisd(-2 * pan, Eigen::Vector3d::UnitY()).toRotationMatrix();
  left_T_right_ = left_T_right;
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.05, 0.3, 0.9), Eigen::Vector3d(0.4, -0.3, 1.5),
                                   Eigen::Vector3d(-0.2, 0.5, 2.5)}) {
    const Pair p = pair_of(x);
    const auto percepts = match({p.left}, {p.right});
    ASSERT_EQ(percepts.size(), 1u);
    EXPECT_LT((percepts[0].left_camera_position_m - x).norm(), 1e-9);
    // The same pixels under the parallel-camera assumption are far off the epipolar line.
    left_T_right_ = calibration_.left_T_right();
    EXPECT_TRUE(match({p.left}, {p.right}).empty());
    left_T_right_ = left_T_right;
  }
}

TEST_F(StereoMatchTest, MajorExtentRangeRejectsImplausibleDepths) {
  // A 16 cm handle at 2 m spans 44 px (detection()); paired with another handle's right image
  // at 1 m it would be 8 cm long.
  const Pair near = pair_of({0.0, 0.1, 1.0}), far = pair_of({0.0, 0.1, 2.0});
  options_.major_extent_range_m = {{"handle", 0.12, 0.25}};
  EXPECT_EQ(match({far.left}, {far.right}).size(), 1u);
  EXPECT_TRUE(match({near.left}, {near.right}).empty());   // 44 px at 1 m: 8 cm
  options_.major_extent_range_m = {{"door", 0.12, 0.25}};  // other classes are not checked
  EXPECT_EQ(match({near.left}, {near.right}).size(), 1u);
}

TEST_F(StereoMatchTest, ReferenceDepthOffsetAlongTheViewingRay) {
  const Eigen::Vector3d surface{0.3, -0.2, 1.8};
  const Pair p = pair_of(surface);
  options_.reference_depth_offset_m = {{"door", 0.0095}, {"handle", 0.006}};
  const auto percepts = match({p.left}, {p.right});
  ASSERT_EQ(percepts.size(), 1u);
  const Eigen::Vector3d expected = surface + 0.006 * surface.normalized();
  EXPECT_LT((percepts[0].left_camera_position_m - expected).norm(), 1e-9);
}

TEST_F(StereoMatchTest, ConfidenceIsTheGeometricMean) {
  Pair p = pair_of({0.0, 0.0, 1.5});
  p.left.confidence = 0.81f;
  p.right.confidence = 0.64f;
  const auto percepts = match({p.left}, {p.right});
  ASSERT_EQ(percepts.size(), 1u);
  EXPECT_NEAR(percepts[0].confidence, 0.72, 1e-6);
}

TEST_F(StereoMatchTest, EmptyInputs) {
  const Pair p = pair_of({0.0, 0.0, 1.5});
  EXPECT_TRUE(match({}, {p.right}).empty());
  EXPECT_TRUE(match({p.left}, {}).empty());
}

TEST(StereoOptionsTest, ReadsEveryKey) {
  const auto root = config::Node::load_string(R"(
stereo:
  max_epipolar_distance_px: 2.5
  min_depth_m: 0.4
  max_depth_m: 5.0
  max_area_ratio: 1.8
  max_orientation_difference_rad: 0.3
  min_elongation_for_orientation: 2.5
  pixel_sigma_px: 0.5
  reference_depth_offset_m: {door: 0.0095, handle: 0.006}
  major_extent_range_m: {handle: [0.12, 0.25]}
  height_range_m: {door: [0.5, 2.5]}
  max_side_tilt_rad: 0.05
  bar_types: [handle]
  min_side_correlation: 0.7
  min_single_view_correlation: 0.75
  min_peak_margin: 0.15
  single_view_min_separation_m: 0.25
  max_bar_height_spread: 0.35
  door_classes:
    door: {typical_heights_m: [0.7, 1.2], height_sigma_m: 0.1, min_width_m: 0.3, max_width_m: 1.0,
           typical_width_m: 0.45, width_sigma_m: 0.08}
  cut_bars: {handle: {typical_length_m: 0.16, length_sigma_m: 0.03}}
  shared_noise: {door: {floor_m: 0.01, shared_disparity_px: 0.1}, handle: {floor_m: 0.0035}}
)",
                                              "stereo.yaml");
  const StereoMatchOptions o = stereo_match_options_from(root.at("stereo"));
  EXPECT_EQ(o.max_epipolar_distance_px, 2.5);
  EXPECT_EQ(o.min_depth_m, 0.4);
  EXPECT_EQ(o.max_depth_m, 5.0);
  EXPECT_EQ(o.max_area_ratio, 1.8);
  EXPECT_EQ(o.max_orientation_difference_rad, 0.3);
  EXPECT_EQ(o.min_elongation_for_orientation, 2.5);
  EXPECT_EQ(o.pixel_sigma_px, 0.5);
  ASSERT_EQ(o.reference_depth_offset_m.size(), 2u);
  EXPECT_EQ(o.reference_depth_offset_m[0].first, "door");
  EXPECT_EQ(o.reference_depth_offset_m[1].second, 0.006);
  ASSERT_EQ(o.major_extent_range_m.size(), 1u);
  EXPECT_EQ(o.major_extent_range_m[0].type, "handle");
  EXPECT_EQ(o.major_extent_range_m[0].min_m, 0.12);
  EXPECT_EQ(o.major_extent_range_m[0].max_m, 0.25);
  ASSERT_EQ(o.height_range_m.size(), 1u);
  EXPECT_EQ(o.height_range_m[0].type, "door");
  EXPECT_EQ(o.height_range_m[0].min_m, 0.5);
  EXPECT_EQ(o.height_range_m[0].max_m, 2.5);
  EXPECT_EQ(o.max_side_tilt_rad, 0.05);
  EXPECT_EQ(o.bar_types, std::vector<std::string>{"handle"});
  EXPECT_EQ(o.min_side_correlation, 0.7);
  EXPECT_EQ(o.min_single_view_correlation, 0.75);
  EXPECT_EQ(o.min_peak_margin, 0.15);
  EXPECT_EQ(o.single_view_min_separation_m, 0.25);
  EXPECT_EQ(o.max_bar_height_spread, 0.35);
  ASSERT_EQ(o.door_classes.size(), 1u);
  EXPECT_EQ(o.door_classes[0].type, "door");
  EXPECT_EQ(o.door_classes[0].typical_heights_m, (std::vector<double>{0.7, 1.2}));
  EXPECT_EQ(o.door_classes[0].height_sigma_m, 0.1);
  EXPECT_EQ(o.door_classes[0].min_width_m, 0.3);
  EXPECT_EQ(o.door_classes[0].max_width_m, 1.0);
  EXPECT_EQ(o.door_classes[0].typical_width_m, 0.45);
  ASSERT_EQ(o.cut_bars.size(), 1u);
  EXPECT_EQ(o.cut_bars[0].type, "handle");
  EXPECT_EQ(o.cut_bars[0].typical_length_m, 0.16);
  EXPECT_EQ(o.cut_bars[0].length_sigma_m, 0.03);
  EXPECT_EQ(o.door_classes[0].width_sigma_m, 0.08);
  ASSERT_EQ(o.shared_noise.size(), 2u);
  EXPECT_EQ(o.shared_noise[0].type, "door");
  EXPECT_EQ(o.shared_noise[0].floor_m, 0.01);
  EXPECT_EQ(o.shared_noise[0].shared_disparity_px, 0.1);
  EXPECT_EQ(o.shared_noise[1].floor_m, 0.0035);
  EXPECT_EQ(o.shared_noise[1].shared_disparity_px, 0.0);  // optional
}

std::string stereo_error(const std::string& body) {
  try {
    stereo_match_options_from(config::Node::load_string("stereo:\n" + body, "s.yaml").at("stereo"));
  } catch (const config::Error& e) {
    return e.what();
  }
  return "";
}

TEST(StereoOptionsTest, RejectsBadValuesInOneLine) {
  EXPECT_NE(stereo_error("  shared_noise: {door: {floor_m: 0.5}}\n")
                .find("s.yaml:2: stereo.shared_noise.door.floor_m"),
            std::string::npos)
      << stereo_error("  shared_noise: {door: {floor_m: 0.5}}\n");
  EXPECT_NE(stereo_error("  shared_noise: {door: {floor: 0.01}}\n").find("unknown key"),
            std::string::npos);
  EXPECT_NE(stereo_error("  shared_noise: {door: {shared_disparity_px: -1}}\n")
                .find("shared_disparity_px"),
            std::string::npos);
  EXPECT_EQ(stereo_error("  max_epipolar_distanse_px: 2\n").rfind("s.yaml:", 0), 0u)
      << stereo_error("  max_epipolar_distanse_px: 2\n");
  EXPECT_NE(stereo_error("  max_epipolar_distanse_px: 2\n").find("unknown key"), std::string::npos);
  EXPECT_NE(stereo_error("  pixel_sigma_px: -1\n").find("s.yaml:2: stereo.pixel_sigma_px"),
            std::string::npos);
  EXPECT_NE(stereo_error("  max_area_ratio: .nan\n").find("max_area_ratio"), std::string::npos);
  EXPECT_NE(stereo_error("  max_side_height_mismatch: 0.2\n").find("unknown key"),
            std::string::npos);
  EXPECT_NE(stereo_error("  max_edge_slope_rad: 0.3\n").find("unknown key"), std::string::npos);
  EXPECT_NE(stereo_error("  min_depth_m: 3\n  max_depth_m: 2\n").find("must exceed"),
            std::string::npos);
  EXPECT_NE(stereo_error("  reference_depth_offset_m: {door: 2}\n")
                .find("stereo.reference_depth_offset_m.door"),
            std::string::npos);
  EXPECT_NE(stereo_error("  reference_depth_offset_m: [1, 2]\n").find("reference_depth_offset_m"),
            std::string::npos);
  EXPECT_NE(stereo_error("  major_extent_range_m: {handle: [0.3, 0.2]}\n")
                .find("s.yaml:2: stereo.major_extent_range_m.handle: expected [min_m, max_m]"),
            std::string::npos)
      << stereo_error("  major_extent_range_m: {handle: [0.3, 0.2]}\n");
  EXPECT_NE(stereo_error("  major_extent_range_m: {handle: [0.3]}\n").find("handle"),
            std::string::npos);
  EXPECT_NE(
      stereo_error("  bar_types: handle\n").find("s.yaml:2: stereo.bar_types: expected a list"),
      std::string::npos)
      << stereo_error("  bar_types: handle\n");
  EXPECT_NE(stereo_error("  bar_types: [[handle]]\n").find("bar_types[0]"), std::string::npos)
      << stereo_error("  bar_types: [[handle]]\n");
  EXPECT_NE(stereo_error("  min_single_view_correlation: 1.5\n")
                .find("s.yaml:2: stereo.min_single_view_correlation"),
            std::string::npos);
  EXPECT_NE(
      stereo_error("  max_bar_height_spread: 1.5\n").find("s.yaml:2: stereo.max_bar_height_spread"),
      std::string::npos)
      << stereo_error("  max_bar_height_spread: 1.5\n");
  EXPECT_NE(stereo_error("  min_peak_margin: 2.5\n").find("s.yaml:2: stereo.min_peak_margin"),
            std::string::npos);
  EXPECT_NE(stereo_error("  min_single_view_correlation: 0.7\n").find("needs min_side_correlation"),
            std::string::npos);
  EXPECT_NE(stereo_error("  door_classes: {door: {typical_heights_m: [0.7], height_sigma_m: 0.1, "
                         "min_width_m: 0.5, max_width_m: 0.4}}\n")
                .find("s.yaml:2: stereo.door_classes.door.max_width_m: must exceed min_width_m"),
            std::string::npos);
  EXPECT_NE(stereo_error("  door_classes: {door: {typical_heights_m: [0.7], height_sigma_m: 0.1, "
                         "min_width_m: 0.3}}\n")
                .find("max_width_m"),
            std::string::npos);
  EXPECT_NE(stereo_error("  door_classes: {door: {typical_heights_m: [0.7], height_sigma_m: 0.9, "
                         "min_width_m: 0.3, max_width_m: 1}}\n")
                .find("stereo.door_classes.door.height_sigma_m"),
            std::string::npos);
  // Cut bars: only of a bar type, a spread below the length.
  EXPECT_NE(stereo_error("  cut_bars: {handle: {typical_length_m: 0.16, length_sigma_m: 0.03}}\n")
                .find("not one of bar_types"),
            std::string::npos);
  EXPECT_NE(stereo_error("  bar_types: [handle]\n  cut_bars: {handle: {typical_length_m: 0.16, "
                         "length_sigma_m: 0.2}}\n")
                .find("s.yaml:3: stereo.cut_bars.handle.length_sigma_m"),
            std::string::npos);
  EXPECT_EQ(stereo_error("  bar_types: [handle]\n  cut_bars: {handle: {typical_length_m: 0.16, "
                         "length_sigma_m: 0.03}}\n"),
            "");
  EXPECT_NE(stereo_error("  door_classes: {door: {typical_height: 0.7}}\n").find("unknown key"),
            std::string::npos);
  EXPECT_NE(stereo_error("  door_classes: {door: {typical_heights_m: [1.2, 0.7], height_sigma_m: "
                         "0.1, min_width_m: 0.3, max_width_m: 1}}\n")
                .find("s.yaml:2: stereo.door_classes.door.typical_heights_m: expected a list of "
                      "heights in metres, ascending"),
            std::string::npos);
  // A door entry with its required keys and `extra` ("key: value"), after `before`.
  const auto cut_door_error = [](const std::string& extra, const std::string& before = "") {
    return stereo_error(before +
                        "  door_classes: {door: {typical_heights_m: [0.7], height_sigma_m: 0.1, "
                        "min_width_m: 0.3, max_width_m: 1, " +
                        extra + "}}\n");
  };
  // The door's constructions are states of its one fit, not switches.
  EXPECT_NE(cut_door_error("from_one_side: true").find("unknown key"), std::string::npos)
      << cut_door_error("from_one_side: true");
  // Doors whose left or right side neither image shows: a door's width, with a spread.
  EXPECT_NE(
      cut_door_error("typical_width_m: 0.2, width_sigma_m: 0.1")
          .find("s.yaml:2: stereo.door_classes.door.typical_width_m: must be 0 (off) or within "
                "min_width_m .. max_width_m"),
      std::string::npos)
      << cut_door_error("typical_width_m: 0.2, width_sigma_m: 0.1");
  EXPECT_NE(
      cut_door_error("typical_width_m: 0.4")
          .find("s.yaml:2: stereo.door_classes.door.typical_width_m: needs width_sigma_m > 0"),
      std::string::npos)
      << cut_door_error("typical_width_m: 0.4");
  EXPECT_EQ(cut_door_error("typical_width_m: 0", ""), "");
  EXPECT_EQ(cut_door_error("typical_width_m: 0.4, width_sigma_m: 0.1"), "");
  EXPECT_NE(cut_door_error("width_sigma_m: -1").find("stereo.door_classes.door.width_sigma_m"),
            std::string::npos);
  for (const std::string& e : {stereo_error("  pixel_sigma_px: -1\n"),
                               stereo_error("  min_depth_m: 3\n  max_depth_m: 2\n")}) {
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

TEST(StereoOptionsTest, FrameRecognizerOptionsReadBothSections) {
  const auto root = config::Node::load_string(R"(
recognition:
  models: [door.yaml]
  segmentation: {min_blob_px: 20}
  stereo: {max_depth_m: 4.5}
)",
                                              "r.yaml");
  const FrameRecognizerOptions o = frame_recognizer_options_from(root.at("recognition"));
  EXPECT_EQ(o.segmentation.min_blob_px, 20);
  EXPECT_EQ(o.stereo.max_depth_m, 4.5);
  EXPECT_THROW(frame_recognizer_options_from(
                   config::Node::load_string("r:\n  stereo: {bad: 1}\n", "r.yaml").at("r")),
               config::Error);
}

}  // namespace
}  // namespace vsl::recognition
