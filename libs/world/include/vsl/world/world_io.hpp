// Loading and writing world-model files (format: docs/world-model.md).
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>

#include "vsl/world/world_model.hpp"

namespace vsl::world {

// Loads and validates a world file. Throws vsl::config::Error with one line naming the file, the
// line, the key and what is wrong (unknown key, duplicate id, missing parent, bad number, ...).
WorldModel load_world(const std::string& path);
// Same, from text; `source_name` stands in for the file name in errors.
WorldModel load_world_from_string(const std::string& text, const std::string& source_name);

// Objects per YAML document when writing: a world of more objects is written as a stream of
// documents (separated by `---`), which load_world parses on all cores.
inline constexpr std::size_t kObjectsPerDocument = 10000;

// Writes a world in the same format (round-trips through load_world up to 1e-6 m / 1e-9 rad;
// mesh vertices to 1e-4 m).
void write_world(const WorldModel& world, std::ostream& out);
void write_world_file(const WorldModel& world, const std::string& path);

}  // namespace vsl::world
