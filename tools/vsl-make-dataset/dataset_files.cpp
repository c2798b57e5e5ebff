// The dataset's files (dataset_files.hpp).
#include "dataset_files.hpp"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <fstream>
#include <system_error>
#include <vector>

namespace vsl::tools {

void prepare_output_dir(const std::filesystem::path& dir, const DatasetOptions& options) {
  std::error_code error;
  if (std::filesystem::exists(dir, error)) {
    if (!std::filesystem::is_directory(dir, error)) {
      throw UsageError("--out " + dir.string() + " exists and is not a directory");
    }
    if (!std::filesystem::is_empty(dir, error)) {
      throw UsageError("--out " + dir.string() + " is not empty (use a new or empty directory)");
    }
  }
  std::vector<std::string> subdirectories{"images", "labels"};
  if (options.depth) subdirectories.emplace_back("depth");
  if (options.ids) subdirectories.emplace_back("ids");
  for (const std::string& sub : subdirectories) {
    std::filesystem::create_directories(dir / sub, error);
    if (error) throw IoError("cannot create " + (dir / sub).string() + ": " + error.message());
  }
}

std::string image_stem(std::uint64_t view, const char* camera) {
  char stem[64];
  std::snprintf(stem, sizeof stem, "view%06llu_%s", static_cast<unsigned long long>(view), camera);
  return stem;
}

std::string image_file_name(const std::string& stem, const DatasetOptions& options) {
  return stem + (options.format == ImageFormat::jpg ? ".jpg" : ".png");
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw IoError("cannot write " + path.string());
}

void write_text_file_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  write_text_file(temporary, text);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) throw IoError("cannot write " + path.string() + ": " + error.message());
}

namespace {

void write_with(const std::filesystem::path& path, const cv::Mat& image,
                const std::vector<int>& parameters) {
  bool written = false;
  try {
    written = cv::imwrite(path.string(), image, parameters);
  } catch (const cv::Exception&) {
  }
  if (!written) throw IoError("cannot write " + path.string());
}

}  // namespace

void write_image_file(const std::filesystem::path& path, const cv::Mat& image,
                      const DatasetOptions& options) {
  if (path.extension() == ".jpg") {
    write_with(path, image, {cv::IMWRITE_JPEG_QUALITY, options.jpeg_quality});
  } else {
    write_with(path, image, {cv::IMWRITE_PNG_COMPRESSION, 1});  // noisy images hardly compress
  }
}

void write_depth_file(const std::filesystem::path& path, const cv::Mat& depth_m) {
  CV_Assert(depth_m.type() == CV_32F);
  cv::Mat millimetres;
  depth_m.convertTo(millimetres, CV_16U, 1000.0);  // rounds and saturates at 65.5 m
  write_with(path, millimetres, {cv::IMWRITE_PNG_COMPRESSION, 1});
}

void write_ids_file(const std::filesystem::path& path, const cv::Mat& object_ids) {
  CV_Assert(object_ids.type() == CV_32S);
  cv::Mat shifted;
  object_ids.convertTo(shifted, CV_16U, 1.0, 1.0);  // -1 -> 0; the caller keeps ids < 65535
  write_with(path, shifted, {cv::IMWRITE_PNG_COMPRESSION, 1});
}

}  // namespace vsl::tools
