// Fusion of one scan (paper §2.1.1): isolated percepts rejected (varpi), per-type mean shift in
// 3D over the kept ones, T_s per mode from the frames' camera poses and the field of view, the
// confidence criterion Eq. 4, and the fused percepts H_f.
//
// Eq. 4 per view. The frames of one view (the scan, or one active look after it: Frame::view)
// look at a place from one robot pose and nearly one head pose, so a recognizer that misses an
// object there misses it in most of them: their misses are not independent trials, and a look
// steeply up at wall cupboards, which cuts a door seen whole in the scan at the image border,
// would otherwise outvote the scan's detections of it. A mode passes when C_v / max(T_v - iota,
// 1) > E_min in some view v (C_v, T_v its frames and expected frames in v); its location and
// covariance use every supporting frame of every view. One view (no active look): the paper's
// Eq. 4 unchanged.
//
// Fused location and covariance of a mode with supporting percepts (x_i, Sigma_i), i = 1..n.
// Each percept's error is a part b shared by every frame of the scan and a part e_i of its own.
// The recognizer sets the shared part of each: B_i = s^2 I + s_ray^2 r r^T (Percept::
// shared_sigma_m and shared_ray_sigma_m, r the unit ray from the frame's left camera to the
// percept: a disparity bias acts along it); the mode's B is the B_i of least trace (what all of
// them share is at most what the least of them claims):
//   x_i = x_true + b + e_i,   Sigma_i = B + E_i,   E_i = Sigma_i - B
// (E_i's eigenvalues kept at or above 1e-8 m^2).
// The percepts of consecutive frames may scatter more than their own parts say (they share one
// calibration and one ego-mapping; a noise model that gives a door's whole error across the ray
// to b leaves E_i an error along the ray alone, while the box still jitters across it). That
// excess is an error u_i of every percept's own, isotropic, of variance tau^2 estimated from the
// mode's scatter (the Paule-Mandel estimator of random-effects meta-analysis):
//   W_i = (E_i + tau^2 I)^-1,   Sigma_e = (sum_i W_i)^-1,   x = Sigma_e sum_i W_i x_i,
//   chi2(tau^2) = sum_i (x_i - x)^T W_i (x_i - x)   (b cancels in x_i - x),
//   tau^2 = 0 when chi2(0) <= 3 (n - 1), else the root of chi2(tau^2) = 3 (n - 1),
//   Sigma = Sigma_e + B.
// Without the excess, a door's percepts seen along rays a few centimetres apart would be
// intersected as exact lines across them and meet metres along the ray; with it, the mean stays
// among the percepts and the covariance covers their scatter. With B = 0 and consistent percepts
// this is the information-weighted mean of the Sigma_i.
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

// Fuses every frame of one scan and its active looks. Percepts must be valid (finite, covariance
// symmetric positive definite): the daemon checks its input.
FusionResult fuse(const std::vector<Frame>& frames, const FieldOfView& field_of_view,
                  const FusionOptions& options);

// Eq. 4 with iota: C / max(T_s - iota, 1) > E_min.
bool passes_confidence(int support, int expected, const FusionOptions& options);

}  // namespace vsl::fusion
