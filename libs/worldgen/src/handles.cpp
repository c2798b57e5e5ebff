// Handles: bars, knobs, cup pulls, recessed grips, rails and the room door's (see handles.hpp).
#include "handles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "vsl/worldgen/geometry.hpp"

namespace vsl::worldgen {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector2d;
using Eigen::Vector3d;
using world::ObjectModel;

// Bars (m).
constexpr double kBarRadius = 0.006;
constexpr double kProjection = 0.032;  // bar axis in front of the front surface
constexpr double kStandoff = 0.010;    // square post side, or round post diameter
constexpr double kStandoffSpacing = 0.128;
constexpr double kHandleEdge = 0.035;   // bar axis from a door's opening edge
constexpr double kHandleEnd = 0.05;     // bar end from a door's top or bottom edge
constexpr double kFlapGripDrop = 0.06;  // a flap's centred grip below its top edge
// Knobs (m): a disc on a thinner stem.
constexpr double kKnobThickness = 0.014;
constexpr double kKnobStem = 0.016;
constexpr double kKnobEdge = 0.04;  // knob centre from the opening edge
constexpr double kKnobEnd = 0.06;   // knob centre from the top or bottom edge
// Cup pulls (m): a quarter-elliptic shell open at the bottom, on a mounting plate.
constexpr double kCupDepth = 0.024;   // out from the front at the lip
constexpr double kCupHeight = 0.032;  // from the opening up to where the shell meets the front
constexpr double kCupShell = 0.003;
constexpr double kCupPlateAbove = 0.012;  // mounting plate above the shell
constexpr double kCupPlateEar = 0.01;     // plate beyond the shell at each end
constexpr double kCupEdge = 0.03;         // plate end from the opening edge, or top/bottom edge
// Recessed grips (m): a channel along the edge, its back set into the door.
constexpr double kGripHeight = 0.032;
constexpr double kGripBack = 0.006;   // the channel's back plate, against the carcass
constexpr double kGripLedge = 0.004;  // the channel's floor (top grips) or roof (bottom grips)
// Rails (m).
constexpr double kRailRadius = 0.007;
constexpr double kRailEdge = 0.035;      // rail axis from the edge it runs along
constexpr double kRailEnd = 0.04;        // rail end from the front's sides (horizontal rails)
constexpr double kTallRailEnd = 0.10;    // rail end from a tall door's top and bottom
constexpr double kRailPostInset = 0.03;  // end standoffs from the rail's ends
constexpr double kRailMiddlePost = 0.9;  // longer rails get a third standoff in the middle

double length_of(const HandleStyle& style) {
  return style.length_m.value_or(default_handle_length_m(style.kind));
}

// A bar or rail: a cylinder on standoffs at `posts` (positions along the bar).
void bar_on_posts(WorldBuilder& builder, const HandleStyle& style, const std::string& id,
                  const std::string& parent, const Isometry3d& front, const Vector2d& at_xz,
                  bool horizontal, double length, double radius, const std::vector<double>& posts) {
  const Vector3d size = horizontal ? Vector3d(length, kProjection + radius, 2 * radius)
                                   : Vector3d(2 * radius, kProjection + radius, length);
  ObjectModel& h =
      builder.add(id, "handle", offset(front, {at_xz.x(), -kProjection, at_xz.y()}), size, parent);
  h.primitives.push_back(
      cylinder("handle", Vector3d::Zero(), radius, length, horizontal ? Axis::x : Axis::z));
  for (double s : posts) {
    const Vector3d centre =
        horizontal ? Vector3d(s, kProjection / 2, 0) : Vector3d(0, kProjection / 2, s);
    if (style.round_standoffs) {
      h.primitives.push_back(cylinder("handle", centre, kStandoff / 2, kProjection, Axis::y));
    } else {
      h.primitives.push_back(box("handle", centre, {kStandoff, kProjection, kStandoff}));
    }
  }
}

void bar(WorldBuilder& builder, const HandleStyle& style, const FrontSpec& f) {
  const double w = f.width_m, h = f.height_m, wanted = length_of(style);
  const std::string id = f.id + ".handle";
  if (f.opening_side == 0.0) {  // drawers (centred), flaps (below the top edge): horizontal
    const double z = f.at == GripAt::top ? h / 2 - kFlapGripDrop : 0.0;
    add_bar_handle(builder, style, id, f.id, f.world_T_front, 0.0, z, true,
                   std::min(wanted, w - 0.1));
    return;
  }
  const double length = std::min(wanted, h - 2 * kHandleEnd);
  const double x = f.opening_side * (w / 2 - kHandleEdge);
  const double z = f.at == GripAt::top      ? h / 2 - kHandleEnd - length / 2
                   : f.at == GripAt::bottom ? -h / 2 + kHandleEnd + length / 2
                                            : 0.0;
  add_bar_handle(builder, style, id, f.id, f.world_T_front, x, z, false, length);
}

void knob(WorldBuilder& builder, const HandleStyle& style, const FrontSpec& f) {
  const double r = length_of(style) / 2, w = f.width_m, h = f.height_m;
  const double x = f.opening_side * (w / 2 - kKnobEdge);
  double z = 0.0;
  if (f.at == GripAt::top) z = h / 2 - (f.opening_side == 0.0 ? kFlapGripDrop : kKnobEnd);
  if (f.at == GripAt::bottom) z = -h / 2 + kKnobEnd;
  const double projection = kKnobThickness + kKnobStem;
  ObjectModel& k =
      builder.add(f.id + ".handle", "handle", offset(f.world_T_front, {x, -projection, z}),
                  Vector3d(2 * r, projection, 2 * r), f.id);
  k.primitives.push_back(
      cylinder("handle", {0, kKnobThickness / 2, 0}, r, kKnobThickness, Axis::y));
  k.primitives.push_back(
      cylinder("handle", {0, kKnobThickness + kKnobStem / 2, 0}, 0.35 * r, kKnobStem, Axis::y));
}

// The cup's outer surface: a quarter ellipse in (y, z) of the handle's frame from the lip
// (-depth/2, 0) up to the front face (depth/2, height), `inset` inside it.
Vector2d cup_arc(double theta, double inset) {
  return {kCupDepth / 2 - (kCupDepth - inset) * std::sin(theta),
          (kCupHeight - inset) * std::cos(theta)};
}

void cup_pull(WorldBuilder& builder, const HandleStyle& style, const FrontSpec& f) {
  const double cup = length_of(style), plate = cup + 2 * kCupPlateEar;
  const double w = f.width_m, h = f.height_m, tall = kCupHeight + kCupPlateAbove;
  const double x = f.opening_side * std::max(0.0, w / 2 - kCupEdge - plate / 2);
  // The cup's opening (its lowest edge) on the front; the object's position is the centre of
  // what a camera sees of it, the shell and its plate, tall / 2 above the opening.
  const double z = f.at == GripAt::top      ? h / 2 - kCupEdge - tall
                   : f.at == GripAt::bottom ? -h / 2 + kCupEdge
                                            : -tall / 2;  // a drawer's: the cup centred
  ObjectModel& c = builder.add(f.id + ".handle", "handle",
                               offset(f.world_T_front, {x, -kCupDepth / 2, z + tall / 2}),
                               Vector3d(plate, kCupDepth, tall), f.id);
  const Vector3d opening(0, 0, -tall / 2);  // in the handle's frame
  constexpr int kSteps = 8;
  std::vector<Vector2d> shell, cap{{kCupDepth / 2, 0.0}};
  for (int i = kSteps; i >= 0; --i) cap.push_back(cup_arc(i * std::numbers::pi / 2 / kSteps, 0));
  for (int i = 0; i <= kSteps; ++i) shell.push_back(cup_arc(i * std::numbers::pi / 2 / kSteps, 0));
  for (int i = kSteps; i >= 0; --i) {
    shell.push_back(cup_arc(i * std::numbers::pi / 2 / kSteps, kCupShell));
  }
  c.primitives.push_back(polyhedron("handle", opening, prism_x(shell, cup)));
  for (double side : {-1.0, 1.0}) {
    c.primitives.push_back(polyhedron(
        "handle", opening + Vector3d(side * (cup - kCupShell) / 2, 0, 0), prism_x(cap, kCupShell)));
  }
  c.primitives.push_back(box_between(
      "handle", opening + Vector3d(-plate / 2, kCupDepth / 2 - kCupShell, kCupHeight - 0.015),
      opening + Vector3d(plate / 2, kCupDepth / 2, tall)));
}

void recessed(WorldBuilder& builder, const FrontSpec& f, const GripCut& cut) {
  const double w = f.width_m, t = f.thickness_m, g = cut.height_m, e = cut.edge;
  const double z = e * (f.height_m / 2 - g / 2);
  ObjectModel& r = builder.add(f.id + ".handle", "handle", offset(f.world_T_front, {0, 0, z}),
                               Vector3d(w, t, g), f.id);
  // The back of the channel, against the carcass, and its ledge on the panel's edge.
  r.primitives.push_back(box_between("handle", {-w / 2, t - kGripBack, -g / 2}, {w / 2, t, g / 2}));
  const double ledge_z = -e * (g / 2 - kGripLedge / 2);
  r.primitives.push_back(
      box("handle", {0, (t - kGripBack) / 2, ledge_z}, {w, t - kGripBack, kGripLedge}));
}

void rail(WorldBuilder& builder, const HandleStyle& style, const FrontSpec& f) {
  const double w = f.width_m, h = f.height_m;
  const bool vertical = f.tall && f.opening_side != 0.0;
  const double length =
      vertical ? std::max(0.1, h - 2 * kTallRailEnd) : std::max(0.1, w - 2 * kRailEnd);
  Vector2d at(0.0, f.at == GripAt::bottom ? -(h / 2 - kRailEdge) : h / 2 - kRailEdge);
  if (vertical) at = {f.opening_side * (w / 2 - kHandleEdge), 0.0};
  std::vector<double> posts = {-(length / 2 - kRailPostInset)};
  if (length > kRailMiddlePost) posts.push_back(0.0);
  posts.push_back(length / 2 - kRailPostInset);
  bar_on_posts(builder, style, f.id + ".handle", f.id, f.world_T_front, at, !vertical, length,
               kRailRadius, posts);
}

}  // namespace

const char* handle_kind_name(HandleKind kind) {
  switch (kind) {
    case HandleKind::bar:
      return "bar";
    case HandleKind::knob:
      return "knob";
    case HandleKind::cup_pull:
      return "cup_pull";
    case HandleKind::recessed:
      return "recessed";
    case HandleKind::rail:
      return "rail";
  }
  return "?";
}

double default_handle_length_m(HandleKind kind) {
  switch (kind) {
    case HandleKind::bar:
      return 0.16;
    case HandleKind::knob:
      return 0.032;  // diameter
    case HandleKind::cup_pull:
      return 0.096;  // the cup's length; its plate is 2 cm longer
    case HandleKind::recessed:
    case HandleKind::rail:
      return 0.0;  // they span the front
  }
  return 0.0;
}

GripCut grip_cut(const HandleStyle& style, const FrontSpec& front) {
  if (style.kind != HandleKind::recessed) return {};
  // Drawers and flaps are gripped at the top, doors at the end they open from.
  return {std::min(kGripHeight, 0.3 * front.height_m), front.at == GripAt::bottom ? -1.0 : 1.0};
}

void add_front_handle(WorldBuilder& builder, const HandleStyle& style, const FrontSpec& front) {
  switch (style.kind) {
    case HandleKind::bar:
      return bar(builder, style, front);
    case HandleKind::knob:
      return knob(builder, style, front);
    case HandleKind::cup_pull:
      return cup_pull(builder, style, front);
    case HandleKind::recessed:
      return recessed(builder, front, grip_cut(style, front));
    case HandleKind::rail:
      return rail(builder, style, front);
  }
}

void add_bar_handle(WorldBuilder& builder, const HandleStyle& style, const std::string& id,
                    const std::string& parent, const Isometry3d& world_T_front, double x_m,
                    double z_m, bool horizontal, double length_m) {
  const double spacing = std::min(kStandoffSpacing, length_m - 0.03);
  bar_on_posts(builder, style, id, parent, world_T_front, {x_m, z_m}, horizontal, length_m,
               kBarRadius, {-spacing / 2, spacing / 2});
}

void add_room_door_handle(WorldBuilder& builder, HandleKind kind, const Isometry3d& world_T_leaf,
                          double leaf_width_m, double handle_z_m, bool hinge_right) {
  const double side = hinge_right ? -1.0 : 1.0;
  const double pivot_x = side * (leaf_width_m / 2 - 0.065), z = handle_z_m;
  if (kind == HandleKind::knob) {  // a round door knob: knob, neck, rosette
    constexpr double proj = 0.065, r = 0.028, knob_t = 0.03, rosette_t = 0.008;
    ObjectModel& handle =
        builder.add("room_door.handle", "handle", offset(world_T_leaf, {pivot_x, -proj, z}),
                    Vector3d(2 * r, proj, 2 * r), "room_door");
    handle.primitives.push_back(cylinder("handle", {0, knob_t / 2, 0}, r, knob_t, Axis::y));
    const double neck = proj - knob_t - rosette_t;
    handle.primitives.push_back(
        cylinder("handle", {0, knob_t + neck / 2, 0}, 0.009, neck, Axis::y));
    handle.primitives.push_back(
        cylinder("handle", {0, proj - rosette_t / 2, 0}, 0.026, rosette_t, Axis::y));
    return;
  }
  // A lever: rosette and neck at the pivot, the lever towards the hinges.
  constexpr double proj = 0.06, lever = 0.13;
  const double bar_x = pivot_x - side * (lever / 2 - 0.01);
  ObjectModel& handle =
      builder.add("room_door.handle", "handle", offset(world_T_leaf, {bar_x, -proj, z}),
                  Vector3d(lever, proj + 0.01, 0.052), "room_door");
  const double px = side * (lever / 2 - 0.01);
  handle.primitives.push_back(cylinder("handle", Vector3d::Zero(), 0.01, lever, Axis::x));
  handle.primitives.push_back(
      cylinder("handle", {px, (proj - 0.008) / 2, 0}, 0.009, proj - 0.008, Axis::y));
  handle.primitives.push_back(cylinder("handle", {px, proj - 0.004, 0}, 0.026, 0.008, Axis::y));
}

}  // namespace vsl::worldgen
