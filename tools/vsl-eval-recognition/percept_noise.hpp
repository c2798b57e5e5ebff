// The percepts' position errors split the way stereo makes them (vsl-eval-recognition): across the
// viewing ray and along it. Per class they are fitted by the noise model the learned recognizer's
// covariances take (BoxStereoOptions::noise), measured here against the
// renderer's ground truth.
//
// Model. A percept at range r whose reference point the left image places with error sigma_ref
// pixels and whose disparity has error sigma_d pixels, plus an error of sigma_m metres in any
// direction that does not shrink with the range (where on the object the reference point is
// taken: a handle's bar seen from aside, a door's top hidden by the worktop's lip), has
//   across the ray:  s_a(r)^2 = sigma_m^2 + (sigma_ref r / f)^2          (each of two directions)
//   along the ray:   s_l(r)^2 = sigma_m^2 + (sigma_d r^2 / (f B))^2       (d = f B / z, the range
//                                                                         standing for the depth)
// with f the focal length and B the baseline. Both are linear in (sigma_m^2, sigma_ref^2,
// sigma_d^2). The errors are binned by range (half-metre bins of at least 8 true positives); in
// each bin the robust sigma (1.4826 times the median absolute error: robust to the few matched
// percepts that are half wrong) across and along; then the bins' squared sigmas are fitted by
// least squares, each weighted by its count over its squared sigma squared (the variance of an
// estimated s^2 is about 2 s^4 / n), with the three unknowns non-negative.
#pragma once

#include <Eigen/Core>

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
  void add(const std::vector<recognition::GroundTruthObject>& ground_truth,
           const recognition::FrameResult& result,
           const std::vector<recognition::PerceptMatch>& matches);

  struct Sigmas {
    std::size_t count = 0;      // true positives
    double reference_px = 0.0;  // sigma_ref
    double disparity_px = 0.0;  // sigma_d
    double floor_m = 0.0;       // sigma_m
  };
  // The fitted model of a class; nullopt when it has fewer than two bins of true positives.
  std::optional<Sigmas> sigmas(const std::string& type) const;
  // The median signed error of a class's true positives, metres: across the viewing ray (image
  // right, image down) and along it (away from the camera); nullopt without true positives.
  // The noise model has no bias; one shows here.
  std::optional<Eigen::Vector3d> bias_m(const std::string& type) const;
  // The same in the object's own axes (GroundTruthObject::ego_R_object; a generated kitchen's
  // door: x along its width, y into its front face, z up), metres: where the recognizer puts a
  // class's reference point on the object, whatever the view (a door's top edge found on the
  // worktop's lip above it shows in z, a rail's bar in y).
  std::optional<Eigen::Vector3d> object_bias_m(const std::string& type) const;
  void print(std::ostream& out) const;

 private:
  struct Error {
    double range_m;
    double across_m[2];
    double along_m;
    Eigen::Vector3d object_m;  // percept minus reference point in the object's axes
  };
  // Per axis, the median of `of` over a class's true positives; nullopt without any.
  std::optional<Eigen::Vector3d> median_per_axis(const std::string& type,
                                                 Eigen::Vector3d (*of)(const Error&)) const;
  double focal_px_;
  double baseline_m_;
  std::map<std::string, std::vector<Error>> by_type_;
};

}  // namespace vsl::tools
