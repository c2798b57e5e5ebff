// Labels from the simulator's id buffer for training and evaluation (labelling.hpp).
#include "vsl/recognition/labelling.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace vsl::recognition {
namespace {

void check_id_buffer(const cv::Mat& object_ids, const char* who) {
  if (object_ids.type() != CV_32SC1 || object_ids.empty()) {
    throw std::invalid_argument(std::string(who) + ": the id buffer must be a non-empty CV_32S");
  }
}

void check_blob_inside(const Blob& blob, const cv::Mat& object_ids, const char* who) {
  for (const PixelRun& run : blob.runs) {
    if (run.v < 0 || run.v >= object_ids.rows || run.u_begin < 0 || run.u_end > object_ids.cols ||
        run.u_begin >= run.u_end) {
      throw std::invalid_argument(std::string(who) + ": the blob leaves the " +
                                  std::to_string(object_ids.cols) + "x" +
                                  std::to_string(object_ids.rows) + " id buffer");
    }
  }
}

}  // namespace

std::vector<int> object_pixel_counts(const cv::Mat& object_ids, std::size_t object_count) {
  check_id_buffer(object_ids, "object_pixel_counts");
  std::vector<int> counts(object_count, 0);
  for (int v = 0; v < object_ids.rows; ++v) {
    const std::int32_t* row = object_ids.ptr<std::int32_t>(v);
    for (int u = 0; u < object_ids.cols; ++u) {
      const std::int32_t id = row[u];
      if (id < 0) {
        if (id != -1) throw std::invalid_argument("object_pixel_counts: id " + std::to_string(id));
        continue;
      }
      if (static_cast<std::size_t>(id) >= object_count) {
        throw std::invalid_argument("object_pixel_counts: id " + std::to_string(id) +
                                    " is not below the object count " +
                                    std::to_string(object_count));
      }
      ++counts[static_cast<std::size_t>(id)];
    }
  }
  return counts;
}

BlobLabel label_blob(const Blob& blob, const cv::Mat& object_ids, std::span<const int> visible_px) {
  check_id_buffer(object_ids, "label_blob");
  check_blob_inside(blob, object_ids, "label_blob");
  std::unordered_map<std::int32_t, int> votes;
  int total = 0;
  for (const PixelRun& run : blob.runs) {
    const std::int32_t* row = object_ids.ptr<std::int32_t>(run.v);
    for (int u = run.u_begin; u < run.u_end; ++u) ++votes[row[u]];
    total += run.u_end - run.u_begin;
  }
  BlobLabel label;
  if (total == 0) return label;
  // The majority id; ties go to the smaller id so that the label never depends on hash order.
  std::int32_t best = -1;
  int best_votes = -1;
  for (const auto& [id, count] : votes) {
    if (count > best_votes || (count == best_votes && id < best)) {
      best = id;
      best_votes = count;
    }
  }
  label.object_index = best;
  label.purity = static_cast<double>(best_votes) / total;
  if (best >= 0) {
    const std::size_t index = static_cast<std::size_t>(best);
    if (index >= visible_px.size() || visible_px[index] <= 0) {
      throw std::invalid_argument("label_blob: no visible pixel count for object " +
                                  std::to_string(best));
    }
    label.coverage = std::min(1.0, static_cast<double>(best_votes) / visible_px[index]);
  }
  return label;
}

double fraction_on_type(const Blob& blob, const cv::Mat& object_ids,
                        std::span<const std::string> object_types, const std::string& type) {
  check_id_buffer(object_ids, "fraction_on_type");
  check_blob_inside(blob, object_ids, "fraction_on_type");
  long on_type = 0;
  long total = 0;
  for (const PixelRun& run : blob.runs) {
    const std::int32_t* row = object_ids.ptr<std::int32_t>(run.v);
    for (int u = run.u_begin; u < run.u_end; ++u) {
      const std::int32_t id = row[u];
      if (id >= 0 && static_cast<std::size_t>(id) < object_types.size() &&
          object_types[static_cast<std::size_t>(id)] == type) {
        ++on_type;
      }
    }
    total += run.u_end - run.u_begin;
  }
  return total == 0 ? 0.0 : static_cast<double>(on_type) / static_cast<double>(total);
}

SampleRole sample_role(const BlobLabel& label, double fraction_on_class, bool object_is_of_class,
                       const SampleLabelOptions& options) {
  if (object_is_of_class && label.object_index >= 0 && label.purity >= options.min_purity &&
      label.coverage >= options.min_coverage) {
    return SampleRole::positive;
  }
  if (fraction_on_class < options.max_negative_fraction_on_class) return SampleRole::negative;
  return SampleRole::unused;
}

SampleRole sample_role(const Blob& blob, const cv::Mat& object_ids, std::span<const int> visible_px,
                       std::span<const std::string> object_types, const std::string& type,
                       const SampleLabelOptions& options) {
  const BlobLabel label = label_blob(blob, object_ids, visible_px);
  const bool of_class = label.object_index >= 0 &&
                        static_cast<std::size_t>(label.object_index) < object_types.size() &&
                        object_types[static_cast<std::size_t>(label.object_index)] == type;
  return sample_role(label, fraction_on_type(blob, object_ids, object_types, type), of_class,
                     options);
}

bool whole_in_both_images(const GroundTruthObject& object) {
  return object.left_unoccluded_px > 0 && object.right_unoccluded_px > 0 &&
         object.left_in_image_px >= object.left_unoccluded_px &&
         object.right_in_image_px >= object.right_unoccluded_px;
}

double visible_fraction(int visible_px, int unoccluded_px) {
  if (unoccluded_px <= 0) return 0.0;
  return std::min(1.0, static_cast<double>(visible_px) / unoccluded_px);
}

void mark_ground_truth_visible(std::vector<GroundTruthObject>& objects,
                               const GroundTruthOptions& options) {
  for (GroundTruthObject& object : objects) {
    object.visible = object.distance_m <= options.max_distance_m &&
                     visible_fraction(object.left_visible_px, object.left_unoccluded_px) >=
                         options.min_visible_fraction &&
                     visible_fraction(object.right_visible_px, object.right_unoccluded_px) >=
                         options.min_visible_fraction;
  }
}

std::vector<PerceptMatch> match_percepts(std::span<const PerceptToMatch> percepts,
                                         std::span<const GroundTruthObject> ground_truth,
                                         double max_error_m) {
  std::vector<std::size_t> order(percepts.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return percepts[a].confidence > percepts[b].confidence;
  });
  std::vector<bool> taken(ground_truth.size(), false);
  std::vector<PerceptMatch> matches(percepts.size());
  for (const std::size_t p : order) {
    double best_m = std::numeric_limits<double>::infinity();
    int best = -1;
    for (std::size_t g = 0; g < ground_truth.size(); ++g) {
      const GroundTruthObject& object = ground_truth[g];
      if (taken[g] || !object.visible || object.type != percepts[p].type) continue;
      const double error_m = (object.ego_position_m - percepts[p].ego_position_m).norm();
      if (error_m <= max_error_m && error_m < best_m) {
        best_m = error_m;
        best = static_cast<int>(g);
      }
    }
    if (best >= 0) {
      taken[static_cast<std::size_t>(best)] = true;
      matches[p] = PerceptMatch{best, best_m};
    }
  }
  return matches;
}

}  // namespace vsl::recognition
