// Blob statistics (paper §2.1): area S_i, outer boundary length L_i, centroid X_c, the pixel
// covariance and its eigen decomposition (rho_1, rho_2), and the colour statistics K_mean, K_min,
// K_max that region growing admits pixels by and the handle descriptor (Eq. 3) compares.
#include "vsl/recognition/blob.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vsl::recognition {
namespace {

void check_runs(const std::vector<PixelRun>& runs, const cv::Mat& bgr_image) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PixelRun& run = runs[i];
    if (run.v < 0 || run.v >= bgr_image.rows || run.u_begin < 0 || run.u_end > bgr_image.cols ||
        run.u_begin >= run.u_end) {
      throw std::invalid_argument("make_blob: run " + std::to_string(i) + " is outside the " +
                                  std::to_string(bgr_image.cols) + "x" +
                                  std::to_string(bgr_image.rows) + " image or empty");
    }
    if (i > 0) {
      const PixelRun& previous = runs[i - 1];
      if (run.v < previous.v || (run.v == previous.v && run.u_begin <= previous.u_end)) {
        throw std::invalid_argument("make_blob: runs are not sorted by (v, u) or overlap at run " +
                                    std::to_string(i));
      }
    }
  }
}

// Length of the outer boundary in pixel edges ("crack length"): holes (a handle inside a door)
// are filled first, so that L_i describes the blob's outline, not its contents.
double outer_crack_length(const Blob& blob) {
  const int width = blob.u_max - blob.u_min + 3;  // one pixel of margin on every side
  const int height = blob.v_max - blob.v_min + 3;
  cv::Mat mask(height, width, CV_8U, cv::Scalar(0));
  for (const PixelRun& run : blob.runs) {
    std::uint8_t* row = mask.ptr<std::uint8_t>(run.v - blob.v_min + 1);
    std::fill(row + run.u_begin - blob.u_min + 1, row + run.u_end - blob.u_min + 1,
              std::uint8_t{1});
  }
  // Everything 4-connected to the margin is outside (2); the rest is the blob or its holes.
  cv::floodFill(mask, cv::Point(0, 0), cv::Scalar(2), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
  // A crack between two neighbouring cells of which one is outside: count the cells that differ
  // from their right and from their lower neighbour (whole-image operations, vectorized by
  // OpenCV; per cell this loop was the largest part of make_blob for wall-sized blobs).
  cv::Mat outside, differ;
  cv::compare(mask, cv::Scalar(2), outside, cv::CMP_EQ);
  cv::compare(outside.colRange(0, width - 1), outside.colRange(1, width), differ, cv::CMP_NE);
  double length = cv::countNonZero(differ);
  cv::compare(outside.rowRange(0, height - 1), outside.rowRange(1, height), differ, cv::CMP_NE);
  length += cv::countNonZero(differ);
  return length;
}

}  // namespace

bool Blob::contains(int u, int v) const {
  // First run not before (v, u): the candidate is it or the one before it.
  auto it = std::upper_bound(runs.begin(), runs.end(), std::make_pair(v, u),
                             [](const std::pair<int, int>& key, const PixelRun& run) {
                               return key.first < run.v ||
                                      (key.first == run.v && key.second < run.u_begin);
                             });
  if (it == runs.begin()) return false;
  --it;
  return it->v == v && u >= it->u_begin && u < it->u_end;
}

Blob make_blob(std::vector<PixelRun> runs, const cv::Mat& bgr_image) {
  if (bgr_image.type() != CV_8UC3) {
    throw std::invalid_argument("make_blob: the image must be CV_8UC3 (BGR)");
  }
  check_runs(runs, bgr_image);
  Blob blob;
  blob.runs = std::move(runs);
  if (blob.runs.empty()) return blob;

  // One pass: sums of positions, their squares and the colours; the bounding box. Positions in
  // closed form per run (a run is an arithmetic series of columns in one row), colours per pixel
  // in integer grey levels.
  double count = 0.0;
  double su = 0.0, sv = 0.0, suu = 0.0, suv = 0.0, svv = 0.0;
  std::int64_t colour_sum_grey[3] = {0, 0, 0};  // R, G, B
  int colour_min_grey[3] = {255, 255, 255};
  int colour_max_grey[3] = {0, 0, 0};
  blob.u_min = blob.runs.front().u_begin;
  blob.u_max = blob.runs.front().u_end - 1;
  blob.v_min = blob.runs.front().v;
  blob.v_max = blob.runs.back().v;
  for (const PixelRun& run : blob.runs) {
    blob.u_min = std::min(blob.u_min, run.u_begin);
    blob.u_max = std::max(blob.u_max, run.u_end - 1);
    const double n = run.u_end - run.u_begin;
    const double first = run.u_begin;
    const double last = run.u_end - 1;
    const double sum_u = n * (first + last) / 2.0;
    // Sum of u^2 over first..last: S(last) - S(first - 1), S(k) = k (k + 1) (2k + 1) / 6.
    const auto squares = [](double k) { return k * (k + 1.0) * (2.0 * k + 1.0) / 6.0; };
    const double v = run.v;
    su += sum_u;
    sv += n * v;
    suu += squares(last) - squares(first - 1.0);
    suv += sum_u * v;
    svv += n * v * v;
    const std::uint8_t* row = bgr_image.ptr<std::uint8_t>(run.v);
    for (int u = run.u_begin; u < run.u_end; ++u) {
      const std::uint8_t* bgr = row + 3 * u;
      for (int c = 0; c < 3; ++c) {
        const int value = bgr[2 - c];
        colour_sum_grey[c] += value;
        colour_min_grey[c] = std::min(colour_min_grey[c], value);
        colour_max_grey[c] = std::max(colour_max_grey[c], value);
      }
    }
    count += n;
  }
  const Eigen::Vector2d sum(su, sv);
  Eigen::Matrix2d sum_squares;
  sum_squares << suu, suv, suv, svv;
  const Eigen::Vector3d colour_sum(static_cast<double>(colour_sum_grey[0]) / 255.0,
                                   static_cast<double>(colour_sum_grey[1]) / 255.0,
                                   static_cast<double>(colour_sum_grey[2]) / 255.0);
  const Eigen::Vector3d colour_min(colour_min_grey[0] / 255.0, colour_min_grey[1] / 255.0,
                                   colour_min_grey[2] / 255.0);
  const Eigen::Vector3d colour_max(colour_max_grey[0] / 255.0, colour_max_grey[1] / 255.0,
                                   colour_max_grey[2] / 255.0);
  blob.area_px = count;
  blob.centroid_px = sum / count;
  blob.covariance_px2 = sum_squares / count - blob.centroid_px * blob.centroid_px.transpose();
  blob.mean_colour_rgb = colour_sum / count;
  blob.min_colour_rgb = colour_min;
  blob.max_colour_rgb = colour_max;

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(blob.covariance_px2);
  // Eigenvalues come in increasing order.
  blob.rho1_px2 = std::max(0.0, eigen.eigenvalues()(1));
  blob.rho2_px2 = std::max(0.0, eigen.eigenvalues()(0));
  blob.major_axis = eigen.eigenvectors().col(1).normalized();
  blob.minor_axis = eigen.eigenvectors().col(0).normalized();
  blob.perimeter_px = outer_crack_length(blob);
  return blob;
}

std::vector<PixelRun> runs_from_mask(const cv::Mat& mask) {
  if (mask.type() != CV_8U) throw std::invalid_argument("runs_from_mask: the mask must be CV_8U");
  std::vector<PixelRun> runs;
  for (int v = 0; v < mask.rows; ++v) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(v);
    int u = 0;
    while (u < mask.cols) {
      while (u < mask.cols && row[u] == 0) ++u;
      if (u == mask.cols) break;
      const int begin = u;
      while (u < mask.cols && row[u] != 0) ++u;
      runs.push_back({v, begin, u});
    }
  }
  return runs;
}

}  // namespace vsl::recognition
