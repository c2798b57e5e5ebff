// How simulated percepts go wrong: the positional noise of paper Eq. 7, misses, and false
// positives (a real object reported with a wrong type, or a recognition where there is nothing).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>

#include "vsl/localization/localizer.hpp"
#include "vsl/scenario/random.hpp"
#include "vsl/scenario/visibility.hpp"

namespace vsl::scenario {

struct PerceptErrorOptions {
  // Each percept written is a false positive with this probability (so about this fraction of a
  // file's percepts are false), in [0, 0.9].
  double false_positive_rate = 0.1;
  // Of the false positives, this fraction reports a seen object with a wrong type; the others are
  // spurious recognitions on a surface somewhere in the scanned view.
  double wrong_type_fraction = 0.5;
  // Each visible object is missed (not recognized in enough frames to pass Eq. 4) with this
  // probability, in [0, 1].
  double miss_rate = 0.2;
  // Write each percept's covariance (sigma^2 I of Eq. 7) into the file; off, the localizer applies
  // its own Eq. 7 model, as it does for percepts without covariance.
  bool write_covariance = false;
};

// Eq. 7: the standard deviation (m, per axis) of a percept at `ego_point_m`,
// ||X - C_L||^2 / zeta, never below the configured floor.
double eq7_sigma_m(const Eigen::Vector3d& ego_point_m,
                   const localization::PerceptNoiseOptions& noise);

// `ego_point_m` plus isotropic Gaussian noise of the Eq. 7 deviation.
Eigen::Vector3d with_eq7_noise(const Eigen::Vector3d& ego_point_m,
                               const localization::PerceptNoiseOptions& noise, Rng& rng);

// Where a spurious recognition lands (ego frame): along a uniformly drawn line of sight within a
// uniformly drawn scan position, the first surface within the stereo range, else (nothing there:
// a window, an open door) a uniform distance in that range. `nearby` from
// head.primitives_near(world_T_ego).
Eigen::Vector3d spurious_ego_point(const HeadModel& head, const Eigen::Isometry3d& world_T_ego,
                                   std::span<const std::uint32_t> nearby, Rng& rng);

}  // namespace vsl::scenario
