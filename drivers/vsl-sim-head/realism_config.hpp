// The `realism:` section of vsl-sim-head's config -> vsl::render::RealismOptions: how far the
// rendered images go beyond flat colours (materials and light, then the camera's own effects).
// Every key optional (defaults are RealismOptions'), every value validated; units and ranges in
// docs/head.md.
#pragma once

#include <optional>
#include <string_view>

#include "vsl/render/renderer.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::sim_head {

render::RealismOptions realism_options_from(const config::Node& section);

using render::realism_level_from_name;

}  // namespace vsl::sim_head
