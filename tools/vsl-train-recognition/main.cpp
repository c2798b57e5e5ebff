// vsl-train-recognition: fits the Gaussian class models of the class-specific recognizers (paper
// §2.1) to labelled blobs, from simulated views of a world (labels from the id buffer) or from a
// user's own images with hand-labelled boxes, and writes config/recognition/<type>.yaml.
#include <opencv2/imgcodecs.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "recognition_config.hpp"
#include "recognition_views.hpp"
#include "training_samples.hpp"
#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/recognition/box_labels.hpp"
#include "vsl/recognition/recognizer_factory.hpp"
#include "vsl/recognition/segmentation.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_io.hpp"

namespace {

using namespace vsl;

constexpr const char* kUsage =
    R"(usage: vsl-train-recognition (--world FILE | --labels FILE) [options]

Trains the class models of the recognizers (docs/recognition.md): segments labelled images into
blobs, takes the blobs of each class as positive samples and the blobs on no object of the class
as negative ones, fits the Gaussian class model (mean, covariance) to the positives' descriptors,
picks the acceptance threshold, reports how many negatives it accepts, and writes
OUTPUT_DIR/<type>.yaml.
sources (one of):
  --world FILE          simulated views of this world: seeded robot poses, the head looking at the
                        cupboards, noisy stereo pairs (left and right images both used), labels
                        from the renderer's id buffer
  --labels FILE         your own images, listed with hand-labelled boxes in a box-label file
options:
  --views N             simulated robot poses (default 200)
  --seed S              seed of the poses and the sensor noise (default 1)
  --types LIST          comma-separated classes to train (default door,handle)
  --config FILE         recognition config whose segmentation options and head are used
                        (default config/recognition_paper.yaml)
  -o, --output-dir DIR  where the model files go (default config/recognition); an existing
                        <type>.yaml there keeps its recognizer parameters, only the model changes
  --keep FRACTION       the threshold is the smallest squared Mahalanobis distance that keeps
                        this fraction of the positives (default 0.98); chi2: the fitted
                        Gaussian's own chi-square quantile; f1: the threshold with the best
                        F1 of the positive against the negative samples; per class as
                        TYPE=FRACTION,... (e.g. door=0.925,handle=0.998; a class not named
                        gets the last plain --keep, else 0.98)
  --realism LEVEL       --world: the simulated views' realism, off (default), materials or full
                        (docs/rendering.md): train for the images the recognizer will see
  --learn-colour        each class's ideal colour (ideal_colour_rgb) becomes the mean colour of
                        its positive blobs, rather than the model file's (for a building whose
                        fronts and handles are not the bundled kitchen's colours)
  --dry-run             report, write nothing
  -q, --quiet           no status line
exit codes: 0 ok, 1 a file could not be written or too few samples, 2 bad usage or input file
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-train-recognition: " << what << " (see vsl-train-recognition --help)\n";
  std::exit(2);
}

std::uint64_t parse_count(const std::string& text, const std::string& option) {
  try {
    std::size_t used = 0;
    const unsigned long long value = std::stoull(text, &used);
    if (used == text.size() && text[0] != '-') return value;
  } catch (const std::exception&) {
  }
  usage_error(option + " wants a non-negative integer, got '" + text + "'");
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, separator);) parts.push_back(part);
  return parts;
}

struct Options {
  std::string world_file;
  std::string labels_file;
  std::uint64_t views = 200;
  std::uint64_t seed = 1;
  std::vector<std::string> types{"door", "handle"};
  std::string config_file = "config/recognition_paper.yaml";
  std::string output_dir = "config/recognition";
  double keep = 0.98;                     // for a class not in keep_of
  std::map<std::string, double> keep_of;  // --keep TYPE=FRACTION,...
  render::RealismLevel realism = render::RealismLevel::off;
  bool learn_colour = false;
  bool dry_run = false;
  bool quiet = false;
  std::string command_line;
};

// A share of positives in (0.5, 1], "chi2": the fit's own chi-square quantile, or "f1": the
// threshold with the best F1 of positives against negatives (train_class's `keep`).
double parse_fraction(const std::string& text) {
  if (text == "chi2") return tools::kKeepChiSquare;
  if (text == "f1") return tools::kKeepBestF1;
  double value = 0.0;
  try {
    std::size_t used = 0;
    value = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    usage_error("--keep wants a number, chi2 or f1, got '" + text + "'");
  }
  if (!(value > 0.5 && value <= 1.0)) {
    usage_error("--keep wants (0.5, 1], chi2 or f1, got " + text);
  }
  return value;
}

// FRACTION, or TYPE=FRACTION,... for each class its own.
void parse_keep(const std::string& text, Options& options) {
  if (text.find('=') == std::string::npos) {
    options.keep = parse_fraction(text);
    return;
  }
  if (text.back() == ',') usage_error("--keep: a trailing comma in '" + text + "'");
  for (const std::string& entry : split(text, ',')) {
    const std::size_t equals = entry.find('=');
    if (equals == std::string::npos || equals == 0) {
      usage_error("--keep wants FRACTION or TYPE=FRACTION,..., got '" + entry + "'");
    }
    if (!options.keep_of.emplace(entry.substr(0, equals), parse_fraction(entry.substr(equals + 1)))
             .second) {
      usage_error("--keep names '" + entry.substr(0, equals) + "' twice");
    }
  }
}

Options parse(int argc, char** argv) {
  Options options;
  options.command_line = "vsl-train-recognition";
  for (int i = 1; i < argc; ++i) options.command_line += std::string(" ") + argv[i];
  auto value_of = [&](int& i, const std::string& arg) -> std::string {
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--world") {
      options.world_file = value_of(i, arg);
    } else if (arg == "--labels") {
      options.labels_file = value_of(i, arg);
    } else if (arg == "--views") {
      options.views = parse_count(value_of(i, arg), arg);
      if (options.views == 0 || options.views > 1000000) usage_error("--views wants 1..1000000");
    } else if (arg == "--seed") {
      options.seed = parse_count(value_of(i, arg), arg);
    } else if (arg == "--types") {
      options.types = split(value_of(i, arg), ',');
      if (options.types.empty()) usage_error("--types wants a comma-separated list");
      for (const std::string& type : options.types) {
        if (type.empty()) usage_error("--types: empty type name");
      }
    } else if (arg == "--config") {
      options.config_file = value_of(i, arg);
    } else if (arg == "-o" || arg == "--output-dir") {
      options.output_dir = value_of(i, arg);
    } else if (arg == "--keep") {
      parse_keep(value_of(i, arg), options);
    } else if (arg == "--realism") {
      const std::string level = value_of(i, arg);
      const std::optional<render::RealismLevel> parsed = render::realism_level_from_name(level);
      if (!parsed) usage_error("--realism wants off, materials or full, got '" + level + "'");
      options.realism = *parsed;
    } else if (arg == "--learn-colour") {
      options.learn_colour = true;
    } else if (arg == "--dry-run") {
      options.dry_run = true;
    } else if (arg == "-q" || arg == "--quiet") {
      options.quiet = true;
    } else {
      usage_error("unknown argument " + arg);
    }
  }
  if (options.world_file.empty() == options.labels_file.empty()) {
    usage_error("give exactly one of --world and --labels");
  }
  for (const auto& [type, keep] : options.keep_of) {
    if (std::find(options.types.begin(), options.types.end(), type) == options.types.end()) {
      usage_error("--keep: '" + type + "' is not among the classes trained (--types)");
    }
  }
  return options;
}

// The model file to train for `type`: the existing one in the output directory (its recognizer
// parameters are kept), or the implementation of the same name with default parameters.
recognition::RecognizerFile template_for(const std::string& type, const Options& options) {
  const std::string path = (std::filesystem::path(options.output_dir) / (type + ".yaml")).string();
  if (std::filesystem::exists(path)) {
    recognition::RecognizerFile file = recognition::read_recognizer_file(path);
    if (file.model.type() != type) {
      throw config::Error(path + ": type: the file is for type '" + file.model.type() + "', not '" +
                          type + "'");
    }
    return file;
  }
  const auto& names = recognition::recognizer_names();
  if (std::find(names.begin(), names.end(), type) == names.end()) {
    std::string known;
    for (const std::string& name : names) known += (known.empty() ? "" : ", ") + name;
    usage_error("--types: no recognizer for type '" + type + "' and no " + path +
                " to say which (recognizers: " + known + ")");
  }
  recognition::RecognizerFile file;
  file.recognizer = type;
  // A placeholder model of the right dimension; training replaces it.
  const auto& component_names = recognition::descriptor_names_of(type);
  const auto k = static_cast<Eigen::Index>(component_names.size());
  file.model = recognition::GaussianClassModel(type, component_names, Eigen::VectorXd::Zero(k),
                                               Eigen::MatrixXd::Identity(k, k), 1.0);
  return file;
}

// A status line on standard error: rewritten in place on a terminal, every 10% otherwise.
class Status {
 public:
  Status(bool quiet, std::uint64_t total) : quiet_(quiet), total_(total), tty_(isatty(2) != 0) {}
  void update(std::uint64_t done, const std::string& text) {
    if (quiet_) return;
    if (tty_) {
      std::fprintf(stderr, "\r\033[Kvsl-train-recognition: %s", text.c_str());
      if (done == total_) std::fputc('\n', stderr);
    } else if (done == total_ || done * 10 / total_ != (done - 1) * 10 / total_) {
      std::fprintf(stderr, "vsl-train-recognition: %s\n", text.c_str());
    }
    std::fflush(stderr);
  }

 private:
  bool quiet_;
  std::uint64_t total_;
  bool tty_;
};

std::string progress_text(const std::string& unit, std::uint64_t done, std::uint64_t total,
                          const std::vector<tools::ClassSamples>& samples) {
  std::string text = unit + " " + std::to_string(done) + "/" + std::to_string(total) + ":";
  for (const tools::ClassSamples& s : samples) {
    text += " " + s.file.model.type() + " " + std::to_string(s.positives.size()) + "+ " +
            std::to_string(s.negatives.size()) + "-";
  }
  return text;
}

void collect_from_world(const Options& options, const tools::RecognitionConfig& config,
                        std::vector<tools::ClassSamples>& samples, std::string& source_text) {
  const world::WorldModel world = world::load_world(options.world_file);
  const head::HeadKinematics head =
      head::HeadKinematics::load(config.head_file, config.calibration_file);
  render::RenderOptions camera = tools::simulated_camera_options();
  camera.realism.level = options.realism;
  const render::Renderer renderer(world, camera);
  const tools::ViewSampler sampler(world, head);
  std::vector<std::string> object_types;
  for (const world::ObjectModel& object : world.objects) object_types.push_back(object.type);
  Status status(options.quiet, options.views);
  for (std::uint64_t k = 0; k < options.views; ++k) {
    const tools::ViewPose view = sampler.sample(options.seed, k);
    const tools::StereoRender frame =
        tools::render_view(renderer, head, view, (options.seed << 32) + k);
    for (const render::RenderedImage* image : {&frame.left, &frame.right}) {
      tools::add_id_buffer_samples(image->image, image->object_ids, object_types,
                                   config.options.segmentation, samples);
    }
    status.update(k + 1, progress_text("view", k + 1, options.views, samples));
  }
  source_text = std::to_string(2 * options.views) + " simulated images of " + options.world_file +
                " (" + std::to_string(options.views) + " views, seed " +
                std::to_string(options.seed) + ", realism " +
                render::realism_level_name(options.realism) + ")";
}

void collect_from_labels(const Options& options, const tools::RecognitionConfig& config,
                         std::vector<tools::ClassSamples>& samples, std::string& source_text) {
  const recognition::BoxLabels labels = recognition::load_box_labels(options.labels_file);
  Status status(options.quiet, labels.images.size());
  std::uint64_t done = 0;
  for (const recognition::LabelledImage& labelled : labels.images) {
    const cv::Mat image = cv::imread(labelled.image_path, cv::IMREAD_COLOR);
    if (image.empty()) {
      throw config::Error(config::format_error(labels.source, labelled.line,
                                               labelled.path + ".image",
                                               "cannot read image " + labelled.image_path));
    }
    recognition::check_boxes_fit(labels, labelled, image.cols, image.rows);
    tools::add_box_samples(image, labelled.boxes, config.options.segmentation, samples);
    ++done;
    status.update(done, progress_text("image", done, labels.images.size(), samples));
  }
  source_text =
      std::to_string(labels.images.size()) + " hand-labelled images of " + options.labels_file;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse(argc, argv);
    const tools::RecognitionConfig config = tools::read_recognition_config(options.config_file);
    std::vector<tools::ClassSamples> samples;
    for (const std::string& type : options.types) {
      samples.push_back(tools::ClassSamples{template_for(type, options), {}, {}, {}, {}});
    }
    std::string source_text;
    if (!options.world_file.empty()) {
      collect_from_world(options, config, samples, source_text);
    } else {
      collect_from_labels(options, config, samples, source_text);
    }
    int exit_code = 0;
    for (tools::ClassSamples& s : samples) {
      const std::string type = s.file.model.type();
      if (s.positives.size() < tools::kMinPositives) {
        std::fprintf(stderr,
                     "vsl-train-recognition: %s: only %zu positive samples (at least %zu needed); "
                     "no model written\n",
                     type.c_str(), s.positives.size(), tools::kMinPositives);
        exit_code = 1;
        continue;
      }
      if (const auto q = options.learn_colour ? tools::learn_ideal_colour(s) : std::nullopt) {
        std::printf("%s: ideal colour learned from the positives: [%.3f, %.3f, %.3f]\n",
                    type.c_str(), q->x(), q->y(), q->z());
      }
      const tools::TrainedModel trained = tools::train_class(
          s, options.keep_of.count(type) ? options.keep_of.at(type) : options.keep);
      s.file.model = trained.model;
      std::ostringstream provenance;
      provenance << options.command_line << ": " << trained.summary << " from " << source_text;
      s.file.model.set_provenance(provenance.str());
      std::printf("%s: %s\n", type.c_str(), trained.summary.c_str());
      if (options.dry_run) continue;
      const std::string path =
          (std::filesystem::path(options.output_dir) / (type + ".yaml")).string();
      try {
        std::filesystem::create_directories(options.output_dir);
        recognition::save_recognizer_file(s.file, path);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "vsl-train-recognition: cannot write %s: %s\n", path.c_str(),
                     e.what());
        exit_code = 1;
        continue;
      }
      std::printf("wrote %s\n", path.c_str());
    }
    return exit_code;
  } catch (const config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "vsl-train-recognition: " << e.what() << "\n";
    return 2;
  }
}
