// The `box_stereo:` section of a recognition config (learned_stereo_recognizer.hpp).
#include <algorithm>
#include <string>

#include "vsl/config/node.hpp"
#include "vsl/recognition/learned_stereo_recognizer.hpp"

namespace vsl::recognition {
namespace {

// {type: [min_m, max_m], ...} replacing the defaults.
std::vector<BoxStereoOptions::Range> ranges_from(const config::Node& ranges) {
  ranges.expect_map();
  std::vector<BoxStereoOptions::Range> out;
  for (const std::string& type : ranges.keys()) {
    const config::Node range = ranges.at(type);
    const auto bounds = range.as_array<2>();
    if (!(bounds[0] >= 0.0 && bounds[0] < bounds[1] && bounds[1] <= 1000.0)) {
      range.fail("expected [min_m, max_m] with 0 <= min_m < max_m <= 1000");
    }
    out.push_back({type, bounds[0], bounds[1]});
  }
  return out;
}

// [type, ...]
std::vector<std::string> types_from(const config::Node& types) {
  if (!types.is_sequence()) types.fail("expected a list of object types, e.g. [door]");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < types.size(); ++i) out.push_back(types[i].as_string());
  return out;
}

// {type: {reference_px, disparity_px, floor_m, shared_disparity_px, shared_floor_m}, ...}
// replacing the defaults; shared_disparity_px optional (0), shared_floor_m optional (all of
// floor_m) and at most floor_m.
std::vector<BoxStereoOptions::Noise> noise_models_from(const config::Node& noise) {
  noise.expect_map();
  std::vector<BoxStereoOptions::Noise> out;
  for (const std::string& type : noise.keys()) {
    const config::Node model = noise.at(type);
    model.expect_keys(
        {"reference_px", "disparity_px", "floor_m", "shared_disparity_px", "shared_floor_m"});
    const auto shared = model.find("shared_disparity_px");
    out.push_back({type, model.at("reference_px").as_double_in(0.0, 100.0),
                   model.at("disparity_px").as_double_in(0.0, 100.0),
                   model.at("floor_m").as_double_in(0.0, 10.0),
                   shared ? shared->as_double_in(0.0, 100.0) : 0.0, std::nullopt});
    BoxStereoOptions::Noise& n = out.back();
    if (const auto shared_floor = model.find("shared_floor_m")) {
      n.shared_floor_m = shared_floor->as_double_in(0.0, n.floor_m);
    }
    if (n.reference_px + n.disparity_px <= 0.0 && n.floor_m <= 0.0) {
      model.fail("a noise model of all zeros gives no covariance");
    }
  }
  return out;
}

// [type, ...], each one of the rectangle types, which must be fitted.
std::vector<std::string> edge_types_from(const config::Node& types,
                                         const BoxStereoOptions& options) {
  std::vector<std::string> out = types_from(types);
  for (const std::string& type : out) {
    if (std::find(options.rectangle_types.begin(), options.rectangle_types.end(), type) ==
        options.rectangle_types.end()) {
      types.fail("'" + type + "' is not one of rectangle_types");
    }
  }
  if (!out.empty() && !options.fit_rectangle) {
    types.fail("placing a rectangle by one edge needs fit_rectangle: true");
  }
  return out;
}

// {door: {drawer_front: [0.1, 0.45]}}: from type -> {to type: [min_m, max_m]}.
std::vector<BoxStereoOptions::Retype> retypes_from(const config::Node& retype) {
  retype.expect_map();
  std::vector<BoxStereoOptions::Retype> out;
  for (const std::string& from : retype.keys()) {
    for (const auto& range : ranges_from(retype.at(from))) {
      out.push_back({from, range.type, range.min_m, range.max_m});
    }
  }
  return out;
}

// {reference_px, disparity_px}, each optional, not both zero.
void read_bar_end_noise(const config::Node& noise, BoxStereoOptions::BarEndNoise& out) {
  noise.expect_keys({"reference_px", "disparity_px"});
  if (const auto v = noise.find("reference_px")) out.reference_px = v->as_double_in(0.0, 100.0);
  if (const auto v = noise.find("disparity_px")) out.disparity_px = v->as_double_in(0.0, 100.0);
  if (out.reference_px + out.disparity_px <= 0.0) {
    noise.fail("a bar end's noise of all zeros gives no covariance");
  }
}

}  // namespace

BoxStereoOptions box_stereo_options_from(const config::Node& section) {
  section.expect_keys({"max_epipolar_distance_px",
                       "epipolar_box_fraction",
                       "min_depth_m",
                       "max_depth_m",
                       "max_size_ratio",
                       "size_tolerance_px",
                       "border_margin_px",
                       "snap_band_fraction",
                       "snap_min_band_px",
                       "min_correlation",
                       "max_template_px",
                       "noise",
                       "rectangle_types",
                       "fit_rectangle",
                       "edge_types",
                       "pair_by_surroundings",
                       "reference_depth_offset_m",
                       "height_range_m",
                       "retype_by_height_m",
                       "width_range_m",
                       "length_range_m",
                       "thickness_range_m",
                       "bar_types",
                       "bar_min_contrast",
                       "bar_end_patch_px",
                       "bar_end_noise",
                       "same_bar_m"});
  BoxStereoOptions out;
  const auto number = [&](const char* key, double& value, double min, double max) {
    if (const auto v = section.find(key)) value = v->as_double_in(min, max);
  };
  number("max_epipolar_distance_px", out.max_epipolar_distance_px, 0.0, 1000.0);
  number("epipolar_box_fraction", out.epipolar_box_fraction, 0.0, 1.0);
  number("min_depth_m", out.min_depth_m, 0.01, 1000.0);
  number("max_depth_m", out.max_depth_m, 0.01, 1000.0);
  if (out.min_depth_m >= out.max_depth_m) {
    section.at(section.has("max_depth_m") ? "max_depth_m" : "min_depth_m")
        .fail("min_depth_m must be below max_depth_m");
  }
  number("max_size_ratio", out.max_size_ratio, 1.0, 100.0);
  number("size_tolerance_px", out.size_tolerance_px, 0.0, 100.0);
  number("border_margin_px", out.border_margin_px, 0.0, 1000.0);
  number("snap_band_fraction", out.snap_band_fraction, 0.0, 0.5);
  number("snap_min_band_px", out.snap_min_band_px, 0.0, 100.0);
  number("min_correlation", out.min_correlation, -1.0, 1.0);
  number("max_template_px", out.max_template_px, 16.0, 1e7);
  if (const auto noise = section.find("noise")) out.noise = noise_models_from(*noise);
  if (const auto types = section.find("rectangle_types")) out.rectangle_types = types_from(*types);
  if (const auto v = section.find("fit_rectangle")) out.fit_rectangle = v->as_bool();
  if (const auto types = section.find("edge_types")) out.edge_types = edge_types_from(*types, out);
  if (const auto v = section.find("pair_by_surroundings")) out.pair_by_surroundings = v->as_bool();
  if (const auto offsets = section.find("reference_depth_offset_m")) {
    offsets->expect_map();
    out.reference_depth_offset_m.clear();
    for (const std::string& type : offsets->keys()) {
      out.reference_depth_offset_m.emplace_back(type, offsets->at(type).as_double_in(-1.0, 1.0));
    }
  }
  if (const auto r = section.find("height_range_m")) out.height_range_m = ranges_from(*r);
  if (const auto r = section.find("width_range_m")) out.width_range_m = ranges_from(*r);
  if (const auto retype = section.find("retype_by_height_m")) {
    out.retype_by_height_m = retypes_from(*retype);
  }
  if (const auto r = section.find("length_range_m")) out.length_range_m = ranges_from(*r);
  if (const auto r = section.find("thickness_range_m")) out.thickness_range_m = ranges_from(*r);
  if (const auto types = section.find("bar_types")) out.bar_types = types_from(*types);
  number("bar_min_contrast", out.bar_min_contrast, 0.0, 765.0);
  number("bar_end_patch_px", out.bar_end_patch_px, 2.0, 100.0);
  number("same_bar_m", out.same_bar_m, 0.0, 10.0);
  if (const auto noise = section.find("bar_end_noise"))
    read_bar_end_noise(*noise, out.bar_end_noise);
  return out;
}

}  // namespace vsl::recognition
