// The `segmentation:` config section -> SegmentationOptions. Every key is
// optional (defaults are the struct's); a wrong value or an unknown key is one
// line "file:line: key: what".
#include <string>

#include "vsl/config/node.hpp"
#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {
namespace {

int int_in(const config::Node& node, std::int64_t min, std::int64_t max) {
  const std::int64_t value = node.as_int();
  if (value < min || value > max) {
    node.fail("must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
              "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

}  // namespace

SegmentationOptions segmentation_options_from(const config::Node& section) {
  SegmentationOptions out;
  section.expect_map();
  section.expect_keys({"max_neighbour_difference_rgb",
                       "max_run_mean_difference_rgb",
                       "max_colour_volume_rgb3",
                       "max_region_px",
                       "min_region_px",
                       "spatial_bandwidth_px",
                       "colour_bandwidth_rgb",
                       "max_mean_shift_iterations",
                       "max_mode_distance",
                       "min_blob_px",
                       "min_line_contrast_rgb",
                       "line_bridge_px",
                       "max_chromaticity_difference",
                       "max_facet_px",
                       "min_split_blob_px",
                       "max_slit_width_px",
                       "min_slit_support",
                       "min_split_piece_fraction",
                       "max_twin_split_px",
                       "min_twin_gap_support",
                       "min_twin_piece_fraction",
                       "min_twin_gap_chromaticity_difference"});
  if (const auto v = section.find("max_neighbour_difference_rgb")) {
    out.max_neighbour_difference_rgb = v->as_double_in(0.0, 1.0);
  }
  if (const auto v = section.find("max_run_mean_difference_rgb")) {
    out.max_run_mean_difference_rgb = v->as_double_in(0.0, 1.0);
  }
  // The ellipsoid of the whole RGB cube: 4/3 pi (1/2)^3 ~ 0.52.
  if (const auto v = section.find("max_colour_volume_rgb3")) {
    out.max_colour_volume_rgb3 = v->as_double_in(1e-12, 1.0);
  }
  if (const auto v = section.find("max_region_px")) out.max_region_px = int_in(*v, 1, 100000000);
  if (const auto v = section.find("min_region_px")) out.min_region_px = int_in(*v, 1, 100000000);
  if (const auto v = section.find("spatial_bandwidth_px")) {
    out.spatial_bandwidth_px = v->as_double_in(1e-3, 1e6);
  }
  if (const auto v = section.find("colour_bandwidth_rgb")) {
    out.colour_bandwidth_rgb = v->as_double_in(1e-3, 2.0);
  }
  if (const auto v = section.find("max_mean_shift_iterations")) {
    out.max_mean_shift_iterations = int_in(*v, 1, 1000);
  }
  if (const auto v = section.find("max_mode_distance")) {
    out.max_mode_distance = v->as_double_in(0.0, 10.0);
  }
  if (const auto v = section.find("min_blob_px")) out.min_blob_px = int_in(*v, 1, 100000000);
  if (const auto v = section.find("min_line_contrast_rgb")) {
    out.min_line_contrast_rgb = v->as_double_in(0.0, 1.0);
  }
  if (const auto v = section.find("line_bridge_px")) out.line_bridge_px = int_in(*v, 0, 100);
  if (const auto v = section.find("max_chromaticity_difference")) {
    out.max_chromaticity_difference = v->as_double_in(0.0, 1.0);
  }
  if (const auto v = section.find("max_facet_px")) out.max_facet_px = int_in(*v, 0, 100000000);
  if (const auto v = section.find("min_split_blob_px")) {
    out.min_split_blob_px = int_in(*v, 0, 100000000);
  }
  if (const auto v = section.find("max_slit_width_px")) out.max_slit_width_px = int_in(*v, 1, 100);
  if (const auto v = section.find("min_split_piece_fraction")) {
    out.min_split_piece_fraction = v->as_double_in(0.0, 0.5);
  }
  if (const auto v = section.find("min_slit_support")) {
    out.min_slit_support = v->as_double_in(0.05, 1.0);
  }
  if (const auto v = section.find("max_twin_split_px")) {
    out.max_twin_split_px = int_in(*v, 0, 100000000);
  }
  if (const auto v = section.find("min_twin_gap_support")) {
    out.min_twin_gap_support = v->as_double_in(0.05, 1.0);
  }
  if (const auto v = section.find("min_twin_piece_fraction")) {
    out.min_twin_piece_fraction = v->as_double_in(0.0, 0.5);
  }
  if (const auto v = section.find("min_twin_gap_chromaticity_difference")) {
    out.min_twin_gap_chromaticity_difference = v->as_double_in(0.0, 1.0);
  }
  if (out.min_region_px > out.max_region_px) {
    section.at("min_region_px")
        .fail("must not exceed max_region_px (" + std::to_string(out.max_region_px) + ")");
  }
  return out;
}

}  // namespace vsl::recognition
