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

FusedPercept percept(const Node& node) {
  node.expect_keys({"type", "position", "covariance", "support"});
  FusedPercept out;
  out.type = node.at("type").as_string();
  out.ego_position_m = as_vector3(node.at("position"));
  if (const auto c = node.find("covariance")) out.ego_covariance_m2 = config::as_covariance3(*c);
  if (const auto support = node.find("support")) {
    const std::int64_t frames = support->as_int();
    if (frames < 1 || frames > 1000000) support->fail("must be a frame count >= 1");
    out.support = static_cast<int>(frames);
  }
  return out;
}

PerceptFile from(const Node& root) {
  root.expect_map();
  root.expect_keys({"percepts", "ground_truth"});
  PerceptFile file;
  const Node list = root.at("percepts");
  for (std::size_t i = 0; i < list.size(); ++i) file.percepts.push_back(percept(list[i]));
  if (const auto truth = root.find("ground_truth"))
    file.ground_truth_world_T_ego = config::as_pose(*truth);
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
    out << "ground_truth: " << config::pose_text(*file.ground_truth_world_T_ego) << "\n";
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
