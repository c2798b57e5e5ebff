// vsl-make-dataset's command line (dataset_options.hpp).
#include "dataset_options.hpp"

#include <limits>

namespace vsl::tools {
namespace {

constexpr const char* kUsage =
    R"(usage: vsl-make-dataset --world W --views N --out DIR [options]

Renders N seeded stereo views of a world as the simulated head sees them and writes the left and
right images with labels from the renderer's id buffer: YOLO text files (DoorDetect's classes: 0
door, 1 handle, 2 cabinet door, 3 refrigerator door) and the project's box-label YAML
(docs/dataset.md).
  --world FILE        world model, e.g. config/worlds/kitchen.yaml
  --views N           number of stereo views (2 N images)
  --out DIR           output directory; created, and must be empty if it exists
options:
  --seed S            random seed (default 1): the same seed gives the same files
  --randomize         every view in a world of its own look: materials, lamps, clutter, exposure
                      and daylight (vsl::worldgen::randomize_looks)
  --views-per-look K  with --randomize: K views share one look (default 1); the renderer's
                      construction per look is most of a view's time
  --realism LEVEL     off, materials or full (default full): the renderer's realism
  --head FILE         head kinematics and calibration (default config/heads/armar3.yaml)
  --format jpg|png    image files (default jpg, quality 95)
  --depth             also write depth/<image>.png: 16-bit millimetres, 0 where nothing
  --ids               also write ids/<image>.png: 16-bit object index + 1, 0 where nothing
  --threads T         worker threads (default: one per core); the files do not depend on it
  --min-visible-px N  skip boxes of fewer visible pixels (default 20)
  --min-box-px N      skip boxes narrower or lower than this (default 3)
  --max-occluded F    skip boxes whose object is hidden more than this fraction (default 0.8)
  --preview FILE      also write a contact sheet of the first six left images with their
                      boxes (room door red, handle yellow, cabinet door green, fridge magenta)
  -q, --quiet         no progress or summary on standard error
exit codes: 0 ok, 1 a file could not be written, 2 bad usage, world or head file
)";

std::uint64_t parse_count(const std::string& text, const std::string& option, std::uint64_t min,
                          std::uint64_t max) {
  try {
    std::size_t used = 0;
    const unsigned long long value = std::stoull(text, &used);
    if (used == text.size() && text[0] != '-' && value >= min && value <= max) return value;
  } catch (const std::exception&) {
  }
  throw UsageError(option + " wants an integer in [" + std::to_string(min) + ", " +
                   std::to_string(max) + "], got '" + text + "'");
}

double parse_fraction(const std::string& text, const std::string& option) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && value >= 0.0 && value <= 1.0) return value;
  } catch (const std::exception&) {
  }
  throw UsageError(option + " wants a number in [0, 1], got '" + text + "'");
}

render::RealismLevel parse_realism(const std::string& text) {
  for (const render::RealismLevel level :
       {render::RealismLevel::off, render::RealismLevel::materials, render::RealismLevel::full}) {
    if (text == render::realism_level_name(level)) return level;
  }
  throw UsageError("--realism wants off, materials or full, got '" + text + "'");
}

ImageFormat parse_format(const std::string& text) {
  if (text == "jpg") return ImageFormat::jpg;
  if (text == "png") return ImageFormat::png;
  throw UsageError("--format wants jpg or png, got '" + text + "'");
}

}  // namespace

const char* dataset_usage() {
  return kUsage;
}

std::optional<DatasetOptions> parse_dataset_options(const std::vector<std::string>& arguments) {
  DatasetOptions o;
  constexpr std::uint64_t kMaxViews = 100'000'000;
  constexpr std::uint64_t kMaxInt = std::numeric_limits<int>::max();
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& arg = arguments[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= arguments.size()) throw UsageError(arg + " needs a value");
      return arguments[++i];
    };
    if (arg == "-h" || arg == "--help") return std::nullopt;
    if (arg == "--world") {
      o.world_file = value();
    } else if (arg == "--views") {
      o.views = parse_count(value(), arg, 1, kMaxViews);
    } else if (arg == "--seed") {
      o.seed = parse_count(value(), arg, 0, std::numeric_limits<std::uint64_t>::max());
    } else if (arg == "--out") {
      o.out_dir = value();
    } else if (arg == "--randomize") {
      o.randomize = true;
    } else if (arg == "--views-per-look") {
      o.views_per_look = parse_count(value(), arg, 1, kMaxViews);
    } else if (arg == "--realism") {
      o.realism = parse_realism(value());
    } else if (arg == "--head") {
      o.head_file = value();
    } else if (arg == "--format") {
      o.format = parse_format(value());
    } else if (arg == "--depth") {
      o.depth = true;
    } else if (arg == "--ids") {
      o.ids = true;
    } else if (arg == "--threads") {
      o.threads = static_cast<unsigned>(parse_count(value(), arg, 1, 1024));
    } else if (arg == "--min-visible-px") {
      o.filter.min_visible_px = static_cast<int>(parse_count(value(), arg, 1, kMaxInt));
    } else if (arg == "--min-box-px") {
      o.filter.min_box_side_px = static_cast<int>(parse_count(value(), arg, 1, kMaxInt));
    } else if (arg == "--max-occluded") {
      o.filter.max_occluded = parse_fraction(value(), arg);
    } else if (arg == "--preview") {
      o.preview_file = value();
    } else if (arg == "-q" || arg == "--quiet") {
      o.quiet = true;
    } else {
      throw UsageError("unknown argument " + arg);
    }
  }
  if (o.world_file.empty()) throw UsageError("--world is required");
  if (o.views == 0) throw UsageError("--views is required");
  if (o.out_dir.empty()) throw UsageError("--out is required");
  return o;
}

}  // namespace vsl::tools
