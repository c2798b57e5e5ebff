// LCM message types -> the plain values the drawing code takes. Anything non-finite (a garbled
// pose, a NaN covariance) is refused here (nullopt / skipped), so the drawing never sees it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

#include "camera_drawing.hpp"
#include "map_drawing.hpp"
#include "vsl/fused_percept_list_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/pose_estimate_t.hpp"
#include "vsl/pose_t.hpp"

namespace vsl::view {

// parent_T_child of a pose_t, the quaternion normalized; nullopt when not finite or of norm ~0.
std::optional<Eigen::Isometry3d> isometry_of(const vsl::pose_t& pose);

// Hypotheses (ranked) of a pose estimate, the unreadable ones skipped.
std::vector<Hypothesis> hypotheses_of(const vsl::pose_estimate_t& estimate);

// The estimate's covariance, when finite.
std::optional<Eigen::Matrix<double, 6, 6>> covariance_of(const vsl::pose_estimate_t& estimate);

std::vector<FusedPercept> fused_percepts_of(const vsl::fused_percept_list_t& list);
// Marks `percepts` (the fused list of the estimate's request) matched or unmatched by the
// estimate's associations; out-of-range indexes are ignored.
void mark_matches(const vsl::pose_estimate_t& estimate, std::vector<FusedPercept>& percepts);
std::vector<CameraPercept> camera_percepts_of(const vsl::percept_list_t& list);

// Caption lines of the map: the localizer's state and message; the counts; the estimate beside
// the ground truth with the errors when both are known.
std::vector<std::string> map_caption(const std::optional<vsl::localizer_status_t>& status,
                                     const std::optional<vsl::pose_estimate_t>& estimate,
                                     const MapOverlay& overlay);

}  // namespace vsl::view
