// One STEREO_FRAME, as bytes off the bus, to what the daemon publishes: decode, validate and
// convert (frame_input.hpp), recognize (vsl::recognition::StereoRecognizer), build the PERCEPTS
// message and, when configured, the debug image. Runs on the worker thread; touches no bus and no
// shared state, so everything the loop thread must do (publish, log, count) is in the outcome.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "vsl/image_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/recognition/stereo_recognizer.hpp"
#include "vsl/runtime/bus.hpp"

namespace vsl::recognition_daemon {

struct FrameOutcome {
  enum class Kind {
    kRecognized,   // `percepts` (and `debug_image` if asked for) are ready to publish
    kUndecodable,  // the bytes are not a stereo_frame_t: a decode error of the bus
    kInvalid,      // decoded, but recognition cannot use it: `problem` says why
    kFailed,       // the recognizer threw something other than std::invalid_argument
    kMoving,       // captured while a joint turned faster than the limit: not recognized
  };
  Kind kind = Kind::kRecognized;
  std::string problem;
  std::size_t message_bytes = 0;
  std::int64_t frame_id = -1;  // -1 when not decoded
  vsl::percept_list_t percepts;
  std::optional<vsl::image_t> debug_image;
  // Wall time from taking the bytes to the finished messages, and the library's stages,
  // milliseconds.
  double total_ms = 0.0;
  double segmentation_ms = 0.0;
  double classification_ms = 0.0;
  double stereo_ms = 0.0;
};

class FrameProcessor {
 public:
  // `recognizer` must outlive the processor. `max_joint_speed_rad_s`: frames captured while a
  // head joint turned faster are not recognized (RecognitionConfig); none: every frame is.
  FrameProcessor(const recognition::StereoRecognizer& recognizer, bool draw_debug_image,
                 std::optional<double> max_joint_speed_rad_s = std::nullopt);

  // Never throws for bad input: every failure is an outcome. Const and thread-safe.
  // `now_utime`: the percept list's utime (its publication).
  FrameOutcome process(runtime::Bytes bytes, std::int64_t now_utime) const;

 private:
  const recognition::StereoRecognizer& recognizer_;
  bool draw_debug_image_;
  std::optional<double> max_joint_speed_rad_s_;
};

}  // namespace vsl::recognition_daemon
