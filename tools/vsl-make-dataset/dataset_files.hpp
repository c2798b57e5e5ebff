// Writing the dataset's files: the output directory's layout, images, depth and id pictures,
// text files (docs/dataset.md). Every failure is an IoError naming the file.
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "dataset_options.hpp"

namespace vsl::tools {

struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Creates `dir` and its images/ and labels/ (and depth/, ids/ when asked). Throws UsageError when
// `dir` exists and is not an empty directory (a dataset must not mix with an older one) and
// IoError when it cannot be made.
void prepare_output_dir(const std::filesystem::path& dir, const DatasetOptions& options);

// The stem of view `view`'s image of camera `camera` ("left" or "right"): view000123_left.
std::string image_stem(std::uint64_t view, const char* camera);
// The image file name: the stem with .jpg or .png.
std::string image_file_name(const std::string& stem, const DatasetOptions& options);

void write_text_file(const std::filesystem::path& path, const std::string& text);
// Writes to `path`.tmp, then renames: never half a file under the final name.
void write_text_file_atomically(const std::filesystem::path& path, const std::string& text);
// An 8-bit BGR image as JPEG (options.jpeg_quality) or PNG, by the path's extension.
void write_image_file(const std::filesystem::path& path, const cv::Mat& image,
                      const DatasetOptions& options);
// Depth (CV_32F, m) as a 16-bit PNG of millimetres, 0 where nothing.
void write_depth_file(const std::filesystem::path& path, const cv::Mat& depth_m);
// Object ids (CV_32S, -1 where nothing) as a 16-bit PNG of index + 1, 0 where nothing.
void write_ids_file(const std::filesystem::path& path, const cv::Mat& object_ids);

}  // namespace vsl::tools
