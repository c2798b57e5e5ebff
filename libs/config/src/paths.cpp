#include "vsl/config/paths.hpp"

#include <filesystem>

#include "vsl/config/node.hpp"

namespace vsl::config {

std::string path_relative_to_file(const Node& node) {
  const std::filesystem::path path(node.as_string());
  if (path.is_absolute()) return path.lexically_normal().string();
  return (std::filesystem::path(node.source()).parent_path() / path).lexically_normal().string();
}

}  // namespace vsl::config
