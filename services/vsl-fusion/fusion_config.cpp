// config/fusion.yaml -> FusionConfig, every key validated.
#include "fusion_config.hpp"

#include <filesystem>

#include "vsl/config/node.hpp"
#include "vsl/config/paths.hpp"

namespace vsl::fusion_daemon {
namespace {

using config::Node;
using config::path_relative_to_file;

}  // namespace

FusionConfig read_fusion_config(const Node& root) {
  root.expect_map();
  root.expect_keys({"runtime", "head", "calibration", "fusion", "max_frames_per_scan",
                    "max_percepts_per_scan", "status_period_s"});
  FusionConfig out;
  out.head_path = path_relative_to_file(root.at("head"));
  if (const auto calibration = root.find("calibration")) {
    out.calibration_path = path_relative_to_file(*calibration);
  }
  if (const auto section = root.find("fusion")) out.options = fusion::fusion_options_from(*section);
  if (const auto n = root.find("max_frames_per_scan")) {
    const std::int64_t value = n->as_int();
    if (value < 1 || value > 1000000) {
      n->fail("must be in [1, 1000000], got " + std::to_string(value));
    }
    out.max_frames_per_scan = static_cast<std::size_t>(value);
  }
  if (const auto n = root.find("max_percepts_per_scan")) {
    const std::int64_t value = n->as_int();
    if (value < 3 || value > 10000) n->fail("must be in [3, 10000], got " + std::to_string(value));
    out.max_percepts_per_scan = static_cast<std::size_t>(value);
  }
  if (const auto n = root.find("status_period_s"))
    out.status_period_s = n->as_double_in(0.1, 3600.0);
  return out;
}

}  // namespace vsl::fusion_daemon
