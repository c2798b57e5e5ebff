// FrameRecognizer (paper §2.1, §2.1.1) on rendered kitchen frames: percepts land on the world
// objects' reference points once registered into ego and moved into the world with the true
// robot pose. An oracle recognizer (classes from the renderer's id buffer) tests segmentation,
// cross match, triangulation and registration independently of the classifiers' quality; the
// shipped class models are then run end to end.
#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "support/stereo_views.hpp"
#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/recognizer_factory.hpp"

namespace vsl::recognition {
namespace {

using test::StereoView;
using test::StereoViews;

// The world object most of the blob's pixels show, or -1 (background, or no 80 % majority).
int majority_object(const Blob& blob, const cv::Mat& object_ids) {
  std::map<int, int> counts;
  for (const PixelRun& run : blob.runs) {
    const int* row = object_ids.ptr<int>(run.v);
    for (int u = run.u_begin; u < run.u_end; ++u) ++counts[row[u]];
  }
  int best = -1, best_count = 0;
  for (const auto& [id, count] : counts) {
    if (count > best_count) best = id, best_count = count;
  }
  return best_count >= 0.8 * blob.area_px ? best : -1;
}

Detection detection_of(const Blob& blob, int index, const std::string& type) {
  Detection d;
  d.type = type;
  d.blob_index = index;
  d.reference_px = blob.centroid_px;
  d.area_px = blob.area_px;
  double angle = std::atan2(blob.major_axis.y(), blob.major_axis.x());
  if (angle < 0) angle += M_PI;
  d.major_axis_angle_rad = std::min(angle, std::nextafter(M_PI, 0.0));
  // Extents of a uniform bar from its second moments: length^2 / 12 = rho.
  d.major_extent_px = std::sqrt(12.0 * blob.rho1_px2);
  d.minor_extent_px = std::sqrt(12.0 * blob.rho2_px2);
  d.confidence = 1.0f;
  return d;
}

// Pixels per world object in an id buffer.
std::map<int, int> visible_pixels(const cv::Mat& object_ids) {
  std::map<int, int> out;
  for (int v = 0; v < object_ids.rows; ++v) {
    const int* row = object_ids.ptr<int>(v);
    for (int u = 0; u < object_ids.cols; ++u) ++out[row[u]];
  }
  return out;
}

// Test-only recognizer, an ideal one: a blob is of `type` when the id buffer of the image it came
// from says so, it covers most of the object's visible pixels and it does not touch the image
// border (the centroid of a fragment or of a cut-off object is not the object's reference point,
// whatever the stereo part does).
class OracleRecognizer final : public ClassRecognizer {
 public:
  OracleRecognizer(std::string type, const world::WorldModel& world, const StereoView& view)
      : type_(std::move(type)),
        world_(world),
        view_(view),
        left_pixels_(visible_pixels(view.left.object_ids)),
        right_pixels_(visible_pixels(view.right.object_ids)) {}
  const std::string& type() const override { return type_; }
  void recognize(const cv::Mat& bgr_image, const std::vector<Blob>& blobs,
                 std::vector<Detection>& out) const override {
    const bool left = bgr_image.data == view_.left.image.data;
    const cv::Mat& ids = left ? view_.left.object_ids : view_.right.object_ids;
    const std::map<int, int>& pixels = left ? left_pixels_ : right_pixels_;
    for (int i = 0; i < static_cast<int>(blobs.size()); ++i) {
      const int object = majority_object(blobs[i], ids);
      const Blob& b = blobs[i];
      const bool inside = b.u_min > 0 && b.v_min > 0 && b.u_max < bgr_image.cols - 1 &&
                          b.v_max < bgr_image.rows - 1;
      if (object >= 0 && world_.objects[object].type == type_ && inside &&
          b.area_px >= 0.6 * pixels.at(object)) {
        out.push_back(detection_of(blobs[i], i, type_));
      }
    }
  }

 private:
  std::string type_;
  const world::WorldModel& world_;
  const StereoView& view_;
  std::map<int, int> left_pixels_, right_pixels_;
};

FrameRecognizerOptions kitchen_options() {
  FrameRecognizerOptions options;
  // World reference points (config/worlds/kitchen.yaml): a door's is the front face of its frame
  // (the recessed panel pulls the blob's centroid 2-3 mm back), a handle's the bar's axis, 6 mm
  // behind the surface the cameras see.
  options.stereo.reference_depth_offset_m = {{"door", 0.0}, {"handle", 0.006}};
  // Door panels are 0.72 to 1.25 m high, handle bars 0.16 m long.
  options.stereo.major_extent_range_m = {{"door", 0.5, 1.5}, {"handle", 0.12, 0.25}};
  return options;
}

FrameRecognizer oracle_recognizer(const StereoViews& views, const StereoView& view,
                                  const FrameRecognizerOptions& options = kitchen_options()) {
  std::vector<std::unique_ptr<ClassRecognizer>> recognizers;
  recognizers.push_back(std::make_unique<OracleRecognizer>("door", views.world(), view));
  recognizers.push_back(std::make_unique<OracleRecognizer>("handle", views.world(), view));
  return FrameRecognizer(options, views.head(), std::move(recognizers));
}

struct PerceptErrors {
  std::vector<double> error_m;              // of percepts of the right object, world frame
  std::vector<double> near_error_m;         // the same, objects within 2.5 m of the left camera
  std::vector<double> near_handle_error_m;  // of those, the handles
  std::vector<double> nees;  // handles: e^T Sigma^-1 e (their blobs are whole objects)
  int wrong_object = 0;      // left and right blobs show different objects, or another type
};

PerceptErrors errors(const StereoViews& views, const StereoView& view, const FrameResult& result) {
  PerceptErrors out;
  for (const FramePercept& p : result.percepts) {
    // These options make pairs only (no single-view doors, stereo_match.hpp).
    EXPECT_GE(p.left_detection, 0);
    EXPECT_GE(p.right_detection, 0);
    if (p.left_detection < 0 || p.right_detection < 0) continue;
    const Detection& l = result.left_detections[p.left_detection];
    const Detection& r = result.right_detections[p.right_detection];
    const int object = majority_object(result.left_blobs[l.blob_index], view.left.object_ids);
    const int right_object =
        majority_object(result.right_blobs[r.blob_index], view.right.object_ids);
    if (object < 0 || object != right_object || views.world().objects[object].type != p.type) {
      ++out.wrong_object;
      continue;
    }
    const Eigen::Vector3d truth_m = views.world().objects[object].world_position_m;
    const Eigen::Vector3d error_m = view.world_T_ego * p.ego_position_m - truth_m;
    out.error_m.push_back(error_m.norm());
    const Eigen::Isometry3d world_T_left = view.world_T_ego * view.ego_T_left_camera;
    if ((world_T_left.inverse() * truth_m).z() <= 2.5) {
      out.near_error_m.push_back(error_m.norm());
      if (p.type == "handle") out.near_handle_error_m.push_back(error_m.norm());
    }
    if (p.type == "handle") {
      const Eigen::Matrix3d world_covariance_m2 =
          view.world_T_ego.linear() * p.ego_covariance_m2 * view.world_T_ego.linear().transpose();
      out.nees.push_back(error_m.dot(world_covariance_m2.inverse() * error_m));
    }
  }
  std::sort(out.error_m.begin(), out.error_m.end());
  std::sort(out.near_error_m.begin(), out.near_error_m.end());
  std::sort(out.near_handle_error_m.begin(), out.near_handle_error_m.end());
  std::sort(out.nees.begin(), out.nees.end());
  return out;
}

double median(const std::vector<double>& sorted) {
  return sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
}

TEST(FrameRecognizerTest, RejectsBadConstructionAndImages) {
  const StereoViews& views = StereoViews::clean_kitchen();
  EXPECT_THROW(FrameRecognizer(FrameRecognizerOptions{}, views.head(), {}), std::invalid_argument);
  std::vector<std::unique_ptr<ClassRecognizer>> null_one(1);
  EXPECT_THROW(FrameRecognizer(FrameRecognizerOptions{}, views.head(), std::move(null_one)),
               std::invalid_argument);
  const StereoView view = views.typical(0);
  const FrameRecognizer recognizer = oracle_recognizer(views, view);
  const cv::Mat small(240, 320, CV_8UC3, cv::Scalar::all(0));
  const cv::Mat grey(480, 640, CV_8UC1, cv::Scalar::all(0));
  EXPECT_THROW(recognizer.recognize(small, view.right.image, view.joints), std::invalid_argument);
  EXPECT_THROW(recognizer.recognize(view.left.image, grey, view.joints), std::invalid_argument);
  head::JointState too_short;
  EXPECT_THROW(recognizer.recognize(view.left.image, view.right.image, too_short),
               std::invalid_argument);
}

// The shipped oracle views: every percept pairs the left and right images of one object, and
// the triangulated reference points agree with the world model to within the pixel noise.
TEST(FrameRecognizerTest, OraclePerceptsLandOnTheWorldObjects) {
  const StereoViews& views = StereoViews::kitchen();
  std::size_t percepts = 0;
  std::vector<double> near_errors_m, nees;
  for (int index = 0; index < StereoViews::fixed_view_count(); ++index) {
    const StereoView view = views.fixed_view(index, 3);
    const FrameResult result =
        oracle_recognizer(views, view).recognize(view.left.image, view.right.image, view.joints);
    SCOPED_TRACE("view " + std::to_string(index));
    EXPECT_TRUE(result.ego_T_left_camera.isApprox(view.ego_T_left_camera, 1e-12));
    const PerceptErrors e = errors(views, view, result);
    EXPECT_EQ(e.wrong_object, 0);
    percepts += result.percepts.size();
    near_errors_m.insert(near_errors_m.end(), e.near_error_m.begin(), e.near_error_m.end());
    nees.insert(nees.end(), e.nees.begin(), e.nees.end());
    EXPECT_GT(result.segmentation_ms, 0.0);
    EXPECT_GE(result.classification_ms, 0.0);
    EXPECT_GE(result.stereo_ms, 0.0);
    for (const FramePercept& p : result.percepts) {
      EXPECT_GT(p.ego_covariance_m2.determinant(), 0.0);
      ASSERT_GE(p.left_detection, 0);
      ASSERT_GE(p.right_detection, 0);
      EXPECT_EQ(p.left_px, result.left_detections[p.left_detection].reference_px);
      EXPECT_EQ(p.right_px, result.right_detections[p.right_detection].reference_px);
      EXPECT_EQ(p.type, result.left_detections[p.left_detection].type);
    }
  }
  std::sort(near_errors_m.begin(), near_errors_m.end());
  std::sort(nees.begin(), nees.end());
  SCOPED_TRACE(std::to_string(percepts) +
               " percepts; within 2.5 m: " + std::to_string(near_errors_m.size()) +
               ", median error " + std::to_string(median(near_errors_m)) +
               " m; median handle NEES " + std::to_string(median(nees)));
  EXPECT_GE(percepts, 20u);  // measured 23 (2 seeds' worth of views, area-sampled renderer)
  EXPECT_GE(near_errors_m.size(), 10u);
  EXPECT_LT(median(near_errors_m), 0.03);  // issue 5: at most 3 cm at 2 m
  // The blob centroids' noise is about the configured 0.7 px: chi^2(3) has median 2.4; measured
  // 6.6, as handle blobs still lose a standoff or an end cap now and then.
  EXPECT_LT(median(nees), 8.0);
}

// A class's shared noise (StereoMatchOptions::shared_noise) is claimed with each of its percepts
// and added to the covariance: s^2 I plus s_r^2 along the ray from the left camera, s_r the
// shared disparity's sigma there (a depth z along the optical axis moves by z^2 / (f B) per pixel,
// the range along the ray by range / z times that); other classes claim none.
TEST(FrameRecognizerTest, SharedNoiseIsClaimedAndInTheCovariance) {
  const StereoViews& views = StereoViews::kitchen();
  const StereoView view = views.fixed_view(0, 3);
  FrameRecognizerOptions options = kitchen_options();
  options.stereo.shared_noise = {{"handle", 0.004, 0.1}};
  const FrameResult plain =
      oracle_recognizer(views, view).recognize(view.left.image, view.right.image, view.joints);
  const FrameResult shared = oracle_recognizer(views, view, options)
                                 .recognize(view.left.image, view.right.image, view.joints);
  ASSERT_EQ(plain.percepts.size(), shared.percepts.size());
  const head::StereoCalibration& calibration = views.head().calibration();
  const double fb = calibration.left.fx_px * calibration.baseline_m();
  int handles = 0;
  for (std::size_t i = 0; i < shared.percepts.size(); ++i) {
    const FramePercept& a = plain.percepts[i];
    const FramePercept& b = shared.percepts[i];
    EXPECT_EQ(a.ego_position_m, b.ego_position_m);
    EXPECT_EQ(a.shared_sigma_m, 0.0);
    EXPECT_EQ(a.shared_ray_sigma_m, 0.0);
    if (b.type != "handle") {
      EXPECT_EQ(b.shared_sigma_m, 0.0);
      EXPECT_EQ(a.ego_covariance_m2, b.ego_covariance_m2);
      continue;
    }
    ++handles;
    const Eigen::Vector3d from_camera = b.ego_position_m - shared.ego_T_left_camera.translation();
    const double range_m = from_camera.norm();
    const Eigen::Vector3d ray = from_camera / range_m;
    EXPECT_EQ(b.shared_sigma_m, 0.004);
    const double depth_m = (shared.ego_T_left_camera.inverse() * b.ego_position_m).z();
    EXPECT_NEAR(b.shared_ray_sigma_m, 0.1 * depth_m * range_m / fb, 0.03 * b.shared_ray_sigma_m);
    const Eigen::Matrix3d added =
        0.004 * 0.004 * Eigen::Matrix3d::Identity() +
        b.shared_ray_sigma_m * b.shared_ray_sigma_m * ray * ray.transpose();
    EXPECT_LT((b.ego_covariance_m2 - a.ego_covariance_m2 - added).norm(), 1e-12);
  }
  EXPECT_GE(handles, 2);
}

TEST(FrameRecognizerTest, VergedEyesAreRegisteredThroughTheKinematics) {
  const StereoViews& views = StereoViews::kitchen();
  const StereoView close = views.fixed_view(1, 5);  // 1.2 m from the north run
  // Both eyes verge on a point 1.2 m ahead: the right camera turns against the left one.
  const head::GazeSolution gaze =
      views.head().gaze_joint_targets(Eigen::Vector3d(1.2, 0.0, 0.8), close.joints);
  const auto pan = [&](const char* name) {
    return gaze.targets.positions_rad[*views.head().joint_index(name)];
  };
  ASSERT_GT(pan("right_eye_pan") - pan("left_eye_pan"), 0.05);
  const StereoView view = views.render(close.world_T_ego, gaze.targets, 5);
  const FrameResult result =
      oracle_recognizer(views, view).recognize(view.left.image, view.right.image, view.joints);
  const PerceptErrors e = errors(views, view, result);
  SCOPED_TRACE(std::to_string(result.percepts.size()) + " percepts, largest error " +
               (e.error_m.empty() ? "-" : std::to_string(e.error_m.back())) + " m");
  EXPECT_GE(result.percepts.size(), 2u);
  EXPECT_EQ(e.wrong_object, 0);
  // Handle blobs are whole handles; a door blob's centroid moves a few cm off the door's
  // reference point where its own handle hides part of it.
  ASSERT_GE(e.near_handle_error_m.size(), 2u);
  EXPECT_LT(e.near_handle_error_m.back(), 0.02);
  ASSERT_FALSE(e.error_m.empty());
  EXPECT_LT(e.error_m.back(), 0.08);
}

// End to end with the shipped class models (config/recognition/): few percepts pair different
// objects, and those near the robot are within the 3 cm.
TEST(FrameRecognizerTest, ShippedModelsEndToEnd) {
  const StereoViews& views = StereoViews::kitchen();
  const FrameRecognizer recognizer(
      kitchen_options(), views.head(),
      load_recognizers({"config/recognition/door.yaml", "config/recognition/handle.yaml"}));
  int percepts = 0, wrong = 0;
  std::vector<double> near_errors_m;
  for (int index = 0; index < StereoViews::fixed_view_count(); ++index) {
    const StereoView view = views.fixed_view(index, 11);
    const FrameResult result = recognizer.recognize(view.left.image, view.right.image, view.joints);
    const PerceptErrors e = errors(views, view, result);
    percepts += static_cast<int>(result.percepts.size());
    wrong += e.wrong_object;
    near_errors_m.insert(near_errors_m.end(), e.near_error_m.begin(), e.near_error_m.end());
  }
  std::sort(near_errors_m.begin(), near_errors_m.end());
  const std::string summary =
      std::to_string(percepts) + " percepts, " + std::to_string(wrong) +
      " of a wrong object; within 2.5 m: " + std::to_string(near_errors_m.size()) +
      ", median error " + std::to_string(median(near_errors_m)) + " m";
  std::printf("shipped models end to end: %s\n", summary.c_str());
  SCOPED_TRACE(summary);
  // Measured with the thin-line barrier: 68 percepts, 2 of a wrong object, 24 within 2.5 m,
  // median error 1.1 cm (before it: 31 percepts, 2 wrong).
  EXPECT_GE(percepts, 50);
  EXPECT_LE(wrong, percepts / 10);
  EXPECT_GE(near_errors_m.size(), 18u);
  EXPECT_LT(median(near_errors_m), 0.02);
}

}  // namespace
}  // namespace vsl::recognition
