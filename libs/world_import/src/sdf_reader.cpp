// SDFormat (SDF files and Gazebo .world files) -> Scene, through libsdformat 12's DOM. Every
// link of every model (nested models too) becomes a part named by its scope ("kitchen::door",
// "kitchen::cupboard::door"), placed by sdformat's own pose resolution (relative_to, frames,
// placement frames), then moved by its joints' positions (forward kinematics along the joint
// tree, product of exponentials with the axes of the file's zero configuration).
#include <sdf/Box.hh>
#include <sdf/Capsule.hh>
#include <sdf/Collision.hh>
#include <sdf/Cylinder.hh>
#include <sdf/Element.hh>
#include <sdf/Ellipsoid.hh>
#include <sdf/Error.hh>
#include <sdf/Geometry.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Link.hh>
#include <sdf/Material.hh>
#include <sdf/Mesh.hh>
#include <sdf/Model.hh>
#include <sdf/ParserConfig.hh>
#include <sdf/Plane.hh>
#include <sdf/Root.hh>
#include <sdf/SemanticPose.hh>
#include <sdf/Sphere.hh>
#include <sdf/Visual.hh>
#include <sdf/World.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>
#include <unordered_map>

#include "quiet_parsers.hpp"
#include "scene.hpp"
#include "vsl/config/node.hpp"

namespace vsl::world_import {
namespace {

namespace fs = std::filesystem;

// sdformat's limits when an axis has no <limit>: +-1e16. Anything this large means "none".
constexpr double kNoLimit = 1e15;
constexpr double kPlaneThicknessM = 0.001;

Eigen::Vector3d to_eigen(const ignition::math::Vector3d& v) {
  return {v.X(), v.Y(), v.Z()};
}

Eigen::Isometry3d to_isometry(const ignition::math::Pose3d& pose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = to_eigen(pose.Pos());
  const auto& q = pose.Rot();
  t.linear() = Eigen::Quaterniond(q.W(), q.X(), q.Y(), q.Z()).normalized().toRotationMatrix();
  return t;
}

// The roots `model://` URIs (includes and meshes) are searched in: the caller's, then Gazebo's.
std::vector<std::string> search_roots(const ReadOptions& options) {
  std::vector<std::string> roots = options.package_paths;
  for (const char* variable : {"SDF_PATH", "GAZEBO_MODEL_PATH"}) {
    const char* value = std::getenv(variable);
    if (value == nullptr) continue;
    std::string list = value;
    std::size_t start = 0;
    while (start <= list.size()) {
      const auto end = std::min(list.find(':', start), list.size());
      if (end > start) roots.push_back(list.substr(start, end - start));
      start = end + 1;
    }
  }
  return roots;
}

// The folder or file `model://NAME/rest` names: NAME a folder under a root, or the root itself.
// sdformat asks for included models this way (the model's folder; it then reads model.config).
std::string find_model_path(const std::string& uri, const std::vector<std::string>& roots) {
  const std::string scheme = "model://";
  if (uri.rfind(scheme, 0) != 0) return {};
  const std::string rest = uri.substr(scheme.size());
  const auto slash = rest.find('/');
  const std::string name = rest.substr(0, slash);
  const std::string inside = slash == std::string::npos ? std::string() : rest.substr(slash + 1);
  std::error_code ec;
  for (const auto& root : roots) {
    for (const fs::path& candidate :
         {fs::path(root) / name / inside,
          fs::path(root).filename() == name ? fs::path(root) / inside : fs::path()}) {
      if (!candidate.empty() && fs::exists(candidate, ec)) return candidate.lexically_normal();
    }
  }
  return {};
}

// Errors after which sdformat still builds the rest of the document (an include it cannot find,
// a material script without a uri, a deprecated element): warnings when a world or model loaded.
bool tolerated(sdf::ErrorCode code) {
  switch (code) {
    case sdf::ErrorCode::URI_LOOKUP:
    case sdf::ErrorCode::ELEMENT_INVALID:
    case sdf::ErrorCode::ELEMENT_MISSING:
    case sdf::ErrorCode::ELEMENT_DEPRECATED:
    case sdf::ErrorCode::ATTRIBUTE_DEPRECATED:
    case sdf::ErrorCode::VERSION_DEPRECATED:
    case sdf::ErrorCode::LINK_INERTIA_INVALID:
    case sdf::ErrorCode::MODEL_WITHOUT_LINK:
      return true;
    default:
      return false;
  }
}

JointKind joint_kind(sdf::JointType type) {
  switch (type) {
    case sdf::JointType::FIXED:
      return JointKind::fixed;
    case sdf::JointType::REVOLUTE:
      return JointKind::revolute;
    case sdf::JointType::CONTINUOUS:
      return JointKind::continuous;
    case sdf::JointType::PRISMATIC:
      return JointKind::prismatic;
    default:  // ball, universal, revolute2, screw, gearbox: no single axis to move along
      return JointKind::other;
  }
}

// How a visual looks: its material's script name and diffuse colour.
struct Look {
  std::string material;
  std::optional<world::Colour> colour;
};

Look look_of(const sdf::Visual& visual) {
  Look look;
  const sdf::Material* material = visual.Material();
  if (material == nullptr) return look;
  look.material = material->ScriptName();
  // Old Gazebo worlds often give only <ambient> (with a script); an absent <diffuse> reads as
  // black in the DOM, so only elements the file has count.
  const sdf::ElementPtr element = material->Element();
  std::optional<ignition::math::Color> colour;
  if (element && element->HasElement("diffuse")) {
    colour = material->Diffuse();
  } else if (element && element->HasElement("ambient")) {
    colour = material->Ambient();
  }
  if (colour) {
    look.colour = world::Colour{to_byte(colour->R()), to_byte(colour->G()), to_byte(colour->B())};
  }
  return look;
}

// One link as read: its part and its pose at the file's (zero) joint positions.
struct LinkRecord {
  ScenePart part;
  Eigen::Isometry3d world_T_link_at_zero;
  std::string joint;  // scoped name of the joint that has it as child, or ""
};

// One joint as read, in the world frame of the zero configuration.
struct JointRecord {
  JointKind kind = JointKind::other;
  std::string parent_part;  // "" when attached to the world
  Eigen::Vector3d world_axis = Eigen::Vector3d::Zero();
  Eigen::Vector3d world_point_m = Eigen::Vector3d::Zero();
  double lower = 0.0;
  double upper = 0.0;
  double position = 0.0;  // rad or m
};

class SdfSceneReader {
 public:
  SdfSceneReader(std::string path, const ReadOptions& options)
      : path_(std::move(path)), options_(options), roots_(search_roots(options)) {}

  Scene read() {
    sdf::ParserConfig config;
    config.SetFindCallback(
        [roots = roots_](const std::string& uri) { return find_model_path(uri, roots); });
    sdf::Root root;
    sdf::Errors errors;
    {
      const QuietParsers quiet;  // the errors come back in `errors`
      errors = root.Load(path_, config);
    }
    const bool loaded = root.Model() != nullptr || root.WorldCount() > 0;
    for (const auto& error : errors) {
      if (!loaded || !tolerated(error.Code())) {
        throw config::Error(path_ + ": not a valid SDF file: " + one_line(error.Message()));
      }
      warn("sdformat: " + one_line(error.Message()));
    }
    if (!loaded) throw config::Error(path_ + ": not a valid SDF file: no world or model in it");

    if (root.Model() != nullptr) {
      read_model(*root.Model(), pose_of(root.Model()->SemanticPose(), "model"), "");
    }
    for (std::uint64_t w = 0; w < root.WorldCount(); ++w) {
      const sdf::World& world = *root.WorldByIndex(w);
      // Names stay unique when one file holds several worlds.
      const std::string prefix = root.WorldCount() > 1 ? world.Name() + "::" : "";
      for (std::uint64_t m = 0; m < world.ModelCount(); ++m) {
        const sdf::Model& model = *world.ModelByIndex(m);
        read_model(model, pose_of(model.SemanticPose(), "model " + model.Name()), prefix);
      }
    }
    read_joints();
    place_links();

    scene_.source = path_;
    for (auto& link : links_) scene_.parts.push_back(std::move(link.part));
    return std::move(scene_);
  }

 private:
  void warn(const std::string& what) { scene_.warnings.push_back(path_ + ": " + what); }

  // The pose sdformat resolves (to the object's default frame unless `to` is given). The
  // document loaded, so its frame graphs are valid; a failure here still only warns.
  Eigen::Isometry3d pose_of(const sdf::SemanticPose& pose, const std::string& what,
                            const std::string& to = "") {
    ignition::math::Pose3d resolved = pose.RawPose();
    const sdf::Errors errors = pose.Resolve(resolved, to);
    if (!errors.empty()) {
      warn("cannot resolve the pose of " + what + ": " + one_line(errors.front().Message()));
    }
    return to_isometry(resolved);
  }

  // world_T_model: the model frame in the world; scope: the enclosing models' names with "::".
  // Links first, every model's; joints after, since a joint's child may be a nested model's link.
  void read_model(const sdf::Model& model, const Eigen::Isometry3d& world_T_model,
                  const std::string& scope) {
    const std::string name = scope + model.Name();
    models_.push_back({&model, world_T_model, name});
    for (std::uint64_t i = 0; i < model.LinkCount(); ++i) {
      const sdf::Link& link = *model.LinkByIndex(i);
      LinkRecord record;
      record.part.name = name + "::" + link.Name();
      // A link's pose resolves to its model's frame by default.
      record.world_T_link_at_zero =
          world_T_model * pose_of(link.SemanticPose(), "link " + record.part.name);
      read_link_geometry(link, record);
      link_index_[record.part.name] = links_.size();
      links_.push_back(std::move(record));
    }
    for (std::uint64_t i = 0; i < model.ModelCount(); ++i) {
      const sdf::Model& nested = *model.ModelByIndex(i);
      // A nested model's pose resolves to its parent model's frame by default.
      const std::string nested_name = name + "::" + nested.Name();
      read_model(nested, world_T_model * pose_of(nested.SemanticPose(), "model " + nested_name),
                 name + "::");
    }
  }

  void read_joints() {
    for (const auto& model : models_) {
      for (std::uint64_t i = 0; i < model.model->JointCount(); ++i) {
        read_joint(*model.model->JointByIndex(i), model.world_T_model, model.name);
      }
    }
  }

  void read_joint(const sdf::Joint& joint, const Eigen::Isometry3d& world_T_model,
                  const std::string& model_name) {
    const std::string name = model_name + "::" + joint.Name();
    // Parent and child may name frames or links of nested models; sdformat resolves them to
    // links in the model's scope ("inner::link"), or "world".
    std::string child;
    std::string parent;
    if (!joint.ResolveChildLink(child).empty() || !joint.ResolveParentLink(parent).empty()) {
      warn("cannot resolve the links of joint " + name + "; ignored");
      return;
    }
    const auto child_it = link_index_.find(model_name + "::" + child);
    if (child_it == link_index_.end()) {
      warn("joint " + name + " has no child link " + child + "; ignored");
      return;
    }
    LinkRecord& child_link = links_[child_it->second];
    if (!child_link.joint.empty()) {
      warn("link " + child_link.part.name + " is the child of two joints; " + name + " ignored");
      return;
    }
    JointRecord record;
    record.kind = joint_kind(joint.Type());
    record.parent_part = parent == "world" ? "" : model_name + "::" + parent;
    // The joint frame's origin is the point on the axis; the axis resolves to the model frame.
    record.world_point_m =
        world_T_model * pose_of(joint.SemanticPose(), "joint " + name, "__model__").translation();
    const sdf::JointAxis* axis = joint.Axis(0);
    if (axis != nullptr) {
      ignition::math::Vector3d xyz = axis->Xyz();
      if (!axis->ResolveXyz(xyz, "__model__").empty()) {
        warn("cannot resolve the axis of joint " + name);
      }
      const Eigen::Vector3d model_axis = to_eigen(xyz);
      if (model_axis.norm() > 0.0) {
        record.world_axis = world_T_model.linear() * model_axis.normalized();
      }
      if (record.kind == JointKind::revolute || record.kind == JointKind::prismatic) {
        if (std::abs(axis->Lower()) < kNoLimit) record.lower = axis->Lower();
        if (std::abs(axis->Upper()) < kNoLimit) record.upper = axis->Upper();
      }
    }
    // Scoped name first: several models of a world may each have a "hinge".
    for (const auto& key : {name, joint.Name()}) {
      const auto it = options_.joint_positions.find(key);
      if (it != options_.joint_positions.end()) {
        record.position = it->second;
        break;
      }
    }
    child_link.joint = name;
    child_link.part.parent = record.parent_part;
    child_link.part.joint = record.kind;
    child_link.part.joint_lower = record.lower;
    child_link.part.joint_upper = record.upper;
    joints_[name] = record;
  }

  // The rigid motion joint `name` applies to its child (and everything below) at its position,
  // about or along its axis of the zero configuration.
  static Eigen::Isometry3d joint_motion(const JointRecord& joint) {
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    if (joint.position == 0.0 || joint.world_axis.isZero()) return motion;
    if (joint.kind == JointKind::revolute || joint.kind == JointKind::continuous) {
      motion.linear() = Eigen::AngleAxisd(joint.position, joint.world_axis).toRotationMatrix();
      motion.translation() = joint.world_point_m - motion.linear() * joint.world_point_m;
    } else if (joint.kind == JointKind::prismatic) {
      motion.translation() = joint.position * joint.world_axis;
    }
    return motion;
  }

  // motion(link) = motion(parent link) * motion(its joint): the product of exponentials.
  Eigen::Isometry3d motion_of(std::size_t index, std::set<std::size_t>& visiting) {
    if (const auto it = motion_.find(index); it != motion_.end()) return it->second;
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    LinkRecord& link = links_[index];
    if (!link.joint.empty() && visiting.insert(index).second) {
      const JointRecord& joint = joints_.at(link.joint);
      Eigen::Isometry3d parent_motion = Eigen::Isometry3d::Identity();
      if (const auto parent = link_index_.find(joint.parent_part); parent != link_index_.end()) {
        parent_motion = motion_of(parent->second, visiting);
      }
      // The joint's axis moves with its parent link.
      link.part.world_joint_axis = parent_motion.linear() * joint.world_axis;
      link.part.world_joint_point_m = parent_motion * joint.world_point_m;
      motion = parent_motion * joint_motion(joint);
    } else if (!link.joint.empty()) {
      warn("joint loop through link " + link.part.name + "; its joints are left at 0");
    }
    motion_[index] = motion;
    return motion;
  }

  void place_links() {
    for (std::size_t i = 0; i < links_.size(); ++i) {
      std::set<std::size_t> visiting;
      const Eigen::Isometry3d motion = motion_of(i, visiting);
      LinkRecord& link = links_[i];
      link.part.world_T_part = motion * link.world_T_link_at_zero;
      for (auto& geometry : link.part.geometry) {
        geometry.world_T_geometry = motion * geometry.world_T_geometry;
      }
    }
  }

  // Geometry in the zero configuration; place_links() moves it with the link.
  void read_link_geometry(const sdf::Link& link, LinkRecord& record) {
    const std::string& part_name = record.part.name;
    std::optional<Look> fallback_look;
    for (std::uint64_t i = 0; i < link.VisualCount(); ++i) {
      const sdf::Visual& visual = *link.VisualByIndex(i);
      const Look look = look_of(visual);
      if (visual.Geom() == nullptr) continue;
      // A visual's pose resolves to its link's frame by default.
      const Eigen::Isometry3d world_T_visual =
          record.world_T_link_at_zero *
          pose_of(visual.SemanticPose(), "visual " + visual.Name() + " of " + part_name);
      if (!add_geometry(*visual.Geom(), world_T_visual, look, "link " + part_name, record.part) &&
          !fallback_look) {
        fallback_look = look;
      }
    }
    if (!fallback_look) return;
    // A visual mesh is missing: the collision shapes stand in, in the visual's appearance.
    for (std::uint64_t i = 0; i < link.CollisionCount(); ++i) {
      const sdf::Collision& collision = *link.CollisionByIndex(i);
      if (collision.Geom() == nullptr) continue;
      const Eigen::Isometry3d world_T_collision =
          record.world_T_link_at_zero *
          pose_of(collision.SemanticPose(), "collision " + collision.Name() + " of " + part_name);
      add_geometry(*collision.Geom(), world_T_collision, *fallback_look,
                   "collision of link " + part_name, record.part);
    }
  }

  // Appends one SDF geometry; false when it is a mesh that is missing or unreadable (warned).
  bool add_geometry(const sdf::Geometry& geometry, const Eigen::Isometry3d& world_T_shape,
                    const Look& look, const std::string& owner, ScenePart& part) {
    auto add = [&](PartShape shape, const Eigen::Isometry3d& world_T_geometry) {
      part.geometry.push_back({world_T_geometry, std::move(shape), look.material, look.colour});
    };
    switch (geometry.Type()) {
      case sdf::GeometryType::BOX:
        add(world::Box{to_eigen(geometry.BoxShape()->Size())}, world_T_shape);
        return true;
      case sdf::GeometryType::CYLINDER:
        add(world::Cylinder{geometry.CylinderShape()->Radius(), geometry.CylinderShape()->Length()},
            world_T_shape);
        return true;
      case sdf::GeometryType::SPHERE:
        add(tessellate_sphere(geometry.SphereShape()->Radius()), world_T_shape);
        return true;
      case sdf::GeometryType::CAPSULE: {
        // A cylinder with a sphere on each end (along the capsule's z).
        const double radius = geometry.CapsuleShape()->Radius();
        const double length = geometry.CapsuleShape()->Length();
        add(world::Cylinder{radius, length}, world_T_shape);
        for (const double end : {-0.5 * length, 0.5 * length}) {
          add(tessellate_sphere(radius),
              world_T_shape * Eigen::Translation3d(Eigen::Vector3d(0.0, 0.0, end)));
        }
        return true;
      }
      case sdf::GeometryType::ELLIPSOID: {
        const Eigen::Vector3d radii = to_eigen(geometry.EllipsoidShape()->Radii());
        TriangleSoup soup = tessellate_sphere(radii.maxCoeff());
        const Eigen::Vector3f stretch = (radii / radii.maxCoeff()).cast<float>();
        for (auto& vertex : soup.vertices_m) vertex = vertex.cwiseProduct(stretch);
        add(std::move(soup), world_T_shape);
        return true;
      }
      case sdf::GeometryType::PLANE: {
        // A thin slab whose top face is the plane (z of the slab along the plane's normal).
        const sdf::Plane& plane = *geometry.PlaneShape();
        const Eigen::Vector3d normal = to_eigen(plane.Normal()).normalized();
        Eigen::Isometry3d shape_T_slab = Eigen::Isometry3d::Identity();
        shape_T_slab.linear() =
            Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), normal).toRotationMatrix();
        shape_T_slab.translation() = -0.5 * kPlaneThicknessM * normal;
        add(world::Box{Eigen::Vector3d(plane.Size().X(), plane.Size().Y(), kPlaneThicknessM)},
            world_T_shape * shape_T_slab);
        return true;
      }
      case sdf::GeometryType::MESH:
        return add_mesh(*geometry.MeshShape(), world_T_shape, look, owner, part);
      case sdf::GeometryType::EMPTY:
        return true;
      default:
        warn("geometry of a kind not imported (heightmap, polyline) skipped (" + owner + ")");
        return true;
    }
  }

  bool add_mesh(const sdf::Mesh& mesh, const Eigen::Isometry3d& world_T_mesh, const Look& look,
                const std::string& owner, ScenePart& part) {
    const std::string& uri = mesh.Uri();
    // Relative URIs are relative to the file the mesh was written in (an included model's).
    const std::string referring = mesh.FilePath().empty() ? path_ : mesh.FilePath();
    const std::string file = resolve_uri(uri, referring, roots_);
    if (file.empty()) {
      warn("mesh not found: " + uri + " (" + owner + ")");
      return false;
    }
    std::vector<MeshPiece> pieces;
    try {
      pieces = load_mesh_pieces(file, to_eigen(mesh.Scale()));
    } catch (const config::Error& error) {
      warn("mesh unreadable: " + uri + " (" + owner + "): " + one_line(error.what()));
      return false;
    }
    for (auto& piece : pieces) {
      // The visual's material, when it has one, overrides the mesh's own (as in Gazebo).
      const bool visual_look = look.colour.has_value() || !look.material.empty();
      part.geometry.push_back({world_T_mesh, std::move(piece.soup),
                               visual_look ? look.material : piece.material,
                               visual_look ? look.colour : piece.colour});
    }
    return true;
  }

  struct ModelRecord {
    const sdf::Model* model;
    Eigen::Isometry3d world_T_model;
    std::string name;  // scoped
  };

  std::string path_;
  const ReadOptions& options_;
  std::vector<std::string> roots_;
  Scene scene_;
  std::vector<LinkRecord> links_;
  std::unordered_map<std::string, std::size_t> link_index_;  // part name -> links_ index
  std::unordered_map<std::string, JointRecord> joints_;      // scoped joint name -> joint
  std::vector<ModelRecord> models_;
  std::unordered_map<std::size_t, Eigen::Isometry3d> motion_;  // links_ index -> FK motion
};

}  // namespace

Scene read_sdf(const std::string& path, const ReadOptions& options) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw config::Error(path + ": no such file");
  return SdfSceneReader(path, options).read();
}

}  // namespace vsl::world_import
