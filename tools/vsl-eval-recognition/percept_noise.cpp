// Percept errors across and along the viewing ray (percept_noise.hpp).
#include "percept_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vsl::tools {
namespace {

double robust_sigma(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  for (double& v : values) v = std::abs(v);
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return 1.4826 * *middle;
}

}  // namespace

void PerceptNoiseTally::add(const std::vector<recognition::GroundTruthObject>& ground_truth,
                            const recognition::FrameResult& result,
                            const std::vector<recognition::PerceptMatch>& matches) {
  const Eigen::Isometry3d left_T_ego = result.ego_T_left_camera.inverse();
  for (std::size_t i = 0; i < result.percepts.size() && i < matches.size(); ++i) {
    if (matches[i].ground_truth < 0) continue;
    const recognition::FramePercept& p = result.percepts[i];
    const auto& object = ground_truth[static_cast<std::size_t>(matches[i].ground_truth)];
    const Eigen::Vector3d position = left_T_ego * p.ego_position_m;
    const double range = position.norm();
    if (range < 1e-6) continue;
    const Eigen::Vector3d n = position / range;
    const Eigen::Vector3d e = left_T_ego.linear() * (p.ego_position_m - object.ego_position_m);
    const double along = e.dot(n);
    // Two directions across the ray: n x y_camera (horizontal in the image) and n x that.
    Eigen::Vector3d across_u = Eigen::Vector3d::UnitY().cross(n);
    if (across_u.norm() < 1e-6) across_u = Eigen::Vector3d::UnitX();
    across_u.normalize();
    const Eigen::Vector3d across_v = n.cross(across_u);
    Errors& errors = by_type_[p.type];
    errors.reference_px.push_back(focal_px_ * e.dot(across_u) / range);
    errors.reference_px.push_back(focal_px_ * e.dot(across_v) / range);
    errors.disparity_px.push_back(focal_px_ * baseline_m_ * along / (range * range));
  }
}

std::optional<PerceptNoiseTally::Sigmas> PerceptNoiseTally::sigmas(const std::string& type) const {
  const auto it = by_type_.find(type);
  if (it == by_type_.end()) return std::nullopt;
  return Sigmas{it->second.disparity_px.size(), robust_sigma(it->second.reference_px),
                robust_sigma(it->second.disparity_px)};
}

void PerceptNoiseTally::print(std::ostream& out) const {
  out << "noise of the true positives (robust sigma, pixels): of the reference point across the "
         "viewing ray, of the disparity along it\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-14s %8s %14s %14s\n", "class", "n", "reference_px",
                "disparity_px");
  out << line;
  for (const auto& entry : by_type_) {
    const Sigmas s = *sigmas(entry.first);
    std::snprintf(line, sizeof line, "%-14s %8zu %14.2f %14.3f\n", entry.first.c_str(), s.count,
                  s.reference_px, s.disparity_px);
    out << line;
  }
}

}  // namespace vsl::tools
