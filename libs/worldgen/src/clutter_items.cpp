// Kitchen clutter (clutter_items.hpp). Sizes are those of common products, in metres.
#include "clutter_items.hpp"

#include <array>
#include <functional>
#include <utility>

#include "look_palettes.hpp"
#include "vsl/worldgen/geometry.hpp"

namespace vsl::worldgen {
namespace {

using Eigen::Vector3d;

// Collects an item's parts and primitives.
class Item {
 public:
  Item(std::string kind, Rng& rng) : rng_(rng) { item_.kind = std::move(kind); }

  // Gives part `name` a look of `kind`.
  Item& part(const std::string& name, ClutterLook kind) {
    world::Material look = draw_clutter_look(kind, rng_);
    look.name = name;
    item_.parts.push_back(std::move(look));
    return *this;
  }
  // A box of `size` standing on z = `z0` (its bottom), centred on (x, y).
  Item& box_on(const std::string& part, double x, double y, double z0, const Vector3d& size) {
    item_.primitives.push_back(box(part, {x, y, z0 + size.z() / 2}, size));
    return *this;
  }
  Item& cylinder_on(const std::string& part, double x, double y, double z0, double radius,
                    double height) {
    item_.primitives.push_back(cylinder(part, {x, y, z0 + height / 2}, radius, height, Axis::z));
    return *this;
  }
  ClutterItem done(bool against_back = false) {
    item_.against_back = against_back;
    return std::move(item_);
  }
  double uniform(double lo, double hi) { return rng_.uniform(lo, hi); }

 private:
  Rng& rng_;
  ClutterItem item_;
};

// An item of one box, its extents drawn uniformly in [lo, hi] along x, y, z (m).
struct BoxKind {
  const char* kind;
  ClutterLook look;
  std::array<double, 3> lo, hi;
};
constexpr BoxKind kPacket{"packet", ClutterLook::printed, {0.14, 0.05, 0.18}, {0.3, 0.09, 0.33}};
constexpr BoxKind kFoldedTowel{"towel", ClutterLook::fabric, {0.2, 0.15, 0.02}, {0.3, 0.25, 0.05}};
constexpr BoxKind kCuttingBoard{
    "cutting_board", ClutterLook::wood, {0.3, 0.2, 0.015}, {0.45, 0.3, 0.025}};
constexpr BoxKind kCardboardBox{"box", ClutterLook::cardboard, {0.3, 0.25, 0.2}, {0.6, 0.5, 0.5}};
constexpr BoxKind kCrate{"crate", ClutterLook::plastic, {0.3, 0.25, 0.25}, {0.4, 0.3, 0.3}};

template <const BoxKind& kind>
ClutterItem box_item(Rng& rng) {
  Item item(kind.kind, rng);
  const Vector3d size(item.uniform(kind.lo[0], kind.hi[0]), item.uniform(kind.lo[1], kind.hi[1]),
                      item.uniform(kind.lo[2], kind.hi[2]));
  return item.part("body", kind.look).box_on("body", 0, 0, 0, size).done();
}

ClutterItem bottle(Rng& rng) {
  Item item("bottle", rng);
  const double r = item.uniform(0.03, 0.045), h = item.uniform(0.17, 0.26);
  const double neck = item.uniform(0.012, 0.016), neck_h = item.uniform(0.05, 0.08);
  item.part("body", ClutterLook::bottle_glass).part("cap", ClutterLook::plastic);
  item.cylinder_on("body", 0, 0, 0, r, h).cylinder_on("body", 0, 0, h, neck, neck_h);
  return item.cylinder_on("cap", 0, 0, h + neck_h, neck + 0.002, 0.015).done();
}

ClutterItem jar(Rng& rng) {
  Item item("jar", rng);
  const double r = item.uniform(0.035, 0.06), h = item.uniform(0.08, 0.16);
  item.part("body", ClutterLook::bottle_glass).part("lid", ClutterLook::steel);
  return item.cylinder_on("body", 0, 0, 0, r, h)
      .cylinder_on("lid", 0, 0, h, r + 0.003, 0.015)
      .done();
}

ClutterItem kettle(Rng& rng) {
  Item item("kettle", rng);
  const double r = item.uniform(0.07, 0.085), h = item.uniform(0.16, 0.22);
  item.part("body", ClutterLook::appliance).part("base", ClutterLook::plastic);
  item.cylinder_on("base", 0, 0, 0, r + 0.01, 0.02).cylinder_on("body", 0, 0, 0.02, r, h);
  item.box_on("body", r + 0.0125, 0, 0.06, {0.035, 0.02, h - 0.05});                      // handle
  return item.box_on("body", -r - 0.02, 0, 0.02 + 0.45 * h, {0.05, 0.025, 0.03}).done();  // spout
}

ClutterItem toaster(Rng& rng) {
  Item item("toaster", rng);
  const Vector3d size(item.uniform(0.26, 0.32), item.uniform(0.15, 0.19), item.uniform(0.18, 0.21));
  item.part("body", ClutterLook::appliance).part("trim", ClutterLook::black_glass);
  item.box_on("body", 0, 0, 0, size);
  item.box_on("trim", 0, -0.035, size.z(), {size.x() * 0.7, 0.025, 0.003});  // slots
  item.box_on("trim", 0, 0.035, size.z(), {size.x() * 0.7, 0.025, 0.003});
  return item.box_on("trim", size.x() / 2 + 0.01, 0, size.z() * 0.6, {0.02, 0.03, 0.02}).done(true);
}

ClutterItem microwave(Rng& rng) {
  Item item("microwave", rng);
  const Vector3d size(item.uniform(0.45, 0.52), item.uniform(0.33, 0.4), item.uniform(0.26, 0.31));
  item.part("body", ClutterLook::appliance).part("window", ClutterLook::black_glass);
  item.box_on("body", 0, 0, 0, size);
  const double front = -size.y() / 2 - 0.004;
  item.box_on("window", -size.x() * 0.1, front, size.z() * 0.12,
              {size.x() * 0.68, 0.008, size.z() * 0.76});
  return item.box_on("window", size.x() * 0.37, front, size.z() * 0.5, {0.06, 0.008, 0.03})
      .done(true);
}

ClutterItem coffee_machine(Rng& rng) {
  Item item("coffee_machine", rng);
  const Vector3d size(item.uniform(0.2, 0.26), item.uniform(0.3, 0.38), item.uniform(0.3, 0.38));
  item.part("body", ClutterLook::appliance).part("jug", ClutterLook::bottle_glass);
  item.box_on("body", 0, 0, 0, size);
  return item.cylinder_on("jug", 0, -size.y() / 2, 0.01, 0.065, 0.13).done(true);
}

ClutterItem fruit_bowl(Rng& rng) {
  Item item("fruit_bowl", rng);
  const double r = item.uniform(0.1, 0.14), h = item.uniform(0.06, 0.09);
  item.part("bowl", ClutterLook::plastic).part("fruit", ClutterLook::fruit);
  item.cylinder_on("bowl", 0, 0, 0, r, h);
  for (int k = 0; k < 3; ++k) {
    const double angle = 2.0944 * k;
    item.cylinder_on("fruit", 0.045 * std::cos(angle), 0.045 * std::sin(angle), h, 0.035, 0.06);
  }
  return item.done();
}

ClutterItem bin(Rng& rng) {
  Item item("bin", rng);
  const double r = item.uniform(0.13, 0.18), h = item.uniform(0.4, 0.6);
  item.part("body", rng.chance(0.5) ? ClutterLook::steel : ClutterLook::plastic)
      .part("lid", ClutterLook::plastic);
  return item.cylinder_on("body", 0, 0, 0, r, h)
      .cylinder_on("lid", 0, 0, h, r + 0.005, 0.02)
      .done();
}

ClutterItem bag(Rng& rng) {
  Item item("bag", rng);
  const Vector3d size(item.uniform(0.3, 0.45), item.uniform(0.12, 0.2), item.uniform(0.3, 0.45));
  item.part("body", rng.chance(0.5) ? ClutterLook::fabric : ClutterLook::printed);
  return item.box_on("body", 0, 0, 0, size).done();
}

ClutterItem bucket(Rng& rng) {
  Item item("bucket", rng);
  const double r = item.uniform(0.11, 0.15), h = item.uniform(0.22, 0.3);
  return item.part("body", ClutterLook::plastic).cylinder_on("body", 0, 0, 0, r, h).done();
}

using Maker = ClutterItem (*)(Rng&);

ClutterItem pick(const std::vector<std::pair<Maker, double>>& makers, Rng& rng) {
  double total = 0.0;
  for (const auto& entry : makers) total += entry.second;
  double roll = rng.uniform() * total;
  for (const auto& [make, weight] : makers) {
    if (roll < weight) return make(rng);
    roll -= weight;
  }
  return makers.back().first(rng);
}

}  // namespace

ClutterItem worktop_item(Rng& rng) {
  static const std::vector<std::pair<Maker, double>> makers{{box_item<kPacket>, 1.2},
                                                            {bottle, 1.5},
                                                            {jar, 1.0},
                                                            {kettle, 1.0},
                                                            {toaster, 0.8},
                                                            {microwave, 0.6},
                                                            {coffee_machine, 0.6},
                                                            {box_item<kFoldedTowel>, 0.6},
                                                            {fruit_bowl, 0.6},
                                                            {box_item<kCuttingBoard>, 0.6}};
  return pick(makers, rng);
}

ClutterItem floor_item(Rng& rng) {
  static const std::vector<std::pair<Maker, double>> makers{
      {box_item<kCardboardBox>, 1.5}, {bin, 1.0},    {bag, 1.0},
      {box_item<kCrate>, 0.7},        {bucket, 0.5}, {bottle, 0.5}};
  return pick(makers, rng);
}

ClutterItem draped_towel(Rng& rng) {
  Item item("towel", rng);
  const double width = item.uniform(0.25, 0.45), on_top = item.uniform(0.06, 0.14);
  const double drop = item.uniform(0.15, 0.35), t = 0.006;
  item.part("cloth", ClutterLook::fabric);
  // The flat part reaches over the edge to meet the hanging part, which stands 3 mm in front of
  // the edge from the flat part's top down.
  const double front = -0.003 - t;
  item.box_on("cloth", 0, (on_top + front) / 2, 0, {width, on_top - front, t});
  item.box_on("cloth", 0, front + t / 2, -drop, {width, t, drop + t});
  ClutterItem towel = item.done();
  towel.draped = true;
  return towel;
}

}  // namespace vsl::worldgen
