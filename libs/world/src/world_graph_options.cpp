#include "vsl/world/world_graph_options.hpp"

#include <utility>

namespace vsl::world {

WorldGraphOptions world_graph_options_from(const config::Node& section,
                                           WorldGraphOptions defaults) {
  WorldGraphOptions options = std::move(defaults);
  if (section.is_null()) return options;
  section.expect_keys({"link_threshold_m", "node_types", "edge_node_types"});
  if (const auto threshold = section.find("link_threshold_m")) {
    options.link_threshold_m = threshold->as_double_in(0.01, 1000.0);
  }
  if (const auto types = section.find("node_types")) {
    options.node_types.clear();
    for (std::size_t i = 0; i < types->size(); ++i)
      options.node_types.push_back((*types)[i].as_string());
  }
  if (const auto types = section.find("edge_node_types")) {
    options.edge_node_types.clear();
    for (std::size_t i = 0; i < types->size(); ++i)
      options.edge_node_types.push_back((*types)[i].as_string());
  }
  return options;
}

}  // namespace vsl::world
