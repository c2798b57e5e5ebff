// Where an imported object is and which way it faces, from its geometry and its place in the
// model: the reference point the localizer and the recognizer agree on (docs/world-model.md),
// its orientation and its size.
//
// Frames follow the world format's convention (as vsl-worldgen writes them):
//  - a door, drawer front or window: x along its width, y into the panel (away from the room),
//    z up; the reference point is the centre of its front face (y at its front);
//  - a handle: x along its bar, y towards the panel it is mounted on; the reference point is the
//    middle of the bar (a knob's centre): half the bar's thickness behind its front;
//  - anything else: the upright box around it, x along its longer side; the box's centre.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "scene.hpp"
#include "vsl/world_import/type_rules.hpp"

namespace vsl::world_import {

struct Candidate {
  const ScenePart* part = nullptr;
  std::string type;
  Reference reference = Reference::kCentre;
  int parent = -1;  // index of the nearest ancestor that is a candidate too, or -1
  std::vector<Eigen::Vector3d> world_points_m;  // its own geometry's points (world)
};

struct ObjectFrame {
  Eigen::Vector3d world_position_m = Eigen::Vector3d::Zero();  // the reference point
  Eigen::Matrix3d world_R_object = Eigen::Matrix3d::Identity();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  // extents along the object's x, y, z
  std::string front_from;  // for panels and handles, what decided the front: for reports
};

// One frame per candidate (same order). Panels first, so that handles can face as their panel.
std::vector<ObjectFrame> object_frames(const std::vector<Candidate>& candidates);

// Points of one piece of geometry in the world frame: a box's corners, points around a
// cylinder's rims, a mesh's vertices.
void append_world_points(const PartGeometry& geometry, std::vector<Eigen::Vector3d>& out);

}  // namespace vsl::world_import
