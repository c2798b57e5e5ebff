// Reading WorldGraphOptions from the `world_graph:` section of a config file.
#pragma once

#include "vsl/config/node.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::world {

// section: {link_threshold_m: 4.0, node_types: [door, handle], edge_node_types: [door]}; every
// key optional. Throws
// config::Error naming file, line and key for a bad value or an unknown key.
WorldGraphOptions world_graph_options_from(const config::Node& section);

}  // namespace vsl::world
