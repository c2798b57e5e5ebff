#include "object_frames.hpp"

#include <cmath>
#include <optional>

#include "upright_box.hpp"

namespace vsl::world_import {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Depth of a drawer front's slab: the drawer's box behind it is not its face.
constexpr double kMaxFrontSlabM = 0.05;

Eigen::Vector3d centroid_of_box(const std::vector<Eigen::Vector3d>& points) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points) box.extend(p);
  return points.empty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : Eigen::Vector3d(box.center());
}

Eigen::Vector3d horizontal(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), 0.0};
}

// Which way a joint opens: the sign of its larger limit (a continuous joint: positive).
double opening_sign(const ScenePart& part) {
  if (std::abs(part.joint_upper) >= std::abs(part.joint_lower)) {
    return part.joint_upper >= 0.0 ? 1.0 : -1.0;
  }
  return part.joint_lower >= 0.0 ? 1.0 : -1.0;
}

bool is_panel(const std::string& type) {
  return type == "door" || type == "drawer_front" || type == "window";
}

bool has_ancestor(const std::vector<Candidate>& candidates, int index, int ancestor) {
  for (int i = candidates[index].parent; i >= 0; i = candidates[i].parent) {
    if (i == ancestor) return true;
  }
  return false;
}

bool has_panel_ancestor(const std::vector<Candidate>& candidates, int index) {
  for (int i = candidates[index].parent; i >= 0; i = candidates[i].parent) {
    if (is_panel(candidates[i].type)) return true;
  }
  return false;
}

struct PanelFace {
  Eigen::Vector3d outward;  // unit horizontal normal pointing to the room
  std::string decided_by;
};

// The panel's normal (a drawer's slide axis, else the thin side of its footprint) and which way
// is out: towards its handles, the way its joint opens, away from its parent, away from what
// stands right behind it, towards the middle of the model, in that order.
PanelFace panel_face(const std::vector<Candidate>& candidates, int index,
                     const Eigen::Vector3d& scene_centre) {
  const Candidate& panel = candidates[index];
  const ScenePart& part = *panel.part;
  const Eigen::Vector3d centre = centroid_of_box(panel.world_points_m);
  Eigen::Vector3d normal = upright_box(panel.world_points_m).axis_y;
  const Eigen::Vector3d slide = horizontal(part.world_joint_axis);
  const bool slides = part.joint == JointKind::prismatic && slide.norm() > 0.7;
  if (slides) normal = slide.normalized();

  // Its handles: those below it in the model, else (a mesh file has no such tree) those on
  // neither side of it by more than 15 cm, within its outline, that belong to no other panel.
  const UprightBox outline = upright_box(panel.world_points_m);
  const Eigen::Vector3d across = normal.cross(Eigen::Vector3d::UnitZ()).normalized();
  double below_side = 0.0, near_side = 0.0;
  for (std::size_t h = 0; h < candidates.size(); ++h) {
    if (candidates[h].type != "handle") continue;
    const Eigen::Vector3d offset = centroid_of_box(candidates[h].world_points_m) - centre;
    if (has_ancestor(candidates, static_cast<int>(h), index)) {
      below_side += offset.dot(normal);
    } else if (!has_panel_ancestor(candidates, static_cast<int>(h)) &&
               std::abs(offset.dot(normal)) < 0.15 &&
               std::abs(offset.dot(across)) < 0.5 * outline.extents_m.x() + 0.03 &&
               std::abs(offset.z()) < 0.5 * outline.extents_m.z() + 0.03) {
      near_side += offset.dot(normal);
    }
  }
  const double handles_side = below_side != 0.0 ? below_side : near_side;
  if (std::abs(handles_side) > 0.005) return {handles_side > 0 ? normal : -normal, "its handle"};
  if (slides) {
    return {opening_sign(part) * part.world_joint_axis.dot(normal) > 0 ? normal : -normal,
            "its slide"};
  }
  if ((part.joint == JointKind::revolute || part.joint == JointKind::continuous) &&
      part.world_joint_axis.norm() > 0.5) {
    // The panel's centre moves out of the cupboard as the joint opens.
    const Eigen::Vector3d motion =
        opening_sign(part) * part.world_joint_axis.cross(centre - part.world_joint_point_m);
    if (std::abs(motion.dot(normal)) > 0.01) {
      return {motion.dot(normal) > 0 ? normal : -normal, "its hinge"};
    }
  }
  if (panel.parent >= 0 && !candidates[panel.parent].world_points_m.empty()) {
    const double away =
        (centre - centroid_of_box(candidates[panel.parent].world_points_m)).dot(normal);
    if (std::abs(away) > 0.01) return {away > 0 ? normal : -normal, "its parent"};
  }
  // No joint and no parent (a mesh file): the carcass it closes stands behind it.
  double behind = 0.0;
  for (std::size_t o = 0; o < candidates.size(); ++o) {
    if (static_cast<int>(o) == index || candidates[o].type == "handle") continue;
    const Eigen::Vector3d offset = centroid_of_box(candidates[o].world_points_m) - centre;
    if (std::abs(offset.dot(normal)) < 0.6 &&
        std::abs(offset.dot(across)) < 0.5 * outline.extents_m.x() + 0.03 &&
        std::abs(offset.z()) < 0.5 * outline.extents_m.z() + 0.03) {
      behind += offset.dot(normal);
    }
  }
  if (std::abs(behind) > 0.01) return {behind > 0 ? -normal : normal, "what stands behind it"};
  // Nothing tells: furniture faces into the room, so the side towards the middle of everything.
  const double inward_of_scene = (scene_centre - centre).dot(normal);
  return {inward_of_scene >= 0 ? normal : -normal, "the middle of the model"};
}

ObjectFrame panel_frame(const Candidate& panel, const PanelFace& face) {
  const Eigen::Vector3d inward = -face.outward;
  Eigen::Matrix3d world_R_object;
  world_R_object << inward.cross(Eigen::Vector3d::UnitZ()).normalized(), inward,
      Eigen::Vector3d::UnitZ();
  const FrameExtents extents = extents_in(panel.world_points_m, world_R_object);
  ObjectFrame frame;
  frame.world_R_object = world_R_object;
  frame.size_m = extents.size();
  // A front's thickness is its slab's, not the drawer box's behind it.
  double slab = 0.0;
  for (const Eigen::Vector3d& p : panel.world_points_m) {
    const double behind = inward.dot(p) - extents.lo.y();
    if (behind <= kMaxFrontSlabM) slab = std::max(slab, behind);
  }
  frame.size_m.y() = slab;
  frame.world_position_m =
      world_R_object * Eigen::Vector3d(extents.mid().x(), extents.lo.y(), extents.mid().z());
  frame.front_from = face.decided_by;
  return frame;
}

// The panel a handle is on: its nearest panel ancestor, else the nearest panel whose front is
// within 15 cm of it.
std::optional<int> panel_of_handle(const std::vector<Candidate>& candidates,
                                   const std::vector<ObjectFrame>& frames, int handle) {
  for (int i = candidates[handle].parent; i >= 0; i = candidates[i].parent) {
    if (is_panel(candidates[i].type)) return i;
  }
  const Eigen::Vector3d centre = centroid_of_box(candidates[handle].world_points_m);
  std::optional<int> best;
  double best_distance = 0.15;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!is_panel(candidates[i].type)) continue;
    const Eigen::Vector3d local =
        frames[i].world_R_object.transpose() * (centre - frames[i].world_position_m);
    const Eigen::Vector3d half = 0.5 * frames[i].size_m;
    // Beside the face (within its outline, 3 cm slack) and in front of it.
    if (std::abs(local.x()) > half.x() + 0.03 || std::abs(local.z()) > half.z() + 0.03) continue;
    const double distance = std::abs(local.y());
    if (distance < best_distance) {
      best_distance = distance;
      best = static_cast<int>(i);
    }
  }
  return best;
}

ObjectFrame handle_frame(const std::vector<Candidate>& candidates,
                         const std::vector<ObjectFrame>& frames, int index) {
  const Candidate& handle = candidates[index];
  Eigen::Vector3d outward;
  std::string decided_by;
  if (const std::optional<int> panel = panel_of_handle(candidates, frames, index)) {
    outward = -frames[*panel].world_R_object.col(1);
    decided_by = "its panel";
  } else {
    // No panel: a bar's standoffs make it deeper than the bar is thick, so the deeper
    // horizontal side is the normal for an upright bar, the shorter one for a level bar.
    const UprightBox box = upright_box(handle.world_points_m);
    outward = box.extents_m.z() > box.extents_m.x() ? box.axis_x : box.axis_y;
    decided_by = "its shape";
    if (handle.parent >= 0 && !candidates[handle.parent].world_points_m.empty()) {
      const double away =
          (box.centre_m - centroid_of_box(candidates[handle.parent].world_points_m)).dot(outward);
      if (away < 0) outward = -outward;
      decided_by = "its parent";
    }
  }
  const Eigen::Vector3d inward = -outward;
  const Eigen::Vector3d across = inward.cross(Eigen::Vector3d::UnitZ()).normalized();
  Eigen::Matrix3d world_R_plane;
  world_R_plane << across, inward, Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d plane_size = extents_in(handle.world_points_m, world_R_plane).size();
  // x along the bar: level or upright, whichever is longer; then y into the panel.
  const Eigen::Vector3d bar = plane_size.x() >= plane_size.z() ? across : Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d world_R_object;
  world_R_object << bar, inward, bar.cross(inward);
  const FrameExtents extents = extents_in(handle.world_points_m, world_R_object);
  const double thickness = std::min(extents.size().z(), extents.size().y());
  ObjectFrame frame;
  frame.world_R_object = world_R_object;
  frame.size_m = extents.size();
  frame.world_position_m =
      world_R_object *
      Eigen::Vector3d(extents.mid().x(), extents.lo.y() + 0.5 * thickness, extents.mid().z());
  frame.front_from = decided_by;
  return frame;
}

ObjectFrame centre_frame(const Candidate& candidate) {
  const UprightBox box = upright_box(candidate.world_points_m);
  ObjectFrame frame;
  frame.world_R_object << box.axis_x, box.axis_y, Eigen::Vector3d::UnitZ();
  frame.size_m = box.extents_m;
  frame.world_position_m = box.centre_m;
  return frame;
}

}  // namespace

void append_world_points(const PartGeometry& geometry, std::vector<Eigen::Vector3d>& out) {
  const Eigen::Isometry3d& T = geometry.world_T_geometry;
  if (const auto* box = std::get_if<world::Box>(&geometry.shape)) {
    const Eigen::Vector3d half = 0.5 * box->size_m;
    for (int k = 0; k < 8; ++k) {
      out.push_back(T * Eigen::Vector3d((k & 1 ? 1 : -1) * half.x(), (k & 2 ? 1 : -1) * half.y(),
                                        (k & 4 ? 1 : -1) * half.z()));
    }
  } else if (const auto* cylinder = std::get_if<world::Cylinder>(&geometry.shape)) {
    for (int k = 0; k < 32; ++k) {
      const double a = 2.0 * kPi * (k % 16) / 16.0;
      const double z = (k < 16 ? -0.5 : 0.5) * cylinder->height_m;
      out.push_back(T * Eigen::Vector3d(cylinder->radius_m * std::cos(a),
                                        cylinder->radius_m * std::sin(a), z));
    }
  } else {
    for (const Eigen::Vector3f& v : std::get<TriangleSoup>(geometry.shape).vertices_m) {
      out.push_back(T * v.cast<double>());
    }
  }
}

std::vector<ObjectFrame> object_frames(const std::vector<Candidate>& candidates) {
  std::vector<ObjectFrame> frames(candidates.size());
  Eigen::AlignedBox3d everything;
  for (const Candidate& c : candidates) {
    for (const Eigen::Vector3d& p : c.world_points_m) everything.extend(p);
  }
  const Eigen::Vector3d scene_centre = everything.isEmpty()
                                           ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                           : Eigen::Vector3d(everything.center());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Candidate& c = candidates[i];
    if (c.reference == Reference::kFrontFaceCentre) {
      frames[i] = panel_frame(c, panel_face(candidates, static_cast<int>(i), scene_centre));
    } else if (c.reference == Reference::kCentre) {
      frames[i] = centre_frame(c);
    }
  }
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].reference == Reference::kBarCentre) {
      frames[i] = handle_frame(candidates, frames, static_cast<int>(i));
    }
  }
  return frames;
}

}  // namespace vsl::world_import
