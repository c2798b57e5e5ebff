#include "debug_image.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace vsl::recognition_daemon {
namespace {

// A 20x10 blob at (30..49, 20..29) detected as a door, with its percept at the centre.
recognition::FrameResult one_door(const cv::Mat& image) {
  std::vector<recognition::PixelRun> runs;
  for (int v = 20; v < 30; ++v) runs.push_back({v, 30, 50});
  recognition::FrameResult result;
  result.left_blobs.push_back(recognition::make_blob(runs, image));
  recognition::Detection detection;
  detection.type = "door";
  detection.blob_index = 0;
  detection.reference_px = result.left_blobs[0].centroid_px;
  detection.confidence = 0.8f;
  result.left_detections.push_back(detection);
  recognition::FramePercept percept;
  percept.type = "door";
  percept.left_px = detection.reference_px;
  percept.ego_position_m = Eigen::Vector3d(2, 0, 1.5);
  result.percepts.push_back(percept);
  return result;
}

TEST(RecognitionDebugImage, OutlinesBlobsAndMarksDetectionsAndPercepts) {
  const cv::Mat left(60, 80, CV_8UC3, cv::Scalar(0, 0, 0));
  const recognition::FrameResult result = one_door(left);
  const cv::Mat drawn = draw_debug_image(left, result, 5, 12.5);
  ASSERT_EQ(drawn.size(), left.size());
  ASSERT_EQ(drawn.type(), CV_8UC3);
  EXPECT_EQ(cv::countNonZero(left.reshape(1)), 0);  // the input is not drawn on
  // The blob's inside stays as it was away from the marks; its corner pixel is on the outline
  // (or under the detection box drawn over it).
  EXPECT_NE(drawn.at<cv::Vec3b>(20, 30), cv::Vec3b(0, 0, 0));
  EXPECT_NE(drawn.at<cv::Vec3b>(29, 49), cv::Vec3b(0, 0, 0));
  // The percept mark at the centroid (39.5, 24.5) has the door colour.
  const cv::Scalar door = type_colour("door");
  EXPECT_EQ(drawn.at<cv::Vec3b>(25, 40),
            cv::Vec3b(cv::saturate_cast<uchar>(door[0]), cv::saturate_cast<uchar>(door[1]),
                      cv::saturate_cast<uchar>(door[2])));
  // Far from everything: untouched.
  EXPECT_EQ(drawn.at<cv::Vec3b>(55, 75), cv::Vec3b(0, 0, 0));
}

TEST(RecognitionDebugImage, ClassColoursDiffer) {
  EXPECT_NE(type_colour("door"), type_colour("handle"));
  EXPECT_EQ(type_colour("window"), type_colour("window"));
}

TEST(RecognitionDebugImage, BadBlobIndicesAreNotDrawn) {
  const cv::Mat left(60, 80, CV_8UC3, cv::Scalar(0, 0, 0));
  recognition::FrameResult result = one_door(left);
  result.left_detections[0].blob_index = 7;
  EXPECT_NO_THROW(draw_debug_image(left, result, 1, 1.0));
}

}  // namespace
}  // namespace vsl::recognition_daemon
