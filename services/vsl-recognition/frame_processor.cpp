#include "frame_processor.hpp"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <variant>

#include "debug_image.hpp"
#include "frame_input.hpp"
#include "messages.hpp"
#include "vsl/runtime/clock.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::recognition_daemon {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// As vsl::runtime::decode, without the bus (the caller reports the decode error on the loop
// thread): the whole buffer must be one stereo_frame_t.
bool decode(runtime::Bytes bytes, vsl::stereo_frame_t& frame) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return false;
  const int size = static_cast<int>(bytes.size());
  try {
    // A corrupt length field can make the generated code allocate and throw.
    return frame.decode(bytes.data(), 0, size) == size;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

FrameProcessor::FrameProcessor(const recognition::StereoRecognizer& recognizer,
                               bool draw_debug_image, std::optional<double> max_joint_speed_rad_s)
    : recognizer_(recognizer),
      draw_debug_image_(draw_debug_image),
      max_joint_speed_rad_s_(max_joint_speed_rad_s) {}

FrameOutcome FrameProcessor::process(runtime::Bytes bytes, std::int64_t now_utime) const {
  const Clock::time_point start = Clock::now();
  FrameOutcome out;
  out.message_bytes = bytes.size();
  vsl::stereo_frame_t frame;
  if (!decode(bytes, frame)) {
    out.kind = FrameOutcome::Kind::kUndecodable;
    return out;
  }
  out.frame_id = frame.frame_id;
  // `input` may share the frame's pixels: `frame` outlives it.
  auto input = stereo_input(frame, recognizer_.head());
  if (const std::string* problem = std::get_if<std::string>(&input)) {
    out.kind = FrameOutcome::Kind::kInvalid;
    out.problem = *problem;
    return out;
  }
  const StereoInput& stereo = std::get<StereoInput>(input);
  if (max_joint_speed_rad_s_) {
    const std::vector<double>& velocities = stereo.joints_at_capture.velocities_rad_s;
    const auto fastest =
        std::max_element(velocities.begin(), velocities.end(),
                         [](double a, double b) { return std::abs(a) < std::abs(b); });
    if (fastest != velocities.end() && std::abs(*fastest) > *max_joint_speed_rad_s_) {
      out.kind = FrameOutcome::Kind::kMoving;
      out.total_ms = ms_since(start);
      return out;
    }
  }
  try {
    const recognition::FrameResult result =
        recognizer_.recognize(stereo.left_bgr, stereo.right_bgr, stereo.joints_at_capture);
    out.percepts = percept_list_message(result, stereo.frame_id, stereo.utime, now_utime);
    out.segmentation_ms = result.segmentation_ms;
    out.classification_ms = result.classification_ms;
    out.stereo_ms = result.stereo_ms;
    if (draw_debug_image_) {
      const cv::Mat drawn =
          draw_debug_image(stereo.left_bgr, result, stereo.frame_id, ms_since(start));
      out.debug_image = image_message(drawn, stereo.utime);
    }
  } catch (const std::invalid_argument& e) {
    // What validation did not catch (an image the library still refuses).
    out.kind = FrameOutcome::Kind::kInvalid;
    out.problem = e.what();
  } catch (const std::exception& e) {
    out.kind = FrameOutcome::Kind::kFailed;
    out.problem = e.what();
  } catch (...) {
    out.kind = FrameOutcome::Kind::kFailed;
    out.problem = "unknown exception";
  }
  out.total_ms = ms_since(start);
  return out;
}

}  // namespace vsl::recognition_daemon
