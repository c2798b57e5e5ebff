// Fusion of one scan (paper §2.1.1): isolated percepts rejected (varpi), per-type mean shift in
// 3D over the kept ones, T_s per mode from the frames' camera poses and the field of view, the
// confidence criterion Eq. 4, and the fused percepts H_f.
//
// Fused location and covariance of a mode with supporting percepts (x_i, Sigma_i), i = 1..n.
// Each percept's error is a part b shared by every frame of the scan (covariance B = s^2 I, s the
// smallest Percept::shared_sigma_m of the mode's percepts, which the recognizer sets) and a part
// e_i of its own:
//   x_i = x_true + b + e_i,   Sigma_i = B + E_i,   E_i = Sigma_i - B
// (E_i's eigenvalues kept at or above 1e-8 m^2).
// The best linear estimate of x_true + b weighs the percepts by E_i^-1; b stays in it:
//   Sigma_e = (sum_i E_i^-1)^-1,   x = Sigma_e sum_i E_i^-1 x_i,   Sigma = Sigma_e + B,
// Sigma_e scaled first by the reduced chi-square when the percepts scatter more than their own
// parts say (b cancels in x_i - x):
//   chi2 = sum_i (x_i - x)^T E_i^-1 (x_i - x),  Sigma_e *= max(1, chi2 / (3 (n - 1)))  (n > 1).
// The percepts of consecutive frames are not independent (one calibration, one ego-mapping), so
// the unscaled information sum would be overconfident whenever they disagree; the scale keeps the
// covariance at least as large as the scatter of the mean. With B = 0 this is the
// information-weighted mean of the Sigma_i.
#pragma once

#include <cstddef>
#include <vector>

#include "vsl/fusion/field_of_view.hpp"
#include "vsl/fusion/fusion_options.hpp"
#include "vsl/fusion/percept.hpp"

namespace vsl::fusion {

struct FusionResult {
  // H_f: the modes that pass Eq. 4, by type name, then by decreasing support, then x, y, z.
  std::vector<FusedPercept> fused;
  // Modes that failed Eq. 4 (same order), for logs and tests.
  std::vector<FusedPercept> rejected;
  std::size_t num_frames = 0;
  std::size_t num_percepts = 0;
  std::size_t num_isolated = 0;  // percepts rejected by the varpi test
};

// Fuses every frame of one scan. Percepts must be valid (finite, covariance symmetric positive
// definite): the daemon checks its input.
FusionResult fuse(const std::vector<Frame>& frames, const FieldOfView& field_of_view,
                  const FusionOptions& options);

// Eq. 4 with iota: C / max(T_s - iota, 1) > E_min.
bool passes_confidence(int support, int expected, const FusionOptions& options);

}  // namespace vsl::fusion
