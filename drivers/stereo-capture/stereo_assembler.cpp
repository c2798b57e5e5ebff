#include "stereo_assembler.hpp"

#include <algorithm>

namespace vsl::stereo_capture {
namespace {

// Joint samples are kept this much longer than a frame may wait, so that a frame that waited
// still finds the sample before its capture time.
constexpr std::int64_t kKeepMarginUs = 500000;

}  // namespace

StereoAssembler::StereoAssembler(AssemblerOptions options)
    : options_(std::move(options)),
      pairer_(options_.pairing_tolerance_us, options_.max_waiting_frames),
      history_(options_.joint_count, options_.joint_max_gap_us,
               options_.joint_max_wait_us + options_.joint_max_gap_us + kKeepMarginUs) {}

void StereoAssembler::add_left(RawImage frame) {
  pairer_.push_left(std::move(frame));
  pair_up();
}

void StereoAssembler::add_right(RawImage frame) {
  pairer_.push_right(std::move(frame));
  pair_up();
}

void StereoAssembler::add_side_by_side(RawImage frame) {
  ++counters_.side_by_side_frames;
  StereoCapture capture;
  capture.utime = frame.utime;
  capture.left = std::move(frame);
  capture.side_by_side = true;
  waiting_.push_back(std::move(capture));
}

void StereoAssembler::add_joint_sample(JointSample sample) {
  if (!history_.add(std::move(sample))) ++counters_.rejected_samples;
}

void StereoAssembler::reset_pairing() {
  pairer_.clear();
}

void StereoAssembler::pair_up() {
  while (auto pair = pairer_.pop_pair()) {
    StereoCapture capture;
    capture.utime = pair->left.utime;
    capture.left = std::move(pair->left);
    capture.right = std::move(pair->right);
    waiting_.push_back(std::move(capture));
  }
}

std::vector<StereoCapture> StereoAssembler::take_ready(std::int64_t now_utime) {
  std::vector<StereoCapture> out;
  // In capture order: a later capture never overtakes an earlier one still waiting.
  while (!waiting_.empty()) {
    StereoCapture& capture = waiting_.front();
    if (options_.fixed_joints) {
      capture.joints = *options_.fixed_joints;
      capture.joints.utime = capture.utime;
    } else {
      const JointLookup lookup = history_.at(capture.utime, capture.joints);
      if (lookup == JointLookup::kWait && now_utime - capture.utime <= options_.joint_max_wait_us) {
        break;  // the next HEAD_STATE may still bracket it
      }
      if (lookup != JointLookup::kReady) {
        ++counters_.no_joint_state;
        waiting_.pop_front();
        continue;
      }
    }
    out.push_back(std::move(capture));
    waiting_.pop_front();
  }
  return out;
}

const AssemblerCounters& StereoAssembler::counters() const {
  counters_.pairing = pairer_.counters();
  return counters_;
}

}  // namespace vsl::stereo_capture
