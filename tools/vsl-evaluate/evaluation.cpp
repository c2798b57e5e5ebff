#include "evaluation.hpp"

#include <chrono>

namespace vsl::evaluate {
namespace {

// The one clock of every time vsl-evaluate reports, for the localizer and the peer alike.
using Clock = std::chrono::steady_clock;

void add(localization::StageTimes& sum, const localization::StageTimes& t) {
  sum.proximity_filter_ms += t.proximity_filter_ms;
  sum.orientation_filter_ms += t.orientation_filter_ms;
  sum.hypothesis_generation_ms += t.hypothesis_generation_ms;
  sum.validation_ms += t.validation_ms;
  sum.refinement_ms += t.refinement_ms;
  sum.total_ms += t.total_ms;
}

}  // namespace

CaseResult run_case(const localization::Localizer& localizer,
                    const scenario::ScenarioGenerator* generator, Case c, int active_rounds,
                    const scenario::Thresholds& thresholds) {
  CaseResult out;
  localization::StageTimes times;
  double wall_ms = 0.0;
  const auto localize = [&]() {
    const auto start = Clock::now();
    localization::LocalizationResult result = localizer.localize(c.percepts);
    wall_ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    add(times, result.timing);
    return result;
  };

  localization::LocalizationResult result = localize();
  for (int round = 1; round <= active_rounds && generator && c.generated &&
                      result.status == localization::Status::kAmbiguous;
       ++round) {
    const auto target = localizer.choose_discriminator(result);
    if (!target) break;
    ++out.active_looks;
    const auto seen = generator->look_at(*c.generated, target->ego_target_m, round);
    if (seen.empty()) break;  // nothing new recognized: the hypotheses stay as they are
    for (const auto& [percept, truth] : seen) {
      c.generated->percepts.push_back(percept);
      c.generated->truth.push_back(truth);
      c.percepts.push_back(percept);
    }
    result = localize();
  }
  result.timing = times;
  out.outcome =
      scenario::assess(result, c.world_T_ego_truth, thresholds, c.percepts.size(), wall_ms);
  out.message = result.message;
  return out;
}

CaseResult run_peer_case(const PeerLocalizer& peer, const Case& c, std::uint32_t seed,
                         const scenario::Thresholds& thresholds) {
  const auto start = Clock::now();
  localization::LocalizationResult result = peer.localize(c.percepts, seed);
  const double wall_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  result.timing.total_ms = wall_ms;
  CaseResult out;
  out.outcome =
      scenario::assess(result, c.world_T_ego_truth, thresholds, c.percepts.size(), wall_ms);
  out.message = result.message;
  return out;
}

}  // namespace vsl::evaluate
