// vsl-make-dataset's command line (docs/dataset.md).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "image_labels.hpp"
#include "vsl/render/renderer.hpp"

namespace vsl::tools {

enum class ImageFormat { jpg, png };

struct DatasetOptions {
  std::string world_file;
  std::uint64_t views = 0;
  std::uint64_t seed = 1;
  bool randomize = false;
  std::uint64_t views_per_look = 1;  // with randomize: views that share one randomized world
  render::RealismLevel realism = render::RealismLevel::full;
  std::string head_file = "config/heads/armar3.yaml";
  bool depth = false;
  bool ids = false;
  unsigned threads = 0;  // 0: one per core
  std::string out_dir;
  ImageFormat format = ImageFormat::jpg;
  int jpeg_quality = 95;
  LabelFilter filter;
  bool quiet = false;
  std::string preview_file;  // "": none
};

// A bad command line; the message names the problem (without the program's name).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* dataset_usage();

// The options of `arguments` (argv without the program), nullopt for --help. Throws UsageError.
std::optional<DatasetOptions> parse_dataset_options(const std::vector<std::string>& arguments);

}  // namespace vsl::tools
