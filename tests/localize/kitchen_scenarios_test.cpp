// End to end, in simulation: the localizer over seeded scenarios of the bundled kitchen in issue
// 3's acceptance setting (Eq. 7 noise, 10 % false positives, 20 % misses), with the shipped
// config. The thresholds are the issue's targets: never confidently wrong, the truth among the
// hypotheses of every ambiguous result, at least 90 % correct-localized (measured: 96 % on seed 1,
// docs/benchmarks.md). Times are measured by vsl-evaluate and the benchmarks, never here.
#include <gtest/gtest.h>

#include "vsl/config/node.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/scenario/metrics.hpp"
#include "vsl/scenario/scenario.hpp"
#include "vsl/world/world_io.hpp"

namespace {

using namespace vsl;

scenario::Summary evaluate_kitchen(std::uint64_t seed, std::size_t count) {
  const world::WorldModel kitchen = world::load_world("config/worlds/kitchen.yaml");
  const localization::LocalizerOptions options =
      localization::localizer_options_from(config::Node::load_file("config/localizer.yaml"));
  const localization::Localizer localizer(kitchen, options);
  scenario::ScenarioOptions scenario_options;
  scenario_options.errors.false_positive_rate = 0.1;
  scenario_options.errors.miss_rate = 0.2;
  const scenario::ScenarioGenerator generator(kitchen, scenario_options, options);
  std::vector<scenario::Outcome> outcomes;
  for (std::size_t i = 0; i < count; ++i) {
    const scenario::Scenario s = generator.generate(seed, i);
    const localization::LocalizationResult result = localizer.localize(s.percepts);
    outcomes.push_back(
        scenario::assess(result, s.world_T_ego, scenario::Thresholds{}, s.percepts.size(), 0.0));
    if (outcomes.back().status == localization::Status::kLocalized) {
      EXPECT_TRUE(outcomes.back().correct) << "seed " << seed << " #" << i << " is localized "
                                           << outcomes.back().error->position_m << " m off";
    }
  }
  return scenario::summarize(outcomes);
}

void expect_targets(const scenario::Summary& s) {
  EXPECT_EQ(s.wrong_confident, 0u);
  EXPECT_EQ(s.ambiguous_with_truth, s.ambiguous);
  EXPECT_GE(s.rate(s.correct), 0.90) << s.correct << " of " << s.scenarios;
  EXPECT_LT(s.position_error_m.median, 0.02);  // measured 0.9 cm
}

TEST(LocalizerOnKitchenScenarios, AcceptanceSettingSeed1) {
  expect_targets(evaluate_kitchen(1, 200));
}
TEST(LocalizerOnKitchenScenarios, AcceptanceSettingSeed2) {
  expect_targets(evaluate_kitchen(2, 200));
}

}  // namespace
