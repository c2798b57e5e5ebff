// Percept errors across and along the viewing ray, and the noise model fitted to them
// (percept_noise.hpp).
#include "percept_noise.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace vsl::tools {
namespace {

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double robust_sigma(std::vector<double> values) {
  for (double& v : values) v = std::abs(v);
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return 1.4826 * *middle;
}

// One equation of the fit: s^2 = row . (sigma_m^2, sigma_ref^2, sigma_d^2), with its weight.
struct Equation {
  Eigen::Vector3d row;
  double s2;
  double weight;
};

// Weighted least squares over the unknowns in `used` (the others held at 0); nullopt when the
// problem is singular or a used unknown comes out negative.
std::optional<Eigen::Vector3d> solve(const std::vector<Equation>& equations,
                                     const std::array<bool, 3>& used, double& residual) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const Equation& e : equations) {
    Eigen::Vector3d row = e.row;
    for (int k = 0; k < 3; ++k) {
      if (!used[static_cast<std::size_t>(k)]) row(k) = 0.0;
    }
    normal += e.weight * row * row.transpose();
    rhs += e.weight * e.s2 * row;
  }
  for (int k = 0; k < 3; ++k) {
    if (!used[static_cast<std::size_t>(k)]) normal(k, k) = 1.0;
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(normal);
  if (!lu.isInvertible()) return std::nullopt;
  const Eigen::Vector3d x = lu.solve(rhs);
  if (x.minCoeff() < 0.0) return std::nullopt;
  residual = 0.0;
  for (const Equation& e : equations) {
    const double r = e.row.dot(x) - e.s2;
    residual += e.weight * r * r;
  }
  return x;
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
    // Two directions across the ray: y_camera x n (horizontal in the image) and n x that.
    Eigen::Vector3d across_u = Eigen::Vector3d::UnitY().cross(n);
    if (across_u.norm() < 1e-6) across_u = Eigen::Vector3d::UnitX();
    across_u.normalize();
    const Eigen::Vector3d across_v = n.cross(across_u);
    const Eigen::Vector3d in_object =
        object.ego_R_object.transpose() * (p.ego_position_m - object.ego_position_m);
    by_type_[p.type].push_back({range, {e.dot(across_u), e.dot(across_v)}, e.dot(n), in_object});
  }
}

std::optional<PerceptNoiseTally::Sigmas> PerceptNoiseTally::sigmas(const std::string& type) const {
  const auto it = by_type_.find(type);
  if (it == by_type_.end()) return std::nullopt;
  constexpr double kBinM = 0.5;
  constexpr std::size_t kMinPerBin = 8;
  std::map<int, std::vector<const Error*>> bins;
  for (const Error& e : it->second) bins[static_cast<int>(e.range_m / kBinM)].push_back(&e);
  std::vector<Equation> equations;
  for (const auto& [bin, errors] : bins) {
    if (errors.size() < kMinPerBin) continue;
    std::vector<double> ranges, across, along;
    for (const Error* e : errors) {
      ranges.push_back(e->range_m);
      across.insert(across.end(), {e->across_m[0], e->across_m[1]});
      along.push_back(e->along_m);
    }
    std::nth_element(ranges.begin(), ranges.begin() + static_cast<long>(ranges.size() / 2),
                     ranges.end());
    const double r = ranges[ranges.size() / 2];
    const double n = static_cast<double>(errors.size());
    const double floor2 = 1e-8;  // (0.1 mm)^2: no bin's weight becomes infinite
    const double sa2 = std::max(floor2, std::pow(robust_sigma(across), 2));
    const double sl2 = std::max(floor2, std::pow(robust_sigma(along), 2));
    const double across_per_px = r / focal_px_;
    const double along_per_px = r * r / (focal_px_ * baseline_m_);
    equations.push_back(
        {Eigen::Vector3d(1.0, across_per_px * across_per_px, 0.0), sa2, 2.0 * n / (sa2 * sa2)});
    equations.push_back(
        {Eigen::Vector3d(1.0, 0.0, along_per_px * along_per_px), sl2, n / (sl2 * sl2)});
  }
  if (equations.size() < 4) return std::nullopt;
  // Non-negative least squares over three unknowns: the best feasible subset.
  std::optional<Eigen::Vector3d> best;
  double best_residual = std::numeric_limits<double>::infinity();
  for (int mask = 1; mask < 8; ++mask) {
    const std::array<bool, 3> used{(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
    double residual = 0.0;
    const auto x = solve(equations, used, residual);
    if (x && residual < best_residual) {
      best = x;
      best_residual = residual;
    }
  }
  if (!best) return std::nullopt;
  return Sigmas{it->second.size(), std::sqrt((*best)(1)), std::sqrt((*best)(2)),
                std::sqrt((*best)(0))};
}

void PerceptNoiseTally::print(std::ostream& out) const {
  out << "noise model of the true positives (percept_noise.hpp): sigma of the reference point "
         "(px), of the disparity (px), and a floor (m) in every direction\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-14s %8s %14s %14s %10s\n", "class", "n", "reference_px",
                "disparity_px", "floor_m");
  out << line;
  for (const auto& entry : by_type_) {
    const auto s = sigmas(entry.first);
    if (!s) {
      std::snprintf(line, sizeof line, "%-14s %8zu %14s %14s %10s\n", entry.first.c_str(),
                    entry.second.size(), "-", "-", "-");
    } else {
      std::snprintf(line, sizeof line, "%-14s %8zu %14.2f %14.3f %10.4f\n", entry.first.c_str(),
                    s->count, s->reference_px, s->disparity_px, s->floor_m);
    }
    out << line;
  }
  // One table of per-class medians, mm, with its title and the three columns' names.
  const auto print_bias = [&](const char* title, std::array<const char*, 3> columns, auto bias_of) {
    out << title;
    std::snprintf(line, sizeof line, "%-14s %8s %10s %10s %10s\n", "class", "n", columns[0],
                  columns[1], columns[2]);
    out << line;
    for (const auto& [type, errors] : by_type_) {
      const std::optional<Eigen::Vector3d> b = bias_of(type);
      if (!b) continue;
      std::snprintf(line, sizeof line, "%-14s %8zu %10.1f %10.1f %10.1f\n", type.c_str(),
                    errors.size(), 1e3 * b->x(), 1e3 * b->y(), 1e3 * b->z());
      out << line;
    }
  };
  // The model has no bias term; a bias shows here (a base unit's door centre found above its
  // face's, a handle behind its bar), and the same bias in every percept of a scan can move the
  // pose (not a height: under the planar prior that goes into the pose's z).
  print_bias(
      "median signed error of the true positives, mm: across the ray (image right, image down) "
      "and along it (away from the camera)\n",
      {"right", "down", "along"}, [this](const std::string& type) { return bias_m(type); });
  print_bias(
      "and in the object's own axes, mm (a generated kitchen's door: x along its width, y into "
      "its front face, z up)\n",
      {"x", "y", "z"}, [this](const std::string& type) { return object_bias_m(type); });
}

std::optional<Eigen::Vector3d> PerceptNoiseTally::median_per_axis(
    const std::string& type, Eigen::Vector3d (*of)(const Error&)) const {
  const auto it = by_type_.find(type);
  if (it == by_type_.end() || it->second.empty()) return std::nullopt;
  std::array<std::vector<double>, 3> axes;
  for (const Error& e : it->second) {
    const Eigen::Vector3d v = of(e);
    for (int k = 0; k < 3; ++k) axes[static_cast<std::size_t>(k)].push_back(v(k));
  }
  return Eigen::Vector3d(median(axes[0]), median(axes[1]), median(axes[2]));
}

std::optional<Eigen::Vector3d> PerceptNoiseTally::bias_m(const std::string& type) const {
  return median_per_axis(type, [](const Error& e) {
    return Eigen::Vector3d(e.across_m[0], e.across_m[1], e.along_m);
  });
}

std::optional<Eigen::Vector3d> PerceptNoiseTally::object_bias_m(const std::string& type) const {
  return median_per_axis(type, [](const Error& e) { return e.object_m; });
}

}  // namespace vsl::tools
