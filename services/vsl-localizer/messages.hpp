// Conversions between the LCM messages of the localizer and the core's plain values
// (docs/messages.md). Malformed input is an error string, never an exception.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "localizer_core.hpp"
#include "vsl/fused_percept_list_t.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/pose_estimate_t.hpp"

namespace vsl::localizer_daemon {

// FUSED_PERCEPTS -> fused percepts (ego frame); an error when counts disagree or a number is not
// finite. A covariance that is not a finite, symmetric, positive-diagonal 3x3 is dropped (the
// localizer then uses the Eq. 7 noise model).
std::variant<std::vector<localization::FusedPercept>, std::string> fused_percepts_from(
    const vsl::fused_percept_list_t& message);

vsl::gaze_command_t gaze_message(const GazeCommand& command, std::int64_t utime);
vsl::localizer_status_t status_message(const StatusReport& report, std::int64_t utime);
// Covariance order x y z roll pitch yaw, rotations about the world axes applied on the left
// (docs/messages.md), which is the core's PoseCovariance order.
vsl::pose_estimate_t pose_message(const PoseReport& report, std::int64_t utime);

// The head of an encoded stereo_frame_t (hash, utime, frame_id, head_name, gaze_request_id,
// gaze_reached), read without decoding the images: a 1.8 MB frame costs the localizer a few
// dozen bytes. nullopt for another type or a truncated buffer.
std::optional<FrameHeader> parse_frame_header(std::span<const std::uint8_t> bytes);

}  // namespace vsl::localizer_daemon
