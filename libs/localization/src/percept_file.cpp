#include "vsl/localization/percept_file.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"

namespace vsl::localization {
namespace {

using config::as_vector3;
using config::Node;

// A covariance must be symmetric positive definite to whiten residuals with it.
Eigen::Matrix3d covariance(const Node& node) {
  const auto v = node.as_array<9>();
  Eigen::Matrix3d c;
  c << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
  if (!c.isApprox(c.transpose(), 1e-9) && (c - c.transpose()).cwiseAbs().maxCoeff() > 1e-12) {
    node.fail("must be symmetric");
  }
  const Eigen::LLT<Eigen::Matrix3d> llt(c);
  if (llt.info() != Eigen::Success) node.fail("must be positive definite");
  return c;
}

FusedPercept percept(const Node& node) {
  node.expect_keys({"type", "position", "covariance", "support"});
  FusedPercept out;
  out.type = node.at("type").as_string();
  out.ego_position_m = as_vector3(node.at("position"));
  if (const auto c = node.find("covariance")) out.ego_covariance_m2 = covariance(*c);
  if (const auto support = node.find("support")) {
    const std::int64_t frames = support->as_int();
    if (frames < 1 || frames > 1000000) support->fail("must be a frame count >= 1");
    out.support = static_cast<int>(frames);
  }
  return out;
}

Eigen::Isometry3d ground_truth(const Node& node) {
  node.expect_keys({"position", "quaternion"});
  const Eigen::Quaterniond rotation = config::as_unit_quaternion(node.at("quaternion"));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation.toRotationMatrix();
  pose.translation() = as_vector3(node.at("position"));
  return pose;
}

PerceptFile from(const Node& root) {
  root.expect_map();
  root.expect_keys({"percepts", "ground_truth"});
  PerceptFile file;
  const Node list = root.at("percepts");
  for (std::size_t i = 0; i < list.size(); ++i) file.percepts.push_back(percept(list[i]));
  if (const auto truth = root.find("ground_truth"))
    file.ground_truth_world_T_ego = ground_truth(*truth);
  return file;
}

}  // namespace

PerceptFile load_percept_file(const std::string& path) {
  return from(Node::load_file(path));
}

PerceptFile load_percept_file_from_string(const std::string& text, const std::string& source) {
  return from(Node::load_string(text, source));
}

std::string percept_file_text(const PerceptFile& file) {
  // 9 significant decimals of a metre: far below any sensor noise, exact enough to round-trip.
  std::ostringstream out;
  out << std::setprecision(9);
  out << "# vsl percept file: fused percepts in the ego frame (metres); see docs/localize.md\n";
  out << "percepts:\n";
  for (const FusedPercept& p : file.percepts) {
    out << "  - {type: " << p.type << ", position: [" << p.ego_position_m.x() << ", "
        << p.ego_position_m.y() << ", " << p.ego_position_m.z() << "]";
    if (p.ego_covariance_m2) {
      out << ", covariance: [";
      for (int k = 0; k < 9; ++k) out << (k ? ", " : "") << (*p.ego_covariance_m2)(k / 3, k % 3);
      out << "]";
    }
    if (p.support != 1) out << ", support: " << p.support;
    out << "}\n";
  }
  if (file.percepts.empty()) out.seekp(-1, std::ios::cur), out << " []\n";
  if (file.ground_truth_world_T_ego) {
    const Eigen::Isometry3d& pose = *file.ground_truth_world_T_ego;
    Eigen::Quaterniond q(pose.rotation());
    if (q.w() < 0) q.coeffs() *= -1.0;
    out << "ground_truth: {position: [" << pose.translation().x() << ", " << pose.translation().y()
        << ", " << pose.translation().z() << "], quaternion: [" << q.w() << ", " << q.x() << ", "
        << q.y() << ", " << q.z() << "]}\n";
  }
  return out.str();
}

void write_percept_file(const PerceptFile& file, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw config::Error(path + ": cannot open for writing");
  out << percept_file_text(file);
  out.flush();
  if (!out) throw config::Error(path + ": write failed");
}

}  // namespace vsl::localization
