#include "vsl/fusion/fusion_options.hpp"

#include <gtest/gtest.h>

#include "vsl/config/node.hpp"

namespace vsl::fusion {
namespace {

FusionOptions read(const std::string& text) {
  return fusion_options_from(config::Node::load_string(text, "fusion.yaml").at("fusion"));
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const config::Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(FusionOptions, DefaultsAndEveryKey) {
  const FusionOptions defaults = read("fusion: {}\n");
  EXPECT_DOUBLE_EQ(defaults.e_min, 0.5);
  EXPECT_EQ(defaults.iota_frames, 1);
  const FusionOptions o = read(
      "fusion:\n"
      "  isolation_distance_m: 0.3\n"
      "  bandwidth_m: 0.08\n"
      "  max_mean_shift_iterations: 20\n"
      "  mode_merge_distance_m: 0.04\n"
      "  image_margin_px: 5\n"
      "  min_depth_m: 0.3\n"
      "  max_range_m: 4\n"
      "  e_min: 0.6\n"
      "  iota_frames: 2\n");
  EXPECT_DOUBLE_EQ(o.isolation_distance_m, 0.3);
  EXPECT_DOUBLE_EQ(o.bandwidth_m, 0.08);
  EXPECT_EQ(o.max_mean_shift_iterations, 20);
  EXPECT_DOUBLE_EQ(o.mode_merge_distance_m, 0.04);
  EXPECT_DOUBLE_EQ(o.image_margin_px, 5.0);
  EXPECT_DOUBLE_EQ(o.min_depth_m, 0.3);
  EXPECT_DOUBLE_EQ(o.max_range_m, 4.0);
  EXPECT_DOUBLE_EQ(o.e_min, 0.6);
  EXPECT_EQ(o.iota_frames, 2);
}

TEST(FusionOptions, BadValuesAreOneLineWithFileLineAndKey) {
  EXPECT_EQ(error_of("fusion:\n  e_min: 1.5\n"),
            "fusion.yaml:2: fusion.e_min: must be in [0, 1], got 1.5");
  EXPECT_EQ(error_of("fusion:\n  iota_frames: -1\n"),
            "fusion.yaml:2: fusion.iota_frames: must be in [0, 1000], got -1");
  EXPECT_NE(error_of("fusion:\n  bandwith_m: 0.1\n").find("fusion.yaml:2: fusion"),
            std::string::npos);
  EXPECT_NE(error_of("fusion:\n  bandwith_m: 0.1\n").find("bandwith_m"), std::string::npos);
  EXPECT_NE(error_of("fusion:\n  bandwidth_m: .nan\n").find("fusion.yaml:2: fusion.bandwidth_m"),
            std::string::npos);
  EXPECT_NE(error_of("fusion:\n  max_mean_shift_iterations: 0\n")
                .find("fusion.yaml:2: fusion.max_mean_shift_iterations: must be in [1, 10000]"),
            std::string::npos);
  EXPECT_NE(error_of("fusion:\n  min_depth_m: 6\n")
                .find("fusion.yaml:2: fusion.min_depth_m: min_depth_m (6.000000) must be below"),
            std::string::npos);
  EXPECT_NE(error_of("fusion:\n  mode_merge_distance_m: 0.1\n")
                .find("fusion.yaml:2: fusion.mode_merge_distance_m: mode_merge_distance_m must not "
                      "exceed bandwidth_m"),
            std::string::npos);
  EXPECT_NE(error_of("fusion: [1, 2]\n").find("fusion.yaml:1: fusion"), std::string::npos);
}

}  // namespace
}  // namespace vsl::fusion
