// Everything a real stereo driver loads before it opens a camera: its config and the head
// kinematics (for head_name, the joint names and order, the limits of fixed joints, and the
// calibrated image size the cameras must deliver). Errors are vsl::config::Error (one line).
#pragma once

#include <string>

#include "capture_config.hpp"
#include "joint_history.hpp"
#include "vsl/head/head_kinematics.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::stereo_capture {

struct DriverSetup {
  CaptureConfig config;
  head::HeadKinematics head;
  // The rest posture with `joints.fixed_rad` over it (velocities 0): every frame's joint state
  // when the source is fixed.
  JointSample fixed_joints;
};

DriverSetup load_driver_setup(const config::Node& root, const std::string& section_name);

}  // namespace vsl::stereo_capture
