// Pictures of evaluated frames (frame_dump.hpp).
#include "frame_dump.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace vsl::tools {
namespace {

// Pinhole projection of a left-camera point (distortion ignored: a picture, not a measurement).
bool project(const head::CameraIntrinsics& k, const Eigen::Vector3d& p, cv::Point& out) {
  if (p.z() <= 1e-3) return false;
  out = cv::Point(static_cast<int>(std::lround(k.fx_px * p.x() / p.z() + k.cx_px)),
                  static_cast<int>(std::lround(k.fy_px * p.y() / p.z() + k.cy_px)));
  return true;
}

// Blobs outlined (grey), detections' boxes (yellow; a learned detector's handles orange), door
// outlines' quadrilaterals (magenta).
void draw_blobs(cv::Mat& picture, const std::vector<recognition::Blob>& blobs,
                const std::vector<recognition::Detection>& detections) {
  for (const recognition::Blob& blob : blobs) {
    cv::Mat mask(picture.size(), CV_8U, cv::Scalar(0));
    for (const recognition::PixelRun& run : blob.runs) {
      mask.row(run.v).colRange(run.u_begin, run.u_end).setTo(255);
    }
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    cv::drawContours(picture, contours, -1, cv::Scalar(160, 160, 160), 1);
  }
  for (const recognition::Detection& d : detections) {
    // A learned detection has no blob: its box is its outline (doors yellow, the rest orange).
    if (d.blob_index < 0 && d.corners_px.size() == 4) {
      const cv::Scalar colour =
          d.type == "door" ? cv::Scalar(0, 220, 255) : cv::Scalar(0, 140, 255);
      cv::rectangle(
          picture,
          cv::Point(int(std::lround(d.corners_px[0].x())), int(std::lround(d.corners_px[0].y()))),
          cv::Point(int(std::lround(d.corners_px[2].x())), int(std::lround(d.corners_px[2].y()))),
          colour, 1);
      continue;
    }
    if (d.blob_index < 0 || d.blob_index >= static_cast<int>(blobs.size())) continue;
    const recognition::Blob& b = blobs[static_cast<std::size_t>(d.blob_index)];
    cv::rectangle(picture, cv::Point(b.u_min, b.v_min), cv::Point(b.u_max, b.v_max),
                  cv::Scalar(0, 220, 255), 1);
    // The outline the recognizer judged (also for a door cut by the image border).
    if (d.corners_px.size() == 4) {
      for (std::size_t i = 0; i < 4; ++i) {
        const Eigen::Vector2d& a = d.corners_px[i];
        const Eigen::Vector2d& c = d.corners_px[(i + 1) % 4];
        cv::line(picture, cv::Point(int(std::lround(a.x())), int(std::lround(a.y()))),
                 cv::Point(int(std::lround(c.x())), int(std::lround(c.y()))),
                 cv::Scalar(255, 0, 255), 1);
      }
    }
  }
}

}  // namespace

bool write_frame_dump(const std::string& path, const cv::Mat& left_bgr,
                      const head::CameraIntrinsics& left_intrinsics,
                      const recognition::FrameResult& result,
                      const std::vector<recognition::GroundTruthObject>& ground_truth,
                      const std::vector<recognition::PerceptMatch>& matches) {
  cv::Mat picture = left_bgr.clone();
  draw_blobs(picture, result.left_blobs, result.left_detections);
  // Why a pair of learned detections was refused, at its left box's top left corner.
  for (const recognition::StereoRefusal& refusal : result.stereo_refusals) {
    if (refusal.left_detection < 0 ||
        refusal.left_detection >= static_cast<int>(result.left_detections.size())) {
      continue;
    }
    const recognition::Detection& d =
        result.left_detections[static_cast<std::size_t>(refusal.left_detection)];
    if (d.corners_px.empty()) continue;
    const cv::Point at(int(std::lround(d.corners_px[0].x())) + 2,
                       int(std::lround(d.corners_px[0].y())) + 10);
    cv::putText(picture, refusal.reason, at, cv::FONT_HERSHEY_PLAIN, 0.8, cv::Scalar(0, 0, 255), 1);
  }
  const Eigen::Isometry3d left_T_ego = result.ego_T_left_camera.inverse();
  for (const recognition::GroundTruthObject& object : ground_truth) {
    cv::Point p;
    if (object.visible && project(left_intrinsics, left_T_ego * object.ego_position_m, p)) {
      cv::circle(picture, p, 6, cv::Scalar(255, 80, 0), 2);
    }
  }
  for (std::size_t i = 0; i < result.percepts.size(); ++i) {
    cv::Point p;
    if (!project(left_intrinsics, left_T_ego * result.percepts[i].ego_position_m, p)) continue;
    const bool hit = i < matches.size() && matches[i].ground_truth >= 0;
    cv::drawMarker(picture, p, hit ? cv::Scalar(0, 200, 0) : cv::Scalar(0, 0, 255),
                   cv::MARKER_CROSS, 10, 2);
  }
  try {
    return cv::imwrite(path, picture);
  } catch (const cv::Exception&) {
    return false;
  }
}

bool write_right_dump(const std::string& path, const cv::Mat& right_bgr,
                      const recognition::FrameResult& result) {
  cv::Mat picture = right_bgr.clone();
  draw_blobs(picture, result.right_blobs, result.right_detections);
  try {
    return cv::imwrite(path, picture);
  } catch (const cv::Exception&) {
    return false;
  }
}

}  // namespace vsl::tools
