#include "vsl/world/world_graph_options.hpp"

namespace vsl::world {

WorldGraphOptions world_graph_options_from(const config::Node& section) {
  WorldGraphOptions options;
  if (section.is_null()) return options;
  section.expect_keys({"link_threshold_m", "node_types", "edge_node_types"});
  if (const auto threshold = section.find("link_threshold_m")) {
    options.link_threshold_m = threshold->as_double_in(0.01, 1000.0);
  }
  if (const auto types = section.find("node_types")) {
    for (std::size_t i = 0; i < types->size(); ++i)
      options.node_types.push_back((*types)[i].as_string());
  }
  if (const auto types = section.find("edge_node_types")) {
    for (std::size_t i = 0; i < types->size(); ++i)
      options.edge_node_types.push_back((*types)[i].as_string());
  }
  return options;
}

}  // namespace vsl::world
