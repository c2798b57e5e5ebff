// Reading WorldGraphOptions from the `world_graph:` section of a config file.
#pragma once

#include "vsl/config/node.hpp"
#include "vsl/world/world_graph.hpp"

namespace vsl::world {

// section: {link_threshold_m: 4.0, node_types: [door, handle], edge_node_types: [door]}; every
// key optional: an absent one keeps its value in `defaults`, a list given replaces the default's.
// Throws config::Error naming file, line and key for a bad value or an unknown key.
WorldGraphOptions world_graph_options_from(const config::Node& section,
                                           WorldGraphOptions defaults = {});

}  // namespace vsl::world
