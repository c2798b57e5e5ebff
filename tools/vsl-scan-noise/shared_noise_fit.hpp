// The part of the percepts' error that every frame of one scan shares, fitted per class from
// recorded scans (scan_frames.hpp) against the world's objects: what fusion must not average
// down (percept_t.shared_sigma_m and shared_ray_sigma_m; docs/fusion.md), and which the
// recognizers' configs claim as `floor_m` and `shared_disparity_px`.
//
// Model. The percepts i = 1..n of one object o in one scan (one robot pose; the frames differ by
// the head's gaze) have errors e_i = b + n_i in the ego frame: b shared by the scan's frames, with
// covariance B = s^2 I + s_r^2 r r^T (r the unit ray from the camera to the object: s is
// isotropic, the reference point's place on the object; s_r a further part along the ray, a
// disparity bias that every frame of the scan makes alike), and n_i each frame's own,
// independent between frames. The shared disparity in pixels is s_d = s_r f B / z^2 at range z
// (f the focal length in pixels, B the baseline: d = f B / z), the same at every range.
//
// Estimation by the method of moments, per (scan, object) group with n >= min_percepts:
//   across the ray: a_i = (I - r_i r_i^T) e_i; the group mean a and the within scatter
//     w = sum |a_i - a|^2 / (n - 1) (an unbiased estimate of the own part's trace across the
//     ray) give E[|a|^2] = 2 s^2 + E[w] / n, so
//       s^2 = mean over groups of (|a|^2 - w / n) / 2;
//   along the ray, as disparity errors delta_i = f B (1 / (z_i + e_i . r_i) - 1 / z_i) (positive:
//     placed nearer than the object), with the group mean delta and scatter v:
//     E[delta^2] = s_d^2 + (f B s / z^2)^2 + E[v] / n, so
//       s_d^2 = mean over groups of (delta^2 - v / n - (f B s / z^2)^2).
// Both are clamped at 0. A group's mean includes any bias common to all scans (a handle always
// placed behind its bar): that is shared too, and fusion must not average it down either. The
// robust figures take the medians instead: |a| of a 2D Gaussian has the median 1.1774 s, |delta|
// of a 1D one 0.6745 s_d; they say whether a few groups carry the mean.
//
// Each percept is matched to an object of its type under the true pose through a gate shaped
// like stereo's errors, long along the ray from its camera and narrow across it: the object
// with the least (across / match_across_m)^2 + (along / match_along_m)^2, when that is at most
// 1. A round gate either cuts the far objects' tails along the ray (the estimate comes out low)
// or takes a neighbour's percepts across it. Percepts outside every gate are false positives
// and left out (counted).
#pragma once

#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "scan_frames.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::scan_noise {

struct FitOptions {
  double focal_px = 554.3;       // f: the left camera's focal length
  double baseline_m = 0.09;      // B
  double match_across_m = 0.06;  // the gate across the ray
  double match_along_m = 0.3;    // ... and along it
  int min_percepts = 3;          // per (scan, object) group
};

struct ClassFit {
  int scans = 0;         // scans with a group of the class
  int groups = 0;        // (scan, object) groups of at least min_percepts
  int percepts = 0;      // matched percepts in those groups
  int unmatched = 0;     // percepts of the class beyond match_distance_m of every object
  double floor_m = 0.0;  // s
  double floor_robust_m = 0.0;
  double shared_disparity_px = 0.0;  // s_d
  double shared_disparity_robust_px = 0.0;
  // What the recognizer claimed, the medians over the percepts: its shared_sigma_m, and its
  // shared_ray_sigma_m as a disparity (s_r f B / z^2).
  double claimed_floor_m = 0.0;
  double claimed_shared_disparity_px = 0.0;
  // Honesty of the covariances. Own part: the deviations from the group mean under the claimed
  // own covariance (the whole minus the claimed shared part, times (n - 1) / n), the median
  // squared Mahalanobis distance (2.37 for an honest 3D Gaussian). Whole: each error under the
  // percept's whole covariance, the median and the share within 3 sigmas (d^2 <= 9: 97 %).
  double own_median_d2 = 0.0;
  double whole_median_d2 = 0.0;
  double whole_within_3_sigma = 0.0;
};

// Scans recorded in one world.
struct ScanSet {
  const world::WorldModel* world = nullptr;
  std::vector<ScanFrames> scans;
};

// Pooled over every set. Throws std::invalid_argument on options out of range or a set without
// a world.
std::map<std::string, ClassFit> fit_shared_noise(const std::vector<ScanSet>& sets,
                                                 const FitOptions& options);

// The table vsl-scan-noise prints.
void print_fits(const std::map<std::string, ClassFit>& fits, std::ostream& out);

}  // namespace vsl::scan_noise
