// What vsl-evaluate prints: a human-readable table, or one JSON object (docs/evaluation.md).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "evaluation.hpp"
#include "peer.hpp"
#include "vsl/scenario/metrics.hpp"

namespace vsl::evaluate {

struct RunInfo {
  std::string world;  // the world's path
  std::string world_name;
  std::size_t world_objects = 0;
  std::string localizer_config;  // file read, or "built-in defaults"
  std::string source;            // "generated" or the scenario directory
  std::uint64_t seed = 0;        // generated only
  double false_positive_rate = 0.0;
  double miss_rate = 0.0;
  int active_rounds = 0;
  scenario::Thresholds thresholds;
};

// The peer's results on the same cases (--peer), scored the same way.
struct PeerReport {
  std::string name;  // PeerLocalizer::name()
  PeerOptions options;
  scenario::Summary summary;
  std::vector<CaseResult> cases;  // in the order of Report::cases
};

struct Report {
  RunInfo info;
  scenario::Summary summary;
  std::size_t active_looks = 0;
  std::vector<std::string> names;  // per case, for --details
  std::vector<CaseResult> cases;
  std::optional<PeerReport> peer;
};

void print_text(const Report& report, bool details, std::ostream& out);
void print_json(const Report& report, bool details, std::ostream& out);

}  // namespace vsl::evaluate
