#include <gtest/gtest.h>

#include "fusion_setup.hpp"
#include "vsl/config/node.hpp"

namespace vsl::fusion_daemon {
namespace {

std::string error_of(const std::string& text) {
  try {
    load_fusion(config::Node::load_string(text, std::string(VSL_SOURCE_DIR "/config/x.yaml")));
  } catch (const config::Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(FusionConfig, ShippedConfigLoads) {
  const FusionSetup setup = load_fusion(config::Node::load_file("config/fusion.yaml"));
  EXPECT_EQ(setup.head_name, "armar3");
  EXPECT_EQ(setup.field_of_view.intrinsics().width_px, 640);
  EXPECT_DOUBLE_EQ(setup.config.options.e_min, 0.5);
  EXPECT_EQ(setup.config.max_frames_per_scan, 2000u);
}

TEST(FusionConfig, BadValuesAreOneLine) {
  const std::string file = std::string(VSL_SOURCE_DIR "/config/x.yaml");
  EXPECT_EQ(error_of("head: heads/armar3.yaml\nfusion:\n  e_min: 2\n"),
            file + ":3: fusion.e_min: must be in [0, 1], got 2");
  EXPECT_EQ(error_of("head: heads/armar3.yaml\nmax_frames_per_scan: 0\n"),
            file + ":2: max_frames_per_scan: must be in [1, 1000000], got 0");
  EXPECT_EQ(error_of("head: heads/nope.yaml\n"), file + ":1: head: " + std::string(VSL_SOURCE_DIR) +
                                                     "/config/heads/nope.yaml: cannot open file");
  EXPECT_NE(error_of("head: heads/armar3.yaml\nfusoin: {}\n").find(file + ":2"), std::string::npos);
  EXPECT_NE(error_of("fusion: {}\n").find("head"), std::string::npos);
}

}  // namespace
}  // namespace vsl::fusion_daemon
