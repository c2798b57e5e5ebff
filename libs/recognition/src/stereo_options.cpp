// The `stereo:` config section -> StereoMatchOptions, and the `recognition:` section's
// `segmentation:` and `stereo:` -> FrameRecognizerOptions. Every key is optional (defaults are the
// structs'); a wrong value or an unknown key is one line "file:line: key: what".
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/segmentation.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition {

namespace {

// One entry of door_classes: a door class's sizes.
StereoMatchOptions::DoorClass door_class_from(const config::Node& classes,
                                              const std::string& type) {
  const config::Node door = classes.at(type);
  door.expect_map();
  door.expect_keys({"typical_heights_m", "height_sigma_m", "min_width_m", "max_width_m",
                    "typical_width_m", "width_sigma_m"});
  StereoMatchOptions::DoorClass parsed;
  parsed.type = type;
  const config::Node heights = door.at("typical_heights_m");
  parsed.typical_heights_m = heights.as_doubles();
  const std::vector<double>& h = parsed.typical_heights_m;
  const bool finite = std::all_of(h.begin(), h.end(), [](double x) { return std::isfinite(x); });
  if (h.empty() || !finite || !(h.front() > 0.0) || !(h.back() <= 100.0) ||
      std::adjacent_find(h.begin(), h.end(), std::greater_equal<>()) != h.end()) {
    heights.fail("expected a list of heights in metres, ascending, in (0, 100]");
  }
  parsed.height_sigma_m = door.at("height_sigma_m").as_double_in(0.0, h.front());
  parsed.min_width_m = door.at("min_width_m").as_double_in(0.0, 100.0);
  parsed.max_width_m = door.at("max_width_m").as_double_in(0.0, 100.0);
  if (!(parsed.max_width_m > parsed.min_width_m)) {
    door.at("max_width_m").fail("must exceed min_width_m");
  }
  if (const auto v = door.find("typical_width_m")) {
    parsed.typical_width_m = v->as_double_in(0.0, 100.0);
    if (parsed.typical_width_m > 0.0 && (parsed.typical_width_m < parsed.min_width_m ||
                                         parsed.typical_width_m > parsed.max_width_m)) {
      v->fail("must be 0 (off) or within min_width_m .. max_width_m");
    }
  }
  if (const auto v = door.find("width_sigma_m")) {
    parsed.width_sigma_m = v->as_double_in(0.0, 100.0);
  }
  // The width prior of a door whose side neither image shows (partly_seen_door.hpp) needs a
  // spread.
  if (parsed.typical_width_m > 0.0 && !(parsed.width_sigma_m > 0.0)) {
    door.at("typical_width_m").fail("needs width_sigma_m > 0 (the width prior's spread)");
  }
  return parsed;
}

// major_extent_range_m, height_range_m: per type, [min_m, max_m].
void read_ranges(const config::Node& section, StereoMatchOptions& out) {
  for (const char* key : {"major_extent_range_m", "height_range_m"}) {
    const auto ranges = section.find(key);
    if (!ranges) continue;
    auto& list =
        std::string(key) == "height_range_m" ? out.height_range_m : out.major_extent_range_m;
    ranges->expect_map();
    for (const std::string& type : ranges->keys()) {
      const config::Node range = ranges->at(type);
      const auto bounds = range.as_array<2>();
      if (!(bounds[0] >= 0.0 && bounds[0] < bounds[1] && bounds[1] <= 1000.0)) {
        range.fail("expected [min_m, max_m] with 0 <= min_m < max_m <= 1000");
      }
      list.push_back({type, bounds[0], bounds[1]});
    }
  }
}

// cut_bars: per bar type, its typical length and that length's sigma.
void read_cut_bars(const config::Node& section, StereoMatchOptions& out) {
  if (const auto classes = section.find("cut_bars")) {
    classes->expect_map();
    for (const std::string& type : classes->keys()) {
      const config::Node bar = classes->at(type);
      bar.expect_map();
      bar.expect_keys({"typical_length_m", "length_sigma_m"});
      if (std::find(out.bar_types.begin(), out.bar_types.end(), type) == out.bar_types.end()) {
        bar.fail("'" + type + "' is not one of bar_types (cut bars are placed from their span)");
      }
      StereoMatchOptions::CutBar parsed;
      parsed.type = type;
      parsed.typical_length_m = bar.at("typical_length_m").as_double_in(1e-3, 100.0);
      parsed.length_sigma_m = bar.at("length_sigma_m").as_double_in(0.0, parsed.typical_length_m);
      out.cut_bars.push_back(parsed);
    }
  }
}

// The section's plain numbers: key, member, allowed range.
// shared_noise: {type: {floor_m, shared_disparity_px}}, both optional (0).
void read_shared_noise(const config::Node& section, StereoMatchOptions& out) {
  const auto noise = section.find("shared_noise");
  if (!noise) return;
  noise->expect_map();
  for (const std::string& type : noise->keys()) {
    const config::Node model = noise->at(type);
    model.expect_map();
    model.expect_keys({"floor_m", "shared_disparity_px"});
    StereoMatchOptions::SharedNoise n{type, 0.0, 0.0};
    // A decimetre shared by every frame is no percept; five pixels of disparity bias neither.
    if (const auto v = model.find("floor_m")) n.floor_m = v->as_double_in(0.0, 0.1);
    if (const auto v = model.find("shared_disparity_px")) {
      n.shared_disparity_px = v->as_double_in(0.0, 5.0);
    }
    out.shared_noise.push_back(n);
  }
}

struct NumberKey {
  const char* key;
  double StereoMatchOptions::*member;
  double lo, hi;
};
constexpr NumberKey kNumberKeys[] = {
    {"max_epipolar_distance_px", &StereoMatchOptions::max_epipolar_distance_px, 0.01, 1000.0},
    {"min_depth_m", &StereoMatchOptions::min_depth_m, 0.01, 1000.0},
    {"max_depth_m", &StereoMatchOptions::max_depth_m, 0.01, 1000.0},
    {"max_area_ratio", &StereoMatchOptions::max_area_ratio, 1.001, 1000.0},
    // Undirected axes differ by at most pi / 2.
    {"max_orientation_difference_rad", &StereoMatchOptions::max_orientation_difference_rad, 1e-3,
     1.5708},
    {"min_elongation_for_orientation", &StereoMatchOptions::min_elongation_for_orientation, 1.0,
     1000.0},
    {"min_side_correlation", &StereoMatchOptions::min_side_correlation, 0.0, 1.0},
    {"min_single_view_correlation", &StereoMatchOptions::min_single_view_correlation, 0.0, 1.0},
    // Correlations differ by at most 2.
    {"min_peak_margin", &StereoMatchOptions::min_peak_margin, 0.0, 2.0},
    {"single_view_min_separation_m", &StereoMatchOptions::single_view_min_separation_m, 0.0, 10.0},
    {"max_bar_height_spread", &StereoMatchOptions::max_bar_height_spread, 0.0, 1.0},
    // Below pi/2: sin() still grows.
    {"max_side_tilt_rad", &StereoMatchOptions::max_side_tilt_rad, 0.0, 1.5},
    {"pixel_sigma_px", &StereoMatchOptions::pixel_sigma_px, 1e-3, 100.0},
};

}  // namespace

StereoMatchOptions stereo_match_options_from(const config::Node& section) {
  StereoMatchOptions out;
  section.expect_map();
  section.expect_keys({"max_epipolar_distance_px",
                       "min_depth_m",
                       "max_depth_m",
                       "max_area_ratio",
                       "max_orientation_difference_rad",
                       "min_elongation_for_orientation",
                       "pixel_sigma_px",
                       "reference_depth_offset_m",
                       "major_extent_range_m",
                       "height_range_m",
                       "max_side_tilt_rad",
                       "bar_types",
                       "min_side_correlation",
                       "min_single_view_correlation",
                       "min_peak_margin",
                       "single_view_min_separation_m",
                       "max_bar_height_spread",
                       "door_classes",
                       "cut_bars",
                       "shared_noise"});
  for (const NumberKey& number : kNumberKeys) {
    if (const auto v = section.find(number.key)) {
      out.*number.member = v->as_double_in(number.lo, number.hi);
    }
  }
  if (out.max_depth_m <= out.min_depth_m) {
    (section.has("max_depth_m") ? section.at("max_depth_m") : section.at("min_depth_m"))
        .fail("max_depth_m (" + std::to_string(out.max_depth_m) + ") must exceed min_depth_m (" +
              std::to_string(out.min_depth_m) + ")");
  }
  // The single view sweeps with the side correlation's correlator and images.
  if (section.has("min_single_view_correlation") && out.min_single_view_correlation > 0.0 &&
      !(out.min_side_correlation > 0.0)) {
    section.at("min_single_view_correlation")
        .fail("needs min_side_correlation > 0 (the side correlation it sweeps with)");
  }
  if (const auto offsets = section.find("reference_depth_offset_m")) {
    offsets->expect_map();
    for (const std::string& type : offsets->keys()) {
      // Half the depth of any object a robot recognizes: a metre either way is far beyond that.
      out.reference_depth_offset_m.emplace_back(type, offsets->at(type).as_double_in(-1.0, 1.0));
    }
  }
  if (const auto types = section.find("bar_types")) {
    if (!types->is_sequence()) types->fail("expected a list of object types, e.g. [handle]");
    for (std::size_t i = 0; i < types->size(); ++i) {
      out.bar_types.push_back((*types)[i].as_string());
    }
  }
  read_ranges(section, out);
  if (const auto classes = section.find("door_classes")) {
    classes->expect_map();
    for (const std::string& type : classes->keys()) {
      out.door_classes.push_back(door_class_from(*classes, type));
    }
  }
  read_cut_bars(section, out);
  read_shared_noise(section, out);
  return out;
}

FrameRecognizerOptions frame_recognizer_options_from(const config::Node& recognition_section) {
  FrameRecognizerOptions out;
  recognition_section.expect_map();
  if (const auto s = recognition_section.find("segmentation")) {
    out.segmentation = segmentation_options_from(*s);
  }
  if (const auto s = recognition_section.find("stereo")) out.stereo = stereo_match_options_from(*s);
  return out;
}

}  // namespace vsl::recognition
