// Handles of the kitchen generator, one function per handle kind (docs/worldgen.md).
//
// A handle is its own object of type `handle`, child of the front it opens. Its position is the
// centre of the visible grip: the bar's (bar, rail), the knob's front face, the cup pull's
// opening, the recessed grip's opening on the front face. Its `size` is its extents along its own
// axes, which are the front's.
#pragma once

#include <Eigen/Geometry>

#include <string>

#include "vsl/worldgen/kitchen.hpp"
#include "vsl/worldgen/world_builder.hpp"

namespace vsl::worldgen {

// Which end of a front its grip goes to (the end away from the hinge of a flap, the top of a
// base door, the bottom of a wall cupboard's door).
enum class GripAt { top, bottom, middle };

// A door or drawer front that gets a handle. Its front face is its object's y = 0 plane (x right,
// y back, z up), centred on the object's origin.
struct FrontSpec {
  std::string id;  // the front's object id; the handle's is id + ".handle"
  Eigen::Isometry3d world_T_front = Eigen::Isometry3d::Identity();
  double width_m = 0.0;
  double height_m = 0.0;
  double thickness_m = 0.0;
  // +1: a door opening at its right edge (hinged left), -1: at its left edge, 0: a drawer or a
  // dishwasher flap, whose grips are centred.
  double opening_side = 0.0;
  GripAt at = GripAt::middle;
  bool tall = false;  // a fridge's or larder's door: a rail runs along its opening edge
};

// The strip along the top or bottom edge that a recessed grip takes from the front's panel.
struct GripCut {
  double height_m = 0.0;  // 0: the panel fills the front
  double edge = 1.0;      // +1: along the top edge, -1: along the bottom edge
};
GripCut grip_cut(const HandleStyle& style, const FrontSpec& front);

// Adds the handle of `front` in `style`.
void add_front_handle(WorldBuilder& builder, const HandleStyle& style, const FrontSpec& front);

// A bar of `length_m` centred at (x_m, -projection, z_m) in front of `world_T_front` (the
// front's face its y = 0 plane) on two standoffs reaching back to the face; horizontal (along x)
// or vertical (along z). Ovens keep such a bar whatever the layout's handle kind.
void add_bar_handle(WorldBuilder& builder, const HandleStyle& style, const std::string& id,
                    const std::string& parent, const Eigen::Isometry3d& world_T_front, double x_m,
                    double z_m, bool horizontal, double length_m);

// The room door's handle on the room side of `world_T_leaf` (the leaf's front face its y = 0
// plane): a round door knob for knob handles, else a lever towards the hinges.
void add_room_door_handle(WorldBuilder& builder, HandleKind kind,
                          const Eigen::Isometry3d& world_T_leaf, double leaf_width_m,
                          double handle_z_m, bool hinge_right);

}  // namespace vsl::worldgen
