// The `render:` section of vsl-sim-head's config -> vsl::render::RenderOptions (every key
// optional, defaults are RenderOptions'; every value validated).
#pragma once

#include "vsl/render/renderer.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::sim_head {

render::RenderOptions render_options_from(const config::Node& section);

}  // namespace vsl::sim_head
