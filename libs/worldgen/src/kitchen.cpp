// The kitchen generator: layout (kitchen_layout.cpp) -> world model. See kitchen.hpp for frames.
#include "vsl/worldgen/kitchen.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "door_styles.hpp"
#include "handles.hpp"
#include "vsl/worldgen/geometry.hpp"
#include "vsl/worldgen/world_builder.hpp"

namespace vsl::worldgen {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector2d;
using Eigen::Vector3d;
using world::ObjectModel;

constexpr double kPi = std::numbers::pi;

// Joinery (m).
constexpr double kBoard = 0.018;         // carcass panels
constexpr double kBack = 0.008;          // carcass back panel
constexpr double kGap = 0.004;           // between neighbouring fronts
constexpr double kPlinthSetback = 0.05;  // kick board behind the fronts
constexpr double kTallSplit = 0.78;      // tall units: height of the lower door's slot
// Sinks (m).
constexpr double kSinkMargin = 0.06;  // worktop left at either side of the bowls
constexpr double kSinkBridge = 0.06;  // worktop between two bowls
constexpr double kSinkBack = 0.10;    // worktop strip behind the bowls (the tap stands on it)
constexpr double kBowlDepth = 0.18;
constexpr double kBowlRim = 0.012;
// Windows (m).
constexpr double kSillThickness = 0.025;
constexpr double kSillOverhang = 0.04;   // into the room
constexpr double kWindowSetback = 0.03;  // frame's inner face behind the wall's inner face
constexpr double kFrameDepth = 0.07;
constexpr double kFrameWidth = 0.06;

const char* wall_name(WallSide w) {
  switch (w) {
    case WallSide::north:
      return "north";
    case WallSide::east:
      return "east";
    case WallSide::south:
      return "south";
    case WallSide::west:
      return "west";
  }
  return "?";
}

bool is_tall(const std::string& kind) {
  return kind.rfind("fridge", 0) == 0 || kind.rfind("tall", 0) == 0;
}
bool hinge_right(const std::string& kind) {
  return kind.size() > 2 && kind.ends_with("_r");
}

std::string fmt(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// A unit (or opening, or the table) as the space it takes in the room, world frame.
struct Footprint {
  Eigen::AlignedBox3d box;
  Origin origin;
  std::string what;
  bool on_floor = false;
};

struct Placed {
  const RunSpec* run = nullptr;
  const UnitSpec* spec = nullptr;
  double a0 = 0.0;  // left end along the wall
  bool upper = false;
  std::string id;
};

struct Cut {
  double a0, a1;
};

struct Carcass {
  double w, d, h;
  double plinth = 0.0;
  bool top_panel = false;
  bool top_rails = false;
  std::vector<double> shelves;  // centre heights, carcass frame
};

class KitchenBuilder {
 public:
  KitchenBuilder(const KitchenLayout& layout, WorldBuilder& builder)
      : layout_(layout), d_(layout.dimensions), b_(builder), room_(layout.room_size_m) {}

  void build() {
    plan();
    emit_structure();
    for (const RunSpec& run : layout_.runs) emit_run(run);
    if (layout_.table) emit_table(*layout_.table);
  }

 private:
  // ---- frames -------------------------------------------------------------------------------

  double wall_length(WallSide w) const {
    return (w == WallSide::north || w == WallSide::south) ? room_.x() : room_.y();
  }

  // Origin at the wall's left corner (seen from inside), on its inner face, at floor level; x
  // along the wall, y into the wall, z up.
  Isometry3d wall_frame(WallSide w) const {
    switch (w) {
      case WallSide::north:
        return pose_yaw({0, room_.y(), 0}, 0.0);
      case WallSide::east:
        return pose_yaw({room_.x(), room_.y(), 0}, -kPi / 2);
      case WallSide::south:
        return pose_yaw({room_.x(), 0, 0}, kPi);
      case WallSide::west:
        return pose_yaw({0, 0, 0}, kPi / 2);
    }
    return Isometry3d::Identity();
  }

  // The world box of a wall-aligned block: `a` along the wall, `o` out from it into the room.
  Eigen::AlignedBox3d wall_box(WallSide w, double a0, double a1, double o0, double o1, double z0,
                               double z1) const {
    const Isometry3d frame = wall_frame(w);
    Eigen::AlignedBox3d box;
    for (double a : {a0, a1}) {
      for (double o : {o0, o1}) {
        for (double z : {z0, z1}) box.extend(frame * Vector3d(a, -o, z));
      }
    }
    return box;
  }

  double worktop_top() const {
    return d_.plinth_height_m + d_.base_height_m + d_.countertop_thickness_m;
  }
  double tall_height() const { return d_.upper_bottom_m + d_.upper_height_m - d_.plinth_height_m; }
  double hood_bottom() const { return worktop_top() + 0.65; }
  double base_reach() const {
    return std::max(d_.base_depth_m + d_.door_thickness_m, d_.countertop_depth_m);
  }

  // ---- planning and checks ------------------------------------------------------------------

  // Every unit, opening and the table placed and checked: inside the room, no two overlapping.
  void plan() {
    const KitchenDimensions& d = d_;
    if (d.upper_bottom_m < worktop_top() + 0.3) {
      layout_.origin.fail("dimensions: wall cupboards must hang at least 0.3 m above the worktop");
    }
    if (d.upper_bottom_m + d.upper_height_m > room_.z() - 0.05) {
      layout_.origin.fail("dimensions: wall cupboards reach the ceiling (room height " +
                          fmt(room_.z()) + " m)");
    }
    plan_units();
    plan_openings();
    if (layout_.table) {
      const TableSpec& t = *layout_.table;
      Footprint fp;
      fp.origin = t.origin;
      fp.what = "the table and its chairs";
      fp.box = table_box(t);
      const Eigen::AlignedBox3d inside(Vector3d(0, 0, 0), room_);
      if (!inside.contains(fp.box))
        t.origin.fail("the table and its chairs do not fit in the room");
      footprints_.push_back(fp);
    }
    // Units against units, openings and the table; the table against the openings.
    for (std::size_t i = 0; i < footprints_.size(); ++i) {
      for (std::size_t j = i + 1; j < footprints_.size(); ++j) {
        const Eigen::AlignedBox3d overlap = footprints_[i].box.intersection(footprints_[j].box);
        if (!overlap.isEmpty() && (overlap.sizes().array() > 1e-6).all()) {
          const Footprint& late = footprints_[j];
          late.origin.fail(late.what + " overlaps " + footprints_[i].what + " (" +
                           footprints_[i].origin.path + ")");
        }
      }
    }
  }

  // The units along their walls' runs (placed_), and their footprints.
  void plan_units() {
    const KitchenDimensions& d = d_;
    std::map<WallSide, int> base_count, upper_count;
    for (const RunSpec& run : layout_.runs) {
      const double length = wall_length(run.wall);
      for (bool upper : {false, true}) {
        double a = upper ? run.upper_at_m : run.at_m;
        for (const UnitSpec& unit : upper ? run.upper : run.base) {
          const double a0 = a;
          a += unit.width_m;
          if (a > length + 1e-9) {
            unit.origin.fail("unit '" + unit.kind + "' ends " + fmt(a) + " m along the " +
                             wall_name(run.wall) + " wall, which is " + fmt(length) + " m long");
          }
          if (unit.kind == "gap") continue;
          Placed placed{&run, &unit, a0, upper, ""};
          int& count = upper ? upper_count[run.wall] : base_count[run.wall];
          placed.id = std::string(wall_name(run.wall)) + (upper ? ".upper" : ".base") +
                      std::to_string(++count);
          Footprint fp{
              {}, unit.origin, (upper ? "upper unit '" : "base unit '") + unit.kind + "'", !upper};
          if (unit.kind == "hood") {
            if (hood_bottom() + 0.35 > room_.z()) {
              unit.origin.fail("no room for a range hood under a ceiling " + fmt(room_.z()) +
                               " m high");
            }
            fp.box = wall_box(run.wall, a0, a, 0.0, 0.5, hood_bottom(), room_.z());
          } else if (upper) {
            fp.box = wall_box(run.wall, a0, a, 0.0, d.upper_depth_m + d.door_thickness_m,
                              d.upper_bottom_m, d.upper_bottom_m + d.upper_height_m);
          } else if (is_tall(unit.kind)) {
            fp.box = wall_box(run.wall, a0, a, 0.0, d.base_depth_m + d.door_thickness_m, 0.0,
                              d.plinth_height_m + tall_height());
          } else {
            fp.box = wall_box(run.wall, a0, a, 0.0, base_reach(), 0.0, worktop_top());
          }
          footprints_.push_back(fp);
          placed_.push_back(placed);
        }
      }
    }
  }

  // The openings' footprints: inside their wall, below the ceiling, not overlapping each other.
  void plan_openings() {
    std::vector<std::pair<const OpeningSpec*, bool>> openings;
    for (const OpeningSpec& w : layout_.windows) openings.push_back({&w, false});
    if (layout_.room_door) openings.push_back({&*layout_.room_door, true});
    for (std::size_t i = 0; i < openings.size(); ++i) {
      const OpeningSpec& o = *openings[i].first;
      const bool door = openings[i].second;
      const double length = wall_length(o.wall);
      if (o.at_m < 0.05 || o.at_m + o.width_m > length - 0.05) {
        o.origin.fail("opening must lie on the " + std::string(wall_name(o.wall)) +
                      " wall at least 0.05 m from its corners (wall length " + fmt(length) + " m)");
      }
      if (o.sill_m + o.height_m > room_.z() - 0.1) {
        o.origin.fail("opening reaches the ceiling (room height " + fmt(room_.z()) + " m)");
      }
      if (!door && o.sill_m < kSillThickness + 0.1) o.origin.fail("window sill must be >= 0.125 m");
      for (std::size_t j = 0; j < i; ++j) {
        const OpeningSpec& p = *openings[j].first;
        if (p.wall == o.wall && o.at_m < p.at_m + p.width_m + 0.1 &&
            p.at_m < o.at_m + o.width_m + 0.1) {
          o.origin.fail("opening overlaps (or is within 0.1 m of) the opening at " + p.origin.path);
        }
      }
      Footprint fp;
      fp.origin = o.origin;
      fp.what = door ? "the room door (and its swing)" : "window";
      fp.box = door ? wall_box(o.wall, o.at_m, o.at_m + o.width_m, 0.0, o.width_m, 0.0, o.height_m)
                    : wall_box(o.wall, o.at_m, o.at_m + o.width_m, 0.0, kSillOverhang + 0.01,
                               o.sill_m - kSillThickness, o.sill_m + o.height_m);
      footprints_.push_back(fp);
    }
  }

  // ---- primitives and small parts ----------------------------------------------------------

  static void carcass_primitives(ObjectModel& o, const Carcass& c) {
    const double w = c.w, d = c.d, h = c.h;
    for (double side : {-1.0, 1.0}) {
      o.primitives.push_back(box("carcass", {side * (w - kBoard) / 2, 0, 0}, {kBoard, d, h}));
    }
    o.primitives.push_back(box("carcass", {0, 0, -(h - kBoard) / 2}, {w - 2 * kBoard, d, kBoard}));
    if (c.top_panel) {
      o.primitives.push_back(box("carcass", {0, 0, (h - kBoard) / 2}, {w - 2 * kBoard, d, kBoard}));
    }
    if (c.top_rails) {
      for (double y : {-d / 2 + 0.05, d / 2 - kBack - 0.05}) {
        o.primitives.push_back(
            box("carcass", {0, y, (h - kBoard) / 2}, {w - 2 * kBoard, 0.1, kBoard}));
      }
    }
    const double back_top = c.top_panel ? h / 2 - kBoard : h / 2;
    o.primitives.push_back(box_between("carcass", {-w / 2 + kBoard, d / 2 - kBack, -h / 2 + kBoard},
                                       {w / 2 - kBoard, d / 2, back_top}));
    for (double z : c.shelves) {
      o.primitives.push_back(box_between("carcass",
                                         {-w / 2 + kBoard, -d / 2 + 0.02, z - kBoard / 2},
                                         {w / 2 - kBoard, d / 2 - kBack, z + kBoard / 2}));
    }
    if (c.plinth > 0.0) {
      o.primitives.push_back(box_between(
          "plinth", {-w / 2, -d / 2 + kPlinthSetback, -h / 2 - c.plinth}, {w / 2, d / 2, -h / 2}));
    }
  }

  const HandleStyle& handles_of(const RunSpec& run) const {
    return run.handles ? *run.handles : layout_.handle;
  }

  // The panel of `front` (whose front face is its object's y = 0 plane) in `style`, leaving free
  // the strip a recessed grip takes, then the front's handle.
  void add_panel_and_handle(world::ObjectModel& object, DoorStyle style, const HandleStyle& handles,
                            const FrontSpec& front) {
    const GripCut cut = grip_cut(handles, front);
    add_door_panel(object, style,
                   {front.width_m, front.height_m - cut.height_m, front.thickness_m,
                    -cut.edge * cut.height_m / 2});
    add_front_handle(b_, handles, front);
  }

  // A door of w x h whose front face centre is at (x, front_y - thickness, z) in `unit`, with its
  // handle near its opening edge (tall: a fridge's or larder's door).
  void add_door(const std::string& id, const std::string& parent, const Isometry3d& unit,
                double front_y, double x, double z, double w, double h, bool hinged_right,
                GripAt at, const HandleStyle& handles, DoorStyle style, bool tall = false) {
    const double t = d_.door_thickness_m;
    const Isometry3d front = offset(unit, {x, front_y - t, z});
    ObjectModel& door = b_.add(id, "door", front, Vector3d(w, t, h), parent);
    add_panel_and_handle(door, style, handles,
                         {id, front, w, h, t, hinged_right ? -1.0 : 1.0, at, tall});
  }

  // A drawer: front (w x h, front face centre at (0, front_y - thickness, z) in `unit`; a slab
  // in every door style), the box behind it inside a carcass of width unit_w and depth unit_d,
  // and its handle.
  void add_drawer(const std::string& id, const std::string& parent, const Isometry3d& unit,
                  double front_y, double z, double w, double h, double unit_w, double unit_d,
                  const HandleStyle& handles) {
    const double t = d_.door_thickness_m;
    const Isometry3d front = offset(unit, {0, front_y - t, z});
    ObjectModel& drawer = b_.add(id, "drawer_front", front, Vector3d(w, t, h), parent);
    const FrontSpec spec{id, front, w, h, t, 0.0, GripAt::middle, false};
    const GripCut cut = grip_cut(handles, spec);
    add_door_panel(drawer, DoorStyle::slab, {w, h - cut.height_m, t, -cut.edge * cut.height_m / 2});
    const double iw = unit_w - 2 * kBoard - 0.026;  // runner clearance
    const double dd = unit_d - kBack - 0.03;
    const double hb = std::max(0.05, h - 0.07);
    const double z0 = -h / 2 + 0.025;
    for (double side : {-1.0, 1.0}) {
      drawer.primitives.push_back(
          box("carcass", {side * (iw / 2 - 0.006), t + dd / 2, z0 + hb / 2}, {0.012, dd, hb}));
    }
    drawer.primitives.push_back(
        box("carcass", {0, t + dd - 0.006, z0 + hb / 2}, {iw - 0.024, 0.012, hb}));
    drawer.primitives.push_back(
        box("carcass", {0, t + dd / 2 - 0.006, z0 + 0.004}, {iw - 0.024, dd - 0.012, 0.008}));
    add_front_handle(b_, handles, spec);
  }

  // ---- structure: floor, ceiling, walls, windows, room door ----------------------------------

  struct Opening {
    double a0, a1, z0, z1;
  };

  void emit_structure() {
    const double t = d_.wall_thickness_m;
    const double x = room_.x(), y = room_.y(), h = room_.z();
    ObjectModel& floor = b_.add("floor", "floor", pose_yaw({x / 2, y / 2, 0}, 0),
                                Vector3d(x + 2 * t, y + 2 * t, 0.05));
    floor.primitives.push_back(box("floor", {0, 0, -0.025}, {x + 2 * t, y + 2 * t, 0.05}));
    ObjectModel& ceiling = b_.add("ceiling", "ceiling", pose_yaw({x / 2, y / 2, h}, 0),
                                  Vector3d(x + 2 * t, y + 2 * t, 0.05));
    ceiling.primitives.push_back(box("ceiling", {0, 0, 0.025}, {x + 2 * t, y + 2 * t, 0.05}));
    const Eigen::Vector2i grid = layout_.ceiling_lights;
    for (int i = 0; i < grid.x(); ++i) {
      for (int j = 0; j < grid.y(); ++j) {
        const Vector3d at((i + 0.5) * x / grid.x() - x / 2, (j + 0.5) * y / grid.y() - y / 2,
                          -0.005);
        // Along z, so that its -z (the way a light material shines) is world down.
        ceiling.primitives.push_back(cylinder("lamp", at, 0.045, 0.01, Axis::z));
      }
    }
    for (WallSide w : {WallSide::north, WallSide::east, WallSide::south, WallSide::west})
      emit_wall(w);
    int index = 0;
    for (const OpeningSpec& w : layout_.windows) emit_window(w, ++index);
    if (layout_.room_door) emit_room_door(*layout_.room_door);
  }

  void emit_wall(WallSide side) {
    const double length = wall_length(side), h = room_.z(), t = d_.wall_thickness_m;
    const double ext = (side == WallSide::north || side == WallSide::south) ? t : 0.0;
    const std::string id = std::string("wall.") + wall_name(side);
    ObjectModel& wall = b_.add(id, "wall", offset(wall_frame(side), {length / 2, 0, h / 2}),
                               Vector3d(length + 2 * ext, t, h));
    auto piece = [&](const char* material, double a0, double a1, double y0, double y1, double z0,
                     double z1) {
      if (a1 - a0 < 1e-6 || z1 - z0 < 1e-6) return;
      wall.primitives.push_back(box_between(material, {a0 - length / 2, y0, z0 - h / 2},
                                            {a1 - length / 2, y1, z1 - h / 2}));
    };
    std::vector<Opening> openings;
    for (const OpeningSpec& w : layout_.windows) {
      if (w.wall == side) {
        openings.push_back(
            {w.at_m, w.at_m + w.width_m, w.sill_m - kSillThickness, w.sill_m + w.height_m});
      }
    }
    const OpeningSpec* door =
        layout_.room_door && layout_.room_door->wall == side ? &*layout_.room_door : nullptr;
    if (door) openings.push_back({door->at_m, door->at_m + door->width_m, 0.0, door->height_m});
    std::sort(openings.begin(), openings.end(),
              [](const Opening& p, const Opening& q) { return p.a0 < q.a0; });
    double cursor = -ext;
    for (const Opening& o : openings) {
      piece("wall", cursor, o.a0, 0, t, 0, h);
      piece("wall", o.a0, o.a1, 0, t, 0, o.z0);
      piece("wall", o.a0, o.a1, 0, t, o.z1, h);
      cursor = o.a1;
    }
    piece("wall", cursor, length + ext, 0, t, 0, h);
    if (door) {  // lining of the door opening
      const double a0 = door->at_m, a1 = door->at_m + door->width_m, dh = door->height_m;
      piece("skirting", a0, a0 + 0.02, 0, t, 0, dh - 0.02);
      piece("skirting", a1 - 0.02, a1, 0, t, 0, dh - 0.02);
      piece("skirting", a0, a1, 0, t, dh - 0.02, dh);
    }
    // Skirting boards wherever nothing stands against the wall.
    std::vector<std::pair<double, double>> blocked;
    if (door) blocked.push_back({door->at_m, door->at_m + door->width_m});
    const Isometry3d inverse = wall_frame(side).inverse();
    for (const Footprint& fp : footprints_) {
      if (!fp.on_floor) continue;
      const Vector3d p = inverse * fp.box.min(), q = inverse * fp.box.max();
      const double o_min = std::min(-p.y(), -q.y());
      if (o_min < 0.03) blocked.push_back({std::min(p.x(), q.x()), std::max(p.x(), q.x())});
    }
    std::sort(blocked.begin(), blocked.end());
    double from = 0.0;
    auto skirting = [&](double a0, double a1) {
      if (a1 - a0 >= 0.05) piece("skirting", a0, a1, -0.012, 0.0, 0.0, 0.08);
    };
    for (const auto& [a0, a1] : blocked) {
      skirting(from, std::min(a0, length));
      from = std::max(from, a1);
    }
    skirting(from, length);
  }

  void emit_window(const OpeningSpec& w, int index) {
    const double h = w.height_m, width = w.width_m, t = d_.wall_thickness_m;
    const std::string wall_id = std::string("wall.") + wall_name(w.wall);
    const Isometry3d front =
        offset(wall_frame(w.wall), {w.at_m + width / 2, kWindowSetback, w.sill_m + h / 2});
    ObjectModel& window = b_.add("window" + std::to_string(index), "window", front,
                                 Vector3d(width, kFrameDepth, h), wall_id);
    const double fw = kFrameWidth, fd = kFrameDepth;
    for (double side : {-1.0, 1.0}) {
      window.primitives.push_back(
          box("window_frame", {side * (width - fw) / 2, fd / 2, 0}, {fw, fd, h}));
      window.primitives.push_back(
          box("window_frame", {0, fd / 2, side * (h - fw) / 2}, {width - 2 * fw, fd, fw}));
    }
    const int sashes = width >= 1.0 ? 2 : 1;
    if (sashes == 2)
      window.primitives.push_back(box("window_frame", {0, fd / 2, 0}, {fw, fd, h - 2 * fw}));
    const double cw = (width - 2 * fw - (sashes - 1) * fw) / sashes, ch = h - 2 * fw;
    constexpr double sw = 0.05, sd = 0.05;
    for (int s = 0; s < sashes; ++s) {
      const double cx = -width / 2 + fw + s * (cw + fw) + cw / 2;
      for (double side : {-1.0, 1.0}) {
        window.primitives.push_back(
            box("window_frame", {cx + side * (cw - sw) / 2, 0.01 + sd / 2, 0}, {sw, sd, ch}));
        window.primitives.push_back(
            box("window_frame", {cx, 0.01 + sd / 2, side * (ch - sw) / 2}, {cw - 2 * sw, sd, sw}));
      }
      window.primitives.push_back(
          box("glass", {cx, 0.01 + sd / 2, 0}, {cw - 2 * sw, 0.012, ch - 2 * sw}));
    }
    // The sill: through the wall and a little into the room, its front top edge chamfered.
    const double yb = t - kWindowSetback, yf = -kSillOverhang - kWindowSetback;
    const double zt = -h / 2, zb = -h / 2 - kSillThickness;
    window.primitives.push_back(polyhedron(
        "window_frame", Vector3d::Zero(),
        prism_x({{yb, zb}, {yb, zt}, {yf + 0.008, zt}, {yf, zt - 0.008}, {yf, zb}}, width)));
  }

  void emit_room_door(const OpeningSpec& door) {
    const std::string wall_id = std::string("wall.") + wall_name(door.wall);
    const double leaf_w = door.width_m - 0.04 - 0.006, leaf_h = door.height_m - 0.02 - 0.013;
    constexpr double leaf_t = 0.04;
    const Isometry3d front =
        offset(wall_frame(door.wall), {door.at_m + door.width_m / 2, 0.01, 0.01 + leaf_h / 2});
    ObjectModel& leaf =
        b_.add("room_door", "room_door", front, Vector3d(leaf_w, leaf_t, leaf_h), wall_id);
    leaf.primitives.push_back(box("room_door", {0, leaf_t / 2, 0}, {leaf_w, leaf_t, leaf_h}));
    add_room_door_handle(b_, layout_.handle.kind, front, leaf_w, 1.05 - (0.01 + leaf_h / 2),
                         layout_.room_door_hinge_right);
  }

  // ---- runs ---------------------------------------------------------------------------------

  void emit_run(const RunSpec& run) {
    std::vector<const Placed*> base;
    for (const Placed& p : placed_) {
      if (p.run == &run && !p.upper) base.push_back(&p);
    }
    for (const Placed* p : base) emit_base_unit(*p);
    // Worktops over each stretch of touching base units.
    std::vector<const Placed*> stretch;
    auto flush = [&] {
      if (!stretch.empty()) emit_worktop(run, stretch);
      stretch.clear();
    };
    for (const Placed* p : base) {
      if (is_tall(p->spec->kind)) {
        flush();
        continue;
      }
      if (!stretch.empty() &&
          std::abs(stretch.back()->a0 + stretch.back()->spec->width_m - p->a0) > 1e-9) {
        flush();
      }
      stretch.push_back(p);
    }
    flush();
    for (const Placed& p : placed_) {
      if (p.run == &run && p.upper) emit_upper_unit(p);
    }
  }

  void emit_base_unit(const Placed& p) {
    const std::string& kind = p.spec->kind;
    const double w = p.spec->width_m, d = d_.base_depth_m, plinth = d_.plinth_height_m;
    const bool tall = is_tall(kind);
    const double h = tall ? tall_height() : d_.base_height_m;
    const Isometry3d unit = offset(wall_frame(p.run->wall), {p.a0 + w / 2, -d / 2, plinth + h / 2});
    const Vector3d size(w, d, h);
    const double fy = -d / 2, dw = w - kGap;
    const bool right = hinge_right(kind);
    const HandleStyle& handles = handles_of(*p.run);
    const DoorStyle style = layout_.door_style;
    Carcass carcass{w, d, h, plinth, false, true, {}};

    if (kind == "dishwasher") return emit_dishwasher(p, unit);
    if (tall) return emit_tall_unit(p, unit);

    ObjectModel* cupboard = nullptr;
    auto make_cupboard = [&] {
      cupboard = &b_.add(p.id, "cupboard", unit, size);
      carcass_primitives(*cupboard, carcass);
    };
    const double dh = h - kGap;
    if (kind == "corner") {
      carcass.shelves = {0.0};
      make_cupboard();
      cupboard->primitives.push_back(
          box("carcass", {0, fy - d_.door_thickness_m / 2, 0}, {dw, d_.door_thickness_m, dh}));
    } else if (kind == "base_1door" || kind == "base_1door_r") {
      carcass.shelves = {0.0};
      make_cupboard();
      add_door(p.id + ".door1", p.id, unit, fy, 0, 0, dw, dh, right, GripAt::top, handles, style);
    } else if (kind == "base_2door" || kind == "sink_2door") {
      if (kind == "sink_2door") {
        carcass.top_rails = false;
      } else {
        carcass.shelves = {0.0};
      }
      make_cupboard();
      add_door(p.id + ".door1", p.id, unit, fy, -w / 4, 0, w / 2 - kGap, dh, false, GripAt::top,
               handles, style);
      add_door(p.id + ".door2", p.id, unit, fy, w / 4, 0, w / 2 - kGap, dh, true, GripAt::top,
               handles, style);
    } else if (kind == "drawers_3" || kind == "drawers_4") {
      make_cupboard();
      const std::vector<double> shares = kind == "drawers_3"
                                             ? std::vector<double>{0.22, 0.33, 0.45}
                                             : std::vector<double>{0.19, 0.19, 0.27, 0.35};
      double top = h / 2;
      for (std::size_t i = 0; i < shares.size(); ++i) {
        const double slot = shares[i] * h;
        add_drawer(p.id + ".drawer" + std::to_string(i + 1), p.id, unit, fy, top - slot / 2, dw,
                   slot - kGap, w, d, handles);
        top -= slot;
      }
    } else if (kind == "oven") {
      const double oven_h = std::min(0.595, h - 0.1);
      const double oven_z = h / 2 - kGap / 2 - oven_h / 2;  // oven front centre, unit frame
      const double body_bottom = oven_z - oven_h / 2 + 0.005;
      carcass.shelves = {body_bottom - kBoard / 2};
      carcass.top_rails = false;  // the oven body reaches up to the worktop
      make_cupboard();
      emit_oven(p, unit, fy, oven_z, oven_h);
      const double drawer_top = oven_z - oven_h / 2 - kGap, drawer_bottom = -h / 2 + kGap / 2;
      add_drawer(p.id + ".drawer1", p.id, unit, fy, (drawer_top + drawer_bottom) / 2, dw,
                 drawer_top - drawer_bottom, w, d, handles);
    }
  }

  void emit_dishwasher(const Placed& p, const Isometry3d& unit) {
    const double w = p.spec->width_m, d = d_.base_depth_m, h = d_.base_height_m;
    const double plinth = d_.plinth_height_m;
    ObjectModel& dw_obj = b_.add(p.id, "dishwasher", unit, Vector3d(w, d, h));
    dw_obj.primitives.push_back(box_between("steel", {-w / 2 + 0.005, -d / 2, -h / 2},
                                            {w / 2 - 0.005, d / 2 - 0.02, h / 2 - 0.005}));
    dw_obj.primitives.push_back(box_between("plinth",
                                            {-w / 2, -d / 2 + kPlinthSetback, -h / 2 - plinth},
                                            {w / 2, d / 2 - 0.02, -h / 2}));
    const std::string door = p.id + ".door";
    const double dw = w - kGap, dh = h - kGap, t = d_.door_thickness_m;
    const Isometry3d front = offset(unit, {0, -d / 2 - t, 0});
    ObjectModel& door_obj = b_.add(door, "door", front, Vector3d(dw, t, dh), p.id);
    add_panel_and_handle(door_obj, solid_style(), handles_of(*p.run),
                         {door, front, dw, dh, t, 0.0, GripAt::top, false});
  }

  // Fridges and dishwashers: their doors hide an appliance, so glass doors become shaker ones.
  DoorStyle solid_style() const {
    return layout_.door_style == DoorStyle::glass ? DoorStyle::shaker : layout_.door_style;
  }

  void emit_tall_unit(const Placed& p, const Isometry3d& unit) {
    const std::string& kind = p.spec->kind;
    const double w = p.spec->width_m, d = d_.base_depth_m, h = tall_height();
    const bool fridge = kind.rfind("fridge", 0) == 0;
    Carcass carcass{w, d, h, d_.plinth_height_m, true, false, {}};
    if (!fridge) {
      for (int i = 1; i <= 5; ++i) carcass.shelves.push_back(-h / 2 + i * h / 6);
    }
    ObjectModel& body = b_.add(p.id, fridge ? "fridge" : "cupboard", unit, Vector3d(w, d, h));
    carcass_primitives(body, carcass);
    if (fridge) {
      body.primitives.push_back(box_between(
          "appliance", {-w / 2 + kBoard + 0.002, -d / 2 + 0.002, -h / 2 + kBoard + 0.002},
          {w / 2 - kBoard - 0.002, d / 2 - kBack - 0.018, h / 2 - kBoard - 0.002}));
    }
    const double split = std::min(kTallSplit, h / 2), dw = w - kGap;
    const double lower_h = split - kGap, upper_h = h - split - kGap;
    const bool right = hinge_right(kind);
    const HandleStyle& handles = handles_of(*p.run);
    const DoorStyle style = fridge ? solid_style() : layout_.door_style;
    add_door(p.id + ".door1", p.id, unit, -d / 2, 0, -h / 2 + split / 2, dw, lower_h, right,
             GripAt::top, handles, style, true);
    add_door(p.id + ".door2", p.id, unit, -d / 2, 0, -h / 2 + split + (h - split) / 2, dw, upper_h,
             right, GripAt::bottom, handles, style, true);
  }

  void emit_oven(const Placed& p, const Isometry3d& unit, double fy, double z, double oven_h) {
    const double w = p.spec->width_m, d = d_.base_depth_m;
    constexpr double t = 0.022, strip = 0.09;
    const double fw = w - kGap;
    const std::string id = p.id + ".oven";
    const Isometry3d front = offset(unit, {0, fy - t, z});
    ObjectModel& oven = b_.add(id, "oven", front, Vector3d(fw, t, oven_h), p.id);
    const double door_h = oven_h - strip - 0.002, door_z = -oven_h / 2 + door_h / 2;
    oven.primitives.push_back(
        box("black_glass", {0, t / 2, oven_h / 2 - strip / 2}, {fw, t, strip}));
    oven.primitives.push_back(box("black_glass", {0, t / 2, door_z}, {fw, t, door_h}));
    oven.primitives.push_back(
        box("glass", {0, -0.0015, door_z - 0.03}, {fw - 0.2, 0.003, door_h * 0.45}));
    oven.primitives.push_back(
        box("glass", {0, -0.0015, oven_h / 2 - strip / 2}, {0.08, 0.003, 0.03}));
    for (double kx : {-0.36, -0.22, 0.22, 0.36}) {
      oven.primitives.push_back(
          cylinder("steel", {kx * fw, -0.01, oven_h / 2 - strip / 2}, 0.017, 0.02, Axis::y));
    }
    oven.primitives.push_back(
        box_between("black_glass", {-w / 2 + kBoard + 0.002, t, -oven_h / 2 + 0.005},
                    {w / 2 - kBoard - 0.002, t + d - 0.06, oven_h / 2 - 0.005}));
    // Ovens keep a bar whatever the handle kind: a knob or recess cannot pull a heavy flap.
    const HandleStyle& handles = handles_of(*p.run);
    const double bar = handles.kind == HandleKind::bar ? handles.length_m.value_or(0.16) : 0.16;
    add_bar_handle(b_, handles, id + ".handle", id, front, 0.0, door_z + door_h / 2 - 0.045, true,
                   std::max(bar, fw - 0.16));
  }

  void emit_worktop(const RunSpec& run, const std::vector<const Placed*>& units) {
    const double a0 = units.front()->a0, a1 = units.back()->a0 + units.back()->spec->width_m;
    const double depth = d_.countertop_depth_m, ct = d_.countertop_thickness_m, top = worktop_top();
    const double mid = (a0 + a1) / 2;
    const Isometry3d wall = wall_frame(run.wall);
    const std::string id =
        std::string(wall_name(run.wall)) + ".worktop" + std::to_string(++worktops_[run.wall]);
    ObjectModel& worktop = b_.add(id, "countertop", offset(wall, {mid, -depth / 2, top}),
                                  Vector3d(a1 - a0, depth, ct));
    const double o0 = kSinkBack, o1 = depth - 0.10;  // the sinks' cut-outs, out from the wall
    std::vector<Cut> cuts;
    for (const Placed* p : units) {
      if (p->spec->kind != "sink_2door") continue;
      const double w = p->spec->width_m;
      const int bowls = w >= 0.8 ? 2 : 1;
      const double bw = (w - 2 * kSinkMargin - (bowls - 1) * kSinkBridge) / bowls;
      for (int k = 0; k < bowls; ++k) {
        const double c0 = p->a0 + kSinkMargin + k * (bw + kSinkBridge);
        cuts.push_back({c0, c0 + bw});
      }
    }
    auto piece = [&](double p0, double p1, double q0, double q1) {
      if (p1 - p0 < 1e-6) return;
      worktop.primitives.push_back(box_between("countertop", {p0 - mid, depth / 2 - q1, -ct},
                                               {p1 - mid, depth / 2 - q0, 0}));
    };
    double cursor = a0;
    for (const Cut& c : cuts) {
      piece(cursor, c.a0, 0, depth);
      piece(c.a0, c.a1, 0, o0);
      piece(c.a0, c.a1, o1, depth);
      cursor = c.a1;
    }
    piece(cursor, a1, 0, depth);
    // What sits in or on the worktop.
    for (const Placed* p : units) {
      const double w = p->spec->width_m, centre = p->a0 + w / 2;
      if (p->spec->kind == "sink_2door") {
        const int bowls = w >= 0.8 ? 2 : 1;
        const double bw = (w - 2 * kSinkMargin - (bowls - 1) * kSinkBridge) / bowls, cd = o1 - o0;
        const std::string sink_id = p->id + ".sink";
        ObjectModel& sink = b_.add(sink_id, "sink", offset(wall, {centre, -(o0 + o1) / 2, top}),
                                   Vector3d(w - 2 * kSinkMargin, cd, kBowlDepth + ct), id);
        for (int k = 0; k < bowls; ++k) {
          const double cx = p->a0 + kSinkMargin + k * (bw + kSinkBridge) + bw / 2 - centre;
          sink.primitives.push_back(polyhedron(
              "steel", {cx, 0, -ct},
              basin({bw + 2 * kBowlRim, cd + 2 * kBowlRim}, kBowlDepth, 0.015, 0.008, kBowlRim)));
        }
        ObjectModel& tap = b_.add(p->id + ".tap", "tap", offset(wall, {centre, -o0 / 2, top}),
                                  Vector3d(0.1, 0.22, 0.3), sink_id);
        tap.primitives.push_back(cylinder("chrome", {0, 0, 0.02}, 0.025, 0.04, Axis::z));
        tap.primitives.push_back(cylinder("chrome", {0, 0, 0.17}, 0.014, 0.26, Axis::z));
        tap.primitives.push_back(cylinder("chrome", {0, -0.1, 0.28}, 0.011, 0.2, Axis::y));
        tap.primitives.push_back(cylinder("chrome", {0.054, 0, 0.1}, 0.006, 0.08, Axis::x));
      } else if (p->spec->kind == "oven") {
        const double gw = std::min(0.58, w - 0.02), gd = std::min(0.51, depth - 0.06);
        ObjectModel& hob =
            b_.add(p->id + ".hob", "hob", offset(wall, {centre, -depth / 2, top + 0.006}),
                   Vector3d(gw, gd, 0.006), id);
        hob.primitives.push_back(box("black_glass", {0, 0, -0.003}, {gw, gd, 0.006}));
        const double rx = gw * 0.24, ry = gd * 0.24;
        for (const Vector3d& at : {Vector3d(-rx, -ry, 0.0005), Vector3d(rx, -ry, 0.0005),
                                   Vector3d(-rx, ry, 0.0005), Vector3d(rx, ry, 0.0005)}) {
          hob.primitives.push_back(
              cylinder("steel", at, at.x() * at.y() > 0 ? 0.09 : 0.07, 0.001, Axis::z));
        }
      }
    }
  }

  void emit_upper_unit(const Placed& p) {
    const std::string& kind = p.spec->kind;
    const double w = p.spec->width_m;
    const Isometry3d wall = wall_frame(p.run->wall);
    if (kind == "hood") {
      constexpr double depth = 0.5, canopy = 0.05, slope = 0.22, cw = 0.30, cd = 0.26;
      const double bottom = hood_bottom();
      ObjectModel& hood =
          b_.add(p.id, "range_hood", offset(wall, {p.a0 + w / 2, -depth / 2, bottom}),
                 Vector3d(w, depth, room_.z() - bottom));
      hood.primitives.push_back(box("steel", {0, 0, canopy / 2}, {w, depth, canopy}));
      hood.primitives.push_back(polyhedron(
          "steel", {0, 0, canopy},
          frustum(rectangle(w, depth), rectangle(cw, cd, {0, depth / 2 - cd / 2}), slope)));
      const double chimney = room_.z() - bottom - canopy - slope;
      hood.primitives.push_back(
          box("steel", {0, depth / 2 - cd / 2, canopy + slope + chimney / 2}, {cw, cd, chimney}));
      return;
    }
    const double d = d_.upper_depth_m, h = d_.upper_height_m;
    const Isometry3d unit = offset(wall, {p.a0 + w / 2, -d / 2, d_.upper_bottom_m + h / 2});
    Carcass carcass{w, d, h, 0.0, true, false, {}};
    if (kind == "wall_open") {
      carcass.shelves = {-h / 6, h / 6};
    } else {
      carcass.shelves = {0.0};
    }
    ObjectModel& cupboard = b_.add(p.id, "cupboard", unit, Vector3d(w, d, h));
    carcass_primitives(cupboard, carcass);
    if (layout_.under_cupboard_lights) {
      // Along z, so that its -z (the way a light material shines) is world down.
      cupboard.primitives.push_back(
          cylinder("strip_light", {0, -d / 4, -h / 2 - 0.004}, 0.03, 0.008, Axis::z));
    }
    const double fy = -d / 2, dh = h - kGap;
    const HandleStyle& handles = handles_of(*p.run);
    const DoorStyle style = layout_.door_style;
    if (kind == "wall_1door" || kind == "wall_1door_r") {
      add_door(p.id + ".door1", p.id, unit, fy, 0, 0, w - kGap, dh, hinge_right(kind),
               GripAt::bottom, handles, style);
    } else if (kind == "wall_2door") {
      add_door(p.id + ".door1", p.id, unit, fy, -w / 4, 0, w / 2 - kGap, dh, false, GripAt::bottom,
               handles, style);
      add_door(p.id + ".door2", p.id, unit, fy, w / 4, 0, w / 2 - kGap, dh, true, GripAt::bottom,
               handles, style);
    }
  }

  // ---- table, chairs, lamp --------------------------------------------------------------------

  struct ChairPlace {
    Vector2d at;  // table frame
    double yaw;   // relative to the table
  };

  static std::vector<ChairPlace> chair_places(const TableSpec& t) {
    const double l = t.size_m.x(), w = t.size_m.y();
    const int ends = t.chairs >= 5 ? (t.chairs >= 8 ? 2 : t.chairs % 2 == 0 ? 2 : 1) : 0;
    const int sides = t.chairs - ends;
    std::vector<ChairPlace> out;
    const int far = (sides + 1) / 2, near = sides / 2;
    for (int i = 0; i < far; ++i)
      out.push_back({{-l / 2 + (i + 0.5) * l / far, w / 2 + 0.10}, 0.0});
    for (int i = 0; i < near; ++i)
      out.push_back({{-l / 2 + (i + 0.5) * l / near, -w / 2 - 0.10}, kPi});
    if (ends >= 1) out.push_back({{l / 2 + 0.10, 0}, -kPi / 2});
    if (ends >= 2) out.push_back({{-l / 2 - 0.10, 0}, kPi / 2});
    return out;
  }

  Isometry3d table_pose(const TableSpec& t) const {
    return pose_yaw({t.centre_m.x(), t.centre_m.y(), t.size_m.z()}, t.yaw_deg * kPi / 180.0);
  }

  Eigen::AlignedBox3d table_box(const TableSpec& t) const {
    const Isometry3d pose = table_pose(t);
    const double l = t.size_m.x(), w = t.size_m.y(), h = t.size_m.z();
    Eigen::AlignedBox3d box;
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        box.extend(pose * Vector3d(sx * l / 2, sy * w / 2, -h));
        box.extend(pose * Vector3d(sx * l / 2, sy * w / 2, 0));
      }
    }
    for (const ChairPlace& c : chair_places(t)) {
      const Isometry3d chair = pose * pose_yaw({c.at.x(), c.at.y(), 0}, c.yaw);
      for (double sx : {-1.0, 1.0}) {
        for (double sy : {-1.0, 1.0}) {
          box.extend(chair * Vector3d(sx * 0.22, sy * 0.2, -h));
          box.extend(chair * Vector3d(sx * 0.22, sy * 0.2, 0.9 - h));
        }
      }
      // Chairs along the sides must clear the legs.
      if (std::abs(c.yaw) < 1e-9 || std::abs(std::abs(c.yaw) - kPi) < 1e-9) {
        if (std::abs(c.at.x()) + 0.22 > l / 2 - 0.1 + 1e-9) {
          t.origin.fail("too many chairs for a table " + fmt(l) + " m long");
        }
      }
    }
    return box;
  }

  void emit_table(const TableSpec& t) {
    const Isometry3d pose = table_pose(t);
    const double l = t.size_m.x(), w = t.size_m.y(), h = t.size_m.z();
    constexpr double top_t = 0.03, inset = 0.07, leg_r = 0.025;
    ObjectModel& table = b_.add("table", "table", pose, t.size_m);
    table.primitives.push_back(box("table", {0, 0, -top_t / 2}, {l, w, top_t}));
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        table.primitives.push_back(
            cylinder("table", {sx * (l / 2 - inset), sy * (w / 2 - inset), -(h + top_t) / 2}, leg_r,
                     h - top_t, Axis::z));
      }
    }
    for (double s : {-1.0, 1.0}) {
      table.primitives.push_back(box("table", {0, s * (w / 2 - inset), -top_t - 0.04},
                                     {l - 2 * inset - 2 * leg_r, 0.02, 0.08}));
      table.primitives.push_back(box("table", {s * (l / 2 - inset), 0, -top_t - 0.04},
                                     {0.02, w - 2 * inset - 2 * leg_r, 0.08}));
    }
    int index = 0;
    for (const ChairPlace& c : chair_places(t)) {
      emit_chair("chair" + std::to_string(++index),
                 pose * pose_yaw({c.at.x(), c.at.y(), 0.45 - h}, c.yaw));
    }
    if (t.lamp) {
      const double shade_bottom = h + 0.85, shade_h = 0.2, z = shade_bottom + shade_h / 2;
      const double cord = room_.z() - 0.02 - (shade_bottom + shade_h);
      ObjectModel& lamp = b_.add("lamp", "lamp", pose_yaw({t.centre_m.x(), t.centre_m.y(), z}, 0),
                                 Vector3d(0.4, 0.4, shade_h), "ceiling");
      lamp.primitives.push_back(
          polyhedron("lamp", {0, 0, -shade_h / 2},
                     frustum(regular_polygon(8, 0.2), regular_polygon(8, 0.07), shade_h)));
      // Only the shade gives light (one lamp per primitive of a light material); cord and
      // ceiling rose are its fitting.
      lamp.primitives.push_back(
          cylinder("lamp_fitting", {0, 0, shade_h / 2 + cord / 2}, 0.004, cord, Axis::z));
      lamp.primitives.push_back(
          cylinder("lamp_fitting", {0, 0, room_.z() - z - 0.01}, 0.05, 0.02, Axis::z));
    }
  }

  // A chair whose seat top centre is at `pose`; its front (-y) faces the table.
  void emit_chair(const std::string& id, const Isometry3d& pose) {
    constexpr double seat_h = 0.45, seat_t = 0.03, leg = 0.17, leg_r = 0.016;
    ObjectModel& chair = b_.add(id, "chair", pose, Vector3d(0.44, 0.42, 0.9));
    const std::vector<Vector2d> seat = {{-0.22, -0.2}, {0.22, -0.2}, {0.2, 0.2}, {-0.2, 0.2}};
    chair.primitives.push_back(polyhedron("chair", {0, 0, -seat_t}, frustum(seat, seat, seat_t)));
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        chair.primitives.push_back(cylinder("chair",
                                            {sx * leg, sy * leg, -seat_t - (seat_h - seat_t) / 2},
                                            leg_r, seat_h - seat_t, Axis::z));
      }
      chair.primitives.push_back(
          box("chair", {sx * leg, 0, -0.30}, {0.02, 2 * leg - 2 * leg_r, 0.02}));
      chair.primitives.push_back(box("chair", {sx * leg, 0.175, 0.21}, {0.03, 0.03, 0.42}));
    }
    chair.primitives.push_back(polyhedron(
        "chair", Vector3d::Zero(),
        prism_x({{0.165, 0.22}, {0.185, 0.22}, {0.195, 0.40}, {0.175, 0.40}}, 2 * leg - 0.03)));
  }

  const KitchenLayout& layout_;
  const KitchenDimensions& d_;
  WorldBuilder& b_;
  Vector3d room_;
  std::vector<Footprint> footprints_;
  std::vector<Placed> placed_;
  std::map<WallSide, int> worktops_;
};

}  // namespace

world::WorldModel generate_kitchen(const KitchenLayout& layout) {
  WorldBuilder builder(layout.name, kitchen_materials(layout));
  KitchenBuilder(layout, builder).build();
  return builder.finish();
}

}  // namespace vsl::worldgen
