#include "scan_frames.hpp"

#include <fstream>
#include <sstream>

#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"

namespace vsl::scan_noise {
namespace {

using config::Node;

double sigma(const Node& node) {
  return node.as_double_in(0.0, 10.0);
}

FramePerceptRecord percept(const Node& node) {
  node.expect_keys({"frame", "type", "position", "covariance", "camera", "shared_sigma_m",
                    "shared_ray_sigma_m"});
  FramePerceptRecord out;
  out.frame_id = node.at("frame").as_int();
  out.type = node.at("type").as_string();
  if (out.type.empty()) node.at("type").fail("must not be empty");
  out.ego_position_m = config::as_vector3(node.at("position"));
  out.ego_covariance_m2 = config::as_covariance3(node.at("covariance"));
  out.ego_camera_position_m = config::as_vector3(node.at("camera"));
  if (const auto s = node.find("shared_sigma_m")) out.shared_sigma_m = sigma(*s);
  if (const auto s = node.find("shared_ray_sigma_m")) out.shared_ray_sigma_m = sigma(*s);
  return out;
}

ScanFrames from(const Node& root) {
  root.expect_map();
  root.expect_keys({"ground_truth", "percepts"});
  ScanFrames scan;
  scan.world_T_ego = config::as_pose(root.at("ground_truth"));
  const Node list = root.at("percepts");
  for (std::size_t i = 0; i < list.size(); ++i) scan.percepts.push_back(percept(list[i]));
  return scan;
}

void write_vector(std::ostream& out, const Eigen::Vector3d& v) {
  out << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
}

}  // namespace

std::string scan_frames_text(const ScanFrames& scan) {
  std::ostringstream out;
  out.precision(9);
  out << "# vsl scan frames: every frame's percepts of one request, ego frame (metres), with the\n"
         "# simulator's world_T_ego; vsl-scan-noise reads it "
         "(tools/vsl-scan-noise/scan_frames.hpp)\n";
  out << "ground_truth: " << config::pose_text(scan.world_T_ego) << "\n";
  out << "percepts:" << (scan.percepts.empty() ? " []" : "") << "\n";
  for (const FramePerceptRecord& p : scan.percepts) {
    out << "  - {frame: " << p.frame_id << ", type: " << p.type << ", position: ";
    write_vector(out, p.ego_position_m);
    out << ", covariance: [";
    for (int k = 0; k < 9; ++k) out << (k ? ", " : "") << p.ego_covariance_m2(k / 3, k % 3);
    out << "], camera: ";
    write_vector(out, p.ego_camera_position_m);
    out << ", shared_sigma_m: " << p.shared_sigma_m
        << ", shared_ray_sigma_m: " << p.shared_ray_sigma_m << "}\n";
  }
  return out.str();
}

void write_scan_frames(const ScanFrames& scan, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw config::Error(path + ": cannot open for writing");
  out << scan_frames_text(scan);
  out.flush();
  if (!out) throw config::Error(path + ": write failed");
}

ScanFrames load_scan_frames(const std::string& path) {
  return from(Node::load_file(path));
}

ScanFrames load_scan_frames_from_string(const std::string& text, const std::string& source) {
  return from(Node::load_string(text, source));
}

}  // namespace vsl::scan_noise
