#include "view_style.hpp"

#include <functional>

namespace vsl::view {

cv::Scalar type_colour(const std::string& type) {
  if (type == "door") return {180, 110, 40};
  if (type == "handle") return {20, 150, 215};
  if (type == "drawer_front") return {150, 150, 0};
  if (type == "window") return {235, 190, 120};
  // A stable mid-tone colour from the name (std::hash is stable within one build, which is all a
  // picture needs).
  const std::size_t h = std::hash<std::string>{}(type);
  return {60.0 + static_cast<double>(h % 140), 60.0 + static_cast<double>((h / 140) % 140),
          60.0 + static_cast<double>((h / 19600) % 140)};
}

std::string type_label(const std::string& type) {
  if (type == "drawer_front") return "drawer";
  return type;
}

}  // namespace vsl::view
