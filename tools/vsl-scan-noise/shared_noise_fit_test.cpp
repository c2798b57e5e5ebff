// The shared-noise fit recovers the parts it was given on synthetic scans: a shared isotropic
// floor and a shared disparity bias on top of each frame's own noise, from seeded draws.
#include "shared_noise_fit.hpp"

#include <gtest/gtest.h>

#include <random>

namespace vsl::scan_noise {
namespace {

constexpr double kFocalPx = 554.3;
constexpr double kBaselineM = 0.09;

// Doors 1.5-3.1 m in front of a robot at the origin, facing +x.
world::WorldModel wall_of_doors() {
  world::WorldModel world;
  for (int i = 0; i < 8; ++i) {
    for (int k = 0; k < 3; ++k) {
      world::ObjectModel door;
      door.id = "door" + std::to_string(i) + "_" + std::to_string(k);
      door.type = "door";
      door.world_position_m = {1.5 + 0.8 * k, -2.8 + 0.8 * i, 0.4 + 0.6 * k};
      world.objects.push_back(door);
    }
  }
  world.index_ids();
  return world;
}

struct Truth {
  double floor_m = 0.0;
  double shared_disparity_px = 0.0;
  double own_sigma_m = 0.01;
  int frames = 8;
  bool claim_truthfully = true;  // the recorded covariances are the true ones
};

// Scans from robot poses near the origin: per (scan, object) one shared draw, per frame its own.
std::vector<ScanFrames> synthetic_scans(const world::WorldModel& world, const Truth& t, int scans,
                                        unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  const auto gaussian = [&] { return Eigen::Vector3d(normal(rng), normal(rng), normal(rng)); };
  std::vector<ScanFrames> out;
  for (int s = 0; s < scans; ++s) {
    ScanFrames scan;
    scan.world_T_ego.translation() = Eigen::Vector3d(0.3 * normal(rng), 0.3 * normal(rng), 0.0);
    scan.world_T_ego.linear() =
        Eigen::AngleAxisd(0.2 * normal(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Isometry3d ego_T_world = scan.world_T_ego.inverse();
    const Eigen::Vector3d camera(0.0, 0.0, 1.5);
    for (const world::ObjectModel& object : world.objects) {
      const Eigen::Vector3d x = ego_T_world * object.world_position_m;
      const double z = (x - camera).norm();
      const Eigen::Vector3d ray = (x - camera) / z;
      const double ray_sigma_m = t.shared_disparity_px * z * z / (kFocalPx * kBaselineM);
      const Eigen::Vector3d shared = t.floor_m * gaussian() + ray_sigma_m * normal(rng) * ray;
      for (int f = 0; f < t.frames; ++f) {
        FramePerceptRecord p;
        p.frame_id = s * 100 + f;
        p.type = "door";
        p.ego_position_m = x + shared + t.own_sigma_m * gaussian();
        p.ego_camera_position_m = camera;
        if (t.claim_truthfully) {
          p.shared_sigma_m = t.floor_m;
          p.shared_ray_sigma_m = ray_sigma_m;
          p.ego_covariance_m2 = (t.own_sigma_m * t.own_sigma_m + t.floor_m * t.floor_m) *
                                    Eigen::Matrix3d::Identity() +
                                ray_sigma_m * ray_sigma_m * ray * ray.transpose();
        } else {
          p.ego_covariance_m2 = t.own_sigma_m * t.own_sigma_m * Eigen::Matrix3d::Identity();
        }
        scan.percepts.push_back(p);
      }
    }
    out.push_back(std::move(scan));
  }
  return out;
}

// The doors are 0.6 m apart: a gate 15 cm across the ray keeps every percept of these draws.
ClassFit fit(const world::WorldModel& world, const std::vector<ScanFrames>& scans) {
  FitOptions options;
  options.focal_px = kFocalPx;
  options.baseline_m = kBaselineM;
  options.match_across_m = 0.15;
  const auto fits = fit_shared_noise({ScanSet{&world, scans}}, options);
  EXPECT_EQ(fits.size(), 1u);
  return fits.at("door");
}

TEST(SharedNoiseFit, RecoversTheFloorAndTheSharedDisparity) {
  const world::WorldModel world = wall_of_doors();
  Truth truth;
  truth.floor_m = 0.02;
  truth.shared_disparity_px = 0.25;
  const ClassFit f = fit(world, synthetic_scans(world, truth, 40, 7));
  EXPECT_EQ(f.groups, 40 * 24);
  EXPECT_EQ(f.percepts, 40 * 24 * 8);
  EXPECT_EQ(f.unmatched, 0);
  EXPECT_NEAR(f.floor_m, 0.02, 0.002);
  EXPECT_NEAR(f.shared_disparity_px, 0.25, 0.025);
  EXPECT_NEAR(f.floor_robust_m, 0.02, 0.003);
  EXPECT_NEAR(f.shared_disparity_robust_px, 0.25, 0.04);
  // What the recorded percepts claimed, and that those claims are honest.
  EXPECT_NEAR(f.claimed_floor_m, 0.02, 1e-9);
  EXPECT_NEAR(f.claimed_shared_disparity_px, 0.25, 0.01);
  EXPECT_NEAR(f.own_median_d2, 2.37, 0.2);
  EXPECT_NEAR(f.whole_median_d2, 2.37, 0.2);
  EXPECT_NEAR(f.whole_within_3_sigma, 0.97, 0.015);
}

TEST(SharedNoiseFit, FindsNoSharedPartWhereEveryFrameErrsOnItsOwn) {
  const world::WorldModel world = wall_of_doors();
  const ClassFit f = fit(world, synthetic_scans(world, Truth{}, 40, 8));
  // The within-group share is taken out: what is left is sampling noise around zero.
  EXPECT_LT(f.floor_m, 0.002);
  EXPECT_LT(f.shared_disparity_px, 0.03);
}

TEST(SharedNoiseFit, ShowsCovariancesThatLeaveTheSharedPartOut) {
  const world::WorldModel world = wall_of_doors();
  Truth truth;
  truth.floor_m = 0.03;
  truth.claim_truthfully = false;
  const ClassFit f = fit(world, synthetic_scans(world, truth, 20, 9));
  EXPECT_NEAR(f.floor_m, 0.03, 0.004);
  EXPECT_EQ(f.claimed_floor_m, 0.0);
  EXPECT_NEAR(f.own_median_d2, 2.37, 0.25);  // the own part is honest
  EXPECT_GT(f.whole_median_d2, 10.0);        // the whole is not
  EXPECT_LT(f.whole_within_3_sigma, 0.5);
}

TEST(SharedNoiseFit, LeavesOutPerceptsFarFromEveryObjectAndSmallGroups) {
  const world::WorldModel world = wall_of_doors();
  std::vector<ScanFrames> scans = synthetic_scans(world, Truth{}, 2, 10);
  FramePerceptRecord stray = scans[0].percepts[0];
  stray.ego_position_m += Eigen::Vector3d(0.0, 0.0, 0.3);  // between two doors' heights
  scans[0].percepts.push_back(stray);
  scans[1].percepts.resize(2);  // one object, two frames: below min_percepts
  const ClassFit f = fit(world, scans);
  EXPECT_EQ(f.unmatched, 1);
  EXPECT_EQ(f.groups, 24);
  EXPECT_EQ(f.scans, 1);
}

TEST(SharedNoiseFit, RefusesOptionsOutOfRange) {
  const world::WorldModel world = wall_of_doors();
  FitOptions options;
  options.match_along_m = 0.0;
  EXPECT_THROW(fit_shared_noise({ScanSet{&world, {}}}, options), std::invalid_argument);
  EXPECT_THROW(fit_shared_noise({ScanSet{nullptr, {}}}, FitOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::scan_noise
