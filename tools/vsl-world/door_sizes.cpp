// The sizes of a world's objects of one type, printed (door_sizes.hpp).
#include "door_sizes.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace vsl::world_tool {
namespace {

using world::SizeCount;

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

void print_class_sizes(const world::ClassSizes& sizes, const std::string& world_name,
                       std::ostream& out) {
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
