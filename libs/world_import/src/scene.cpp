#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "scene.hpp"

namespace vsl::world_import {

const char* joint_kind_name(JointKind kind) {
  switch (kind) {
    case JointKind::none:
      return "none";
    case JointKind::fixed:
      return "fixed";
    case JointKind::revolute:
      return "revolute";
    case JointKind::continuous:
      return "continuous";
    case JointKind::prismatic:
      return "prismatic";
    case JointKind::floating:
      return "floating";
    case JointKind::planar:
      return "planar";
    case JointKind::other:
      return "other";
  }
  return "other";
}

std::uint8_t to_byte(float unit) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(unit, 0.0f, 1.0f)));
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string one_line(const std::string& text) {
  std::string line;
  for (const char c : text) {
    if (!std::isspace(static_cast<unsigned char>(c))) {
      line += c;
    } else if (!line.empty() && line.back() != ' ') {
      line += ' ';
    }
  }
  if (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

TriangleSoup tessellate_sphere(double radius_m) {
  // About 1 cm edges at the equator, between a coarse 8 and a fine 32 segments.
  constexpr double kPi = 3.14159265358979323846;
  const int segments = std::clamp(static_cast<int>(std::ceil(2.0 * kPi * radius_m / 0.01)), 8, 32);
  const int rings = std::max(4, segments / 2);
  TriangleSoup soup;
  for (int ring = 0; ring <= rings; ++ring) {
    const double polar = kPi * ring / rings;
    for (int s = 0; s < segments; ++s) {
      const double azimuth = 2.0 * kPi * s / segments;
      soup.vertices_m.emplace_back(
          static_cast<float>(radius_m * std::sin(polar) * std::cos(azimuth)),
          static_cast<float>(radius_m * std::sin(polar) * std::sin(azimuth)),
          static_cast<float>(radius_m * std::cos(polar)));
    }
  }
  auto index = [&](int ring, int s) {
    return static_cast<std::uint32_t>(ring * segments + (s % segments));
  };
  for (int ring = 0; ring < rings; ++ring) {
    for (int s = 0; s < segments; ++s) {
      // Counter-clockwise seen from outside (z up at ring 0).
      if (ring > 0)
        soup.triangles.push_back({index(ring, s), index(ring + 1, s), index(ring, s + 1)});
      if (ring + 1 < rings) {
        soup.triangles.push_back({index(ring, s + 1), index(ring + 1, s), index(ring + 1, s + 1)});
      }
    }
  }
  return soup;
}

}  // namespace vsl::world_import
