// The state of a head's joints, in the order of HeadKinematics::joint_names().
#pragma once

#include <vector>

namespace vsl::head {

struct JointState {
  std::vector<double> positions_rad;
  std::vector<double> velocities_rad_s;  // same size as positions_rad; 0 at rest
};

}  // namespace vsl::head
