// The building generator (building.hpp).
#include "vsl/worldgen/building.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "random.hpp"
#include "vsl/worldgen/geometry.hpp"
#include "vsl/worldgen/world_builder.hpp"

namespace vsl::worldgen {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
using world::ObjectModel;

constexpr double kPi = std::numbers::pi;
constexpr double kSlab = 0.2;       // floor slab under every storey
constexpr double kPartition = 0.1;  // walls between rooms and along corridors
constexpr double kOuterWall = 0.25;
constexpr double kDoorT = 0.019;  // furniture fronts
constexpr double kGap = 0.004;
constexpr double kProjection = 0.03;  // handle bar axis in front of its front
constexpr double kBarRadius = 0.006;
constexpr double kSill = 0.9, kLintel = 2.2;  // ribbon windows
constexpr double kDoorWidth = 0.9, kDoorHeight = 2.05;

enum class Kind { office, kitchenette, meeting, store };
enum class HandleAt { top, bottom, middle };
enum class Wall { outer, left, right };

// One room being furnished. Room frame: origin at the interior's corner by the corridor on the
// room's left (seen from the corridor), x along the corridor, y from the corridor wall to the outer
// wall, z up from the floor.
class RoomBuilder {
 public:
  RoomBuilder(WorldBuilder& b, Rng& rng, const BuildingOptions& o, const Isometry3d& frame,
              std::string prefix)
      : b_(b),
        rng_(rng),
        frame_(frame),
        prefix_(std::move(prefix)),
        w_(o.room_width_m - kPartition),
        d_(o.room_depth_m),
        h_(o.storey_height_m - kSlab) {}

  void build(Kind kind, bool left_wall, bool right_wall) {
    structure(left_wall, right_wall);
    switch (kind) {
      case Kind::office:
        office();
        break;
      case Kind::kitchenette:
        kitchenette();
        break;
      case Kind::meeting:
        meeting();
        break;
      case Kind::store:
        store();
        break;
    }
  }

 private:
  std::string id(const std::string& suffix) const { return prefix_ + "." + suffix; }

  // An object at `position` (room frame) turned by `yaw` relative to the room; `boxes` are given
  // as [lo, hi] corners in the room frame and converted to the object's frame.
  ObjectModel& add_boxes(const std::string& object_id, const std::string& type,
                         const std::string& parent, const Vector3d& position, double yaw,
                         const Vector3d& size,
                         const std::vector<std::pair<Vector3d, Vector3d>>& boxes,
                         const char* material) {
    const Isometry3d room_T_object = pose_yaw(position, yaw);
    ObjectModel& o = b_.add(object_id, type, frame_ * room_T_object, size, parent);
    const Isometry3d object_T_room = room_T_object.inverse();
    const Eigen::Matrix3d r = object_T_room.linear();
    for (const auto& [lo, hi] : boxes) {
      o.primitives.push_back(
          box(material, object_T_room * (0.5 * (lo + hi)), (r.cwiseAbs() * (hi - lo)).cwiseAbs()));
    }
    return o;
  }

  // The frame of a unit w wide, dp deep, standing against `wall` with its left end `s` along it
  // (seen from the room) and its centre at height `zc`: x right, y into the wall, z up.
  Isometry3d unit_frame(Wall wall, double s, double w, double dp, double zc) const {
    switch (wall) {
      case Wall::outer:
        return frame_ * pose_yaw({s + w / 2, d_ - dp / 2, zc}, 0.0);
      case Wall::left:
        return frame_ * pose_yaw({dp / 2, s + w / 2, zc}, kPi / 2);
      case Wall::right:
        return frame_ * pose_yaw({w_ - dp / 2, d_ - s - w / 2, zc}, -kPi / 2);
    }
    return frame_;
  }

  void handle(const std::string& handle_id, const std::string& parent, const Isometry3d& front,
              double x, double z, bool horizontal, double length) {
    const Vector3d size = horizontal ? Vector3d(length, kProjection + kBarRadius, 2 * kBarRadius)
                                     : Vector3d(2 * kBarRadius, kProjection + kBarRadius, length);
    ObjectModel& h = b_.add(handle_id, "handle", offset(front, {x, -kProjection, z}), size, parent);
    h.primitives.push_back(
        cylinder("handle", Vector3d::Zero(), kBarRadius, length, horizontal ? Axis::x : Axis::z));
    // One mounting plate behind the bar, reaching back to the front.
    const Vector3d plate = horizontal ? Vector3d(length - 0.04, kProjection, 0.008)
                                      : Vector3d(0.008, kProjection, length - 0.04);
    h.primitives.push_back(box("handle", {0, kProjection / 2, 0}, plate));
  }

  // A carcass (one box) with `doors` doors across its front (0 for open shelving).
  void cupboard(const std::string& cid, const Isometry3d& unit, double w, double dp, double h,
                int doors, HandleAt at) {
    ObjectModel& c = b_.add(cid, "cupboard", unit, Vector3d(w, dp, h));
    c.primitives.push_back(box("carcass", {0, kDoorT / 2, 0}, {w, dp - kDoorT, h}));
    const double dw = w / doors - kGap, dh = h - kGap, length = std::min(0.16, dh - 0.1);
    for (int k = 0; k < doors; ++k) {
      const std::string did = cid + ".d" + std::to_string(k + 1);
      const double x = -w / 2 + (k + 0.5) * w / doors;
      const Isometry3d front = offset(unit, {x, -dp / 2, 0});
      ObjectModel& door = b_.add(did, "door", front, Vector3d(dw, kDoorT, dh), cid);
      door.primitives.push_back(box("door", {0, kDoorT / 2, 0}, {dw, kDoorT, dh}));
      const bool hinge_right = doors == 2 ? k == 1 : rng_.chance(0.5);
      const double hx = (hinge_right ? -1.0 : 1.0) * (dw / 2 - 0.035);
      const double hz = at == HandleAt::top      ? dh / 2 - 0.05 - length / 2
                        : at == HandleAt::bottom ? -dh / 2 + 0.05 + length / 2
                                                 : 0.0;
      handle(did + ".h", did, front, hx, hz, false, length);
    }
  }

  void drawers(const std::string& cid, const Isometry3d& unit, double w, double dp, double h,
               int n) {
    ObjectModel& c = b_.add(cid, "cupboard", unit, Vector3d(w, dp, h));
    c.primitives.push_back(box("carcass", {0, kDoorT / 2, 0}, {w, dp - kDoorT, h}));
    const double slot = h / n;
    for (int k = 0; k < n; ++k) {
      const std::string did = cid + ".dr" + std::to_string(k + 1);
      const Isometry3d front = offset(unit, {0, -dp / 2, h / 2 - (k + 0.5) * slot});
      ObjectModel& drawer =
          b_.add(did, "drawer_front", front, Vector3d(w - kGap, kDoorT, slot - kGap), cid);
      drawer.primitives.push_back(box("door", {0, kDoorT / 2, 0}, {w - kGap, kDoorT, slot - kGap}));
      handle(did + ".h", did, front, 0, 0, true, std::min(0.16, w - 0.1));
    }
  }

  // A chair with its seat top centre at `seat_room` (room frame), turned by `yaw` (its front, -y,
  // faces where the sitter looks).
  void chair(const std::string& cid, const Vector3d& seat_room, double yaw) {
    const Isometry3d pose = frame_ * pose_yaw(seat_room, yaw);
    ObjectModel& c = b_.add(cid, "chair", pose, Vector3d(0.46, 0.46, 0.9));
    c.primitives.push_back(cylinder("chair", {0, 0, -0.24}, 0.025, 0.42, Axis::z));
    c.primitives.push_back(box("chair", {0, 0, -0.03}, {0.46, 0.46, 0.06}));
    c.primitives.push_back(box("chair", {0, 0.21, 0.225}, {0.44, 0.04, 0.45}));
  }

  // A table with its top centre at (x, y, height) in the room, `length` along `yaw`.
  void table(const std::string& tid, double x, double y, double length, double width, double yaw) {
    const Isometry3d pose = frame_ * pose_yaw({x, y, 0.74}, yaw);
    ObjectModel& t = b_.add(tid, "table", pose, Vector3d(length, width, 0.74));
    t.primitives.push_back(box("table", {0, 0, -0.015}, {length, width, 0.03}));
    t.primitives.push_back(box("table", {0, 0, -0.385}, {std::max(0.1, length - 0.6), 0.08, 0.71}));
  }

  // ---- the room's shell ----------------------------------------------------------------------

  void structure(bool left_wall, bool right_wall) {
    const double w = w_, d = d_, h = h_;
    add_boxes(id("floor"), "floor", "", {w / 2, d / 2, 0}, 0.0, {w + kPartition, d, kSlab},
              {{{-kPartition / 2, 0, -kSlab}, {w + kPartition / 2, d + kOuterWall, 0}}}, "floor");
    // Corridor wall with the door opening; its front faces into the room.
    door_x_ = std::round(rng_.uniform(0.25, w - kDoorWidth - 0.25) * 100.0) / 100.0;  // to the cm
    const std::string corridor_wall = id("wall_c");
    add_boxes(corridor_wall, "wall", "", {w / 2, 0, h / 2}, kPi, {w + kPartition, kPartition, h},
              {{{-kPartition / 2, -kPartition, 0}, {door_x_, 0, h}},
               {{door_x_ + kDoorWidth, -kPartition, 0}, {w + kPartition / 2, 0, h}},
               {{door_x_, -kPartition, kDoorHeight}, {door_x_ + kDoorWidth, 0, h}}},
              "wall");
    const std::string outer_wall = id("wall_o");
    add_boxes(outer_wall, "wall", "", {w / 2, d, h / 2}, 0.0, {w + kPartition, kOuterWall, h},
              {{{-kPartition / 2, d, 0}, {w + kPartition / 2, d + kOuterWall, kSill}},
               {{-kPartition / 2, d, kLintel}, {w + kPartition / 2, d + kOuterWall, h}}},
              "wall");
    if (left_wall) {
      add_boxes(id("wall_l"), "wall", "", {0, d / 2, h / 2}, kPi / 2, {d, kPartition, h},
                {{{-kPartition, 0, 0}, {0, d, h}}}, "wall");
    }
    if (right_wall) {
      add_boxes(id("wall_r"), "wall", "", {w, d / 2, h / 2}, -kPi / 2, {d, kPartition, h},
                {{{w, 0, 0}, {w + kPartition, d, h}}}, "wall");
    }
    // Ribbon window from partition to partition, its pane set into the outer wall.
    const double wh = kLintel - kSill, ww = w + kPartition;
    const Isometry3d window_pose = frame_ * pose_yaw({w / 2, d + 0.08, (kSill + kLintel) / 2}, 0.0);
    ObjectModel& window =
        b_.add(id("window"), "window", window_pose, Vector3d(ww, 0.07, wh), outer_wall);
    window.primitives.push_back(box("window_frame", {0, 0.035, -wh / 2 + 0.025}, {ww, 0.07, 0.05}));
    window.primitives.push_back(box("glass", {0, 0.01, 0.025}, {ww, 0.02, wh - 0.05}));
    // The door leaf, its front facing the corridor, and the lever handle on that side.
    const double leaf_w = kDoorWidth - 0.02, leaf_h = kDoorHeight - 0.02;
    const Isometry3d leaf_pose =
        frame_ * pose_yaw({door_x_ + kDoorWidth / 2, -0.07, 0.01 + leaf_h / 2}, 0.0);
    const std::string door = id("door");
    ObjectModel& leaf =
        b_.add(door, "room_door", leaf_pose, Vector3d(leaf_w, 0.04, leaf_h), corridor_wall);
    leaf.primitives.push_back(box("room_door", {0, 0.02, 0}, {leaf_w, 0.04, leaf_h}));
    const double side = rng_.chance(0.5) ? 1.0 : -1.0;  // which edge the handle is on
    const double pivot = side * (leaf_w / 2 - 0.065), lever = 0.13;
    const double bar_x = pivot - side * (lever / 2 - 0.01), z = 1.05 - (0.01 + leaf_h / 2);
    ObjectModel& lever_handle = b_.add(door + ".h", "handle", offset(leaf_pose, {bar_x, -0.06, z}),
                                       Vector3d(lever, 0.07, 0.024), door);
    lever_handle.primitives.push_back(cylinder("handle", Vector3d::Zero(), 0.01, lever, Axis::x));
    lever_handle.primitives.push_back(
        cylinder("handle", {side * (lever / 2 - 0.01), 0.03, 0}, 0.012, 0.06, Axis::y));
  }

  // ---- furnishing ---------------------------------------------------------------------------

  void office() {
    const int desks = w_ >= 3.6 && rng_.chance(0.7) ? 2 : 1;
    const double desk_l = 1.6, span = w_ / desks;
    for (int k = 0; k < desks; ++k) {
      const std::string n = std::to_string(k + 1);
      const double x0 = k * span + (span - desk_l) / 2;  // desk's left end
      // Desk top on an end panel (left) and a drawer pedestal (right), against the outer wall.
      const std::string desk = id("desk" + n);
      add_boxes(desk, "desk", "", {x0 + desk_l / 2, d_ - 0.4, 0.74}, 0.0, {desk_l, 0.8, 0.74},
                {{{x0, d_ - 0.8, 0.71}, {x0 + desk_l, d_, 0.74}},
                 {{x0, d_ - 0.75, 0}, {x0 + 0.03, d_, 0.71}}},
                "table");
      drawers(id("ped" + n), unit_frame(Wall::outer, x0 + desk_l - 0.45, 0.42, 0.6, 0.355), 0.42,
              0.6, 0.71, rng_.chance(0.5) ? 3 : 4);
      chair(id("chair" + n), {x0 + desk_l / 2 - 0.2, d_ - 1.05, 0.45}, kPi);
    }
    // Cupboards on the side walls, clear of the door and of the desks.
    const int tall = rng_.between(1, 2);
    for (int k = 0; k < tall; ++k) {
      const double w = rng_.chance(0.5) ? 0.8 : 1.0, h = rng_.chance(0.5) ? 2.0 : 1.2;
      cupboard(id("cb" + std::to_string(k + 1)),
               unit_frame(Wall::left, 1.1 + k * 1.05, w, 0.42, h / 2), w, 0.42, h, 2,
               h > 1.5 ? HandleAt::middle : HandleAt::top);
    }
    if (rng_.chance(0.6)) {
      cupboard(id("cb3"), unit_frame(Wall::right, 0.9, 0.8, 0.45, 0.4), 0.8, 0.45, 0.8, 2,
               HandleAt::top);
      cupboard(id("cb4"), unit_frame(Wall::right, 1.7, 0.8, 0.45, 0.4), 0.8, 0.45, 0.8, 2,
               HandleAt::top);
    } else {
      const Isometry3d shelf = unit_frame(Wall::right, 0.9, 1.0, 0.35, 1.0);
      ObjectModel& s = b_.add(id("shelf1"), "shelf", shelf, Vector3d(1.0, 0.35, 2.0));
      s.primitives.push_back(box("carcass", {0, 0.16, 0}, {1.0, 0.03, 2.0}));
      s.primitives.push_back(box("carcass", {0, 0, -0.99}, {1.0, 0.35, 0.02}));
    }
  }

  void kitchenette() {
    // Base units along the left wall from the outer wall's end towards the corridor.
    const double base_h = 0.72, plinth = 0.14, dp = 0.6;
    double s = 1.2;
    int n = 0;
    const double end = d_;
    const std::vector<int> kinds = {0, 1, 2, 1};  // 0 two-door, 1 drawers, 2 sink cupboard
    std::string sink_unit;
    double sink_s = 0;
    while (s + 0.6 <= end - 0.6 + 1e-9 && n < 4) {
      const int kind = n == 0 ? 2 : rng_.pick(kinds);
      const std::string u = id("base" + std::to_string(++n));
      const Isometry3d unit = unit_frame(Wall::left, s, 0.6, dp, plinth + base_h / 2);
      if (kind == 1) {
        drawers(u, unit, 0.6, dp, base_h, 3);
      } else {
        cupboard(u, unit, 0.6, dp, base_h, kind == 2 ? 2 : 1, HandleAt::top);
      }
      if (kind == 2 && sink_unit.empty()) {
        sink_unit = u;
        sink_s = s;
      }
      s += 0.6;
    }
    const double run_end = s;
    // The fridge closes the run against the outer wall.
    {
      const double fh = 1.8;
      const std::string f = id("fridge");
      const Isometry3d unit = unit_frame(Wall::left, run_end, 0.6, 0.62, fh / 2);
      ObjectModel& body = b_.add(f, "fridge", unit, Vector3d(0.6, 0.62, fh));
      body.primitives.push_back(box("appliance", {0, kDoorT / 2, 0}, {0.6, 0.62 - kDoorT, fh}));
      for (int k = 0; k < 2; ++k) {
        const double slot = k == 0 ? 0.8 : fh - 0.8,
                     z = k == 0 ? -fh / 2 + 0.4 : -fh / 2 + 0.8 + slot / 2;
        const std::string did = f + ".d" + std::to_string(k + 1);
        const Isometry3d front = offset(unit, {0, -0.31, z});
        ObjectModel& door =
            b_.add(did, "door", front, Vector3d(0.6 - kGap, kDoorT, slot - kGap), f);
        door.primitives.push_back(
            box("door", {0, kDoorT / 2, 0}, {0.6 - kGap, kDoorT, slot - kGap}));
        handle(did + ".h", did, front, 0.6 / 2 - 0.04, k == 0 ? slot / 2 - 0.15 : -slot / 2 + 0.15,
               false, 0.2);
      }
    }
    // Worktop, a sit-on sink bowl, wall cupboards above.
    const double top = plinth + base_h + 0.04;
    const std::string worktop = id("worktop");
    add_boxes(worktop, "countertop", "", {0.31, (1.2 + run_end) / 2, top}, kPi / 2,
              {run_end - 1.2, 0.62, 0.04}, {{{0, 1.2, top - 0.04}, {0.62, run_end, top}}},
              "countertop");
    if (!sink_unit.empty()) {
      const Isometry3d sink_pose = unit_frame(Wall::left, sink_s, 0.6, dp, top);
      ObjectModel& sink =
          b_.add(sink_unit + ".sink", "sink", sink_pose, Vector3d(0.44, 0.36, 0.15), worktop);
      sink.primitives.push_back(
          polyhedron("steel", {0, 0, 0.15}, basin({0.44, 0.36}, 0.15, 0.03, 0.01, 0.015)));
    }
    for (int k = 0; k < rng_.between(2, 3); ++k) {
      const double s0 = 1.2 + k * 0.6;
      if (s0 + 0.6 > run_end + 1e-9) break;
      cupboard(id("upper" + std::to_string(k + 1)),
               unit_frame(Wall::left, s0, 0.6, 0.34, 1.45 + 0.36), 0.6, 0.34, 0.72, 1,
               HandleAt::bottom);
    }
    table(id("table"), w_ * 0.6, d_ * 0.55, 1.2, 0.8, 0.0);
    const int chairs = rng_.between(2, 4);
    const double tx = w_ * 0.6, ty = d_ * 0.55;
    const Vector3d places[4] = {{tx - 0.3, ty + 0.5, 0.45},
                                {tx + 0.3, ty + 0.5, 0.45},
                                {tx - 0.3, ty - 0.5, 0.45},
                                {tx + 0.3, ty - 0.5, 0.45}};
    const double yaws[4] = {0.0, 0.0, kPi, kPi};
    for (int k = 0; k < chairs; ++k) chair(id("chair" + std::to_string(k + 1)), places[k], yaws[k]);
  }

  void meeting() {
    const double length = std::min(2.4, w_ - 1.6), width = 1.0;
    const double tx = w_ / 2, ty = d_ / 2 + 0.2;
    table(id("table"), tx, ty, length, width, 0.0);
    const int per_side = length >= 2.2 ? 3 : 2;
    int n = 0;
    for (double side : {1.0, -1.0}) {
      for (int k = 0; k < per_side; ++k) {
        const double x = tx - length / 2 + (k + 0.5) * length / per_side;
        chair(id("chair" + std::to_string(++n)), {x, ty + side * (width / 2 + 0.15), 0.45},
              side > 0 ? 0.0 : kPi);
      }
    }
    if (rng_.chance(0.5))
      chair(id("chair" + std::to_string(++n)), {tx + length / 2 + 0.15, ty, 0.45}, -kPi / 2);
    cupboard(id("sideboard"), unit_frame(Wall::right, 0.4, 1.6, 0.45, 0.4), 1.6, 0.45, 0.8, 2,
             HandleAt::top);
    drawers(id("sideboard2"), unit_frame(Wall::right, 2.0, 0.6, 0.45, 0.4), 0.6, 0.45, 0.8, 3);
    const Isometry3d board = unit_frame(Wall::left, 1.3, 2.0, 0.02, 1.5);
    ObjectModel& b = b_.add(id("board"), "whiteboard", board, Vector3d(2.0, 0.02, 1.2));
    b.primitives.push_back(box("appliance", Vector3d::Zero(), {2.0, 0.02, 1.2}));
  }

  void store() {
    int n = 0;
    for (Wall wall : {Wall::left, Wall::right}) {
      double s = wall == Wall::left ? 1.1 : 0.0;
      const double end = wall == Wall::left ? d_ : d_ - 1.1;
      while (true) {
        const double w = rng_.chance(0.5) ? 0.8 : 1.0;
        if (s + w > end + 1e-9) break;
        const double h = 2.0;
        cupboard(id("cb" + std::to_string(++n)), unit_frame(wall, s, w, 0.5, h / 2), w, 0.5, h, 2,
                 HandleAt::middle);
        s += w;
      }
    }
    // Low cupboards under the window, between the tall rows.
    double s = 0.55;
    while (s + 0.8 <= w_ - 0.55 + 1e-9) {
      cupboard(id("cb" + std::to_string(++n)), unit_frame(Wall::outer, s, 0.8, 0.45, 0.4), 0.8,
               0.45, 0.8, 2, HandleAt::top);
      s += 0.8;
    }
  }

  WorldBuilder& b_;
  Rng& rng_;
  Isometry3d frame_;
  std::string prefix_;
  double w_, d_, h_;
  double door_x_ = 0.0;
};

std::uint64_t mix(std::uint64_t seed, std::uint64_t index) {
  Rng rng(seed ^ (index * 0xd1b54a32d192ed03ull));
  return rng.next();
}

}  // namespace

void validate(const BuildingOptions& o) {
  auto fail = [](const std::string& what) { throw config::Error(what); };
  if (o.objects < 1 || o.objects > 10'000'000) fail("objects must be in [1, 10000000]");
  if (o.room_width_m < 3.0 || o.room_width_m > 20.0) fail("room width must be in [3, 20] m");
  if (o.room_depth_m < 3.0 || o.room_depth_m > 20.0) fail("room depth must be in [3, 20] m");
  if (o.corridor_width_m < 1.2 || o.corridor_width_m > 10.0)
    fail("corridor width must be in [1.2, 10] m");
  if (o.storey_height_m < 2.6 || o.storey_height_m > 10.0)
    fail("storey height must be in [2.6, 10] m");
  if (o.courtyard_m < 0.0 || o.courtyard_m > 100.0) fail("courtyard must be in [0, 100] m");
  if (o.rooms_per_side < 0 || o.rooms_per_side > 1000) fail("rooms per side must be in [0, 1000]");
  if (o.max_rooms_per_storey < 2) fail("max rooms per storey must be >= 2");
  for (double share : {o.office, o.kitchenette, o.meeting, o.store}) {
    if (!(share >= 0.0) || !std::isfinite(share)) fail("room mix shares must be >= 0");
  }
  if (!(o.office + o.kitchenette + o.meeting + o.store > 0.0))
    fail("room mix shares must not all be 0");
}

world::WorldModel generate_building(const BuildingOptions& o, const Progress& progress) {
  validate(o);
  const std::size_t target = o.objects;
  // Storey plan: about 40 objects per room; corridor blocks side by side on each storey.
  const std::size_t rooms_estimate = target / 40 + 1;
  const int per_storey = static_cast<int>(
      std::clamp<std::size_t>(rooms_estimate, 2, static_cast<std::size_t>(o.max_rooms_per_storey)));
  const int per_side = o.rooms_per_side > 0
                           ? o.rooms_per_side
                           : std::clamp(static_cast<int>(std::ceil(std::sqrt(per_storey))), 1, 24);
  const int blocks = std::max(1, (per_storey + 2 * per_side - 1) / (2 * per_side));
  const std::size_t rooms_per_storey = static_cast<std::size_t>(2 * per_side * blocks);
  const double pitch = 2 * o.room_depth_m + o.corridor_width_m + o.courtyard_m;
  const double total = o.office + o.kitchenette + o.meeting + o.store;

  WorldBuilder b(o.name, palette_materials());
  std::size_t reported = 0;
  for (std::size_t r = 0; b.size() < target; ++r) {
    const std::size_t storey = r / rooms_per_storey, in_storey = r % rooms_per_storey;
    const int block = static_cast<int>(in_storey / (2 * per_side));
    const int in_block = static_cast<int>(in_storey % (2 * per_side));
    const bool north = in_block >= per_side;
    const int i = in_block % per_side;
    const double z0 = static_cast<double>(storey) * o.storey_height_m;
    const double y0 = block * pitch;
    const std::string block_id = "s" + std::to_string(storey) + "b" + std::to_string(block);
    if (in_block == 0) {  // the corridor's floor
      const double length = per_side * o.room_width_m;
      ObjectModel& floor =
          b.add(block_id + ".corridor", "floor",
                pose_yaw({length / 2, y0 + o.room_depth_m + o.corridor_width_m / 2, z0}, 0.0),
                Vector3d(length, o.corridor_width_m, kSlab));
      floor.primitives.push_back(
          box("floor", {0, 0, -kSlab / 2}, {length, o.corridor_width_m, kSlab}));
    }
    const Isometry3d frame =
        north ? pose_yaw({i * o.room_width_m + kPartition / 2,
                          y0 + o.room_depth_m + o.corridor_width_m, z0},
                         0.0)
              : pose_yaw({(i + 1) * o.room_width_m - kPartition / 2, y0 + o.room_depth_m, z0}, kPi);
    Rng rng(mix(o.seed, r));
    const double roll = rng.uniform() * total;
    const Kind kind = roll < o.office                               ? Kind::office
                      : roll < o.office + o.kitchenette             ? Kind::kitchenette
                      : roll < o.office + o.kitchenette + o.meeting ? Kind::meeting
                                                                    : Kind::store;
    char number[16];
    std::snprintf(number, sizeof number, "%02d", i);
    RoomBuilder room(b, rng, o, frame, block_id + (north ? "n" : "s") + number);
    const bool last = north ? i == per_side - 1 : i == 0;
    room.build(kind, true, last);
    if (progress && b.size() - reported >= 5000) {
      reported = b.size();
      progress(std::min(reported, target), target);
    }
  }
  b.truncate(target);
  if (progress) progress(target, target);
  return b.finish();
}

BuildingOptions parse_building_layout(const config::Node& root) {
  root.expect_map();
  root.expect_keys({"name", "objects", "seed", "room", "corridor_width", "courtyard",
                    "rooms_per_side", "max_rooms_per_storey", "mix"});
  BuildingOptions o;
  o.name = root.get("name", o.name);
  if (const auto n = root.find("objects")) {
    const std::int64_t v = n->as_int();
    if (v < 1 || v > 10'000'000) n->fail("must be in [1, 10000000]");
    o.objects = static_cast<std::size_t>(v);
  }
  if (const auto s = root.find("seed")) {
    const std::int64_t v = s->as_int();
    if (v < 0) s->fail("must not be negative");
    o.seed = static_cast<std::uint64_t>(v);
  }
  if (const auto room = root.find("room")) {
    room->expect_keys({"size", "storey_height"});
    if (const auto size = room->find("size")) {
      const auto v = size->as_array<2>();
      if (v[0] < 3.0 || v[0] > 20.0 || v[1] < 3.0 || v[1] > 20.0)
        size->fail("each extent must be in [3, 20] m");
      o.room_width_m = v[0];
      o.room_depth_m = v[1];
    }
    if (const auto h = room->find("storey_height")) o.storey_height_m = h->as_double_in(2.6, 10.0);
  }
  if (const auto c = root.find("corridor_width")) o.corridor_width_m = c->as_double_in(1.2, 10.0);
  if (const auto c = root.find("courtyard")) o.courtyard_m = c->as_double_in(0.0, 100.0);
  if (const auto r = root.find("rooms_per_side")) {
    const std::int64_t v = r->as_int();
    if (v < 0 || v > 1000) r->fail("must be in [0, 1000] (0: automatic)");
    o.rooms_per_side = static_cast<int>(v);
  }
  if (const auto r = root.find("max_rooms_per_storey")) {
    const std::int64_t v = r->as_int();
    if (v < 2 || v > 100000) r->fail("must be in [2, 100000]");
    o.max_rooms_per_storey = static_cast<int>(v);
  }
  if (const auto mix_node = root.find("mix")) {
    mix_node->expect_keys({"office", "kitchenette", "meeting", "store"});
    o.office = mix_node->get("office", 0.0);
    o.kitchenette = mix_node->get("kitchenette", 0.0);
    o.meeting = mix_node->get("meeting", 0.0);
    o.store = mix_node->get("store", 0.0);
    for (const char* key : {"office", "kitchenette", "meeting", "store"}) {
      if (const auto v = mix_node->find(key); v && v->as_double() < 0.0)
        v->fail("must not be negative");
    }
    if (!(o.office + o.kitchenette + o.meeting + o.store > 0.0))
      mix_node->fail("at least one share must be positive");
  }
  return o;
}

BuildingOptions load_building_layout(const std::string& path) {
  return parse_building_layout(config::Node::load_file(path));
}

}  // namespace vsl::worldgen
