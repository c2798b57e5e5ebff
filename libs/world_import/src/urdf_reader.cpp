// URDF through urdfdom: every link is a part, placed by forward kinematics from the root at the
// joint positions given (0 when not given: doors closed, drawers in).
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "quiet_parsers.hpp"
#include "scene.hpp"
#include "vsl/config/node.hpp"

namespace vsl::world_import {
namespace {

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  Eigen::Quaterniond q(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
  out.linear() = q.normalized().toRotationMatrix();
  return out;
}

JointKind kind_of(int type) {
  switch (type) {
    case urdf::Joint::REVOLUTE:
      return JointKind::revolute;
    case urdf::Joint::CONTINUOUS:
      return JointKind::continuous;
    case urdf::Joint::PRISMATIC:
      return JointKind::prismatic;
    case urdf::Joint::FLOATING:
      return JointKind::floating;
    case urdf::Joint::PLANAR:
      return JointKind::planar;
    case urdf::Joint::FIXED:
      return JointKind::fixed;
    default:
      return JointKind::other;
  }
}

urdf::ModelInterfaceSharedPtr parse(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw config::Error(path + ": cannot open file");
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const QuietParsers quiet;
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  if (!model) {
    const std::string reason =
        quiet.first_error().empty() ? "not a valid URDF file" : one_line(quiet.first_error());
    throw config::Error(path + ": " + reason);
  }
  return model;
}

class UrdfReader {
 public:
  UrdfReader(const std::string& path, const ReadOptions& options) : path_(path), options_(options) {
    scene_.source = path;
  }

  Scene read() {
    const urdf::ModelInterfaceSharedPtr model = parse(path_);
    add_link(*model->getRoot(), Eigen::Isometry3d::Identity());
    return std::move(scene_);
  }

 private:
  void add_link(const urdf::Link& link, const Eigen::Isometry3d& world_T_link) {
    ScenePart part;
    part.name = link.name;
    part.world_T_part = world_T_link;
    if (const urdf::JointSharedPtr& joint = link.parent_joint) {
      part.parent = joint->parent_link_name;
      part.joint = kind_of(joint->type);
      // The joint frame is the child link's frame at position 0; the axis is in it.
      const Eigen::Vector3d axis(joint->axis.x, joint->axis.y, joint->axis.z);
      if (axis.norm() > 0.0) part.world_joint_axis = world_T_link.linear() * axis.normalized();
      part.world_joint_point_m = world_T_link.translation();
      if (joint->limits) {
        part.joint_lower = joint->limits->lower;
        part.joint_upper = joint->limits->upper;
      }
    }
    add_geometry(link, part);
    scene_.parts.push_back(std::move(part));
    for (const urdf::LinkSharedPtr& child : link.child_links) {
      add_link(*child, world_T_link * joint_transform(*child->parent_joint));
    }
  }

  // parent_T_child: the joint's origin, then its motion at the position given.
  Eigen::Isometry3d joint_transform(const urdf::Joint& joint) const {
    Eigen::Isometry3d out = to_isometry(joint.parent_to_joint_origin_transform);
    const auto it = options_.joint_positions.find(joint.name);
    const double q = it == options_.joint_positions.end() ? 0.0 : it->second;
    Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (q == 0.0 || axis.norm() == 0.0) return out;
    axis.normalize();
    if (joint.type == urdf::Joint::REVOLUTE || joint.type == urdf::Joint::CONTINUOUS) {
      out.rotate(Eigen::AngleAxisd(q, axis));
    } else if (joint.type == urdf::Joint::PRISMATIC) {
      out.translate(q * axis);
    }
    return out;
  }

  void add_geometry(const urdf::Link& link, ScenePart& part) {
    bool all_visuals_loaded = true;
    for (const urdf::VisualSharedPtr& visual : link.visual_array) {
      if (!visual || !visual->geometry) continue;
      std::optional<world::Colour> colour;
      std::string material;
      if (visual->material) {
        material = visual->material->name;
        const urdf::Color& c = visual->material->color;
        colour = world::Colour{to_byte(c.r), to_byte(c.g), to_byte(c.b)};
      }
      all_visuals_loaded &=
          add_shape(*visual->geometry, to_isometry(visual->origin), material, colour, part);
    }
    if (all_visuals_loaded && !part.geometry.empty()) return;
    // A visual mesh that is missing: the collision geometry stands in (the warning is out).
    if (!link.visual_array.empty() || part.geometry.empty()) {
      for (const urdf::CollisionSharedPtr& collision : link.collision_array) {
        if (collision && collision->geometry) {
          add_shape(*collision->geometry, to_isometry(collision->origin), "", std::nullopt, part);
        }
      }
    }
  }

  // Returns false (after a warning) when a mesh cannot be loaded.
  bool add_shape(const urdf::Geometry& geometry, const Eigen::Isometry3d& link_T_geometry,
                 const std::string& material, const std::optional<world::Colour>& colour,
                 ScenePart& part) {
    PartGeometry piece;
    piece.world_T_geometry = part.world_T_part * link_T_geometry;
    piece.material = material;
    piece.colour = colour;
    switch (geometry.type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(geometry);
        piece.shape = world::Box{Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z)};
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
        piece.shape = world::Cylinder{cylinder.radius, cylinder.length};
        break;
      }
      case urdf::Geometry::SPHERE:
        piece.shape = tessellate_sphere(static_cast<const urdf::Sphere&>(geometry).radius);
        break;
      case urdf::Geometry::MESH: {
        const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
        const std::string file = resolve_uri(mesh.filename, path_, options_.package_paths);
        if (file.empty()) {
          scene_.warnings.push_back(path_ + ": mesh not found: " + mesh.filename + " (link " +
                                    part.name + ")");
          return false;
        }
        try {
          for (MeshPiece& loaded :
               load_mesh_pieces(file, Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z))) {
            PartGeometry one = piece;
            one.shape = std::move(loaded.soup);
            if (!loaded.material.empty()) one.material = loaded.material;
            // The URDF's own colour wins: it is what ROS tools show.
            if (!one.colour) one.colour = loaded.colour;
            part.geometry.push_back(std::move(one));
          }
        } catch (const config::Error& e) {
          scene_.warnings.push_back(std::string(e.what()) + " (link " + part.name + ")");
          return false;
        }
        return true;
      }
      default:
        return true;
    }
    part.geometry.push_back(std::move(piece));
    return true;
  }

  std::string path_;
  const ReadOptions& options_;
  Scene scene_;
};

}  // namespace

Scene read_urdf(const std::string& path, const ReadOptions& options) {
  return UrdfReader(path, options).read();
}

}  // namespace vsl::world_import
