// The sizes of a world's objects of one type (object_sizes.hpp).
#include "vsl/world/object_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace vsl::world {
namespace {

// Sizes within this are one (metres): a model's rounding, not another kind of door.
constexpr double kSameSizeM = 0.005;

std::vector<SizeCount> counted(std::vector<double> sizes) {
  std::sort(sizes.begin(), sizes.end());
  std::vector<SizeCount> out;
  for (const double s : sizes) {
    if (out.empty() || s - out.back().size_m > kSameSizeM) out.push_back({s, 0});
    ++out.back().count;
  }
  return out;
}

// The most common size (the smaller of equals) and the RMS of all about it.
std::pair<double, double> mode_and_spread(const std::vector<SizeCount>& counts) {
  const auto mode =
      std::max_element(counts.begin(), counts.end(),
                       [](const SizeCount& a, const SizeCount& b) { return a.count < b.count; });
  double sum2 = 0.0;
  int n = 0;
  for (const SizeCount& c : counts) {
    sum2 += c.count * (c.size_m - mode->size_m) * (c.size_m - mode->size_m);
    n += c.count;
  }
  return {mode->size_m, std::sqrt(sum2 / n)};
}

}  // namespace

ClassSizes class_sizes(const WorldModel& world, const std::string& type) {
  ClassSizes out;
  out.type = type;
  std::vector<double> heights, widths;
  for (const ObjectModel& object : world.objects) {
    if (object.type != type || !object.size_m) continue;
    widths.push_back(object.size_m->x());
    heights.push_back(object.size_m->z());
  }
  out.objects = static_cast<int>(heights.size());
  if (out.objects == 0) return out;
  out.heights = counted(heights);
  out.widths = counted(widths);
  // Spreads below kSameSizeM are not measured (sizes within it are one): at least that, so that
  // a world whose doors are all one width still has a prior with a spread.
  std::tie(out.typical_width_m, out.width_sigma_m) = mode_and_spread(out.widths);
  out.width_sigma_m = std::max(out.width_sigma_m, kSameSizeM);
  // At most the smallest height: a spread wider than a door is no prior (and the recognizer's
  // config refuses it); doors of very different heights are each among the typical heights.
  out.height_sigma_m =
      std::clamp(mode_and_spread(out.heights).second, kSameSizeM, out.heights.front().size_m);
  return out;
}

}  // namespace vsl::world
