// Running the localizer over scenarios and judging each result (issue 3).
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "peer.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/scenario/metrics.hpp"
#include "vsl/scenario/scenario.hpp"

namespace vsl::evaluate {

// One scenario to localize: generated in memory (with its truth per percept, so that active
// validation can be simulated), or read from a scenario file.
struct Case {
  std::string name;  // "seed 1 #17" or the file's path
  std::optional<scenario::Scenario> generated;
  std::vector<localization::FusedPercept> percepts;
  Eigen::Isometry3d world_T_ego_truth = Eigen::Isometry3d::Identity();
};

struct CaseResult {
  scenario::Outcome outcome;
  int active_looks = 0;  // gazes of active validation that were simulated
  std::string message;   // the localizer's, for failed and ambiguous results
};

// Localizes `c` once; when the result is ambiguous and `active_rounds` > 0 (generated cases
// only), looks at the localizer's discriminating object (paper §2.4.2) as the simulated head
// would see it from the true pose, adds what it recognized and localizes again, up to
// `active_rounds` times. Stage times are summed over the rounds; wall time is measured around
// every localize() call.
CaseResult run_case(const localization::Localizer& localizer,
                    const scenario::ScenarioGenerator* generator, Case c, int active_rounds,
                    const scenario::Thresholds& thresholds);

// Localizes `c`'s percepts (as generated, before any active look) with the peer, seeded by
// `seed`; wall time (the same clock as run_case) is measured around the peer's call only and is
// also its total_ms.
CaseResult run_peer_case(const PeerLocalizer& peer, const Case& c, std::uint32_t seed,
                         const scenario::Thresholds& thresholds);

}  // namespace vsl::evaluate
