// The percepts' position errors split the way stereo makes them (vsl-eval-recognition): across the
// viewing ray, as pixels of the reference point in the left image, and along it, as pixels of
// disparity. Their robust spreads per class are the noise model the learned recognizer's
// covariances take (BoxStereoOptions::reference_sigma_px, disparity_sigma_px), measured here
// against the renderer's ground truth.
#pragma once

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "vsl/recognition/frame_result.hpp"
#include "vsl/recognition/labelling.hpp"

namespace vsl::tools {

class PerceptNoiseTally {
 public:
  // `focal_px`: the left camera's focal length; `baseline_m`: the distance between the cameras.
  PerceptNoiseTally(double focal_px, double baseline_m)
      : focal_px_(focal_px), baseline_m_(baseline_m) {}

  // Adds the error of every true positive of the frame (match_percepts' matches).
  // With e the error in the left camera frame, r the range and n the unit ray to the percept:
  // along the ray e_r = e.n, the disparity error is f B e_r / r^2 (d = f B / z, dd/dz = -f B /
  // z^2, the range standing for the depth z); across it the two components of e - e_r n, times
  // f / r, are pixels of the reference point.
  void add(const std::vector<recognition::GroundTruthObject>& ground_truth,
           const recognition::FrameResult& result,
           const std::vector<recognition::PerceptMatch>& matches);

  // Per class: the true positives, and 1.4826 times the median absolute error (a Gaussian's
  // sigma, robust to the few matched percepts that are half wrong) across and along the ray.
  struct Sigmas {
    std::size_t count = 0;
    double reference_px = 0.0;
    double disparity_px = 0.0;
  };
  std::optional<Sigmas> sigmas(const std::string& type) const;
  void print(std::ostream& out) const;

 private:
  struct Errors {
    std::vector<double> reference_px;  // two per percept (both components across the ray)
    std::vector<double> disparity_px;
  };
  double focal_px_;
  double baseline_m_;
  std::map<std::string, Errors> by_type_;
};

}  // namespace vsl::tools
