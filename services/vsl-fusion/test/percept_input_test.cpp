#include "percept_input.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace vsl::fusion_daemon {
namespace {

vsl::percept_list_t good_list() {
  vsl::percept_list_t list{};
  list.utime = 2000;
  list.frame_id = 4;
  list.frame_utime = 1000;
  list.ego_T_left_camera.position_m[2] = 1.5;
  list.ego_T_left_camera.orientation_wxyz[0] = 1.0;
  vsl::percept_t p{};
  p.frame_id = 4;
  p.utime = 1000;
  p.type = "door";
  p.ego_position_m[0] = 2.0;
  p.ego_covariance_m2[0] = p.ego_covariance_m2[4] = p.ego_covariance_m2[8] = 1e-4;
  p.ego_covariance_m2[1] = p.ego_covariance_m2[3] = 2e-5;
  list.percepts = {p, p};
  list.percepts[1].type = "handle";
  list.percepts[1].shared_sigma_m = 0.008;
  list.percepts[0].shared_ray_sigma_m = 0.009;
  list.num_percepts = 2;
  return list;
}

std::string problem_of(const vsl::percept_list_t& list) {
  const auto result = frame_from(list);
  if (const auto* p = std::get_if<std::string>(&result)) return *p;
  return "";
}

TEST(PerceptInput, GoodListBecomesAFrame) {
  const auto result = frame_from(good_list());
  ASSERT_TRUE(std::holds_alternative<fusion::Frame>(result)) << std::get<std::string>(result);
  const fusion::Frame& frame = std::get<fusion::Frame>(result);
  EXPECT_EQ(frame.frame_id, 4);
  ASSERT_EQ(frame.percepts.size(), 2u);
  EXPECT_EQ(frame.percepts[1].type, "handle");
  EXPECT_DOUBLE_EQ(frame.percepts[0].ego_covariance_m2(0, 1), 2e-5);
  EXPECT_DOUBLE_EQ(frame.percepts[0].shared_sigma_m, 0.0);
  EXPECT_DOUBLE_EQ(frame.percepts[1].shared_sigma_m, 0.008);
  EXPECT_DOUBLE_EQ(frame.percepts[0].shared_ray_sigma_m, 0.009);
  EXPECT_DOUBLE_EQ(frame.percepts[1].shared_ray_sigma_m, 0.0);
  EXPECT_DOUBLE_EQ(frame.ego_T_left_camera.translation().z(), 1.5);
}

TEST(PerceptInput, MalformedListsAreOneLineProblems) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vsl::percept_list_t l = good_list();
  l.num_percepts = 3;
  EXPECT_EQ(problem_of(l), "num_percepts 3, 2 percepts");
  l = good_list();
  l.ego_T_left_camera.position_m[0] = nan;
  EXPECT_EQ(problem_of(l), "ego_T_left_camera is not finite");
  l = good_list();
  l.ego_T_left_camera.orientation_wxyz[0] = 0.5;
  EXPECT_EQ(problem_of(l), "ego_T_left_camera quaternion has norm 0.500000, not 1");
  l = good_list();
  l.percepts[1].ego_position_m[2] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(problem_of(l), "percept 1 (handle): ego_position_m is not finite");
  // Finite but absurd: once fused into non-finite positions the localizer dropped.
  l = good_list();
  l.percepts[1].ego_position_m[0] = 1e308;
  EXPECT_EQ(problem_of(l), "percept 1 (handle): ego_position_m is more than 100 m away");
  l = good_list();
  l.ego_T_left_camera.position_m[1] = -1e300;
  EXPECT_EQ(problem_of(l), "ego_T_left_camera is more than 100 m from the ego origin");
  l = good_list();
  l.percepts[0].ego_covariance_m2[0] = 1e300;
  EXPECT_EQ(problem_of(l), "percept 0 (door): covariance entry beyond 1e4 m^2");
  l = good_list();
  l.percepts[0].ego_covariance_m2[5] = nan;
  EXPECT_EQ(problem_of(l), "percept 0 (door): covariance is not finite");
  l = good_list();
  l.percepts[0].ego_covariance_m2[1] = 5e-5;
  EXPECT_EQ(problem_of(l), "percept 0 (door): covariance is not symmetric");
  l = good_list();
  l.percepts[0].ego_covariance_m2[8] = -1e-4;
  EXPECT_EQ(problem_of(l), "percept 0 (door): covariance is not positive definite");
  l = good_list();
  for (double& c : l.percepts[1].ego_covariance_m2) c = 0.0;
  EXPECT_EQ(problem_of(l), "percept 1 (handle): covariance is not positive definite");
  // The shared part is inside the covariance: at most its smallest sigma, sqrt(8e-5) m here.
  l = good_list();
  l.percepts[1].shared_sigma_m = 0.0095;
  EXPECT_EQ(problem_of(l),
            "percept 1 (handle): shared_sigma_m 0.009500 exceeds the covariance's smallest sigma "
            "0.008944");
  l = good_list();
  l.percepts[1].shared_sigma_m = -0.01;
  EXPECT_EQ(problem_of(l), "percept 1 (handle): shared_sigma_m -0.010000 is not in [0, 1] m");
  l = good_list();
  l.percepts[1].shared_sigma_m = nan;
  EXPECT_EQ(problem_of(l), "percept 1 (handle): shared_sigma_m nan is not in [0, 1] m");
  // The shared part along the ray (from the camera at (0, 0, 1.5) to the door at (2, 0, 0),
  // r = (0.8, 0, -0.6)) is inside the covariance's variance along it, r^T C r = 1e-4 here, with
  // the isotropic shared part.
  l = good_list();
  l.percepts[0].shared_ray_sigma_m = 0.0101;
  EXPECT_EQ(problem_of(l),
            "percept 0 (door): shared_ray_sigma_m 0.010100 with shared_sigma_m exceeds the "
            "covariance's sigma along the ray 0.010000");
  l = good_list();
  l.percepts[0].shared_ray_sigma_m = nan;
  EXPECT_EQ(problem_of(l), "percept 0 (door): shared_ray_sigma_m nan is not in [0, 1] m");
  l = good_list();
  l.percepts[0].shared_ray_sigma_m = -0.001;
  EXPECT_EQ(problem_of(l), "percept 0 (door): shared_ray_sigma_m -0.001000 is not in [0, 1] m");
  l = good_list();
  l.percepts[1].frame_id = 5;
  EXPECT_EQ(problem_of(l), "percept 1 (handle): frame_id 5, the list's is 4");
  l = good_list();
  l.percepts[0].type.clear();
  EXPECT_EQ(problem_of(l), "percept 0: empty type");
}

TEST(PerceptInput, RequestsAndStatuses) {
  vsl::localize_request_t request{};
  request.request_id = 0;
  EXPECT_EQ(request_problem(request), "request_id 0 (must be > 0)");
  request.request_id = 3;
  EXPECT_FALSE(request_problem(request));
  vsl::localizer_status_t status{};
  status.state = 42;
  EXPECT_EQ(status_problem(status), "unknown state 42");
  status.state = vsl::localizer_status_t::FUSING;
  EXPECT_FALSE(status_problem(status));
}

}  // namespace
}  // namespace vsl::fusion_daemon
