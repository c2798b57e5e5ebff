// vsl-eval-recognition: runs the recognition pipeline (FrameRecognizer, paper §2.1 and §2.1.1) on
// noisy stereo frames rendered from seeded robot poses in a world and judges its percepts against
// the renderer's ground truth: precision and recall per class, the 3D error of matched percepts by
// distance band, and the time per stereo pair.
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "evaluation.hpp"
#include "frame_dump.hpp"
#include "frame_text.hpp"
#include "funnel.hpp"
#include "image_evaluation.hpp"
#include "json_writer.hpp"
#include "percept_noise.hpp"
#include "recognition_config.hpp"
#include "recognition_views.hpp"
#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/learned_stereo_recognizer.hpp"
#include "vsl/recognition/recognizer_factory.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/randomize_looks.hpp"

namespace {

using namespace vsl;

constexpr const char* kUsage =
    R"(usage: vsl-eval-recognition --world FILE [options]
       vsl-eval-recognition --images DIR --yolo-labels DIR [options]   (see --images --help)

Evaluates recognition (docs/recognition.md): renders noisy stereo frames from seeded robot poses in
the world (the head looking at the cupboards), runs the recognition pipeline with the settings of
the recognition config, and prints per class the precision (over the true and false positives
within range: a correct percept of a real object the ground truth leaves out is neither; "precision
strict" counts it as false) and the recall (over the objects within 4 m of the left camera and at least half visible in both images; beside it
the recall over those whose whole outline lies inside both images, not cut by the border), the 3D
error of the matched percepts (within 10 cm of their object's reference point) by distance band,
the recall of flat objects (doors) by viewing angle, the time per stereo pair, and the noise of
the true positives' reference points and disparities (the learned recognizer's `noise:` model)
with their median signed error, across and along the ray and in the object's own axes.
  --world FILE[,FILE]   world model, e.g. config/worlds/kitchen_galley.yaml; several, comma-
                        separated: --views of each, tallied together (the noise model of
                        several layouts at once)
options:
  --views N             robot poses (default 100)
  --seed S              seed of the poses and the sensor noise (default 2; training uses 1)
  --config FILE         recognition config: head, model files, segmentation and stereo options
                        (default config/recognition_paper.yaml; config/recognition.yaml
                        runs the learned detector)
  --models LIST         comma-separated model files instead of the config's (paper's recognizer)
  --realism LEVEL       the rendered frames' realism: off (default), materials or full
                        (docs/rendering.md)
  --looks K             every K views a look of the world of their own (materials, lamps,
                        clutter: vsl::worldgen::randomize_looks, seeded by --seed), as the
                        detector's training renders; default: the world's own look
  --max-distance M      ground truth: objects within M metres of the left camera (default 4)
  --target-distance M   each view looks at an object up to M metres from the robot (default 4;
                        a scan from the middle of a room sees its far wall at 5-6 m)
  --match-distance M    a percept within M metres of its object is a true positive (default 0.1)
  --dump DIR            write DIR/frame_NNNN.png per frame: the left image with the blobs
                        (grey), detections (yellow; learned handles orange, with why a
                        refused pair was refused), visible ground truth (blue circles) and
                        percepts (green crosses: true positives, red: false ones); and
                        DIR/frame_NNNN.txt: the objects in view, their pixel counts, distances
                        and whether they count as ground truth, and where each was lost
                        (funnel lines); DIR/frame_NNNN_raw.png: the left image as the
                        recognizer saw it; and a table of where the ground-truth objects were
                        lost (no blob, merged, fragment, refused at stereo by which gate,
                        undetected), printed and written to DIR/funnel.txt; with the learned
                        recognizer instead, what became of the left detections (a percept,
                        refused by which test, unpaired)
  --json FILE           also write the results as JSON (- for standard output, then no table)
  -q, --quiet           no status line
exit codes: 0 ok, 1 an output file could not be written, 2 bad usage or input file
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-eval-recognition: " << what << " (see vsl-eval-recognition --help)\n";
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

double parse_positive(const std::string& text, const std::string& option) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value) && value > 0.0) return value;
  } catch (const std::exception&) {
  }
  usage_error(option + " wants a positive number, got '" + text + "'");
}

struct Options {
  std::string world_file;
  std::uint64_t views_per_look = 0;  // --looks K; 0: the world's own look
  std::uint64_t views = 100;
  std::uint64_t seed = 2;
  std::string config_file = "config/recognition_paper.yaml";
  std::vector<std::string> model_files;
  double max_distance_m = 4.0;
  double max_target_distance_m = 4.0;
  double match_distance_m = 0.10;
  std::string json_file;
  std::string dump_dir;
  render::RealismLevel realism = render::RealismLevel::off;
  bool quiet = false;
};

Options parse(int argc, char** argv) {
  Options options;
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
    } else if (arg == "--views") {
      options.views = parse_count(value_of(i, arg), arg);
      if (options.views == 0 || options.views > 1000000) usage_error("--views wants 1..1000000");
    } else if (arg == "--seed") {
      options.seed = parse_count(value_of(i, arg), arg);
    } else if (arg == "--config") {
      options.config_file = value_of(i, arg);
    } else if (arg == "--models") {
      std::stringstream list(value_of(i, arg));
      for (std::string file; std::getline(list, file, ',');) {
        if (file.empty()) usage_error("--models: empty file name");
        options.model_files.push_back(file);
      }
      if (options.model_files.empty()) usage_error("--models wants a comma-separated list");
    } else if (arg == "--realism") {
      const std::string level = value_of(i, arg);
      const std::optional<render::RealismLevel> parsed = render::realism_level_from_name(level);
      if (!parsed) usage_error("--realism wants off, materials or full, got '" + level + "'");
      options.realism = *parsed;
    } else if (arg == "--max-distance") {
      options.max_distance_m = parse_positive(value_of(i, arg), arg);
    } else if (arg == "--target-distance") {
      options.max_target_distance_m = parse_positive(value_of(i, arg), arg);
      if (options.max_target_distance_m < 1.0 || options.max_target_distance_m > 20.0) {
        usage_error("--target-distance wants metres in 1..20");
      }
    } else if (arg == "--match-distance") {
      options.match_distance_m = parse_positive(value_of(i, arg), arg);
    } else if (arg == "--looks") {
      options.views_per_look = parse_count(value_of(i, arg), arg);
      if (options.views_per_look == 0) usage_error("--looks wants a count of at least 1");
    } else if (arg == "--dump") {
      options.dump_dir = value_of(i, arg);
    } else if (arg == "--json") {
      options.json_file = value_of(i, arg);
    } else if (arg == "-q" || arg == "--quiet") {
      options.quiet = true;
    } else {
      usage_error("unknown argument " + arg);
    }
  }
  if (options.world_file.empty()) usage_error("--world is required");
  return options;
}

const char* const kBandNames[tools::kDistanceBands] = {"0-1 m", "1-2 m", "2-3 m", "3-4 m"};

// Recall of the flat objects (doors) by viewing angle: true positives over ground truth, all and
// whole in both images, per band; classes without flat objects are left out.
void print_viewing_angle_table(const tools::EvaluationTally& tally) {
  bool any = false;
  for (const tools::ClassTally& c : tally.classes) {
    for (const int n : c.flat_ground_truth) any = any || n > 0;
  }
  if (!any) return;
  std::printf(
      "recall of flat objects by viewing angle (between the face's normal and the ray to the left "
      "camera), true+/objects, and of those whole in both images:\n");
  std::printf("%-8s %-10s %14s %14s\n", "class", "band", "recall", "recall whole");
  for (const tools::ClassTally& c : tally.classes) {
    int total = 0;
    for (const int n : c.flat_ground_truth) total += n;
    if (total == 0) continue;
    for (int b = 0; b < tools::kViewingAngleBands; ++b) {
      const auto k = static_cast<std::size_t>(b);
      char band[16];
      std::snprintf(
          band, sizeof band, "%.0f-%.0f deg", tools::kViewingAngleBandStartsDeg[k],
          b + 1 < tools::kViewingAngleBands ? tools::kViewingAngleBandStartsDeg[k + 1] : 90.0);
      const auto ratio = [](int hit, int all) {
        char text[32];
        if (all == 0) {
          std::snprintf(text, sizeof text, "-");
        } else {
          std::snprintf(text, sizeof text, "%d/%d %5.1f%%", hit, all, 100.0 * hit / all);
        }
        return std::string(text);
      };
      std::printf("%-8s %-10s %14s %14s\n", c.type.c_str(), band,
                  ratio(c.flat_true_positives[k], c.flat_ground_truth[k]).c_str(),
                  ratio(c.flat_true_positives_whole[k], c.flat_ground_truth_whole[k]).c_str());
    }
  }
}

void print_table(const Options& options, const tools::EvaluationTally& tally) {
  std::printf(
      "world %s: %d stereo frames (seed %llu), objects within %.1f m, at least half "
      "visible in both images\n",
      options.world_file.c_str(), tally.frames, static_cast<unsigned long long>(options.seed),
      options.max_distance_m);
  std::printf("%-8s %8s %8s %8s %8s %10s %8s %14s %10s %10s %10s\n", "class", "objects", "percepts",
              "true+", "false+", "precision", "recall", "recall whole", "on non-", "precision",
              "beyond");
  std::printf("%-8s %8s %8s %8s %8s %10s %8s %14s %10s %10s %10s\n", "", "", "", "", "", "", "",
              "(objects)", "truth", "strict", "range");
  for (const tools::ClassTally& c : tally.classes) {
    std::printf("%-8s %8d %8d %8d %8d %9.1f%% %7.1f%% %7.1f%% %5d %10d %9.1f%% %10d\n",
                c.type.c_str(), c.ground_truth, c.percepts, c.true_positives, c.false_positives(),
                100.0 * c.precision(), 100.0 * c.recall(), 100.0 * c.recall_whole(),
                c.ground_truth_whole, c.false_positives_on_other_objects,
                100.0 * c.precision_strict(), c.out_of_range);
  }
  for (const tools::ClassTally& c : tally.classes) {
    std::printf(
        "%-8s false+: %d misplaced (within %.1f m of an object of the type), %d mistyped "
        "(on an object of another type), %d on nothing\n",
        c.type.c_str(), c.false_misplaced, tools::kMisplacedDistanceM, c.false_mistyped,
        c.false_positives() - c.false_misplaced - c.false_mistyped);
  }
  std::printf(
      "(recall whole: over the ground-truth objects whose whole outline lies inside both images, "
      "not cut by the image border)\n");
  std::printf(
      "(on non-truth: percepts within the match distance of a real object of the type that is "
      "not ground truth (farther than %.1f m or less than half visible), neither true nor false "
      "positives; precision strict counts them as false positives; beyond range: percepts "
      "farther than %.2f m, not counted)\n",
      options.max_distance_m, options.max_distance_m + options.match_distance_m);
  std::printf("3D error of matched percepts by distance from the left camera (cm):\n");
  std::printf(
      "(and their squared Mahalanobis distances under the percepts' covariances, honest: median "
      "2.37, 97 %% within 3 sigmas)\n");
  std::printf("%-8s %-7s %6s %8s %8s %10s %11s\n", "class", "band", "n", "median", "p90",
              "median d2", "within 3 sd");
  for (const tools::ClassTally& c : tally.classes) {
    for (int b = 0; b < tools::kDistanceBands; ++b) {
      const auto& errors = c.errors_m[static_cast<std::size_t>(b)];
      if (errors.empty()) {
        std::printf("%-8s %-7s %6d %8s %8s %10s %11s\n", c.type.c_str(), kBandNames[b], 0, "-", "-",
                    "-", "-");
        continue;
      }
      const auto& d2 = c.mahalanobis2[static_cast<std::size_t>(b)];
      const double within = d2.empty()
                                ? 0.0
                                : static_cast<double>(std::count_if(
                                      d2.begin(), d2.end(), [](double v) { return v <= 9.0; })) /
                                      static_cast<double>(d2.size());
      std::printf("%-8s %-7s %6zu %8.2f %8.2f %10.2f %10.0f%%\n", c.type.c_str(), kBandNames[b],
                  errors.size(), 100.0 * tools::quantile(errors, 0.5),
                  100.0 * tools::quantile(errors, 0.9), tools::quantile(d2, 0.5), 100.0 * within);
    }
  }
  print_viewing_angle_table(tally);
  std::printf(
      "time per stereo pair: median %.2f ms, p90 %.2f ms (median segmentation %.2f, "
      "classification %.2f, stereo %.2f ms)\n",
      tools::quantile(tally.frame_ms, 0.5), tools::quantile(tally.frame_ms, 0.9),
      tools::quantile(tally.segmentation_ms, 0.5), tools::quantile(tally.classification_ms, 0.5),
      tools::quantile(tally.stereo_ms, 0.5));
}

void write_json(std::ostream& out, const Options& options, const tools::EvaluationTally& tally) {
  tools::JsonWriter json(out);
  json.begin_object();
  json.key("world").string(options.world_file);
  json.key("frames").number(tally.frames);
  json.key("seed").number(static_cast<double>(options.seed));
  json.key("max_distance_m").number(options.max_distance_m);
  json.key("match_distance_m").number(options.match_distance_m);
  json.key("classes").begin_array();
  for (const tools::ClassTally& c : tally.classes) {
    json.begin_object();
    json.key("type").string(c.type);
    json.key("ground_truth_objects").number(c.ground_truth);
    json.key("percepts").number(c.percepts);
    json.key("true_positives").number(c.true_positives);
    json.key("false_positives").number(c.false_positives());
    json.key("percepts_on_objects_outside_ground_truth").number(c.false_positives_on_other_objects);
    json.key("false_positives_misplaced").number(c.false_misplaced);
    json.key("false_positives_mistyped").number(c.false_mistyped);
    json.key("percepts_beyond_range").number(c.out_of_range);
    json.key("precision").number(c.precision());
    json.key("precision_strict").number(c.precision_strict());
    json.key("recall").number(c.recall());
    json.key("ground_truth_objects_whole_in_both_images").number(c.ground_truth_whole);
    json.key("true_positives_whole_in_both_images").number(c.true_positives_whole);
    json.key("recall_whole_in_both_images").number(c.recall_whole());
    json.key("recall_by_viewing_angle").begin_array();
    for (int b = 0; b < tools::kViewingAngleBands; ++b) {
      const auto k = static_cast<std::size_t>(b);
      json.begin_object();
      json.key("min_angle_deg").number(tools::kViewingAngleBandStartsDeg[k]);
      json.key("max_angle_deg")
          .number(b + 1 < tools::kViewingAngleBands ? tools::kViewingAngleBandStartsDeg[k + 1]
                                                    : 90.0);
      json.key("ground_truth_objects").number(c.flat_ground_truth[k]);
      json.key("true_positives").number(c.flat_true_positives[k]);
      json.key("ground_truth_objects_whole_in_both_images").number(c.flat_ground_truth_whole[k]);
      json.key("true_positives_whole_in_both_images").number(c.flat_true_positives_whole[k]);
      json.end_object();
    }
    json.end_array();
    json.key("error_by_distance_band").begin_array();
    for (int b = 0; b < tools::kDistanceBands; ++b) {
      const auto& errors = c.errors_m[static_cast<std::size_t>(b)];
      json.begin_object();
      json.key("min_distance_m").number(b);
      json.key("max_distance_m").number(b + 1);
      json.key("matched").number(static_cast<double>(errors.size()));
      json.key("median_error_m").number(tools::quantile(errors, 0.5));
      json.key("p90_error_m").number(tools::quantile(errors, 0.9));
      json.key("median_mahalanobis2")
          .number(tools::quantile(c.mahalanobis2[static_cast<std::size_t>(b)], 0.5));
      json.end_object();
    }
    json.end_array();
    json.end_object();
  }
  json.end_array();
  json.key("time_per_stereo_pair_ms").begin_object();
  json.key("median").number(tools::quantile(tally.frame_ms, 0.5));
  json.key("p90").number(tools::quantile(tally.frame_ms, 0.9));
  json.key("median_segmentation").number(tools::quantile(tally.segmentation_ms, 0.5));
  json.key("median_classification").number(tools::quantile(tally.classification_ms, 0.5));
  json.key("median_stereo").number(tools::quantile(tally.stereo_ms, 0.5));
  json.end_object();
  json.end_object();
  out << "\n";
}

// The ground truth of percepts placed by one edge (BoxStereoOptions::edge_types): each visible
// object of such a type again as its front face's top and bottom edges' middles, of the world
// graph's edge node types. Their recall is over the objects of the type, most of which are placed
// whole instead.
void add_edge_ground_truth(const world::WorldModel& world, const std::vector<std::string>& types,
                           const tools::StereoRender& frame,
                           std::vector<recognition::GroundTruthObject>& truth) {
  const Eigen::Isometry3d ego_T_world = frame.pose.world_T_ego.inverse();
  const Eigen::Vector3d camera = frame.ego_T_left_camera.translation();
  const std::size_t objects = truth.size();
  for (std::size_t i = 0; i < objects; ++i) {
    if (std::find(types.begin(), types.end(), truth[i].type) == types.end()) continue;
    for (const world::FaceEdge edge : {world::FaceEdge::kTop, world::FaceEdge::kBottom}) {
      const auto middle = world::face_edge_middle_m(world.objects[truth[i].object_index], edge);
      if (!middle) continue;
      recognition::GroundTruthObject edge_truth = truth[i];
      edge_truth.type = world::edge_node_type(truth[i].type, edge);
      edge_truth.ego_position_m = ego_T_world * *middle;
      edge_truth.distance_m = (edge_truth.ego_position_m - camera).norm();
      truth.push_back(std::move(edge_truth));
    }
  }
}

// Per class, the left detections that became a percept, were paired and refused (by which test),
// or found no partner in the right image.
void tally_learned_stereo(const recognition::FrameResult& result,
                          const std::vector<recognition::PerceptMatch>& matches,
                          cv::Size image_size,
                          std::map<std::string, std::map<std::string, int>>& tally) {
  std::vector<std::string> fate(result.left_detections.size(), "unpaired");
  for (std::size_t i = 0; i < result.percepts.size(); ++i) {
    const recognition::FramePercept& p = result.percepts[i];
    if (p.left_detection < 0) continue;
    const bool right = i < matches.size() && matches[i].ground_truth >= 0;
    fate[static_cast<std::size_t>(p.left_detection)] =
        std::string(p.right_detection < 0 ? "percept by search" : "percept") +
        (right ? " (true)" : " (false)");
  }
  for (const recognition::StereoRefusal& r : result.stereo_refusals) {
    if (r.left_detection >= 0) fate[static_cast<std::size_t>(r.left_detection)] = r.reason;
  }
  for (std::size_t i = 0; i < fate.size(); ++i) {
    const recognition::Detection& d = result.left_detections[i];
    const bool at_border =
        d.corners_px.size() == 4 && (d.corners_px[0].x() < 2.0 || d.corners_px[0].y() < 2.0 ||
                                     d.corners_px[2].x() > image_size.width - 3.0 ||
                                     d.corners_px[2].y() > image_size.height - 3.0);
    if (fate[i] == "unpaired" && at_border) fate[i] = "unpaired at the border";
    ++tally[d.type][fate[i]];
  }
}

void print_learned_stereo(std::ostream& out,
                          const std::map<std::string, std::map<std::string, int>>& tally) {
  if (tally.empty()) return;
  out << "what became of the left detections (percept, paired and refused by a test, or "
         "unpaired):\n";
  for (const auto& [type, fates] : tally) {
    out << "  " << type << ":";
    for (const auto& [fate, count] : fates) out << " " << fate << " " << count << ",";
    out << "\n";
  }
}

// What one evaluation shares over its worlds, and what their frames add up to.
struct Run {
  Run(const Options& options, const tools::RecognitionConfig& config, bool learned,
      const head::HeadKinematics& head, const recognition::StereoRecognizer& recognizer,
      const std::vector<std::string>& types,
      const std::vector<recognition::RecognizerFile>& model_contents)
      : options(options),
        config(config),
        learned(learned),
        head(head),
        recognizer(recognizer),
        types(types),
        model_contents(model_contents),
        noise(head.calibration().left.fx_px, head.calibration().baseline_m()) {}

  const Options& options;
  const tools::RecognitionConfig& config;
  bool learned;
  const head::HeadKinematics& head;
  const recognition::StereoRecognizer& recognizer;
  const std::vector<std::string>& types;
  const std::vector<recognition::RecognizerFile>& model_contents;  // for the --dump funnel
  tools::EvaluationTally tally;
  tools::FunnelTally funnel;  // with --dump
  tools::PerceptNoiseTally noise;
  // With --dump and the learned recognizer: per class, what became of the left detections.
  std::map<std::string, std::map<std::string, int>> learned_stereo;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    if (comma > from) out.push_back(text.substr(from, comma - from));
    from = comma + 1;
  }
  return out;
}

// --dump's pictures and text of frame `index`; false (after one line on stderr) when a file
// cannot be written.
bool dump_frame(std::uint64_t index, const world::WorldModel& world,
                const tools::StereoRender& frame, const tools::ViewPose& view,
                const std::vector<recognition::GroundTruthObject>& truth,
                const recognition::FrameResult& result,
                const std::vector<recognition::PerceptMatch>& matches, Run& run) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04llu.png", static_cast<unsigned long long>(index));
  const std::string path = (std::filesystem::path(run.options.dump_dir) / name).string();
  const std::string stem = path.substr(0, path.size() - 4);
  if (!tools::write_frame_dump(path, frame.left.image, run.head.calibration().left, result, truth,
                               matches)) {
    std::cerr << "vsl-eval-recognition: cannot write " << path << "\n";
    return false;
  }
  if (!tools::write_right_dump(stem + "_right.png", frame.right.image, result)) {
    std::cerr << "vsl-eval-recognition: cannot write the right picture beside " << path << "\n";
    return false;
  }
  // The image as the recognizer saw it, without the drawing, to inspect the segmentation.
  if (!cv::imwrite(stem + "_raw.png", frame.left.image)) {
    std::cerr << "vsl-eval-recognition: cannot write the raw image beside " << path << "\n";
    return false;
  }
  if (run.learned) {
    tally_learned_stereo(result, matches, frame.left.image.size(), run.learned_stereo);
    return true;
  }
  if (!tools::write_frame_text(stem + ".txt",
                               {.world = world,
                                .frame = frame,
                                .joints = view.joints,
                                .head = run.head,
                                .stereo_options = run.config.options.stereo,
                                .result = result,
                                .ground_truth = truth,
                                .matches = matches,
                                .model_contents = run.model_contents},
                               run.funnel)) {
    std::cerr << "vsl-eval-recognition: cannot write " << stem << ".txt\n";
    return false;
  }
  return true;
}

// The status line after `done` of `total` frames: on a terminal rewritten in place, else every
// tenth.
void print_status(std::uint64_t done, std::uint64_t total, const tools::EvaluationTally& tally) {
  std::string text = "frame " + std::to_string(done) + "/" + std::to_string(total);
  for (const tools::ClassTally& c : tally.classes) {
    char item[96];
    std::snprintf(item, sizeof item, ", %s P %.1f%% R %.1f%%", c.type.c_str(),
                  100.0 * c.precision(), 100.0 * c.recall());
    text += item;
  }
  if (isatty(2) != 0) {
    std::fprintf(stderr, "\r\033[Kvsl-eval-recognition: %s%s", text.c_str(),
                 done == total ? "\n" : "");
  } else if (done == total || done * 10 / total != (done - 1) * 10 / total) {
    std::fprintf(stderr, "vsl-eval-recognition: %s\n", text.c_str());
  }
}

// Renders options.views frames of one world (seeded by options.seed and the view's index in
// it), recognizes and tallies them; frames are numbered from `first` of `total` for --dump and
// the status line. False when a --dump file cannot be written.
bool evaluate_world(const std::string& world_file, std::uint64_t first, std::uint64_t total,
                    Run& run) {
  const Options& options = run.options;
  const world::WorldModel world = world::load_world(world_file);
  render::RenderOptions camera = tools::simulated_camera_options();
  camera.realism.level = options.realism;
  tools::ViewSamplingOptions sampling;
  sampling.max_target_distance_m = options.max_target_distance_m;
  const tools::ViewSampler sampler(world, run.head, sampling);
  recognition::GroundTruthOptions truth_options;
  truth_options.max_distance_m = options.max_distance_m;
  // Views in blocks of one look each: the world's own, or with --looks K a randomized one per K
  // views, kept clear of the block's robot poses.
  const std::uint64_t per_look =
      options.views_per_look > 0 ? options.views_per_look : options.views;
  for (std::uint64_t block = 0; block * per_look < options.views; ++block) {
    const std::uint64_t begin = block * per_look;
    const std::uint64_t end = std::min(options.views, begin + per_look);
    std::vector<tools::ViewPose> views;
    for (std::uint64_t k = begin; k < end; ++k) views.push_back(sampler.sample(options.seed, k));
    std::optional<world::WorldModel> looks;
    if (options.views_per_look > 0) {
      worldgen::LookRandomization randomization;
      for (const tools::ViewPose& view : views) {
        randomization.keep_clear.push_back({view.world_T_ego.translation().head<2>(), 0.6});
      }
      looks = worldgen::randomize_looks(world, (options.seed << 32) + block, randomization);
    }
    const world::WorldModel& seen = looks ? *looks : world;
    const render::Renderer renderer(seen, camera);
    const tools::GroundTruthRenderer truth_renderer(seen, run.head, run.types);
    for (std::uint64_t k = begin; k < end; ++k) {
      const tools::ViewPose& view = views[k - begin];
      const tools::StereoRender frame =
          tools::render_view(renderer, run.head, view, (options.seed << 32) + k);
      std::vector<recognition::GroundTruthObject> truth = truth_renderer.objects(frame);
      if (run.learned) add_edge_ground_truth(seen, run.config.box_stereo.edge_types, frame, truth);
      recognition::mark_ground_truth_visible(truth, truth_options);
      const auto start = std::chrono::steady_clock::now();
      const recognition::FrameResult result =
          run.recognizer.recognize(frame.left.image, frame.right.image, view.joints);
      const double frame_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      const std::vector<recognition::PerceptMatch> matches = tools::tally_frame(
          truth, result, frame_ms, options.max_distance_m, options.match_distance_m, run.tally);
      run.noise.add(truth, result, matches);
      if (!options.dump_dir.empty() &&
          !dump_frame(first + k, seen, frame, view, truth, result, matches, run)) {
        return false;
      }
      if (!options.quiet) print_status(first + k + 1, total, run.tally);
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--images") return tools::run_image_evaluation(argc, argv);
  }
  try {
    const Options options = parse(argc, argv);
    const tools::RecognitionConfig config = tools::read_recognition_config(options.config_file);
    const bool learned = config.recognizer == "learned";
    if (learned && !options.model_files.empty()) {
      usage_error("--models needs the paper's recognizer; " + options.config_file +
                  " runs the learned detector");
    }
    const std::vector<std::string> model_files =
        options.model_files.empty() ? config.model_files : options.model_files;
    const head::HeadKinematics head =
        head::HeadKinematics::load(config.head_file, config.calibration_file);
    std::vector<std::unique_ptr<recognition::ClassRecognizer>> recognizers;
    if (!learned) recognizers = recognition::load_recognizers(model_files);
    std::vector<recognition::RecognizerFile> model_contents;  // for the --dump funnel
    for (const std::string& file : model_files) {
      model_contents.push_back(recognition::read_recognizer_file(file));
    }
    std::vector<std::string> types;
    std::unique_ptr<recognition::StereoRecognizer> recognizer;
    if (learned) {
      auto detector = std::make_shared<const recognition::LearnedDetector>(
          recognition::read_learned_detector_file(config.detector_file));
      types = detector->options().classes;
      for (const auto& rule : config.box_stereo.retype_by_height_m) {
        if (std::find(types.begin(), types.end(), rule.to) == types.end()) types.push_back(rule.to);
      }
      for (const std::string& type : config.box_stereo.edge_types) {
        types.push_back(world::edge_node_type(type, world::FaceEdge::kTop));
        types.push_back(world::edge_node_type(type, world::FaceEdge::kBottom));
      }
      recognizer = std::make_unique<recognition::LearnedStereoRecognizer>(std::move(detector),
                                                                          config.box_stereo, head);
    } else {
      for (const auto& r : recognizers) types.push_back(r->type());
      recognizer = std::make_unique<recognition::FrameRecognizer>(config.options, head,
                                                                  std::move(recognizers));
    }
    Run run{options, config, learned, head, *recognizer, types, model_contents};
    for (const std::string& type : types) run.tally.classes.emplace_back().type = type;
    if (!options.dump_dir.empty()) {
      std::error_code error;
      std::filesystem::create_directories(options.dump_dir, error);
      if (error) {
        std::cerr << "vsl-eval-recognition: cannot create " << options.dump_dir << ": "
                  << error.message() << "\n";
        return 1;
      }
    }
    const std::vector<std::string> world_files = split_list(options.world_file);
    for (std::size_t w = 0; w < world_files.size(); ++w) {
      if (!evaluate_world(world_files[w], w * options.views, world_files.size() * options.views,
                          run)) {
        return 1;
      }
    }
    const tools::EvaluationTally& tally = run.tally;
    const tools::FunnelTally& funnel = run.funnel;
    const auto& noise = run.noise;
    const auto& learned_stereo = run.learned_stereo;

    if (options.json_file != "-") {
      print_table(options, tally);
      noise.print(std::cout);
    }
    if (!options.dump_dir.empty()) {
      if (options.json_file != "-") {
        if (!learned) funnel.print(std::cout);
        print_learned_stereo(std::cout, learned_stereo);
      }
      const std::string path = (std::filesystem::path(options.dump_dir) / "funnel.txt").string();
      std::ofstream out(path);
      if (out) funnel.print(out);
      if (!out) {
        std::cerr << "vsl-eval-recognition: cannot write " << path << "\n";
        return 1;
      }
    }
    if (options.json_file == "-") {
      write_json(std::cout, options, tally);
    } else if (!options.json_file.empty()) {
      std::ofstream out(options.json_file);
      if (out) write_json(out, options, tally);
      if (!out) {
        std::cerr << "vsl-eval-recognition: cannot write " << options.json_file << "\n";
        return 1;
      }
    }
  } catch (const config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "vsl-eval-recognition: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
