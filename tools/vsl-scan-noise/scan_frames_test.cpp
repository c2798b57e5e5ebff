// The scan frames file: written and read back exactly; a malformed one is one line naming where.
#include "scan_frames.hpp"

#include <gtest/gtest.h>

#include "vsl/config/node.hpp"

namespace vsl::scan_noise {
namespace {

ScanFrames example() {
  ScanFrames scan;
  scan.world_T_ego.translation() = Eigen::Vector3d(4.4, 1.0, 0.0);
  scan.world_T_ego.linear() = Eigen::AngleAxisd(2.356, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  FramePerceptRecord p;
  p.frame_id = 17;
  p.type = "handle";
  p.ego_position_m = {2.1, -0.4, 0.83};
  p.ego_covariance_m2 << 4e-4, 1e-5, 0, 1e-5, 3e-4, 2e-6, 0, 2e-6, 2.5e-4;
  p.ego_camera_position_m = {0.05, 0.04, 1.52};
  p.shared_sigma_m = 0.012;
  p.shared_ray_sigma_m = 0.0071;
  scan.percepts = {p, p};
  scan.percepts[1].frame_id = 18;
  scan.percepts[1].type = "door";
  return scan;
}

TEST(ScanFrames, RoundTripsThroughItsText) {
  const ScanFrames scan = example();
  const ScanFrames back = load_scan_frames_from_string(scan_frames_text(scan), "scan.yaml");
  EXPECT_TRUE(back.world_T_ego.isApprox(scan.world_T_ego, 1e-8));
  ASSERT_EQ(back.percepts.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const FramePerceptRecord& a = scan.percepts[i];
    const FramePerceptRecord& b = back.percepts[i];
    EXPECT_EQ(b.frame_id, a.frame_id);
    EXPECT_EQ(b.type, a.type);
    EXPECT_TRUE(b.ego_position_m.isApprox(a.ego_position_m, 1e-8));
    EXPECT_TRUE(b.ego_covariance_m2.isApprox(a.ego_covariance_m2, 1e-8));
    EXPECT_TRUE(b.ego_camera_position_m.isApprox(a.ego_camera_position_m, 1e-8));
    EXPECT_DOUBLE_EQ(b.shared_sigma_m, a.shared_sigma_m);
    EXPECT_DOUBLE_EQ(b.shared_ray_sigma_m, a.shared_ray_sigma_m);
  }
}

TEST(ScanFrames, AnEmptyScanRoundTrips) {
  ScanFrames scan;
  EXPECT_TRUE(load_scan_frames_from_string(scan_frames_text(scan), "empty.yaml").percepts.empty());
}

std::string failure(const std::string& text) {
  try {
    load_scan_frames_from_string(text, "bad.yaml");
  } catch (const config::Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(ScanFrames, AMalformedFileIsOneLineNamingWhere) {
  const std::string truth = "ground_truth: {position: [0, 0, 0], quaternion: [1, 0, 0, 0]}\n";
  const std::string good =
      "{frame: 1, type: door, position: [1, 2, 3], covariance: [1, 0, 0, 0, 1, 0, 0, 0, 1], "
      "camera: [0, 0, 1.5], shared_sigma_m: 0.01, shared_ray_sigma_m: 0}";
  EXPECT_EQ(failure(truth + "percepts: [" + good + "]"), "no error");
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string p = good;
    p.replace(p.find(from), from.size(), to);
    return failure(truth + "percepts: [" + p + "]");
  };
  EXPECT_NE(
      with("1, 0, 0, 0, 1, 0, 0, 0, 1", "1, 0, 0, 0, -1, 0, 0, 0, 1").find("positive definite"),
      std::string::npos);
  EXPECT_NE(with("shared_sigma_m: 0.01", "shared_sigma_m: -0.01").find("bad.yaml:2"),
            std::string::npos);
  EXPECT_NE(with("camera: [0, 0, 1.5], ", "").find("camera"), std::string::npos);
  EXPECT_NE(with("frame: 1", "frame: 1, colour: red").find("colour"), std::string::npos);
  EXPECT_NE(failure("percepts: [" + good + "]").find("ground_truth"), std::string::npos);
  EXPECT_NE(failure(truth).find("percepts"), std::string::npos);
}

}  // namespace
}  // namespace vsl::scan_noise
