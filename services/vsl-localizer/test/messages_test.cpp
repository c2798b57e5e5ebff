// Message conversions and the stereo frame head reader.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "messages.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::localizer_daemon {
namespace {

std::vector<std::uint8_t> encode(const vsl::stereo_frame_t& frame) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(frame.getEncodedSize()));
  frame.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

TEST(Messages, FrameHeaderWithoutDecodingImages) {
  vsl::stereo_frame_t frame{};
  frame.utime = 123;
  frame.frame_id = 4567;
  frame.head_name = "armar3";
  frame.gaze_request_id = 1'700'000'000'000'000;
  frame.gaze_reached = true;
  frame.left.size = 300;
  frame.left.data.assign(300, 7);
  const auto bytes = encode(frame);
  const auto header = parse_frame_header(bytes);
  ASSERT_TRUE(header);
  EXPECT_EQ(header->frame_id, 4567);
  EXPECT_EQ(header->gaze_request_id, 1'700'000'000'000'000);
  EXPECT_TRUE(header->gaze_reached);
  frame.gaze_reached = false;
  frame.gaze_request_id = -1;
  const auto moving = parse_frame_header(encode(frame));
  ASSERT_TRUE(moving);
  EXPECT_FALSE(moving->gaze_reached);
  EXPECT_EQ(moving->gaze_request_id, -1);
}

TEST(Messages, FrameHeaderRejectsGarbage) {
  vsl::stereo_frame_t frame{};
  frame.head_name = "armar3";
  const auto bytes = encode(frame);
  for (std::size_t n = 0; n < 40; ++n) {
    EXPECT_FALSE(parse_frame_header(std::span(bytes.data(), n))) << n;
  }
  auto wrong_hash = bytes;
  wrong_hash[3] ^= 0x10;
  EXPECT_FALSE(parse_frame_header(wrong_hash));
  auto huge_name = bytes;
  huge_name[24] = 0x7f;  // the name length's top byte
  EXPECT_FALSE(parse_frame_header(huge_name));
}

TEST(Messages, FusedPercepts) {
  vsl::fused_percept_list_t m{};
  m.request_id = 3;
  vsl::fused_percept_t p{};
  p.type = "door";
  p.ego_position_m[0] = 1;
  p.ego_position_m[1] = 2;
  p.ego_position_m[2] = 0.5;
  p.ego_covariance_m2[0] = p.ego_covariance_m2[4] = p.ego_covariance_m2[8] = 1e-4;
  p.support = 4;
  m.percepts = {p, p};
  m.percepts[1].ego_covariance_m2[0] = 0;  // not positive: dropped, Eq. 7 applies
  m.num_percepts = 2;
  auto out = fused_percepts_from(m);
  ASSERT_EQ(out.index(), 0u) << std::get<1>(out);
  const auto& percepts = std::get<0>(out);
  ASSERT_EQ(percepts.size(), 2u);
  EXPECT_EQ(percepts[0].type, "door");
  EXPECT_EQ(percepts[0].ego_position_m, Eigen::Vector3d(1, 2, 0.5));
  ASSERT_TRUE(percepts[0].ego_covariance_m2);
  EXPECT_DOUBLE_EQ((*percepts[0].ego_covariance_m2)(2, 2), 1e-4);
  EXPECT_EQ(percepts[0].support, 4);
  EXPECT_FALSE(percepts[1].ego_covariance_m2);

  m.num_percepts = 3;
  EXPECT_EQ(fused_percepts_from(m).index(), 1u);
  m.num_percepts = 2;
  m.percepts[0].ego_position_m[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(fused_percepts_from(m).index(), 1u);
}

TEST(Messages, PoseEstimate) {
  PoseReport report;
  report.request_id = 9;
  report.result.status = localization::Status::kLocalized;
  report.result.world_T_ego.translation() = Eigen::Vector3d(1, 2, 0);
  report.result.world_T_ego.linear() =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  report.result.covariance(5, 5) = 0.01;
  report.result.covariance(0, 1) = 0.002;
  localization::Hypothesis h;
  h.score = 12;
  h.associations = {{0, 3, "door_3"}, {1, 5, "handle_5"}};
  report.result.hypotheses = {h};
  report.result.associations = h.associations;
  report.message = "localized";
  const vsl::pose_estimate_t m = pose_message(report, 77);
  EXPECT_EQ(m.utime, 77);
  EXPECT_EQ(m.request_id, 9);
  EXPECT_EQ(m.status, vsl::pose_estimate_t::LOCALIZED);
  EXPECT_DOUBLE_EQ(m.world_T_ego.position_m[1], 2);
  EXPECT_NEAR(m.world_T_ego.orientation_wxyz[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(m.world_T_ego.orientation_wxyz[3], std::sqrt(0.5), 1e-12);
  EXPECT_DOUBLE_EQ(m.covariance[35], 0.01);  // yaw, yaw
  EXPECT_DOUBLE_EQ(m.covariance[1], 0.002);  // x, y
  ASSERT_EQ(m.num_hypotheses, 1);
  EXPECT_EQ(m.hypotheses[0].num_associations, 2);
  ASSERT_EQ(m.num_associations, 2);
  EXPECT_EQ(m.associations[1].model_object_id, "handle_5");
  EXPECT_GT(m.getEncodedSize(), 0);
}

TEST(Messages, StatusAndGaze) {
  StatusReport s{5, State::kActiveValidation, 0.5, "step 3 of 6", 12, 2};
  const vsl::localizer_status_t m = status_message(s, 1);
  EXPECT_EQ(m.state, vsl::localizer_status_t::ACTIVE_VALIDATION);
  EXPECT_EQ(m.num_fused_percepts, 12);
  const vsl::gaze_command_t g = gaze_message({42, Eigen::Vector3d(1, 2, 3)}, 1);
  EXPECT_EQ(g.request_id, 42);
  EXPECT_EQ(g.mode, vsl::gaze_command_t::TARGET_POINT);
  EXPECT_DOUBLE_EQ(g.ego_target_m[2], 3);
  EXPECT_EQ(g.num_joints, 0);
}

}  // namespace
}  // namespace vsl::localizer_daemon
