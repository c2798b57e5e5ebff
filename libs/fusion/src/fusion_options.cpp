// fusion: section -> FusionOptions, every key validated.
#include "vsl/fusion/fusion_options.hpp"

#include <string>

#include "vsl/config/node.hpp"

namespace vsl::fusion {

using config::Node;

namespace {

int int_in(const Node& node, std::int64_t min, std::int64_t max) {
  const std::int64_t value = node.as_int();
  if (value < min || value > max) {
    node.fail("must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
              std::to_string(value));
  }
  return static_cast<int>(value);
}

}  // namespace

FusionOptions fusion_options_from(const Node& section) {
  FusionOptions options;
  if (section.is_null()) return options;
  section.expect_map();
  section.expect_keys({"isolation_distance_m", "bandwidth_m", "max_mean_shift_iterations",
                       "mode_merge_distance_m", "image_margin_px", "min_depth_m", "max_range_m",
                       "e_min", "iota_frames"});
  if (const auto n = section.find("isolation_distance_m")) {
    options.isolation_distance_m = n->as_double_in(1e-3, 100.0);
  }
  if (const auto n = section.find("bandwidth_m")) options.bandwidth_m = n->as_double_in(1e-3, 10.0);
  if (const auto n = section.find("max_mean_shift_iterations")) {
    options.max_mean_shift_iterations = int_in(*n, 1, 10000);
  }
  if (const auto n = section.find("mode_merge_distance_m")) {
    options.mode_merge_distance_m = n->as_double_in(1e-4, 10.0);
  }
  if (const auto n = section.find("image_margin_px")) {
    options.image_margin_px = n->as_double_in(0.0, 1000.0);
  }
  if (const auto n = section.find("min_depth_m")) options.min_depth_m = n->as_double_in(0.0, 10.0);
  if (const auto n = section.find("max_range_m"))
    options.max_range_m = n->as_double_in(0.1, 1000.0);
  if (const auto n = section.find("e_min")) options.e_min = n->as_double_in(0.0, 1.0);
  if (const auto n = section.find("iota_frames")) options.iota_frames = int_in(*n, 0, 1000);
  // Cross-key rules, reported at the second key of the pair.
  if (options.min_depth_m >= options.max_range_m) {
    section.at(section.has("min_depth_m") ? "min_depth_m" : "max_range_m")
        .fail("min_depth_m (" + std::to_string(options.min_depth_m) +
              ") must be below max_range_m (" + std::to_string(options.max_range_m) + ")");
  }
  if (options.mode_merge_distance_m > options.bandwidth_m) {
    section.at(section.has("mode_merge_distance_m") ? "mode_merge_distance_m" : "bandwidth_m")
        .fail(
            "mode_merge_distance_m must not exceed bandwidth_m (points of one mode converge "
            "within a fraction of the bandwidth)");
  }
  return options;
}

}  // namespace vsl::fusion
