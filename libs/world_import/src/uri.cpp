// Where a model's mesh reference points: ROS `package://`, Gazebo `model://`, `file://` or a path
// relative to the referring file.
#include <filesystem>
#include <string_view>

#include "scene.hpp"

namespace vsl::world_import {
namespace {

namespace fs = std::filesystem;

bool is_file(const fs::path& p) {
  std::error_code error;
  return fs::is_regular_file(p, error);
}

// `NAME/rest` under one of the roots: the root holds a folder NAME, or the root is NAME itself
// (a package checked out alone), or, for the first `searched_roots` roots, any folder up to three
// levels below the root is NAME (a ROS workspace's src/).
std::string find_in_packages(std::string_view name_and_rest, const std::vector<std::string>& roots,
                             std::size_t searched_roots) {
  const std::size_t slash = name_and_rest.find('/');
  const std::string name(name_and_rest.substr(0, slash));
  const std::string rest(slash == std::string_view::npos ? "" : name_and_rest.substr(slash + 1));
  for (const std::string& root : roots) {
    const fs::path base(root);
    if (is_file(base / name / rest)) return (base / name / rest).string();
    if (base.filename() == name && is_file(base / rest)) return (base / rest).string();
    if (&root - roots.data() >= static_cast<std::ptrdiff_t>(searched_roots)) continue;
    std::error_code error;
    fs::recursive_directory_iterator it(base, fs::directory_options::skip_permission_denied, error);
    for (int visited = 0; !error && it != fs::recursive_directory_iterator() && visited < 20000;
         it.increment(error), ++visited) {
      if (it.depth() > 3) {
        it.disable_recursion_pending();
        continue;
      }
      if (it->is_directory(error) && it->path().filename() == name && is_file(it->path() / rest)) {
        return (it->path() / rest).string();
      }
    }
  }
  return "";
}

}  // namespace

std::string resolve_uri(const std::string& uri, const std::string& referring_file,
                        const std::vector<std::string>& package_paths) {
  const std::string_view view(uri);
  for (const std::string_view scheme : {"package://", "model://"}) {
    if (view.starts_with(scheme)) {
      // The referring file's own package is the first place to look: a package that refers to
      // itself by name needs no --package-path.
      std::vector<std::string> roots = package_paths;
      for (fs::path p = fs::absolute(referring_file).parent_path(); !p.empty();
           p = p.parent_path()) {
        roots.push_back(p.string());
        if (p == p.root_path()) break;
        if (roots.size() > package_paths.size() + 4) break;
      }
      return find_in_packages(view.substr(scheme.size()), roots, package_paths.size());
    }
  }
  fs::path path(view.starts_with("file://") ? std::string(view.substr(7)) : uri);
  if (path.is_relative()) path = fs::path(referring_file).parent_path() / path;
  return is_file(path) ? path.lexically_normal().string() : "";
}

}  // namespace vsl::world_import
