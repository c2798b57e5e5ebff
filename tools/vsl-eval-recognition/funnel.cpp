#include "funnel.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace vsl::tools {
namespace {

// A blob under this share of the object is another object's too; one holding under this share of
// the object is a piece of it.
constexpr double kMinPurity = 0.9;
constexpr double kMinCoverage = 0.6;

}  // namespace

const char* funnel_stage_name(FunnelStage stage) {
  switch (stage) {
    case FunnelStage::kPercept:
      return "percept";
    case FunnelStage::kNoBlob:
      return "no blob";
    case FunnelStage::kMerged:
      return "merged";
    case FunnelStage::kFragment:
      return "fragment";
    case FunnelStage::kStereo:
      return "stereo";
    case FunnelStage::kUndetectedAtBorder:
      return "undetected, at border";
    case FunnelStage::kUndetected:
      return "undetected";
  }
  return "?";
}

FunnelStage funnel_stage(const FunnelSide& left, const FunnelSide& right, bool matched) {
  if (matched) return FunnelStage::kPercept;
  if (left.blob < 0 || right.blob < 0) return FunnelStage::kNoBlob;
  if (left.purity < kMinPurity || right.purity < kMinPurity) return FunnelStage::kMerged;
  if (left.coverage < kMinCoverage || right.coverage < kMinCoverage) return FunnelStage::kFragment;
  if (left.detected && right.detected) return FunnelStage::kStereo;
  if ((!left.detected && left.at_border) || (!right.detected && right.at_border)) {
    return FunnelStage::kUndetectedAtBorder;
  }
  return FunnelStage::kUndetected;
}

void FunnelTally::add(const std::string& type, bool whole, FunnelStage stage,
                      const std::string& stereo) {
  Row& row = rows_[{type, whole}];
  ++row.stages[static_cast<std::size_t>(stage)];
  if (stage == FunnelStage::kStereo) ++row.stereo[stereo];
}

void FunnelTally::print(std::ostream& out) const {
  out << "where the ground-truth objects were lost (per image, the blob holding most of the "
         "object's pixels):\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-7s %-5s %7s %8s %7s %7s %8s %7s %10s %10s\n", "class", "",
                "objects", "percept", "no blob", "merged", "fragment", "stereo", "undet.bord",
                "undetected");
  out << line;
  for (const auto& [key, row] : rows_) {
    int total = 0;
    for (const int n : row.stages) total += n;
    std::snprintf(line, sizeof line, "%-7s %-5s %7d %8d %7d %7d %8d %7d %10d %10d\n",
                  key.first.c_str(), key.second ? "whole" : "cut", total, row.stages[0],
                  row.stages[1], row.stages[2], row.stages[3], row.stages[4], row.stages[5],
                  row.stages[6]);
    out << line;
  }
  for (const auto& [key, row] : rows_) {
    if (row.stereo.empty()) continue;
    std::vector<std::pair<std::string, int>> gates(row.stereo.begin(), row.stereo.end());
    std::stable_sort(gates.begin(), gates.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    out << "  " << key.first << " " << (key.second ? "whole" : "cut")
        << ", detected in both images without a true percept:";
    for (std::size_t i = 0; i < gates.size(); ++i) {
      out << (i ? ", " : " ") << gates[i].first << " " << gates[i].second;
    }
    out << "\n";
  }
  out << "(merged: the blob is under 90% this object in an image; fragment: it holds under 60% "
         "of the object; stereo: the gate that refused the pair of its two detections, "
         "'assigned' when kept but more than the match distance off, 'not_assigned' when the "
         "assignment kept another pair)\n";
}

}  // namespace vsl::tools
