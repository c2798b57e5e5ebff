// Lambert shading of a flat facet under the renderer's ambient + directional light. The light is
// fixed in the world, so a facet's shade does not depend on the view: the scene bakes it once.
#pragma once

#include <Eigen/Core>

#include <array>

#include "vsl/render/renderer.hpp"

namespace vsl::render {

// Blue, green, red in grey levels (0-255, not yet rounded or clamped), before exposure gain.
using ShadedColour = std::array<float, 3>;

ShadedColour lambert_bgr(const world::Colour& albedo, const Eigen::Vector3d& world_normal,
                         const RenderOptions& options);

}  // namespace vsl::render
