#include "vsl/fusion/fuse.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

#include "synthetic_scan.hpp"

namespace vsl::fusion {
namespace {

using testing::look_at;

Percept percept(const std::string& type, const Eigen::Vector3d& p, double sigma_m) {
  return Percept{type, p, Eigen::Matrix3d::Identity() * sigma_m * sigma_m};
}

double nearest_of_type(const std::vector<testing::SyntheticObject>& objects,
                       const FusedPercept& fused) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& o : objects) {
    if (o.type == fused.type)
      best = std::min(best, (o.ego_position_m - fused.ego_position_m).norm());
  }
  return best;
}

// A scan of 40 frames (10 head stops) over 15 objects with 1 cm noise, 10 % misses and 25
// isolated false positives: every object seen often enough comes out once, near its truth, and
// no false positive survives.
TEST(Fuse, RecoversObjectsAndRejectsIsolatedFalsePositives) {
  testing::ScanSpec spec;
  spec.objects = testing::room_objects(15, 3);
  spec.ego_gaze_targets_m = testing::sweep_targets(10);
  spec.detection_probability = 0.9;
  spec.false_positives = 25;
  spec.seed = 11;
  const std::vector<Frame> frames = testing::synthetic_scan(spec);
  const FusionOptions options;
  const FieldOfView fov(spec.camera, options);
  const FusionResult result = fuse(frames, fov, options);
  EXPECT_EQ(result.num_frames, 40u);
  EXPECT_GE(result.num_isolated, 20u);  // a false positive may land near a real percept

  int seen_objects = 0;
  for (const auto& object : spec.objects) {
    int frames_seeing = 0;
    for (const Frame& f : frames) {
      frames_seeing += testing::in_image(spec.camera, f.ego_T_left_camera, object.ego_position_m);
    }
    if (frames_seeing < 4) continue;  // seen at one head stop at least
    ++seen_objects;
    int found = 0;
    for (const FusedPercept& fused : result.fused) {
      if (fused.type == object.type &&
          (fused.ego_position_m - object.ego_position_m).norm() < 0.1) {
        ++found;
        // 1 cm per axis and percept: the mean's error is chi(3) * 1 cm / sqrt(n), below 4 of
        // those but for 1 in 1000.
        EXPECT_LT((fused.ego_position_m - object.ego_position_m).norm(),
                  4.0 * 0.01 / std::sqrt(double(fused.num_percepts)));
        EXPECT_GE(fused.support, 3);
        EXPECT_LE(fused.support, fused.expected);
        EXPECT_DOUBLE_EQ(fused.confidence, double(fused.support) / fused.expected);
        // Covariance of the mean: about sigma^2 / n per axis (scaled up when they scatter).
        const double per_axis = 1e-4 / fused.num_percepts;
        EXPECT_GE(fused.ego_covariance_m2.trace(), 3 * per_axis * 0.999);
        EXPECT_LE(fused.ego_covariance_m2.trace(), 3 * per_axis * 4.0);
      }
    }
    EXPECT_EQ(found, 1) << object.type << " at " << object.ego_position_m.transpose();
  }
  EXPECT_GE(seen_objects, 8);
  for (const FusedPercept& fused : result.fused) {
    EXPECT_LT(nearest_of_type(spec.objects, fused), 0.05)
        << "false positive fused: " << fused.type << " at " << fused.ego_position_m.transpose();
  }
}

// T_s counts the frames whose camera looked at the fused location (empty frames included), not
// the frames of the scan.
TEST(Fuse, ExpectedCountsOnlyFramesThatLookedThere) {
  const Eigen::Vector3d camera(0.05, 0.045, 1.5);
  const Eigen::Vector3d door(2.0, 0.0, 1.2);
  std::vector<Frame> frames(7);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    frames[f].frame_id = static_cast<std::int64_t>(f);
    // Frames 0-3 look at the door, 4-6 to the left, away from it.
    frames[f].ego_T_left_camera =
        look_at(camera, f < 4 ? Eigen::Vector3d(2.0, 0.0, 1.2) : Eigen::Vector3d(0.0, 2.0, 1.2));
  }
  frames[0].percepts = {percept("door", door + Eigen::Vector3d(0.01, 0, 0), 0.01)};
  frames[2].percepts = {percept("door", door - Eigen::Vector3d(0.01, 0, 0), 0.01)};
  frames[3].percepts = {percept("door", door, 0.01)};
  // Frame 1 saw it and is empty: it still counts toward T_s.
  FusionOptions options;
  const head::CameraIntrinsics camera_model;
  const FusionResult result = fuse(frames, FieldOfView(camera_model, options), options);
  ASSERT_EQ(result.fused.size(), 1u);
  const FusedPercept& fused = result.fused[0];
  EXPECT_EQ(fused.support, 3);
  EXPECT_EQ(fused.expected, 4);
  EXPECT_DOUBLE_EQ(fused.confidence, 0.75);
  EXPECT_TRUE(fused.ego_position_m.isApprox(door, 1e-9));
  EXPECT_TRUE(fused.ego_camera_position_m.isApprox(camera, 1e-9));
  // Beyond max_range_m a frame is not expected to see it, also when it points there.
  options.max_range_m = 1.5;
  const FusionResult far = fuse(frames, FieldOfView(camera_model, options), options);
  ASSERT_EQ(far.fused.size(), 1u);
  EXPECT_EQ(far.fused[0].expected, 3);  // only the frames that saw it
}

// Eq. 4 per view: a door the scan saw in 3 of its 4 frames that looked at it, then missed in
// all 6 frames of an active look that also had it in view (steeply, cut by the border), stays a
// fused percept; pooled over both views (3 of 10) it would fail. A mode the look alone saw
// must pass in the look's own frames.
TEST(Fuse, EachViewDecidesForItself) {
  const Eigen::Vector3d camera(0.05, 0.045, 1.5);
  const Eigen::Vector3d door(2.0, 0.0, 1.2);
  const Eigen::Vector3d cupboard(2.0, 0.3, 1.9);
  std::vector<Frame> frames(10);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    frames[f].frame_id = static_cast<std::int64_t>(f);
    const bool scan = f < 4;
    frames[f].view = scan ? 0 : 1;
    frames[f].ego_T_left_camera = look_at(camera, scan ? door : Eigen::Vector3d(2.0, 0.2, 1.7));
  }
  frames[0].percepts = {percept("door", door + Eigen::Vector3d(0.01, 0, 0), 0.01)};
  frames[2].percepts = {percept("door", door - Eigen::Vector3d(0.01, 0, 0), 0.01)};
  frames[3].percepts = {percept("door", door, 0.01)};
  // The look sees a handle in 4 of its 6 frames, and something once that does not pass there.
  for (std::size_t f : {4, 5, 7, 9}) frames[f].percepts = {percept("handle", cupboard, 0.01)};
  frames[6].percepts = {percept("knob", cupboard, 0.01)};
  frames[8].percepts = {percept("knob", cupboard + Eigen::Vector3d(0, 0.01, 0), 0.01)};
  FusionOptions options;
  options.iota_frames = 1;
  const head::CameraIntrinsics camera_model;
  const FieldOfView fov(camera_model, options);
  ASSERT_TRUE(fov.sees(frames[5].ego_T_left_camera, door));
  const FusionResult result = fuse(frames, fov, options);
  ASSERT_EQ(result.fused.size(), 2u);
  EXPECT_EQ(result.fused[0].type, "door");
  EXPECT_EQ(result.fused[0].support, 3);
  EXPECT_EQ(result.fused[0].expected, 10);
  EXPECT_DOUBLE_EQ(result.fused[0].confidence, 0.75);  // the scan's 3 of 4
  EXPECT_EQ(result.fused[1].type, "handle");
  ASSERT_EQ(result.rejected.size(), 1u);
  EXPECT_EQ(result.rejected[0].type, "knob");  // 2 of 6 frames of its only view
  // One view for all (no active look): the paper's Eq. 4 over the 10 frames rejects the door,
  // and the handle too (the scan's frames had its place in view: 4 of 10).
  for (Frame& f : frames) f.view = 0;
  const FusionResult pooled = fuse(frames, fov, options);
  EXPECT_TRUE(pooled.fused.empty());
  EXPECT_EQ(pooled.rejected.size(), 3u);
}

// Eq. 4: C / max(T_s - iota, 1) > E_min, strictly.
TEST(Fuse, ConfidenceCriterionWithIota) {
  FusionOptions options;
  options.e_min = 0.5;
  options.iota_frames = 1;
  EXPECT_FALSE(passes_confidence(2, 5, options));  // 2/4 = E_min: not above
  EXPECT_TRUE(passes_confidence(3, 5, options));
  EXPECT_TRUE(passes_confidence(1, 2, options));   // relaxed to 1/1
  EXPECT_FALSE(passes_confidence(1, 3, options));  // 1/2
  EXPECT_TRUE(passes_confidence(1, 1, options));   // never below one frame
  options.iota_frames = 0;
  EXPECT_FALSE(passes_confidence(1, 2, options));
  EXPECT_TRUE(passes_confidence(2, 3, options));
}

// A place seen in 2 of 8 frames that looked at it is a mode but no fused percept.
TEST(Fuse, RarelySeenModeFailsEq4AndIsReported) {
  const Eigen::Vector3d camera(0.05, 0.045, 1.5);
  const Eigen::Vector3d handle(2.0, 0.3, 1.0);
  std::vector<Frame> frames(8);
  for (Frame& frame : frames) frame.ego_T_left_camera = look_at(camera, handle);
  frames[2].percepts = {percept("handle", handle, 0.01)};
  frames[5].percepts = {percept("handle", handle + Eigen::Vector3d(0, 0.01, 0), 0.01)};
  const FusionOptions options;
  const FusionResult result = fuse(frames, FieldOfView(head::CameraIntrinsics{}, options), options);
  EXPECT_TRUE(result.fused.empty());
  ASSERT_EQ(result.rejected.size(), 1u);
  EXPECT_EQ(result.rejected[0].support, 2);
  EXPECT_EQ(result.rejected[0].expected, 8);
  EXPECT_EQ(result.num_isolated, 0u);
}

// The fused location weighs each percept by its information; the covariance is the combined
// one. Percepts that disagree by more than their covariances allow get an excess variance tau^2
// each, in every direction, as large as makes the chi-square its expectation (fuse.hpp).
TEST(Fuse, InformationWeightedMeanAndCovariance) {
  const Eigen::Vector3d camera(0.05, 0.045, 1.5);
  const Eigen::Vector3d at(2.0, 0.0, 1.0);
  std::vector<Frame> frames(2);
  for (Frame& frame : frames) frame.ego_T_left_camera = look_at(camera, at);
  // Sigma 1 cm and 2 cm along x, 2 cm apart: weights 4:1.
  frames[0].percepts = {percept("door", at, 0.01)};
  frames[1].percepts = {percept("door", at + Eigen::Vector3d(0.02, 0, 0), 0.02)};
  const FusionOptions options;
  const FusionResult result = fuse(frames, FieldOfView(head::CameraIntrinsics{}, options), options);
  ASSERT_EQ(result.fused.size(), 1u);
  const FusedPercept& fused = result.fused[0];
  EXPECT_NEAR(fused.ego_position_m.x(), 2.0 + 0.02 * 1.0 / 5.0, 1e-9);
  // Combined variance 1 / (1/1e-4 + 1/4e-4) = 8e-5; chi2 = (0.004^2/1e-4 + 0.016^2/4e-4) = 0.8,
  // within its expectation 3 (n - 1) = 3: no excess.
  EXPECT_NEAR(fused.ego_covariance_m2(0, 0), 8e-5, 1e-12);
  EXPECT_NEAR(fused.ego_covariance_m2(1, 1), 8e-5, 1e-12);
  EXPECT_NEAR(fused.ego_covariance_m2(0, 1), 0.0, 1e-15);
  EXPECT_EQ(fused.num_percepts, 2);
  // Disagreeing by d = 10 cm along x (still one mode with a wide bandwidth). For two percepts the
  // chi-square about their weighted mean is d^2 / (v1 + v2), here with v_i = sigma_i^2 + tau^2:
  // d^2 / (5e-4 + 2 tau^2) = 3 gives tau^2; the x variance is v1 v2 / (v1 + v2), the mean
  // weighs them v2 : v1. Across x they agree: no excess there would be needed, but it is one
  // tau^2 for every direction.
  frames[1].percepts[0].ego_position_m = at + Eigen::Vector3d(0.1, 0, 0);
  FusionOptions wide = options;
  wide.bandwidth_m = 0.2;
  const FusionResult scattered = fuse(frames, FieldOfView(head::CameraIntrinsics{}, wide), wide);
  ASSERT_EQ(scattered.fused.size(), 1u);
  const double tau2 = (0.1 * 0.1 / 3.0 - 5e-4) / 2.0;
  const double v1 = 1e-4 + tau2, v2 = 4e-4 + tau2;
  EXPECT_NEAR(scattered.fused[0].ego_covariance_m2(0, 0), v1 * v2 / (v1 + v2), 1e-10);
  EXPECT_NEAR(scattered.fused[0].ego_covariance_m2(1, 1), v1 * v2 / (v1 + v2), 1e-10);
  EXPECT_NEAR(scattered.fused[0].ego_position_m.x(), 2.0 + 0.1 * v1 / (v1 + v2), 1e-9);
}

// A recognizer whose noise model puts all of a door's error across the ray into the shared part
// (the learned one: door reference_px 0) leaves each percept an own part along its ray alone.
// Frames from head stops a few centimetres apart see the door along slightly different rays, and
// their percepts scatter across them by the box's jitter: taken at their word, the rays'
// near-parallel constraints would meet metres from the door. The excess variance keeps the
// fused door where the percepts are.
TEST(Fuse, PerceptsKnownOnlyAlongTheirRaysStayWhereTheyWereSeen) {
  const Eigen::Vector3d door(3.7, 0.0, 0.5);
  const double shared_sigma_m = 0.022, along_sigma_m = 0.05;
  std::vector<Frame> frames(6);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const double k = static_cast<double>(f);
    const Eigen::Vector3d camera(0.05 + 0.01 * k, -0.06 + 0.025 * k, 1.48 + 0.004 * k);
    frames[f].ego_T_left_camera = look_at(camera, door);
    const Eigen::Vector3d ray = (door - camera).normalized();
    // 1 cm of jitter across the ray, alternating sides, and a little along it.
    const Eigen::Vector3d across = ray.cross(Eigen::Vector3d::UnitZ()).normalized();
    const double side = f % 2 == 0 ? 1.0 : -1.0;
    const Eigen::Vector3d seen = door + 0.01 * side * across +
                                 0.005 * side * Eigen::Vector3d::UnitZ() +
                                 0.02 * (k - 2.5) / 2.5 * ray;
    Percept p{"door", seen,
              shared_sigma_m * shared_sigma_m * Eigen::Matrix3d::Identity() +
                  along_sigma_m * along_sigma_m * ray * ray.transpose()};
    p.shared_sigma_m = shared_sigma_m;
    frames[f].percepts = {p};
  }
  FusionOptions options;
  options.iota_frames = 4;
  const FusionResult result = fuse(frames, FieldOfView(head::CameraIntrinsics{}, options), options);
  ASSERT_EQ(result.fused.size(), 1u);
  EXPECT_LT((result.fused[0].ego_position_m - door).norm(), 0.02);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(result.fused[0].ego_covariance_m2);
  EXPECT_LT(std::sqrt(eigen.eigenvalues().maxCoeff()), 0.05);
  EXPECT_GE(std::sqrt(eigen.eigenvalues().minCoeff()), shared_sigma_m);
}

// Four frames of one door, each percept 2 cm per axis of which 1.5 cm is shared by the scan:
// the fused covariance keeps the shared part, (4e-4 - 2.25e-4) / 4 + 2.25e-4, instead of
// shrinking to 4e-4 / 4; the mean is the same. Handles claiming no shared part keep the
// independent rule.
TEST(Fuse, SharedErrorIsNotAveragedDown) {
  const Eigen::Vector3d camera(0.05, 0.045, 1.5);
  const Eigen::Vector3d at(2.0, 0.0, 1.0);
  const auto scan = [&](double door_shared_sigma_m) {
    std::vector<Frame> frames(4);
    for (std::size_t f = 0; f < frames.size(); ++f) {
      frames[f].ego_T_left_camera = look_at(camera, at);
      frames[f].percepts = {percept("door", at, 0.02),
                            percept("handle", at + Eigen::Vector3d::UnitY(), 0.02)};
      frames[f].percepts[0].shared_sigma_m = door_shared_sigma_m;
    }
    return frames;
  };
  const FusionOptions options;
  const FusionResult result =
      fuse(scan(0.015), FieldOfView(head::CameraIntrinsics{}, options), options);
  ASSERT_EQ(result.fused.size(), 2u);
  for (const FusedPercept& fused : result.fused) {
    const double expected = fused.type == "door" ? (4e-4 - 2.25e-4) / 4.0 + 2.25e-4 : 4e-4 / 4.0;
    EXPECT_NEAR(fused.ego_covariance_m2(0, 0), expected, 1e-12) << fused.type;
    EXPECT_NEAR(fused.ego_covariance_m2(2, 2), expected, 1e-12) << fused.type;
    EXPECT_NEAR(fused.ego_covariance_m2(0, 1), 0.0, 1e-15) << fused.type;
  }
  // A percept narrower than the shared part: its own part is kept at the floor, and the fused
  // covariance is the shared part.
  const FusionResult narrow =
      fuse(scan(0.05), FieldOfView(head::CameraIntrinsics{}, options), options);
  ASSERT_EQ(narrow.fused.size(), 2u);
  EXPECT_NEAR(narrow.fused[0].ego_covariance_m2(0, 0), 0.05 * 0.05, 1e-8);
  EXPECT_EQ(narrow.fused[0].type, "door");
  // Percepts claiming different shared parts: only the smallest is shared by all of them.
  std::vector<Frame> mixed = scan(0.015);
  mixed[0].percepts[0].shared_sigma_m = 0.0;
  const FusionResult independent =
      fuse(mixed, FieldOfView(head::CameraIntrinsics{}, options), options);
  ASSERT_EQ(independent.fused.size(), 2u);
  EXPECT_NEAR(independent.fused[0].ego_covariance_m2(0, 0), 4e-4 / 4.0, 1e-12);
}

// Four frames of one handle from one camera, each percept 1 cm per axis own plus a shared
// part: 1 cm in every direction and 4 cm along the ray (a disparity bias every frame of the scan
// shares). The fused covariance keeps the whole shared part, the own one shrinks by the frames:
// along the ray 1e-4 / 4 + 1e-4 + 16e-4, across it 1e-4 / 4 + 1e-4.
TEST(Fuse, SharedPartAlongTheRayIsNotAveragedDown) {
  const Eigen::Vector3d camera(0.05, 0.045, 1.5);
  const Eigen::Vector3d at(3.0, 0.8, 0.9);
  const Eigen::Vector3d ray = (at - camera).normalized();
  std::vector<Frame> frames(4);
  for (Frame& frame : frames) {
    frame.ego_T_left_camera = look_at(camera, at);
    Percept p{"handle", at,
              2e-4 * Eigen::Matrix3d::Identity() + 0.04 * 0.04 * ray * ray.transpose()};
    p.shared_sigma_m = 0.01;
    p.shared_ray_sigma_m = 0.04;
    frame.percepts = {p};
  }
  const FusionOptions options;
  const FusionResult result = fuse(frames, FieldOfView(head::CameraIntrinsics{}, options), options);
  ASSERT_EQ(result.fused.size(), 1u);
  const Eigen::Matrix3d& c = result.fused[0].ego_covariance_m2;
  EXPECT_NEAR(ray.dot(c * ray), 1e-4 / 4.0 + 1e-4 + 16e-4, 1e-10);
  const Eigen::Vector3d across = ray.cross(Eigen::Vector3d::UnitZ()).normalized();
  EXPECT_NEAR(across.dot(c * across), 1e-4 / 4.0 + 1e-4, 1e-10);
  // Without the ray part claimed, the 4 cm along the ray are the frames' own and shrink by 4.
  for (Frame& frame : frames) frame.percepts[0].shared_ray_sigma_m = 0.0;
  const FusionResult own = fuse(frames, FieldOfView(head::CameraIntrinsics{}, options), options);
  ASSERT_EQ(own.fused.size(), 1u);
  EXPECT_NEAR(ray.dot(own.fused[0].ego_covariance_m2 * ray), (1e-4 + 16e-4) / 4.0 + 1e-4, 1e-10);
}

TEST(Fuse, EmptyScan) {
  const FusionOptions options;
  const FusionResult result = fuse({}, FieldOfView(head::CameraIntrinsics{}, options), options);
  EXPECT_TRUE(result.fused.empty());
  EXPECT_EQ(result.num_frames, 0u);
}

}  // namespace
}  // namespace vsl::fusion
