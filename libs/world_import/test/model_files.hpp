// Small model files the tests write themselves into a fresh temporary folder.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace vsl::world_import::test {

class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("vsl_import_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  // Writes `text` to `relative` (folders created); returns the full path.
  std::string write(const std::string& relative, const std::string& text) const {
    const std::filesystem::path file = path_ / relative;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file.string();
  }
  std::string path(const std::string& relative = "") const { return (path_ / relative).string(); }

 private:
  std::filesystem::path path_;
};

// An axis-aligned box as an OBJ file's triangles, in one group with one material.
inline std::string box_obj(const std::string& group, const std::string& material, double sx,
                           double sy, double sz, double cx = 0, double cy = 0, double cz = 0) {
  std::string out = "o " + group + "\n";
  if (!material.empty()) out += "usemtl " + material + "\n";
  for (int k = 0; k < 8; ++k) {
    out += "v " + std::to_string(cx + (k & 1 ? 0.5 : -0.5) * sx) + " " +
           std::to_string(cy + (k & 2 ? 0.5 : -0.5) * sy) + " " +
           std::to_string(cz + (k & 4 ? 0.5 : -0.5) * sz) + "\n";
  }
  return out;
}
// The 12 triangles of the box whose 8 vertices start at 1-based index `first`.
inline std::string box_obj_faces(int first) {
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  std::string out;
  for (const auto& f : faces) {
    out += "f " + std::to_string(first + f[0]) + " " + std::to_string(first + f[1]) + " " +
           std::to_string(first + f[2]) + "\n";
  }
  return out;
}

}  // namespace vsl::world_import::test
