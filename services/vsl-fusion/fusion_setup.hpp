// Everything vsl-fusion loads before it runs: its config and the left camera model of the head's
// calibration. A bad file or value throws vsl::config::Error (one line, file:line: key: what), so
// the daemon exits 2 and the shipped-config test finds the same errors.
#pragma once

#include <string>

#include "fusion_config.hpp"
#include "vsl/fusion/field_of_view.hpp"

namespace vsl::fusion_daemon {

struct FusionSetup {
  FusionConfig config;
  std::string head_name;
  fusion::FieldOfView field_of_view;
};

FusionSetup load_fusion(const config::Node& root);

}  // namespace vsl::fusion_daemon
