// PERCEPTS, LOCALIZE_REQUEST and LOCALIZER_STATUS -> what the scan tracker takes. Anything fusion
// cannot use (a non-finite number, a covariance that is not symmetric positive definite, a count
// that does not match, an unknown state) is a one-line problem instead, so the daemon counts,
// logs and skips the message.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "vsl/fusion/percept.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"

namespace vsl::fusion_daemon {

// Smallest eigenvalue a percept covariance may have (m^2): a 1 um standard deviation. Below it
// the information-weighted mean would trust one percept absolutely.
inline constexpr double kMinCovarianceEigenvalue_m2 = 1e-12;
// How far from the ego origin a percept (and the left camera) may be (m), and the largest
// covariance entry (m^2, a 100 m standard deviation). A stereo head triangulates a few metres
// out; finite but absurd numbers (1e308 m) would overflow the fusion's sums into non-finite
// fused positions, which the localizer then drops, failing with the wrong reason.
inline constexpr double kMaxPerceptDistance_m = 100.0;
inline constexpr double kMaxCovariance_m2 = 1e4;
// The largest shared error sigma a percept may claim (m): where on an object a recognizer takes
// its reference point is wrong by centimetres, not metres.
inline constexpr double kMaxSharedSigma_m = 1.0;

// The frame (percepts and left camera pose) or the list's problem ("percept 2 (door): covariance
// is not positive definite").
std::variant<fusion::Frame, std::string> frame_from(const vsl::percept_list_t& list);

// The message's problem, or nullopt when it is usable.
std::optional<std::string> request_problem(const vsl::localize_request_t& request);
std::optional<std::string> status_problem(const vsl::localizer_status_t& status);

}  // namespace vsl::fusion_daemon
