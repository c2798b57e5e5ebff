// Door styles and handle kinds: closed solids within their fronts, reference points on the grip,
// sizes that are the geometry's extents, parents, and looks that differ from one another.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "vsl/worldgen/inspect.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace vsl::worldgen {
namespace {

using Eigen::AlignedBox3d;
using Eigen::Isometry3d;
using Eigen::Vector3d;

// Every kind of front: base doors (both hinges), drawers, an oven, a dishwasher, a fridge, a
// larder, wall cupboards and a room door.
std::string layout_with(const std::string& doors, const std::string& handles) {
  return "room: {size: [5.0, 3.6, 2.5]}\n"
         "doors: {style: " +
         doors + "}\nhandles: " + handles +
         "\n"
         "room_door: {wall: south, at: 1.0}\n"
         "runs:\n"
         "  - wall: north\n"
         "    at: 0.2\n"
         "    base: [fridge, tall_2door_r, base_1door, base_2door, drawers_4, oven, dishwasher]\n"
         "    upper_at: 1.4\n"
         "    upper: [wall_1door_r, wall_2door, wall_1door, {gap: 0.4}, hood]\n";
}

world::WorldModel generate(const std::string& text) {
  return generate_kitchen(parse_kitchen_layout(config::Node::load_string(text, "test.yaml")));
}

const world::ObjectModel& object_of(const world::WorldModel& world, const std::string& id) {
  const auto index = world.find(id);
  EXPECT_TRUE(index.has_value()) << id;
  return world.objects.at(index.value_or(0));
}

// The primitive's bounds in its object's frame.
AlignedBox3d bounds(const world::Primitive& p) {
  const Isometry3d pose = p.object_T_primitive();
  AlignedBox3d out;
  if (const auto* box = std::get_if<world::Box>(&p.shape)) {
    for (int corner = 0; corner < 8; ++corner) {
      const Vector3d sign(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
      out.extend(pose * Vector3d(0.5 * box->size_m.cwiseProduct(sign)));
    }
  } else if (const auto* c = std::get_if<world::Cylinder>(&p.shape)) {
    // Generated cylinders lie along an object axis, so their bounds are exact.
    for (double z : {-c->height_m / 2, c->height_m / 2}) {
      for (double x : {-c->radius_m, c->radius_m}) {
        for (double y : {-c->radius_m, c->radius_m}) out.extend(pose * Vector3d(x, y, z));
      }
    }
  } else {
    for (const Vector3d& v : std::get<world::Polyhedron>(p.shape).vertices_m) {
      out.extend(pose * v);
    }
  }
  return out;
}

AlignedBox3d bounds(const world::ObjectModel& o) {
  AlignedBox3d out;
  for (const world::Primitive& p : o.primitives) out.extend(bounds(p));
  return out;
}

// `child`'s geometry bounds in `parent`'s frame.
AlignedBox3d bounds_in(const world::ObjectModel& child, const world::ObjectModel& parent) {
  const Isometry3d parent_T_child = parent.world_T_object().inverse() * child.world_T_object();
  AlignedBox3d out;
  const AlignedBox3d own = bounds(child);
  for (int corner = 0; corner < 8; ++corner) {
    out.extend(parent_T_child * own.corner(static_cast<AlignedBox3d::CornerType>(corner)));
  }
  return out;
}

std::map<std::string, int> materials_of(const world::ObjectModel& o) {
  std::map<std::string, int> out;
  for (const world::Primitive& p : o.primitives) ++out[p.material];
  return out;
}

bool is_front(const std::string& type) {
  return type == "door" || type == "drawer_front";
}

constexpr const char* kStyles[] = {"slab", "shaker", "glass", "framed"};
constexpr const char* kKinds[] = {"bar", "knob", "cup_pull", "recessed", "rail"};

TEST(DoorStyles, PanelsAreClosedSolidsWithinTheirDoor) {
  for (const char* style : kStyles) {
    const world::WorldModel world = generate(layout_with(style, "{kind: bar}"));
    for (const std::string& problem : check_generated_world(world)) {
      ADD_FAILURE() << style << ": " << problem;
    }
    for (const world::ObjectModel& o : world.objects) {
      if (!is_front(o.type)) continue;
      // The door's position is the centre of its front face: its panel spans the door's width
      // and height, from y = 0 back to the thickness (a drawer's box behind it is carcass).
      AlignedBox3d b;
      for (const world::Primitive& p : o.primitives) {
        if (p.material != "carcass") b.extend(bounds(p));
      }
      const Vector3d half = 0.5 * o.size_m.value();
      EXPECT_NEAR(b.min().y(), 0.0, 1e-9) << style << " " << o.id;
      EXPECT_NEAR(b.max().y(), 2 * half.y(), 1e-9) << style << " " << o.id;
      EXPECT_NEAR(b.min().x(), -half.x(), 1e-9) << style << " " << o.id;
      EXPECT_NEAR(b.max().x(), half.x(), 1e-9) << style << " " << o.id;
      EXPECT_NEAR(b.min().z(), -half.z(), 1e-9) << style << " " << o.id;
      EXPECT_NEAR(b.max().z(), half.z(), 1e-9) << style << " " << o.id;
      EXPECT_EQ(o.primitives.front().material, "door") << style << " " << o.id;
    }
  }
}

TEST(DoorStyles, LookDifferent) {
  std::map<std::string, std::string> signature;  // style -> a cupboard door's primitive makeup
  for (const char* style : kStyles) {
    const world::WorldModel world = generate(layout_with(style, "{kind: bar}"));
    const world::ObjectModel& door = object_of(world, "north.base4.door1");
    const WorldCounts counts = count_world(world);
    std::string text = std::to_string(door.primitives.size());
    for (const auto& [material, n] : materials_of(door)) text += " " + material;
    signature[style] = text;
    const bool glass = std::string(style) == "glass", framed = std::string(style) == "framed";
    EXPECT_EQ(materials_of(door).count("glass"), glass ? 1u : 0u) << style;
    // A framed door's raised panel is a bevelled polyhedron; no other door has one.
    int polyhedra = 0;
    for (const auto& p : door.primitives)
      polyhedra += std::holds_alternative<world::Polyhedron>(p.shape);
    EXPECT_EQ(polyhedra, framed ? 1 : 0) << style;
    EXPECT_GT(counts.of_type("door"), 10u);
    // Fridge and dishwasher doors hide an appliance: never glass.
    for (const char* id : {"north.base1.door1", "north.base1.door2", "north.base7.door"}) {
      EXPECT_EQ(materials_of(object_of(world, id)).count("glass"), 0u) << style << " " << id;
    }
    // Drawer fronts are slabs in every style.
    EXPECT_EQ(object_of(world, "north.base5.drawer1").primitives.front().material, "door");
  }
  EXPECT_EQ(signature["slab"], "1 door");
  EXPECT_EQ(signature["shaker"], "5 door");
  EXPECT_EQ(signature["glass"], "5 door glass");
  EXPECT_EQ(signature["framed"], "6 door");
  EXPECT_EQ(object_of(generate(layout_with("glass", "{kind: bar}")), "north.base2.door1")
                .primitives.size(),
            5u);  // a larder's door is glass too
}

TEST(HandleKinds, EveryFrontHasOneHandleThatIsItsGrip) {
  for (const char* kind : kKinds) {
    const world::WorldModel world =
        generate(layout_with("shaker", std::string("{kind: ") + kind + "}"));
    for (const std::string& problem : check_generated_world(world)) {
      ADD_FAILURE() << kind << ": " << problem;
    }
    std::map<std::string, int> handles;
    for (const world::ObjectModel& o : world.objects) {
      if (o.type != "handle") continue;
      ++handles[o.parent_id];
      EXPECT_EQ(o.id, o.parent_id + ".handle");
      const world::ObjectModel& front = object_of(world, o.parent_id);
      if (!is_front(front.type)) continue;
      // Its size is its geometry's extents; it reaches the front face (nothing floats) and stays
      // within the front's width and height.
      const AlignedBox3d own = bounds(o), in_front = bounds_in(o, front);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(own.sizes()(i), o.size_m.value()(i), 1e-9) << kind << " " << o.id << " " << i;
      }
      const Vector3d half = 0.5 * front.size_m.value();
      EXPECT_GE(in_front.max().y(), -1e-9) << kind << " " << o.id;
      EXPECT_LE(in_front.min().x(), half.x() + 1e-9);
      EXPECT_GE(in_front.min().x(), -half.x() - 1e-9) << kind << " " << o.id;
      EXPECT_LE(in_front.max().x(), half.x() + 1e-9) << kind << " " << o.id;
      EXPECT_GE(in_front.min().z(), -half.z() - 1e-9) << kind << " " << o.id;
      EXPECT_LE(in_front.max().z(), half.z() + 1e-9) << kind << " " << o.id;
      for (const world::Primitive& p : o.primitives) EXPECT_EQ(p.material, "handle") << o.id;
    }
    for (const world::ObjectModel& o : world.objects) {
      if (is_front(o.type)) {
        EXPECT_EQ(handles[o.id], 1) << kind << " " << o.id;
      }
    }
  }
}

// The handle of `id` in a kitchen of `kind` handles: (reference point in the front's frame,
// the handle's own geometry bounds, the handle).
struct Grip {
  Vector3d at;
  AlignedBox3d own;
  world::ObjectModel handle;
  Vector3d front_size;
};

Grip grip(const world::WorldModel& world, const std::string& front_id) {
  const world::ObjectModel& front = object_of(world, front_id);
  const world::ObjectModel& h = object_of(world, front_id + ".handle");
  return {front.world_T_object().inverse() * h.world_position_m, bounds(h), h,
          front.size_m.value()};
}

TEST(HandleKinds, ReferencePointIsTheCentreOfTheVisibleGrip) {
  const std::string base_door = "north.base3.door1", drawer = "north.base5.drawer2";
  {  // Bar: the bar's centre, a cylinder on the reference point.
    const Grip g = grip(generate(layout_with("shaker", "{kind: bar}")), base_door);
    EXPECT_NEAR(g.own.center().x(), 0.0, 1e-9);
    EXPECT_NEAR(g.own.center().z(), 0.0, 1e-9);
    EXPECT_LT(g.at.y(), -0.02);
  }
  {  // Knob: the centre of its front face, near the opening (right) edge and the top.
    const Grip g = grip(generate(layout_with("shaker", "{kind: knob}")), base_door);
    EXPECT_NEAR(g.own.min().y(), 0.0, 1e-9);
    EXPECT_NEAR(g.own.center().x(), 0.0, 1e-9);
    EXPECT_NEAR(g.own.center().z(), 0.0, 1e-9);
    EXPECT_NEAR(g.at.y(), -g.handle.size_m->y(), 1e-9);
    EXPECT_GT(g.at.x(), 0.0);
    EXPECT_GT(g.at.z(), 0.0);
    EXPECT_NEAR(g.handle.size_m->x(), 0.032, 1e-9);  // default diameter
  }
  {  // Cup pull: the centre of the shell and its plate; the opening faces down.
    const Grip g = grip(generate(layout_with("shaker", "{kind: cup_pull}")), drawer);
    EXPECT_NEAR(g.own.center().z(), 0.0, 1e-9);
    EXPECT_NEAR(g.own.min().z(), -g.handle.size_m->z() / 2, 1e-9);
    EXPECT_NEAR(g.own.center().y(), 0.0, 1e-9);
    EXPECT_NEAR(g.own.center().x(), 0.0, 1e-9);
    EXPECT_NEAR(g.at.y(), -g.handle.size_m->y() / 2, 1e-9);
    EXPECT_NEAR(g.at.z(), 0.0, 1e-9);  // centred on the drawer
  }
  {  // Recessed: the opening on the front face along the top edge, the front's full width.
    const world::WorldModel world = generate(layout_with("shaker", "{kind: recessed}"));
    const Grip g = grip(world, base_door);
    EXPECT_NEAR(g.at.y(), 0.0, 1e-9);
    EXPECT_NEAR(g.at.x(), 0.0, 1e-9);
    EXPECT_NEAR(g.at.z() + g.handle.size_m->z() / 2, g.front_size.z() / 2, 1e-9);
    EXPECT_NEAR(g.handle.size_m->x(), g.front_size.x(), 1e-9);
    EXPECT_NEAR(g.own.max().y(), g.front_size.y(), 1e-9);  // back to the carcass
    // Wall cupboards open at the bottom: their channel runs along the bottom edge.
    const Grip wall = grip(world, "north.upper1.door1");
    EXPECT_NEAR(wall.at.z() - wall.handle.size_m->z() / 2, -wall.front_size.z() / 2, 1e-9);
    // The door's panel leaves the channel's strip free.
    const AlignedBox3d panel = bounds(object_of(world, base_door));
    EXPECT_NEAR(panel.max().z(), g.front_size.z() / 2 - g.handle.size_m->z(), 1e-9);
  }
  {  // Rail: the bar's centre; horizontal along most of a base door's top edge, vertical along
     // a tall door's opening edge.
    const world::WorldModel world = generate(layout_with("shaker", "{kind: rail}"));
    const Grip g = grip(world, base_door);
    EXPECT_NEAR(g.at.x(), 0.0, 1e-9);
    EXPECT_GT(g.handle.size_m->x(), 0.8 * g.front_size.x());
    EXPECT_GT(g.at.z(), g.front_size.z() / 2 - 0.05);
    const Grip tall = grip(world, "north.base1.door2");
    EXPECT_GT(tall.handle.size_m->z(), 0.8 * tall.front_size.z());
    EXPECT_LT(tall.handle.size_m->x(), 0.02);
  }
}

TEST(HandleKinds, LookDifferent) {
  std::map<std::string, std::string> signature;
  for (const char* kind : kKinds) {
    const world::WorldModel world =
        generate(layout_with("slab", std::string("{kind: ") + kind + "}"));
    const world::ObjectModel& h = object_of(world, "north.base3.door1.handle");
    std::string text;
    for (const world::Primitive& p : h.primitives) {
      text += std::holds_alternative<world::Box>(p.shape)        ? "b"
              : std::holds_alternative<world::Cylinder>(p.shape) ? "c"
                                                                 : "p";
    }
    signature[kind] = text;
    // The oven keeps a bar whatever the kind; the room door has a knob or a lever.
    EXPECT_EQ(object_of(world, "north.base6.oven.handle").primitives.size(), 3u) << kind;
    const auto& room = object_of(world, "room_door.handle").size_m.value();
    if (std::string(kind) == "knob") {
      EXPECT_NEAR(room.x(), room.z(), 1e-9);
    } else {
      EXPECT_GT(room.x(), 2 * room.z());
    }
  }
  EXPECT_EQ(signature["bar"], "cbb");
  EXPECT_EQ(signature["knob"], "cc");
  EXPECT_EQ(signature["cup_pull"], "pppb");
  EXPECT_EQ(signature["recessed"], "bb");
  EXPECT_EQ(signature["rail"], "cbb");
}

TEST(HandleKinds, RunsMayHaveTheirOwn) {
  const std::string text =
      "room: {size: [5.0, 3.6, 2.5]}\n"
      "handles: {kind: knob, length: 0.04}\n"
      "runs:\n"
      "  - {wall: north, at: 0.2, base: [base_2door]}\n"
      "  - {wall: south, at: 0.2, base: [drawers_3], handles: {kind: cup_pull, length: 0.128}}\n";
  const world::WorldModel world = generate(text);
  EXPECT_NEAR(object_of(world, "north.base1.door1.handle").size_m->x(), 0.04, 1e-9);
  EXPECT_NEAR(object_of(world, "south.base1.drawer1.handle").size_m->x(), 0.148, 1e-9);
  for (const std::string& problem : check_generated_world(world)) ADD_FAILURE() << problem;
}

TEST(HandleKinds, EveryUnitWorksInEveryStyleWithEveryKind) {
  for (const UnitKind& unit : kitchen_unit_kinds()) {
    if (std::string(unit.name) == "gap") continue;
    for (const char* style : kStyles) {
      for (const char* kind : kKinds) {
        std::string text = "room: {size: [4.0, 3.0, 2.5]}\ndoors: {style: ";
        text += style;
        text += "}\nhandles: {kind: ";
        text += kind;
        text += "}\nruns:\n  - {wall: north, at: 1.0, ";
        text += unit.upper ? "upper: [" : "base: [";
        text += unit.name;
        text += ", {";
        text += unit.name;
        text += ": 0.5}]}\n";
        const world::WorldModel world = generate(text);
        for (const std::string& problem : check_generated_world(world)) {
          ADD_FAILURE() << unit.name << " " << style << " " << kind << ": " << problem;
        }
      }
    }
  }
}

}  // namespace
}  // namespace vsl::worldgen
