// Eq. 7 noise statistics, and misses and false positives at their configured rates.
#include <gtest/gtest.h>

#include <cmath>

#include "vsl/localization/localizer.hpp"
#include "vsl/scenario/percept_errors.hpp"
#include "vsl/scenario/scenario.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::scenario {
namespace {

localization::PerceptNoiseOptions noise() {
  localization::PerceptNoiseOptions n;
  n.zeta_m = 133.0;
  n.ego_camera_position_m = Eigen::Vector3d(0.05, 0.0, 0.6);
  n.min_sigma_m = 0.005;
  return n;
}

TEST(PerceptErrors, Eq7DeviationGrowsWithTheSquareOfTheDistance) {
  const auto n = noise();
  const Eigen::Vector3d camera = n.ego_camera_position_m;
  EXPECT_NEAR(eq7_sigma_m(camera + Eigen::Vector3d(2, 0, 0), n), 0.030, 0.0005);  // ~3 cm at 2 m
  EXPECT_DOUBLE_EQ(eq7_sigma_m(camera + Eigen::Vector3d(0, 3, 0), n), 9.0 / 133.0);
  EXPECT_DOUBLE_EQ(eq7_sigma_m(camera + Eigen::Vector3d(0, 0, 0.1), n), 0.005);  // the floor
}

TEST(PerceptErrors, NoiseSamplesMatchEq7) {
  const auto n = noise();
  for (const double distance : {1.0, 2.0, 3.5}) {
    const Eigen::Vector3d point = n.ego_camera_position_m + Eigen::Vector3d(0.6, 0.8, 0) * distance;
    const double sigma = distance * distance / n.zeta_m;
    Rng rng(static_cast<std::uint64_t>(distance * 1000));
    constexpr int kSamples = 40000;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum_sq = Eigen::Vector3d::Zero();
    double cross = 0;
    for (int i = 0; i < kSamples; ++i) {
      const Eigen::Vector3d e = with_eq7_noise(point, n, rng) - point;
      sum += e;
      sum_sq += e.cwiseAbs2();
      cross += e.x() * e.y();
    }
    const Eigen::Vector3d mean = sum / kSamples;
    const Eigen::Vector3d std_dev = (sum_sq / kSamples - mean.cwiseAbs2()).cwiseSqrt();
    for (int axis = 0; axis < 3; ++axis) {
      // Standard error of the mean sigma/200, of the deviation about sigma/280: 5 of them.
      EXPECT_NEAR(mean[axis], 0.0, 5 * sigma / 200) << distance;
      EXPECT_NEAR(std_dev[axis], sigma, 5 * sigma / 280) << distance;
    }
    EXPECT_NEAR(cross / kSamples / (sigma * sigma), 0.0, 0.03) << "axes independent";
  }
}

class KitchenScenarios : public ::testing::Test {
 protected:
  static const world::WorldModel& kitchen() {
    static const world::WorldModel world = world::load_world("config/worlds/kitchen.yaml");
    return world;
  }
  static localization::LocalizerOptions localizer() {
    localization::LocalizerOptions o;
    o.graph.node_types = {"door", "handle", "drawer_front", "window"};
    o.noise = noise();
    return o;
  }
};

TEST_F(KitchenScenarios, MissesAndFalsePositivesMatchTheirRates) {
  ScenarioOptions options;
  options.errors.false_positive_rate = 0.1;
  options.errors.miss_rate = 0.2;
  options.errors.wrong_type_fraction = 0.5;
  const ScenarioGenerator generator(kitchen(), options, localizer());
  std::size_t visible = 0, missed = 0, percepts = 0, false_positives = 0, wrong_type = 0;
  for (std::size_t i = 0; i < 300; ++i) {
    const Scenario s = generator.generate(17, i);
    visible += s.visible.size();
    for (const bool m : s.missed) missed += m;
    percepts += s.percepts.size();
    for (const PerceptTruth& t : s.truth) {
      if (t.source != PerceptSource::object) ++false_positives;
      if (t.source == PerceptSource::wrong_type) ++wrong_type;
    }
  }
  ASSERT_GT(visible, 3000u);
  const double miss_rate = static_cast<double>(missed) / visible;
  const double fp_rate = static_cast<double>(false_positives) / percepts;
  const double wrong_type_share = static_cast<double>(wrong_type) / false_positives;
  EXPECT_NEAR(miss_rate, 0.2, 0.02);
  EXPECT_NEAR(fp_rate, 0.1, 0.015);
  EXPECT_NEAR(wrong_type_share, 0.5, 0.08);
  std::printf("visible %zu, miss rate %.4f, false-positive share %.4f (wrong type %.3f)\n", visible,
              miss_rate, fp_rate, wrong_type_share);
}

TEST_F(KitchenScenarios, FalsePositivesLookLikePercepts) {
  ScenarioOptions options;
  options.errors.false_positive_rate = 0.5;
  const ScenarioGenerator generator(kitchen(), options, localizer());
  const auto& objects = kitchen().objects;
  int spurious = 0, wrong = 0;
  for (std::size_t i = 0; i < 40; ++i) {
    const Scenario s = generator.generate(3, i);
    for (std::size_t k = 0; k < s.percepts.size(); ++k) {
      const auto& p = s.percepts[k];
      const auto& t = s.truth[k];
      const double range = (p.ego_position_m - noise().ego_camera_position_m).norm();
      EXPECT_GE(p.support, 1);
      switch (t.source) {
        case PerceptSource::object:
          EXPECT_EQ(p.type, objects[*t.object_index].type);
          break;
        case PerceptSource::wrong_type:
          ++wrong;
          EXPECT_NE(p.type, objects[*t.object_index].type);
          EXPECT_LT(range, 4.5 + 0.5);
          break;
        case PerceptSource::spurious:
          ++spurious;
          EXPECT_FALSE(t.object_index);
          EXPECT_GE(range, 0.5 - 1e-9);
          EXPECT_LE(range, 4.5 + 1e-9);
          EXPECT_GE(views_containing(options.scan, noise().ego_camera_position_m, p.ego_position_m),
                    1);
          break;
      }
    }
  }
  EXPECT_GT(spurious, 20);
  EXPECT_GT(wrong, 20);
}

TEST_F(KitchenScenarios, WithoutErrorsEveryVisibleObjectIsReportedNearItsTruePlace) {
  ScenarioOptions options;
  options.errors.false_positive_rate = 0.0;
  options.errors.miss_rate = 0.0;
  options.errors.write_covariance = true;
  const ScenarioGenerator generator(kitchen(), options, localizer());
  for (std::size_t i = 0; i < 50; ++i) {
    const Scenario s = generator.generate(5, i);
    ASSERT_EQ(s.percepts.size(), s.visible.size());
    for (std::size_t k = 0; k < s.percepts.size(); ++k) {
      const auto& p = s.percepts[k];
      ASSERT_EQ(s.truth[k].source, PerceptSource::object);
      const auto seen = std::find_if(s.visible.begin(), s.visible.end(), [&](const SeenObject& v) {
        return v.object_index == *s.truth[k].object_index;
      });
      ASSERT_NE(seen, s.visible.end());
      const double sigma = eq7_sigma_m(seen->ego_position_m, noise());
      EXPECT_LT((p.ego_position_m - seen->ego_position_m).norm(), 6 * sigma);
      EXPECT_EQ(p.support, seen->views);
      ASSERT_TRUE(p.ego_covariance_m2);
      EXPECT_NEAR((*p.ego_covariance_m2)(0, 0), std::pow(eq7_sigma_m(p.ego_position_m, noise()), 2),
                  1e-15);
      // The ego-frame point is the world point seen from the true pose.
      EXPECT_TRUE((s.world_T_ego * seen->ego_position_m)
                      .isApprox(kitchen().objects[seen->object_index].world_position_m, 1e-12));
    }
  }
}

}  // namespace
}  // namespace vsl::scenario
