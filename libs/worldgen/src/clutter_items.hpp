// The things that stand about in kitchens, as closed solids for randomized looks
// (randomize_looks.hpp): packets, bottles, jars, kettles, toasters, microwaves, coffee machines,
// towels, bowls, boards; on the floor boxes, bins, bags, crates, buckets. Internal to
// vsl_worldgen.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "random.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::worldgen {

// An item in its own frame: the origin on the surface it rests on (z up), x right, y back, so that
// its front faces -y. Primitives name parts ("body", "lid"); `parts` gives each part's look.
struct ClutterItem {
  std::string kind;
  std::vector<world::Primitive> primitives;
  std::vector<world::Material> parts;
  bool against_back = false;  // an appliance: stands at the back, square to the worktop's edge
  bool draped = false;        // a towel over the worktop's front edge (origin on the edge)
};

ClutterItem worktop_item(Rng& rng);
ClutterItem floor_item(Rng& rng);
// A towel hanging over a worktop's front edge: its origin on the edge's top, a flat part on the
// top (y > 0), a hanging part in front of the edge (y < 0), down to 0.15-0.35 m below it.
ClutterItem draped_towel(Rng& rng);

}  // namespace vsl::worldgen
