// Door and handle recognizers: Shi-Tomasi corner verification on drawn bars and smears, the
// recognizers on synthetic images, and on the ground-truth blobs of rendered kitchen views.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "../src/corner_verification.hpp"
#include "support/stereo_views.hpp"
#include "vsl/recognition/descriptors.hpp"
#include "vsl/recognition/door_recognizer.hpp"
#include "vsl/recognition/handle_recognizer.hpp"
#include "vsl/recognition/recognizer_factory.hpp"

namespace vsl::recognition {
namespace {

const cv::Scalar kDoorBgr(0x8f, 0x5f, 0x2f);
const cv::Scalar kBrassBgr(0x3a, 0x9a, 0xc2);
const cv::Scalar kWallBgr(0xdc, 0xe8, 0xec);

// Adds seeded sensor noise (sigma 2 grey levels, as the renderer's).
void add_noise(cv::Mat& image, std::uint64_t seed) {
  cv::RNG rng(seed);
  cv::Mat noise(image.size(), CV_16SC3);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 2.0);
  cv::Mat wide;
  image.convertTo(wide, CV_16SC3);
  wide += noise;
  wide.convertTo(image, CV_8UC3);
}

// The blob of the pixels of `image` within `max_distance` (max over channels, grey levels) of
// `bgr`, inside `region`.
Blob colour_blob(const cv::Mat& image, const cv::Scalar& bgr, double max_distance,
                 const cv::Rect& region) {
  cv::Mat mask(image.size(), CV_8U, cv::Scalar(0));
  for (int v = region.y; v < region.y + region.height; ++v) {
    for (int u = region.x; u < region.x + region.width; ++u) {
      const cv::Vec3b& p = image.at<cv::Vec3b>(v, u);
      double d = 0.0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(p[c] - bgr[c]));
      if (d <= max_distance) mask.at<std::uint8_t>(v, u) = 1;
    }
  }
  return make_blob(runs_from_mask(mask), image);
}

// A brass bar `length` x `width` px at `angle_deg` from +u, centred in a door-blue image.
cv::Mat bar_image(double length, double width, double angle_deg) {
  cv::Mat image(160, 160, CV_8UC3, kDoorBgr);
  cv::Point2f corners[4];
  cv::RotatedRect(cv::Point2f(80.f, 80.f),
                  cv::Size2f(static_cast<float>(length), static_cast<float>(width)),
                  static_cast<float>(angle_deg))
      .points(corners);
  std::vector<cv::Point> points;
  for (const cv::Point2f& p : corners) points.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillConvexPoly(image, points, kBrassBgr);
  return image;
}

CornerVerification verify(const cv::Mat& image, const Blob& blob) {
  return verify_handle_corners(image, blob, blob_axes(blob), CornerVerificationParameters{});
}

TEST(CornerVerification, DrawnBarsHaveCornersAtBothEnds) {
  std::uint64_t seed = 1;
  for (const double width : {2.0, 3.0, 4.0, 7.0, 12.0}) {
    for (const double length : {24.0, 50.0, 110.0}) {
      for (const double angle : {0.0, 90.0, 30.0, -70.0}) {
        SCOPED_TRACE(testing::Message() << width << " x " << length << " at " << angle);
        cv::Mat image = bar_image(length, width, angle);
        add_noise(image, seed++);
        const Blob blob = colour_blob(image, kBrassBgr, 12.0, cv::Rect(0, 0, 160, 160));
        const CornerVerification result = verify(image, blob);
        EXPECT_TRUE(result.accepted)
            << "contrast " << result.contrast_grey << " ends " << result.end_fraction[0] << ", "
            << result.end_fraction[1] << " side " << result.side_fraction;
      }
    }
  }
}

TEST(CornerVerification, SmearsWithoutEndsAreRejected) {
  // A brass streak whose brightness fades out over the outer third at each end (a reflection or
  // motion smear): the blob of its brass-like pixels has edges but no corners.
  cv::Mat fading(160, 160, CV_8UC3, kDoorBgr);
  for (int u = 20; u < 140; ++u) {
    const double t = std::min({1.0, (u - 20) / 40.0, (139 - u) / 40.0});
    const cv::Scalar colour = kDoorBgr * (1.0 - t) + kBrassBgr * t;
    cv::line(fading, cv::Point(u, 76), cv::Point(u, 83), colour);
  }
  add_noise(fading, 100);
  // Brass-like: nearer brass than door in every channel.
  const Blob fading_blob = colour_blob(fading, kBrassBgr, 45.0, cv::Rect(0, 0, 160, 160));
  ASSERT_GT(fading_blob.area_px, 100.0);
  const CornerVerification fading_result = verify(fading, fading_blob);
  EXPECT_FALSE(fading_result.accepted)
      << "ends " << fading_result.end_fraction[0] << ", " << fading_result.end_fraction[1];

  // A blurred brass ellipse.
  cv::Mat blurred(160, 160, CV_8UC3, kDoorBgr);
  cv::ellipse(blurred, cv::Point(80, 80), cv::Size(50, 5), 20.0, 0, 360, kBrassBgr, -1);
  cv::GaussianBlur(blurred, blurred, cv::Size(0, 0), 3.0);
  add_noise(blurred, 101);
  const Blob blurred_blob = colour_blob(blurred, kBrassBgr, 45.0, cv::Rect(0, 0, 160, 160));
  ASSERT_GT(blurred_blob.area_px, 50.0);
  const CornerVerification blurred_result = verify(blurred, blurred_blob);
  EXPECT_FALSE(blurred_result.accepted)
      << "ends " << blurred_result.end_fraction[0] << ", " << blurred_result.end_fraction[1];

  // No contrast at all: a blob drawn around uniform brass.
  const cv::Mat uniform(60, 60, CV_8UC3, kBrassBgr);
  cv::Mat mask(60, 60, CV_8U, cv::Scalar(0));
  mask(cv::Rect(10, 28, 40, 4)).setTo(1);
  EXPECT_FALSE(verify(uniform, make_blob(runs_from_mask(mask), uniform)).accepted);
}

TEST(CornerVerification, BadBlockSizeThrows) {
  const cv::Mat image = bar_image(40, 4, 0);
  const Blob blob = colour_blob(image, kBrassBgr, 5.0, cv::Rect(0, 0, 160, 160));
  CornerVerificationParameters parameters;
  parameters.block_size_px = 1;
  EXPECT_THROW(verify_handle_corners(image, blob, blob_axes(blob), parameters),
               std::invalid_argument);
}

// --- Recognizers on synthetic images ---------------------------------------------------------

// Models set here rather than read from config/recognition/ (which vsl-train-recognition
// rewrites): a diagonal Gaussian around hand-picked means, threshold the chi-square 0.99 quantile.
GaussianClassModel diagonal_model(const std::string& type, const std::vector<std::string>& names,
                                  const std::vector<double>& mean,
                                  const std::vector<double>& stddev) {
  const auto k = static_cast<Eigen::Index>(mean.size());
  Eigen::VectorXd m = Eigen::Map<const Eigen::VectorXd>(mean.data(), k);
  Eigen::VectorXd s = Eigen::Map<const Eigen::VectorXd>(stddev.data(), k);
  return GaussianClassModel(type, names, m, s.cwiseAbs2().asDiagonal().toDenseMatrix(),
                            chi_square_quantile(0.99, static_cast<int>(k)), "test");
}

std::vector<std::unique_ptr<ClassRecognizer>> synthetic_recognizers() {
  std::vector<std::unique_ptr<ClassRecognizer>> out;
  // Doors: rectangles (chords 1, elasticity 1), upright, about twice as tall as wide.
  out.push_back(std::make_unique<DoorRecognizer>(
      diagonal_model("door", door_descriptor_names(), {1.1, 1.1, 0.95, 0.04, 0.08, 0.7, 0.01},
                     {0.3, 0.3, 0.1, 0.06, 0.1, 0.5, 0.03}),
      DoorRecognizerParameters{}));
  // Handles: bars about 20 times longer than wide, brass shaded to 0.62 (distance 0.4 from Q).
  out.push_back(std::make_unique<HandleRecognizer>(
      diagonal_model("handle", handle_descriptor_names(), {4.4, 0.003, 0.4}, {0.8, 0.02, 0.13}),
      HandleRecognizerParameters{}));
  return out;
}

TEST(Recognizers, SyntheticKitchenFront) {
  // Door and handle colours as the renderer shades them facing the camera (about 0.62 of the
  // material colour): rendered handles' mean colour is about 0.4 from the ideal brass Q.
  const cv::Scalar door_bgr = kDoorBgr * 0.62;
  const cv::Scalar brass_bgr = kBrassBgr * 0.62;
  cv::Mat image(480, 640, CV_8UC3, kWallBgr);
  const cv::Rect door(40, 60, 70, 170);  // an upright door panel
  // Two neighbouring wall-cupboard doors (0.5 x 0.7 m each) merged into one blob: wider than
  // tall. (Two 0.3 m doors merged are a 0.6 m door by shape; only their 3D size tells.)
  const cv::Rect merged(130, 60, 200, 140);
  const cv::Rect drawer(350, 60, 170, 60);      // a drawer front
  const cv::Rect wall_patch(540, 60, 60, 160);  // upright, wall-coloured
  image(door).setTo(door_bgr);
  image(merged).setTo(door_bgr);
  image(drawer).setTo(door_bgr);
  // Handles: a vertical bar on the door, a horizontal one on the drawer.
  image(cv::Rect(95, 120, 4, 44)).setTo(brass_bgr);
  image(cv::Rect(400, 88, 60, 4)).setTo(brass_bgr);
  add_noise(image, 5);

  std::vector<Blob> blobs;
  for (const cv::Rect& region : {door, merged, drawer}) {
    blobs.push_back(colour_blob(image, door_bgr, 12.0, region));
  }
  blobs.push_back(colour_blob(image, kWallBgr, 12.0, wall_patch));
  blobs.push_back(colour_blob(image, brass_bgr, 12.0, cv::Rect(90, 110, 20, 70)));
  blobs.push_back(colour_blob(image, brass_bgr, 12.0, cv::Rect(390, 80, 80, 20)));

  const auto recognizers = synthetic_recognizers();
  std::vector<Detection> doors, handles;
  recognizers[0]->recognize(image, blobs, doors);
  recognizers[1]->recognize(image, blobs, handles);
  ASSERT_EQ(doors.size(), 1u);
  EXPECT_EQ(doors[0].blob_index, 0);
  EXPECT_EQ(doors[0].type, "door");
  EXPECT_NEAR(doors[0].reference_px.x(), 74.5, 0.5);  // the door's centre (a hole for the handle)
  EXPECT_NEAR(doors[0].major_axis_angle_rad, std::numbers::pi / 2.0, 0.05);
  EXPECT_NEAR(doors[0].major_extent_px, 170.0, 1.0);
  EXPECT_NEAR(doors[0].minor_extent_px, 70.0, 1.0);
  EXPECT_GT(doors[0].confidence, 0.0f);
  EXPECT_LE(doors[0].confidence, 1.0f);
  ASSERT_EQ(handles.size(), 2u);
  EXPECT_EQ(handles[0].blob_index, 4);
  EXPECT_EQ(handles[1].blob_index, 5);
  EXPECT_EQ(handles[1].type, "handle");
  EXPECT_NEAR(handles[1].major_axis_angle_rad, 0.0, 0.05);
  EXPECT_NEAR(handles[1].reference_px.y(), 89.5, 0.3);
}

TEST(Recognizers, DoorsBeyondTheModelsThresholdAreNotReported) {
  cv::Mat image(240, 200, CV_8UC3, kWallBgr);
  const cv::Rect door(60, 30, 70, 170);
  image(door).setTo(kDoorBgr * 0.62);
  add_noise(image, 11);
  const std::vector<Blob> blobs{colour_blob(image, kDoorBgr * 0.62, 12.0, door)};
  GaussianClassModel model =
      diagonal_model("door", door_descriptor_names(), {1.1, 1.1, 0.95, 0.04, 0.08, 0.7, 0.01},
                     {0.3, 0.3, 0.1, 0.06, 0.1, 0.5, 0.03});
  const auto detect = [&](const GaussianClassModel& m) {
    std::vector<Detection> out;
    DoorRecognizer(m, DoorRecognizerParameters{}).recognize(image, blobs, out);
    return out;
  };
  const std::vector<Detection> accepted = detect(model);
  ASSERT_EQ(accepted.size(), 1u);
  const double d2 = accepted[0].mahalanobis2;
  ASSERT_GT(d2, 0.1);
  // The same blob with the model's threshold just below its D^2.
  model.set_max_mahalanobis2(0.9 * d2);
  EXPECT_TRUE(detect(model).empty());
}

TEST(Recognizers, BlobsOnThreeImageBordersAreNotJudged) {
  cv::Mat image(200, 200, CV_8UC3, kWallBgr);
  image(cv::Rect(0, 0, 60, 200)).setTo(kDoorBgr);  // cut by the left, top and bottom border
  const std::vector<Blob> blobs{colour_blob(image, kDoorBgr, 5.0, cv::Rect(0, 0, 200, 200))};
  const auto door = load_recognizer("config/recognition/door.yaml");
  std::vector<Detection> out;
  door->recognize(image, blobs, out);
  EXPECT_TRUE(out.empty());
}

// The detections of the synthetic door model (synthetic_recognizers) with border-cut doors on or
// off (DoorRecognizerParameters::detect_border_cut).
std::vector<Detection> synthetic_door_detections(const cv::Mat& image,
                                                 const std::vector<Blob>& blobs, bool border_cut) {
  DoorRecognizerParameters parameters;
  parameters.detect_border_cut = border_cut;
  std::vector<Detection> out;
  DoorRecognizer(
      diagonal_model("door", door_descriptor_names(), {1.1, 1.1, 0.95, 0.04, 0.08, 0.7, 0.01},
                     {0.3, 0.3, 0.1, 0.06, 0.1, 0.5, 0.03}),
      parameters)
      .recognize(image, blobs, out);
  return out;
}

TEST(Recognizers, DoorsCutByOneBorderAreBorderCutDetections) {
  // A door panel whose top the image's upper border cuts (a wall cupboard seen from close by),
  // one whose bottom the lower border cuts, one cut by the left border, and one cut by the top
  // border with a hole where its handle's blob would be: its outline is the panel's.
  cv::Mat image(240, 320, CV_8UC3, kWallBgr);
  const cv::Scalar door_bgr = kDoorBgr * 0.62;
  const cv::Rect top_cut(30, 0, 60, 110), bottom_cut(120, 130, 70, 110), left_cut(0, 60, 20, 120),
      holed(230, 0, 60, 90);
  for (const cv::Rect& r : {top_cut, bottom_cut, left_cut, holed}) image(r).setTo(door_bgr);
  image(cv::Rect(245, 30, 30, 40)).setTo(kWallBgr);
  add_noise(image, 17);
  std::vector<Blob> blobs;
  for (const cv::Rect& r : {top_cut, bottom_cut, left_cut, holed}) {
    blobs.push_back(colour_blob(image, door_bgr, 12.0, r));
  }
  EXPECT_TRUE(synthetic_door_detections(image, blobs, false).empty());
  const std::vector<Detection> cut = synthetic_door_detections(image, blobs, true);
  ASSERT_EQ(cut.size(), 4u);
  // Top cut: the corners on the cut side where the sides leave the image (the outer edge of
  // row 0), the reference point the middle of the bottom edge, the height the visible sides'.
  EXPECT_EQ(cut[0].blob_index, 0);
  EXPECT_EQ(cut[0].border_cut, BorderCut::kTop);
  ASSERT_EQ(cut[0].corners_px.size(), 4u);
  EXPECT_NEAR(cut[0].corners_px[0].x(), 29.5, 1.0);
  EXPECT_DOUBLE_EQ(cut[0].corners_px[0].y(), -0.5);
  EXPECT_DOUBLE_EQ(cut[0].corners_px[1].y(), -0.5);
  EXPECT_NEAR(cut[0].corners_px[2].y(), 109.5, 1.0);
  EXPECT_NEAR(cut[0].reference_px.x(), 59.5, 1.0);
  EXPECT_NEAR(cut[0].reference_px.y(), 109.5, 1.0);
  EXPECT_NEAR(cut[0].height_px, 110.0, 1.5);
  EXPECT_GT(cut[0].confidence, 0.0f);
  // Bottom cut: the top edge is the whole one.
  EXPECT_EQ(cut[1].blob_index, 1);
  EXPECT_EQ(cut[1].border_cut, BorderCut::kBottom);
  EXPECT_DOUBLE_EQ(cut[1].corners_px[2].y(), 239.5);
  EXPECT_NEAR(cut[1].reference_px.y(), 129.5, 1.0);
  // Left cut: the right side is the whole one, the corners on the cut side where
  // the top and bottom edges leave the image (the outer edge of column 0).
  EXPECT_EQ(cut[2].blob_index, 2);
  EXPECT_EQ(cut[2].border_cut, BorderCut::kLeft);
  ASSERT_EQ(cut[2].corners_px.size(), 4u);
  EXPECT_DOUBLE_EQ(cut[2].corners_px[0].x(), -0.5);
  EXPECT_DOUBLE_EQ(cut[2].corners_px[3].x(), -0.5);
  EXPECT_NEAR(cut[2].corners_px[0].y(), 59.5, 1.0);
  EXPECT_NEAR(cut[2].corners_px[3].y(), 179.5, 1.0);
  EXPECT_NEAR(cut[2].corners_px[1].x(), 19.5, 1.0);
  EXPECT_NEAR(cut[2].corners_px[2].y(), 179.5, 1.0);
  EXPECT_NEAR(cut[2].reference_px.x(), 19.5, 1.0);
  EXPECT_NEAR(cut[2].reference_px.y(), 119.5, 1.0);
  EXPECT_NEAR(cut[2].height_px, 120.0, 1.5);
  EXPECT_EQ(cut[3].blob_index, 3);
  EXPECT_EQ(cut[3].border_cut, BorderCut::kTop);
  EXPECT_NEAR(cut[3].height_px, 90.0, 1.5);
}

// The detections of the synthetic handle model (synthetic_recognizers) with border-cut bars on or
// off (HandleRecognizerParameters::detect_border_cut).
std::vector<Detection> synthetic_handle_detections(const cv::Mat& image,
                                                   const std::vector<Blob>& blobs,
                                                   bool border_cut) {
  HandleRecognizerParameters parameters;
  parameters.detect_border_cut = border_cut;
  std::vector<Detection> out;
  HandleRecognizer(
      diagonal_model("handle", handle_descriptor_names(), {4.4, 0.003, 0.4}, {0.8, 0.02, 0.13}),
      parameters)
      .recognize(image, blobs, out);
  return out;
}

TEST(Recognizers, HandlesCutAtOneEndByTheBorderAreBorderCutDetections) {
  // Brass bars on door blue (shaded as rendered): cut at their top end by the upper border, at
  // their bottom end by the lower one, at their left end by the left one; and a bar lying along
  // the top border, cut along its side, which says nothing of its ends.
  const cv::Scalar brass_bgr = kBrassBgr * 0.62;
  cv::Mat image(240, 320, CV_8UC3, kDoorBgr * 0.62);
  const cv::Rect top_cut(60, 0, 4, 34), bottom_cut(150, 206, 4, 34), left_cut(0, 120, 34, 4),
      along_top(220, 0, 40, 4);
  for (const cv::Rect& r : {top_cut, bottom_cut, left_cut, along_top}) image(r).setTo(brass_bgr);
  add_noise(image, 23);
  std::vector<Blob> blobs;
  for (const cv::Rect& r : {top_cut, bottom_cut, left_cut, along_top}) {
    blobs.push_back(colour_blob(image, brass_bgr, 12.0, r));
  }
  EXPECT_TRUE(synthetic_handle_detections(image, blobs, false).empty());
  const std::vector<Detection> cut = synthetic_handle_detections(image, blobs, true);
  ASSERT_EQ(cut.size(), 3u);
  EXPECT_EQ(cut[0].blob_index, 0);
  EXPECT_EQ(cut[0].border_cut, BorderCut::kTop);
  EXPECT_EQ(cut[1].blob_index, 1);
  EXPECT_EQ(cut[1].border_cut, BorderCut::kBottom);
  EXPECT_EQ(cut[2].blob_index, 2);
  EXPECT_EQ(cut[2].border_cut, BorderCut::kLeft);
  // The reference point is the middle of what the image shows, the extent its visible length.
  EXPECT_NEAR(cut[0].reference_px.x(), 61.5, 0.5);
  EXPECT_NEAR(cut[0].reference_px.y(), 16.5, 1.0);
  EXPECT_NEAR(cut[0].major_extent_px, 34.0, 1.0);
  EXPECT_NEAR(cut[2].reference_px.x(), 16.5, 1.0);
}

TEST(CornerVerification, ABarCutByTheBorderHasACornerAtItsOwnEndOnly) {
  // A bar whose top end the image's upper border cuts: no corner there (the response sees the bar
  // go on), a clear one at its bottom end.
  cv::Mat image(120, 120, CV_8UC3, kDoorBgr);
  image(cv::Rect(50, 0, 4, 40)).setTo(kBrassBgr);
  add_noise(image, 29);
  const Blob blob = colour_blob(image, kBrassBgr, 12.0, cv::Rect(0, 0, 120, 120));
  const BlobAxes axes = blob_axes(blob);
  // Which end of the major axis is the top one (the cut one).
  const int top_end = (blob.centroid_px + axes.a_min_px * blob.major_axis).y() <
                              (blob.centroid_px + axes.a_max_px * blob.major_axis).y()
                          ? 0
                          : 1;
  const CornerVerificationParameters parameters;
  EXPECT_FALSE(verify_handle_corners(image, blob, axes, parameters).accepted);
  EXPECT_TRUE(verify_handle_corners(image, blob, axes, parameters, top_end).accepted);
  EXPECT_FALSE(verify_handle_corners(image, blob, axes, parameters, 1 - top_end).accepted);
}

TEST(Recognizers, DoorsCutAtAnImageCornerAreCornerCutDetections) {
  // A door panel that the bottom and the left border cut: its one real corner is the top right;
  // the corners on the cut sides where its top edge and right side leave the image, the last the
  // image's corner.
  cv::Mat image(240, 320, CV_8UC3, kWallBgr);
  const cv::Scalar door_bgr = kDoorBgr * 0.62;
  const cv::Rect corner(0, 130, 70, 110);
  image(corner).setTo(door_bgr);
  add_noise(image, 23);
  const std::vector<Blob> blobs{colour_blob(image, door_bgr, 12.0, corner)};
  EXPECT_TRUE(synthetic_door_detections(image, blobs, false).empty());
  const std::vector<Detection> out = synthetic_door_detections(image, blobs, true);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].border_cut, BorderCut::kBottomLeft);
  const std::vector<Eigen::Vector2d>& c = out[0].corners_px;
  ASSERT_EQ(c.size(), 4u);
  EXPECT_DOUBLE_EQ(c[0].x(), -0.5);  // the top edge at the left border
  EXPECT_NEAR(c[0].y(), 129.5, 1.0);
  EXPECT_NEAR(c[1].x(), 69.5, 1.0);  // the real corner
  EXPECT_NEAR(c[1].y(), 129.5, 1.0);
  EXPECT_NEAR(c[2].x(), 69.5, 1.0);  // the right side at the bottom border
  EXPECT_DOUBLE_EQ(c[2].y(), 239.5);
  EXPECT_EQ(c[3], Eigen::Vector2d(-0.5, 239.5));
  EXPECT_NEAR((out[0].reference_px - c[1]).norm(), 0.0, 1e-9);
  EXPECT_NEAR(out[0].height_px, 110.0, 1.5);
}

TEST(Recognizers, ABorderCutDoorWithASteepTopEdgeIsNumberedFromItsCut) {
  // Seen from the side and above, the top edge of a door cut by the lower border climbs 60 px
  // over its 40: its top right corner, not its top left, has the least u + v, where the outline's
  // clockwise numbering starts (quadrilateral.hpp). The cut (bottom) side is still corners 2-3.
  cv::Mat image(240, 320, CV_8UC3, kWallBgr);
  const cv::Scalar door_bgr = kDoorBgr * 0.62;
  const std::vector<cv::Point> outline{{150, 150}, {190, 90}, {190, 239}, {150, 239}};
  cv::fillConvexPoly(image, outline, door_bgr);
  add_noise(image, 19);
  const std::vector<Blob> blobs{colour_blob(image, door_bgr, 12.0, cv::Rect(0, 0, 320, 240))};
  const std::vector<Detection> out = synthetic_door_detections(image, blobs, true);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].border_cut, BorderCut::kBottom);
  const std::vector<Eigen::Vector2d>& c = out[0].corners_px;
  EXPECT_NEAR(c[0].x(), 149.5, 1.5);  // top left
  EXPECT_NEAR(c[0].y(), 150.0, 1.5);
  EXPECT_NEAR(c[1].x(), 190.5, 1.5);  // top right
  EXPECT_NEAR(c[1].y(), 89.5, 1.5);
  EXPECT_DOUBLE_EQ(c[2].y(), 239.5);  // where the sides leave the image
  EXPECT_DOUBLE_EQ(c[3].y(), 239.5);
}

TEST(Recognizers, ModelMustMatchTheDescriptor) {
  const GaussianClassModel handle_model =
      read_recognizer_file("config/recognition/handle.yaml").model;
  EXPECT_THROW(DoorRecognizer(handle_model, {}), std::invalid_argument);
  const GaussianClassModel door_model = read_recognizer_file("config/recognition/door.yaml").model;
  EXPECT_THROW(HandleRecognizer(door_model, {}), std::invalid_argument);
}

// --- Recognizers on rendered kitchen views ---------------------------------------------------

// The ground-truth blob of every whole, sizeable object of `type` in the left image: the pixels
// its id buffer shows, when it is not cut by the image border and not much hidden (at least
// `min_solidity` of its convex hull is its own: a chair in front of a door cuts a notch).
std::vector<Blob> ground_truth_blobs(const test::StereoView& view, const world::WorldModel& world,
                                     const std::string& type, int min_px, double min_solidity) {
  std::vector<Blob> out;
  const cv::Mat& ids = view.left.object_ids;
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    if (world.objects[i].type != type) continue;
    const cv::Mat mask = ids == static_cast<int>(i);
    if (cv::countNonZero(mask) < min_px) continue;
    Blob blob = make_blob(runs_from_mask(mask), view.left.image);
    if (blob.u_min < 2 || blob.v_min < 2 || blob.u_max > ids.cols - 3 ||
        blob.v_max > ids.rows - 3) {
      continue;
    }
    std::vector<cv::Point> points, hull;
    cv::findNonZero(mask, points);
    cv::convexHull(points, hull);
    // The hull runs through pixel centres: add half a pixel all round (perimeter / 2 + 1).
    const double hull_px = cv::contourArea(hull) + 0.5 * cv::arcLength(hull, true) + 1.0;
    if (blob.area_px < min_solidity * hull_px) continue;
    out.push_back(std::move(blob));
  }
  return out;
}

TEST(Recognizers, RenderedKitchenGroundTruthBlobs) {
  // Fits both models to the ground-truth blobs of 48 views from a grid of robot poses (the shipped
  // models are trained on segmented blobs by vsl-train-recognition and change), then recognizes
  // the ground-truth blobs of the fixed views, which the grid does not contain.
  const test::StereoViews& views = test::StereoViews::kitchen();
  std::vector<Eigen::VectorXd> door_samples, handle_samples;
  const DoorRecognizerParameters door_parameters;
  const HandleRecognizerParameters handle_parameters;
  std::uint64_t seed = 100;
  for (const double x : {1.6, 3.4, 4.2}) {
    for (const double y : {0.8, 2.8}) {
      for (double yaw = 0.0; yaw < 360.0; yaw += 45.0) {
        const test::StereoView view = views.render(x, y, yaw, 0.0, 0.2, seed++);
        for (const Blob& blob : ground_truth_blobs(view, views.world(), "door", 600, 0.9)) {
          door_samples.push_back(door_descriptor(blob, door_parameters.ideal_colour_rgb));
        }
        for (const Blob& blob : ground_truth_blobs(view, views.world(), "handle", 20, 0.0)) {
          handle_samples.push_back(handle_descriptor(blob, handle_parameters.ideal_colour_rgb));
        }
      }
    }
  }
  RecordProperty("door_samples", static_cast<int>(door_samples.size()));
  ASSERT_GT(door_samples.size(), 20u);
  ASSERT_GT(handle_samples.size(), 40u);
  std::vector<std::unique_ptr<ClassRecognizer>> recognizers;
  recognizers.push_back(std::make_unique<DoorRecognizer>(
      fit_class_model("door", door_descriptor_names(), door_samples, default_fit_options("door")),
      door_parameters));
  recognizers.push_back(std::make_unique<HandleRecognizer>(
      fit_class_model("handle", handle_descriptor_names(), handle_samples,
                      default_fit_options("handle")),
      handle_parameters));
  int doors = 0, doors_found = 0, handles = 0, handles_found = 0, drawers = 0, drawers_as_door = 0;
  for (int i = 0; i < test::StereoViews::fixed_view_count(); ++i) {
    const test::StereoView view = views.fixed_view(i, static_cast<std::uint64_t>(i));
    const auto door_blobs = ground_truth_blobs(view, views.world(), "door", 600, 0.9);
    const auto handle_blobs = ground_truth_blobs(view, views.world(), "handle", 20, 0.0);
    const auto drawer_blobs = ground_truth_blobs(view, views.world(), "drawer_front", 600, 0.9);
    std::vector<Detection> out;
    recognizers[0]->recognize(view.left.image, door_blobs, out);
    doors += static_cast<int>(door_blobs.size());
    doors_found += static_cast<int>(out.size());
    out.clear();
    recognizers[0]->recognize(view.left.image, drawer_blobs, out);
    drawers += static_cast<int>(drawer_blobs.size());
    drawers_as_door += static_cast<int>(out.size());
    out.clear();
    recognizers[1]->recognize(view.left.image, handle_blobs, out);
    handles += static_cast<int>(handle_blobs.size());
    handles_found += static_cast<int>(out.size());
  }
  RecordProperty("doors", doors);
  RecordProperty("handles", handles);
  RecordProperty("doors_found", doors_found);
  RecordProperty("handles_found", handles_found);
  RecordProperty("drawers", drawers);
  RecordProperty("drawers_as_door", drawers_as_door);
  ASSERT_GT(doors, 5);
  ASSERT_GT(handles, 5);
  EXPECT_GE(doors_found, 0.85 * doors) << doors_found << " of " << doors;
  EXPECT_GE(handles_found, 0.9 * handles) << handles_found << " of " << handles;
  EXPECT_LE(drawers_as_door, 0.05 * drawers + 0.5) << drawers_as_door << " of " << drawers;
}

}  // namespace
}  // namespace vsl::recognition
