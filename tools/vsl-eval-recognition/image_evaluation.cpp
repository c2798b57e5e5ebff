#include "image_evaluation.hpp"

#include <unistd.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "box_evaluation.hpp"
#include "json_writer.hpp"
#include "vsl/config/node.hpp"

namespace vsl::tools {
namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    R"(usage: vsl-eval-recognition --images DIR --yolo-labels DIR [options]

Evaluates the learned door and handle detector (docs/recognition.md) on labelled photographs: per
class the precision and recall at the detector's confidence thresholds (IoU >= 0.5, detections
matched greedily by confidence as in PASCAL VOC), AP50, and the precision reached at recall 0.3 and
0.5.
  --images DIR          the images (.jpg, .jpeg, .png, .bmp)
  --yolo-labels DIR     DIR/NAME.txt per image NAME.ext: lines "class cx cy w h", relative to the
                        image size; an image without a file has no objects
options:
  --class-map MAP       label class -> detector class, e.g. 0=door,1=handle,2=door,3=door
                        (the default: DoorDetect's and vsl-make-dataset's classes); label classes
                        not named are ignored
  --detector FILE       the detector's description (default
                        config/recognition/detector/door_handle.yaml)
  --min-confidence P    one threshold for every class instead of the detector's
  --json FILE           the figures and each class's precision-recall curve as JSON (- for
                        standard output, then no table)
  --grid FILE           a picture grid (.jpg or .png): the first images with their labels (white)
                        and the detections at the thresholds (door blue, handle red)
  --grid-images N       images in the grid (default 12)
  -q, --quiet           no status line
exit codes: 0 ok, 1 an output file could not be written, 2 bad usage or input file
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-eval-recognition: " << what << " (see vsl-eval-recognition --help)\n";
  std::exit(2);
}

struct Options {
  std::string images_dir;
  std::string labels_dir;
  std::string class_map = "0=door,1=handle,2=door,3=door";
  std::string detector_file = "config/recognition/detector/door_handle.yaml";
  double min_confidence = -1.0;
  std::string json_file;
  std::string grid_file;
  int grid_images = 12;
  bool quiet = false;
};

Options parse(int argc, char** argv) {
  Options o;
  // --help anywhere, also after an option that takes a value ("--images --help", as the main
  // usage says), prints this mode's usage.
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    }
  }
  auto value_of = [&](int& i, const std::string& arg) -> std::string {
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--images") {
      o.images_dir = value_of(i, arg);
    } else if (arg == "--yolo-labels") {
      o.labels_dir = value_of(i, arg);
    } else if (arg == "--class-map") {
      o.class_map = value_of(i, arg);
    } else if (arg == "--detector") {
      o.detector_file = value_of(i, arg);
    } else if (arg == "--min-confidence") {
      const std::string text = value_of(i, arg);
      char* end = nullptr;
      o.min_confidence = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !(o.min_confidence >= 0.0 && o.min_confidence <= 1.0)) {
        usage_error("--min-confidence wants a number in [0, 1], got '" + text + "'");
      }
    } else if (arg == "--json") {
      o.json_file = value_of(i, arg);
    } else if (arg == "--grid") {
      o.grid_file = value_of(i, arg);
    } else if (arg == "--grid-images") {
      const std::string text = value_of(i, arg);
      char* end = nullptr;
      const long n = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || n < 1 || n > 1000) {
        usage_error("--grid-images wants 1..1000, got '" + text + "'");
      }
      o.grid_images = static_cast<int>(n);
    } else if (arg == "-q" || arg == "--quiet") {
      o.quiet = true;
    } else {
      usage_error("unknown argument '" + arg + "'");
    }
  }
  if (o.images_dir.empty() || o.labels_dir.empty()) {
    usage_error("--images and --yolo-labels are both required");
  }
  return o;
}

// "0=door,1=handle" -> {0: index of door, 1: index of handle} among the detector's classes.
std::map<int, int> parse_class_map(const std::string& text,
                                   const std::vector<std::string>& classes) {
  std::map<int, int> out;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    const std::size_t eq = item.find('=');
    const std::string id = item.substr(0, eq);
    const std::string name = eq == std::string::npos ? "" : item.substr(eq + 1);
    const auto at = std::find(classes.begin(), classes.end(), name);
    if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos || id.size() > 6 ||
        at == classes.end()) {
      usage_error("--class-map: '" + item + "' is not ID=CLASS with CLASS one of the detector's");
    }
    out[std::stoi(id)] = static_cast<int>(at - classes.begin());
  }
  if (out.empty()) usage_error("--class-map is empty");
  return out;
}

struct LabelledImage {
  std::string path;
  std::vector<LabelledBox> boxes;
};

std::vector<LabelledBox> read_yolo_labels(const fs::path& file, const std::map<int, int>& class_map,
                                          int width, int height) {
  std::vector<LabelledBox> boxes;
  std::ifstream in(file);
  if (!in && fs::exists(file)) usage_error(file.string() + ": cannot be read");
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::istringstream fields(line);
    int id = 0;
    double cx = 0.0, cy = 0.0, w = 0.0, h = 0.0;
    std::string extra;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!(fields >> id >> cx >> cy >> w >> h) || (fields >> extra) ||
        !(cx >= 0.0 && cx <= 1.0 && cy >= 0.0 && cy <= 1.0 && w > 0.0 && w <= 1.0 && h > 0.0 &&
          h <= 1.0)) {
      std::cerr << "vsl-eval-recognition: " << file.string() << ":" << number
                << ": expected 'class cx cy w h' with cx, cy, w, h in [0, 1]\n";
      std::exit(2);
    }
    const auto mapped = class_map.find(id);
    if (mapped == class_map.end()) continue;
    LabelledBox box;
    box.class_index = mapped->second;
    box.min_px = Eigen::Vector2d((cx - w / 2) * width, (cy - h / 2) * height);
    box.max_px = Eigen::Vector2d((cx + w / 2) * width, (cy + h / 2) * height);
    boxes.push_back(box);
  }
  return boxes;
}

cv::Scalar class_colour(int class_index) {
  static const cv::Scalar colours[] = {{255, 160, 0}, {0, 0, 255}, {0, 200, 0}, {255, 0, 255}};
  return colours[class_index % 4];
}

cv::Mat grid_tile(const cv::Mat& image, const std::vector<LabelledBox>& labels,
                  const std::vector<recognition::BoxDetection>& shown, int tile_width) {
  const double scale = static_cast<double>(tile_width) / image.cols;
  cv::Mat tile;
  cv::resize(image, tile, cv::Size(tile_width, static_cast<int>(std::lround(image.rows * scale))),
             0, 0, cv::INTER_AREA);
  const auto point = [scale](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::lround(p.x() * scale)),
                     static_cast<int>(std::lround(p.y() * scale)));
  };
  for (const LabelledBox& box : labels) {
    cv::rectangle(tile, point(box.min_px), point(box.max_px), cv::Scalar(255, 255, 255), 1);
  }
  for (const recognition::BoxDetection& d : shown) {
    cv::rectangle(tile, point(d.min_px), point(d.max_px), class_colour(d.class_index), 2);
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", d.confidence);
    cv::putText(tile, text, point(d.min_px) + cv::Point(2, 12), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                class_colour(d.class_index), 1, cv::LINE_AA);
  }
  return tile;
}

// Tiles of equal width in rows of four, each row as tall as its tallest tile.
cv::Mat compose_grid(const std::vector<cv::Mat>& tiles, int tile_width) {
  constexpr int kColumns = 4;
  std::vector<cv::Mat> rows;
  for (std::size_t start = 0; start < tiles.size(); start += kColumns) {
    int height = 0;
    for (std::size_t k = start; k < std::min(tiles.size(), start + kColumns); ++k) {
      height = std::max(height, tiles[k].rows);
    }
    cv::Mat row(height, tile_width * kColumns, CV_8UC3, cv::Scalar::all(40));
    for (std::size_t k = start; k < std::min(tiles.size(), start + kColumns); ++k) {
      tiles[k].copyTo(
          row(cv::Rect(static_cast<int>(k - start) * tile_width, 0, tiles[k].cols, tiles[k].rows)));
    }
    rows.push_back(row);
  }
  cv::Mat grid;
  cv::vconcat(rows, grid);
  return grid;
}

// The greatest precision among the curve's points at recall >= `recall` (0 when never reached).
double precision_at_recall(const ClassCurve& curve, double recall) {
  double best = 0.0;
  for (const CurvePoint& p : curve.points) {
    if (p.recall >= recall) best = std::max(best, p.precision);
  }
  return best;
}

}  // namespace

int run_image_evaluation(int argc, char** argv) {
  const Options options = parse(argc, argv);
  recognition::LearnedDetectorOptions detector_options;
  try {
    detector_options = recognition::read_learned_detector_file(options.detector_file);
  } catch (const config::Error& e) {
    usage_error(e.what());
  }
  const std::map<int, int> class_map = parse_class_map(options.class_map, detector_options.classes);
  std::vector<std::string> images;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(options.images_dir, error)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".jpg" || ext == ".jpeg" || ext == ".png" || ext == ".bmp") {
      images.push_back(entry.path().string());
    }
  }
  if (error) usage_error(options.images_dir + ": " + error.message());
  if (!fs::is_directory(options.labels_dir)) usage_error(options.labels_dir + ": not a folder");
  if (images.empty()) usage_error(options.images_dir + ": no images");
  std::sort(images.begin(), images.end());

  std::unique_ptr<recognition::LearnedDetector> detector;
  try {
    detector = std::make_unique<recognition::LearnedDetector>(detector_options);
  } catch (const config::Error& e) {
    usage_error(e.what());
  }
  const std::vector<double> thresholds =
      options.min_confidence >= 0.0
          ? std::vector<double>(detector_options.classes.size(), options.min_confidence)
          : detector_options.min_confidence;
  // Every detection down to a low confidence, for the whole curve.
  constexpr double kCurveFloor = 0.01;
  std::vector<std::vector<recognition::BoxDetection>> detections;
  std::vector<std::vector<LabelledBox>> labels;
  std::vector<double> milliseconds;
  std::vector<cv::Mat> tiles;
  constexpr int kTileWidth = 320;
  const bool tty = isatty(2) != 0;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const cv::Mat image = cv::imread(images[i], cv::IMREAD_COLOR);
    if (image.empty()) usage_error(images[i] + ": not a readable image");
    labels.push_back(
        read_yolo_labels(fs::path(options.labels_dir) / fs::path(images[i]).stem().concat(".txt"),
                         class_map, image.cols, image.rows));
    const auto start = std::chrono::steady_clock::now();
    detections.push_back(detector->detect(image, kCurveFloor));
    milliseconds.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    if (!options.grid_file.empty() && static_cast<int>(tiles.size()) < options.grid_images) {
      std::vector<recognition::BoxDetection> shown;
      for (const auto& d : detections.back()) {
        if (d.confidence >= thresholds[static_cast<std::size_t>(d.class_index)]) shown.push_back(d);
      }
      tiles.push_back(grid_tile(image, labels.back(), shown, kTileWidth));
    }
    if (!options.quiet && tty) {
      std::cerr << "\r" << i + 1 << "/" << images.size() << " images" << std::flush;
    }
  }
  if (!options.quiet && tty) std::cerr << "\n";
  std::sort(milliseconds.begin(), milliseconds.end());
  const double median_ms = milliseconds[milliseconds.size() / 2];

  std::vector<ClassCurve> curves;
  for (std::size_t c = 0; c < detector_options.classes.size(); ++c) {
    curves.push_back(evaluate_class(detections, labels, static_cast<int>(c)));
  }
  if (options.json_file != "-") {
    std::printf(
        "%zu images, detector %s, median %.1f ms per image (detection, OpenCV threads %d)\n",
        images.size(), options.detector_file.c_str(), median_ms, cv::getNumThreads());
    std::printf("%-8s %7s %6s %10s %9s %7s %9s %9s\n", "class", "objects", "AP50", "threshold",
                "precision", "recall", "P@R=0.3", "P@R=0.5");
    for (std::size_t c = 0; c < curves.size(); ++c) {
      const CurvePoint at = at_confidence(curves[c], thresholds[c]);
      std::printf("%-8s %7d %6.3f %10.3f %9.3f %7.3f %9.3f %9.3f\n",
                  detector_options.classes[c].c_str(), curves[c].objects, curves[c].ap50,
                  thresholds[c], at.precision, at.recall, precision_at_recall(curves[c], 0.3),
                  precision_at_recall(curves[c], 0.5));
    }
  }
  if (!options.json_file.empty()) {
    std::ofstream file;
    if (options.json_file != "-") {
      file.open(options.json_file);
      if (!file) {
        std::cerr << "vsl-eval-recognition: " << options.json_file << ": cannot be written\n";
        return 1;
      }
    }
    std::ostream& out = options.json_file == "-" ? std::cout : file;
    JsonWriter json(out);
    json.begin_object().key("images").number(static_cast<double>(images.size()));
    json.key("detector").string(options.detector_file);
    json.key("median_ms_per_image").number(median_ms);
    json.key("classes").begin_array();
    for (std::size_t c = 0; c < curves.size(); ++c) {
      const CurvePoint at = at_confidence(curves[c], thresholds[c]);
      json.begin_object().key("type").string(detector_options.classes[c]);
      json.key("objects").number(curves[c].objects).key("ap50").number(curves[c].ap50);
      json.key("threshold").number(thresholds[c]).key("precision").number(at.precision);
      json.key("recall").number(at.recall);
      json.key("precision_at_recall_0.3").number(precision_at_recall(curves[c], 0.3));
      json.key("precision_at_recall_0.5").number(precision_at_recall(curves[c], 0.5));
      // [confidence, precision, recall] per detection, by decreasing confidence.
      json.key("curve").begin_array();
      for (const CurvePoint& p : curves[c].points)
        json.numbers({p.confidence, p.precision, p.recall});
      json.end_array().end_object();
    }
    json.end_array().end_object();
    out << "\n";
    if (!out) {
      std::cerr << "vsl-eval-recognition: " << options.json_file << ": cannot be written\n";
      return 1;
    }
  }
  if (!options.grid_file.empty() &&
      !cv::imwrite(options.grid_file, compose_grid(tiles, kTileWidth))) {
    std::cerr << "vsl-eval-recognition: " << options.grid_file << ": cannot be written\n";
    return 1;
  }
  return 0;
}

}  // namespace vsl::tools
