// Chessboard views rendered by the simulator's renderer (libs/render), for calibration tests with
// a known camera: a world of black and white boxes (the squares, on a white margin) fixed in the
// world frame, seen by a stereo pair at seeded random poses in front of it.
// Board frame = world frame: origin at the first inner corner, x along a row of corners, y along
// a column, z into the board; the squares' front faces lie in z = 0, facing the camera (-z).
#pragma once

#include <opencv2/core/mat.hpp>

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

#include "chessboard.hpp"
#include "vsl/head/stereo_calibration.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::calibration::testing {

world::WorldModel chessboard_world(const BoardSpec& board);

struct RenderedPair {
  Eigen::Isometry3d board_T_left;  // the left camera's pose in the board frame
  cv::Mat left;                    // CV_8UC3
  cv::Mat right;
};

// `count` views from poses drawn with `seed`: 0.45-0.9 m from the board, tilted up to 35 deg
// about its x and y axes, rolled up to 20 deg, the whole board (with margin) inside both images.
// Rendered with 4x4 area sampling (edges blend as on a real sensor) and the renderer's default
// sensor noise and exposure variation.
std::vector<RenderedPair> render_chessboard_views(const BoardSpec& board,
                                                  const head::StereoCalibration& camera, int count,
                                                  std::uint64_t seed);

}  // namespace vsl::calibration::testing
