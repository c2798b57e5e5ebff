#include "yaml_read.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>

#include "vsl/config/eigen.hpp"

namespace vsl::head::detail {

std::string format_g(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

Eigen::Matrix3d rotation_matrix(const config::Node& node) {
  if (!node.is_sequence() || node.size() != 3) {
    node.fail("expected a 3x3 rotation matrix [[r00, r01, r02], [r10, r11, r12], [r20, r21, r22]]");
  }
  Eigen::Matrix3d r;
  for (std::size_t row = 0; row < 3; ++row) {
    const auto values = node[row].as_array<3>();
    for (std::size_t col = 0; col < 3; ++col) r(row, col) = values[col];
  }
  const double orthogonality =
      (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthogonality > 1e-5 || r.determinant() < 0.0) {
    node.fail("not a rotation matrix (R^T R differs from I by " + format_g(orthogonality) +
              ", det " + format_g(r.determinant()) + ")");
  }
  return Eigen::Quaterniond(r).normalized().toRotationMatrix();
}

Eigen::Quaterniond orientation(const config::Node& parent) {
  const std::optional<config::Node> rpy_rad = parent.find("rpy_rad");
  const std::optional<config::Node> rpy_deg = parent.find("rpy_deg");
  const std::optional<config::Node> quaternion = parent.find("orientation_wxyz");
  const int given =
      int(rpy_rad.has_value()) + int(rpy_deg.has_value()) + int(quaternion.has_value());
  if (given > 1) {
    (quaternion ? *quaternion : *rpy_deg)
        .fail("give only one of rpy_rad, rpy_deg, orientation_wxyz");
  }
  if (quaternion) return config::as_unit_quaternion(*quaternion);
  if (!rpy_rad && !rpy_deg) return Eigen::Quaterniond::Identity();
  const double scale = rpy_rad ? 1.0 : std::numbers::pi / 180.0;
  const auto a = (rpy_rad ? *rpy_rad : *rpy_deg).as_array<3>();
  return Eigen::Quaterniond(Eigen::AngleAxisd(scale * a[2], Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(scale * a[1], Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(scale * a[0], Eigen::Vector3d::UnitX()));
}

int int_in(const config::Node& node, int min, int max) {
  const std::int64_t value = node.as_int();
  if (value < min || value > max) {
    node.fail("must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
              "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

std::string resolve_relative_to(const std::string& source, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (std::filesystem::path(source).parent_path() / p).lexically_normal().string();
}

}  // namespace vsl::head::detail
