// Fusion of one scan (paper §2.1.1): isolated percepts rejected (varpi), per-type mean shift in
// 3D over the kept ones, T_s per mode from the frames' camera poses and the field of view, the
// confidence criterion Eq. 4, and the fused percepts H_f.
//
// Fused location and covariance of a mode with supporting percepts (x_i, Sigma_i), i = 1..n:
//   information-weighted mean   Sigma = (sum_i Sigma_i^-1)^-1,  x = Sigma sum_i Sigma_i^-1 x_i
//   scaled by the reduced chi-square when the percepts scatter more than their covariances say:
//   chi2 = sum_i (x_i - x)^T Sigma_i^-1 (x_i - x),  Sigma *= max(1, chi2 / (3 (n - 1)))  (n > 1).
// The percepts of consecutive frames are not independent (one calibration, one ego-mapping), so
// the unscaled information sum would be overconfident whenever they disagree; the scale keeps the
// covariance at least as large as the scatter of the mean.
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
