// The top-down map: the world model's footprints and, over them, what the pipeline knows (fused
// percepts, hypotheses, gaze target, pose estimate with its covariance, ground truth). Plain values
// in, cv::Mat (CV_8UC3, BGR) out; no LCM here.
// Frames: world x to the right of the picture, world y up; the map is a vertical projection onto
// the floor (z ignored).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::view {

// World (metres) to map pixels. The caption strip sits above the drawn area.
struct MapFrame {
  double px_per_m = 100.0;
  Eigen::Vector2d world_min_m = Eigen::Vector2d::Zero();  // world x, y at the bottom-left corner
  int margin_px = 40;                                     // around the world's bounding box
  int caption_px = 84;                                    // caption strip above the map
  int width_px = 0;                                       // whole image
  int height_px = 0;

  // Pixel (u right, v down) of a world point's floor projection.
  cv::Point2d to_pixel(const Eigen::Vector2d& world_xy_m) const;
};

// A frame that fits every object of `world` except the ceiling (whose footprint is the whole room).
MapFrame map_frame_for(const world::WorldModel& world, double px_per_m);

// The world alone: floor, then footprints sorted by height (what is higher hides what is lower, as
// seen from above), doors and handles in their type colours on top, and a metric scale bar. Drawn
// once; the overlay is drawn on a copy for every picture.
cv::Mat draw_world(const world::WorldModel& world, const MapFrame& frame);

// The scale bar: a round length (0.5, 1, 2 or 5 m) spanning roughly a sixth of the map, drawn from
// `start_px` to `end_px` (same row) at the bottom-left.
struct ScaleBar {
  double length_m = 1.0;
  cv::Point start_px;
  cv::Point end_px;
};
ScaleBar scale_bar_for(const MapFrame& frame);

struct FusedPercept {
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d ego_covariance_m2 = Eigen::Matrix3d::Zero();
  // Whether the pose estimate associated it with a world object; unknown before an estimate.
  // Unmatched percepts (false positives, objects missing from the model) are drawn hollow.
  enum class Match { kUnknown, kMatched, kUnmatched } match = Match::kUnknown;
};

struct Hypothesis {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  double score = 0.0;
};

// What the pipeline knows, in plain values.
struct MapOverlay {
  std::optional<Eigen::Isometry3d> world_T_ego_estimate;
  // Covariance of the estimate, (x, y, z, roll, pitch, yaw), m^2 / rad^2 (pose_estimate_t).
  std::optional<Eigen::Matrix<double, 6, 6>> estimate_covariance;
  std::optional<Eigen::Isometry3d> world_T_ego_truth;
  std::vector<Hypothesis> hypotheses;  // ranked best first
  std::vector<FusedPercept> fused_percepts;
  std::optional<Eigen::Vector3d> ego_gaze_target_m;
  std::vector<std::string> caption;  // lines of text in the caption strip
};

// The pose through which ego-frame things (fused percepts, gaze target) are drawn: the estimate
// when there is one, else the ground truth, else none (they are then not drawn).
std::optional<Eigen::Isometry3d> drawing_pose(const MapOverlay& overlay);

// Robot footprint radius on the map, metres (an ARMAR-III-sized mobile base).
inline constexpr double kRobotRadiusM = 0.35;

// `world_picture` (from draw_world with the same frame) with the overlay; a new image.
cv::Mat draw_map(const cv::Mat& world_picture, const MapFrame& frame, const MapOverlay& overlay);

// Semi-axes (metres) and angle (radians, from world x) of the n-sigma ellipse of a 2x2 covariance.
struct Ellipse2 {
  double major_m = 0.0;
  double minor_m = 0.0;
  double angle_rad = 0.0;
};
Ellipse2 sigma_ellipse(const Eigen::Matrix2d& covariance_m2, double n_sigma);

}  // namespace vsl::view
