// Door panels: slab, shaker, glass and framed (see door_styles.hpp).
#include "door_styles.hpp"

#include <algorithm>
#include <numbers>

#include "vsl/worldgen/geometry.hpp"

namespace vsl::worldgen {
namespace {

using Eigen::Vector3d;

constexpr double kMinFrameDoor = 0.25;  // smaller panels are slabs: a frame would leave no centre
// Shaker: a narrow frame around a flat panel set back from it.
constexpr double kShakerStile = 0.06;
constexpr double kShakerRecess = 0.006;
// Glass: a narrow frame around a pane in the middle of the door's thickness.
constexpr double kGlassStile = 0.055;
constexpr double kPaneThickness = 0.004;
// Framed: a wide flat frame; a field set deep behind it carries a raised panel whose bevelled
// edges slope from the field up to just behind the frame's face, so the panel reads as a
// separate raised shape (unlike shaker's flat recessed centre).
constexpr double kMinFramedDoor = 0.3;
constexpr double kFramedStile = 0.08;
constexpr double kFieldRecess = 0.01;    // field's face behind the frame's face
constexpr double kFieldMargin = 0.012;   // flat field left around the raised panel
constexpr double kBevel = 0.03;          // bevel width, each side
constexpr double kRaisedBehind = 0.002;  // raised panel's face behind the frame's face

void slab(world::ObjectModel& door, const PanelRect& p) {
  const double t = p.thickness_m;
  door.primitives.push_back(box("door", {0, t / 2, p.centre_z_m}, {p.width_m, t, p.height_m}));
}

// Two stiles, then two rails between them, all the door's thickness: the order shaker doors have
// always been written in.
void frame(world::ObjectModel& door, const PanelRect& p, double stile) {
  const double t = p.thickness_m, w = p.width_m, h = p.height_m, z = p.centre_z_m;
  for (double side : {-1.0, 1.0}) {
    door.primitives.push_back(box("door", {side * (w - stile) / 2, t / 2, z}, {stile, t, h}));
  }
  for (double side : {-1.0, 1.0}) {
    door.primitives.push_back(
        box("door", {0, t / 2, z + side * (h - stile) / 2}, {w - 2 * stile, t, stile}));
  }
}

void shaker(world::ObjectModel& door, const PanelRect& p) {
  const double t = p.thickness_m;
  frame(door, p, kShakerStile);
  door.primitives.push_back(
      box("door", {0, (t + kShakerRecess) / 2, p.centre_z_m},
          {p.width_m - 2 * kShakerStile, t - kShakerRecess, p.height_m - 2 * kShakerStile}));
}

void glass(world::ObjectModel& door, const PanelRect& p) {
  frame(door, p, kGlassStile);
  door.primitives.push_back(
      box("glass", {0, p.thickness_m / 2, p.centre_z_m},
          {p.width_m - 2 * kGlassStile, kPaneThickness, p.height_m - 2 * kGlassStile}));
}

void framed(world::ObjectModel& door, const PanelRect& p) {
  const double t = p.thickness_m, z = p.centre_z_m;
  const double iw = p.width_m - 2 * kFramedStile, ih = p.height_m - 2 * kFramedStile;
  frame(door, p, kFramedStile);
  door.primitives.push_back(
      box("door", {0, (t + kFieldRecess) / 2, z}, {iw, t - kFieldRecess, ih}));
  // The raised panel: a frustum built along its own z, turned so that its z is the door's -y
  // (out of the door), standing on the field's face.
  const double bw = iw - 2 * kFieldMargin, bh = ih - 2 * kFieldMargin;
  world::Primitive raised =
      polyhedron("door", {0, kFieldRecess, z},
                 frustum(rectangle(bw, bh), rectangle(bw - 2 * kBevel, bh - 2 * kBevel),
                         kFieldRecess - kRaisedBehind));
  raised.object_orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Vector3d::UnitX()));
  door.primitives.push_back(std::move(raised));
}

}  // namespace

void add_door_panel(world::ObjectModel& door, DoorStyle style, const PanelRect& panel) {
  const double smaller = std::min(panel.width_m, panel.height_m);
  if (style == DoorStyle::framed && smaller < kMinFramedDoor) style = DoorStyle::shaker;
  if (style != DoorStyle::slab && smaller < kMinFrameDoor) style = DoorStyle::slab;
  switch (style) {
    case DoorStyle::slab:
      return slab(door, panel);
    case DoorStyle::shaker:
      return shaker(door, panel);
    case DoorStyle::glass:
      return glass(door, panel);
    case DoorStyle::framed:
      return framed(door, panel);
  }
}

}  // namespace vsl::worldgen
