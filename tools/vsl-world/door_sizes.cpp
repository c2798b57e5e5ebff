// The sizes of a world's objects of one type (door_sizes.hpp).
#include "door_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace vsl::world_tool {
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

std::string listed(const std::vector<SizeCount>& counts) {
  std::string out;
  char buffer[64];
  for (const SizeCount& c : counts) {
    std::snprintf(buffer, sizeof(buffer), "%s%.3f x%d", out.empty() ? "" : ", ", c.size_m, c.count);
    out += buffer;
  }
  return out;
}

}  // namespace

ClassSizes class_sizes(const world::WorldModel& world, const std::string& type) {
  ClassSizes out;
  out.type = type;
  std::vector<double> heights, widths;
  for (const world::ObjectModel& object : world.objects) {
    if (object.type != type || !object.size_m) continue;
    widths.push_back(object.size_m->x());
    heights.push_back(object.size_m->z());
  }
  out.objects = static_cast<int>(heights.size());
  if (out.objects == 0) return out;
  out.heights = counted(heights);
  out.widths = counted(widths);
  std::tie(out.typical_width_m, out.width_sigma_m) = mode_and_spread(out.widths);
  out.height_sigma_m = mode_and_spread(out.heights).second;
  return out;
}

void print_class_sizes(const ClassSizes& sizes, const std::string& world_name, std::ostream& out) {
  out << "# " << sizes.type << " sizes of " << world_name << " (" << sizes.objects
      << " with a size): heights " << listed(sizes.heights) << "; widths " << listed(sizes.widths)
      << "\n";
  std::ostringstream line;
  line << std::fixed << std::setprecision(3) << sizes.type << ": {typical_heights_m: [";
  for (std::size_t k = 0; k < sizes.heights.size(); ++k) {
    line << (k > 0 ? ", " : "") << sizes.heights[k].size_m;
  }
  line << "], height_sigma_m: " << sizes.height_sigma_m
       << ", typical_width_m: " << sizes.typical_width_m
       << ", width_sigma_m: " << sizes.width_sigma_m << "}\n";
  out << line.str();
}

}  // namespace vsl::world_tool
