// The import report: what became what, so that a user can fix the rules in one pass.
#include <cstdio>
#include <sstream>

#include "vsl/world_import/import.hpp"

namespace vsl::world_import {
namespace {

void list(std::ostringstream& out, const char* title, const std::vector<std::string>& items,
          std::size_t max_items) {
  if (items.empty()) return;
  out << title << " (" << items.size() << "):\n";
  for (std::size_t i = 0; i < items.size() && i < max_items; ++i) out << "  " << items[i] << "\n";
  if (items.size() > max_items) out << "  ... and " << items.size() - max_items << " more\n";
}

}  // namespace

std::string format_report(const ImportReport& report, bool list_objects,
                          const world::WorldModel& world) {
  std::ostringstream out;
  for (const ImportReport::File& file : report.files) {
    out << "read " << file.path << " (" << model_format_name(file.format) << ", " << file.parts
        << " parts)\n";
  }
  std::size_t objects = 0;
  for (const auto& [type, count] : report.objects_by_type) objects += count;
  out << "objects: " << objects << "\n";
  for (const auto& [type, count] : report.objects_by_type) {
    char line[96];
    std::snprintf(line, sizeof line, "  %-20s %6zu\n", type.c_str(), count);
    out << line;
  }
  out << "rules that fired:\n";
  for (const auto& [rule, count] : report.rules_fired) {
    char line[32];
    std::snprintf(line, sizeof line, "  %6zu  ", count);
    out << line << rule << "\n";
  }
  if (report.rules_fired.empty()) out << "  none\n";
  list(out, "unmatched names, kept as type 'part'", report.unmatched, 200);
  list(out, "skipped by rules", report.skipped, 200);
  list(out, "dropped", report.dropped, 200);
  list(out, "warnings", report.warnings, 200);
  if (report.triangles_read > 0) {
    out << "mesh triangles: " << report.triangles_read << " read, " << report.triangles_kept
        << " kept";
    if (report.simplified_objects > 0) {
      out << " (" << report.simplified_objects << " objects simplified)";
    }
    out << "\n";
  }
  if (list_objects) {
    out << "objects (id, type, reference point in the world frame, m; front decided by):\n";
    for (const world::ObjectModel& object : world.objects) {
      if (object.type == kUnmatchedType) continue;
      char line[256];
      std::snprintf(line, sizeof line, "  %-36s %-14s [%7.3f, %7.3f, %7.3f]", object.id.c_str(),
                    object.type.c_str(), object.world_position_m.x(), object.world_position_m.y(),
                    object.world_position_m.z());
      out << line;
      const auto faced = report.front_decided_by.find(object.id);
      if (faced != report.front_decided_by.end()) out << "  front: " << faced->second;
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace vsl::world_import
