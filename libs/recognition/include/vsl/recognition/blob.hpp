// A blob (paper §2.1, Fig. 2-a/b): the pixels of one colour cluster in one raw (unrectified)
// camera image, after region growing and mean-shift clustering of the regions' 5-D features
// F_i = [X_c, K_mean] (Eq. 1), with the statistics every class-specific descriptor is built from.
// Pixel (u, v) = (column, row), pixel centres at integer coordinates (OpenCV's convention).
// Colours are RGB in [0, 1] (linear in the 8-bit grey levels: value / 255).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace cv {
class Mat;
}

namespace vsl::recognition {

// A horizontal run of blob pixels: row v, columns u_begin .. u_end - 1.
struct PixelRun {
  int v = 0;
  int u_begin = 0;
  int u_end = 0;  // one past the last column
};

struct Blob {
  // The blob's pixels, sorted by (v, u_begin), non-overlapping, not touching within a row.
  std::vector<PixelRun> runs;
  // Inclusive bounding box, pixels.
  int u_min = 0;
  int v_min = 0;
  int u_max = -1;
  int v_max = -1;
  double area_px = 0.0;       // S_i: number of pixels
  double perimeter_px = 0.0;  // L_i: length of the outer boundary (4-connected crack length)
  Eigen::Vector2d centroid_px = Eigen::Vector2d::Zero();      // X_c, (u, v)
  Eigen::Matrix2d covariance_px2 = Eigen::Matrix2d::Zero();   // of the pixel positions
  Eigen::Vector3d mean_colour_rgb = Eigen::Vector3d::Zero();  // K_mean
  Eigen::Vector3d min_colour_rgb = Eigen::Vector3d::Zero();   // K_min, per channel
  Eigen::Vector3d max_colour_rgb = Eigen::Vector3d::Zero();   // K_max, per channel
  // Eigen decomposition of covariance_px2: rho_1 >= rho_2 >= 0 (px^2) and their unit
  // eigenvectors (major axis, minor axis) in image coordinates.
  double rho1_px2 = 0.0;
  double rho2_px2 = 0.0;
  Eigen::Vector2d major_axis = Eigen::Vector2d::UnitX();
  Eigen::Vector2d minor_axis = Eigen::Vector2d::UnitY();

  bool empty() const { return runs.empty(); }
  bool contains(int u, int v) const;  // binary search over the runs
};

// Computes every statistic of a blob from its runs (sorted as documented above; throws
// std::invalid_argument otherwise) and the image they index (CV_8UC3, BGR).
Blob make_blob(std::vector<PixelRun> runs, const cv::Mat& bgr_image);

// The runs of the non-zero pixels of `mask` (CV_8U), for tests and for labelled training data.
std::vector<PixelRun> runs_from_mask(const cv::Mat& mask);

}  // namespace vsl::recognition
