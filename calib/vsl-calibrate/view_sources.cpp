#include "view_sources.hpp"

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "messages.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace vsl::calibration {
namespace {

namespace fs = std::filesystem;

double mean_motion_px(const Corners& a, const Corners& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += cv::norm(a[i] - b[i]);
  return sum / static_cast<double>(a.size());
}

}  // namespace

std::vector<std::pair<std::string, std::string>> find_image_pairs(const std::string& directory) {
  std::error_code error;
  if (!fs::is_directory(directory, error)) {
    throw std::runtime_error("no directory " + directory);
  }
  std::vector<std::pair<std::string, std::string>> out;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("left", 0) != 0 || !entry.is_regular_file()) continue;
    const fs::path right = entry.path().parent_path() / ("right" + name.substr(4));
    if (fs::is_regular_file(right)) out.emplace_back(entry.path().string(), right.string());
  }
  if (out.empty()) {
    throw std::runtime_error("no image pairs left<name> / right<name> in " + directory);
  }
  std::sort(out.begin(), out.end());
  return out;
}

StereoView detect_view(const std::string& name, const cv::Mat& left, const cv::Mat& right,
                       const BoardSpec& board) {
  StereoView view;
  view.name = name;
  const std::optional<Corners> l = detect_corners(left, board);
  if (!l) return view;
  std::optional<Corners> r = detect_corners(right, board);
  if (!r) return view;
  align_corner_order(*l, *r);
  view.left = *l;
  view.right = *r;
  return view;
}

FileViews views_from_files(const std::string& directory, const BoardSpec& board) {
  FileViews out;
  for (const auto& [left_path, right_path] : find_image_pairs(directory)) {
    const cv::Mat left = cv::imread(left_path, cv::IMREAD_GRAYSCALE);
    const cv::Mat right = cv::imread(right_path, cv::IMREAD_GRAYSCALE);
    if (left.empty()) throw std::runtime_error("cannot read image " + left_path);
    if (right.empty()) throw std::runtime_error("cannot read image " + right_path);
    if (out.image_size.empty()) out.image_size = left.size();
    if (left.size() != out.image_size || right.size() != out.image_size) {
      throw std::runtime_error("images of different sizes: " + left_path + " and " + right_path +
                               " (all must be " + std::to_string(out.image_size.width) + "x" +
                               std::to_string(out.image_size.height) + ")");
    }
    out.views.push_back(detect_view(fs::path(left_path).filename().string(), left, right, board));
  }
  return out;
}

LiveViews views_from_channel(const BoardSpec& board, const LiveOptions& options,
                             const std::function<void(const std::string&)>& progress) {
  runtime::LcmBus bus(options.lcm_url, runtime::Logger("vsl-calibrate", runtime::Level::kWarn));
  LiveViews out;
  std::optional<vsl::stereo_frame_t> newest;
  // A short queue: detection is slower than the frame rate, only the newest frame matters.
  runtime::subscribe<vsl::stereo_frame_t>(
      bus, options.channel, [&](const vsl::stereo_frame_t& frame, std::int64_t) { newest = frame; },
      2);
  using Clock = std::chrono::steady_clock;
  const Clock::time_point end =
      Clock::now() + std::chrono::milliseconds(static_cast<long>(options.timeout_s * 1000.0));
  while (static_cast<int>(out.views.size()) < options.views && Clock::now() < end) {
    newest.reset();
    const runtime::HandleResult handled = bus.handle(std::chrono::milliseconds(100));
    if (handled == runtime::HandleResult::kError) {
      throw std::runtime_error("cannot receive from " + options.lcm_url);
    }
    if (handled == runtime::HandleResult::kEndOfLog) break;  // a replayed log is over
    if (!newest) continue;
    ++out.frames_seen;
    std::string error;
    const cv::Mat left = stereo_capture::image_from_message(newest->left, error);
    const cv::Mat right = stereo_capture::image_from_message(newest->right, error);
    if (left.empty() || right.empty() || left.size() != right.size()) continue;
    if (out.image_size.empty()) out.image_size = left.size();
    if (left.size() != out.image_size) continue;
    StereoView view = detect_view("frame" + std::to_string(newest->frame_id), left, right, board);
    if (view.left.empty()) continue;
    if (!out.views.empty() && options.min_motion_px > 0.0 &&
        mean_motion_px(view.left, out.views.back().left) < options.min_motion_px) {
      continue;  // the board has not moved: the same view again adds nothing
    }
    if (!options.save_directory.empty()) {
      fs::create_directories(options.save_directory);
      const std::string suffix = "_" + std::to_string(newest->frame_id) + ".png";
      cv::imwrite((fs::path(options.save_directory) / ("left" + suffix)).string(), left);
      cv::imwrite((fs::path(options.save_directory) / ("right" + suffix)).string(), right);
    }
    out.views.push_back(std::move(view));
    progress("view " + std::to_string(out.views.size()) + " of " + std::to_string(options.views) +
             ": " + out.views.back().name);
  }
  return out;
}

}  // namespace vsl::calibration
