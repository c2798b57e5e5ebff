#include <gtest/gtest.h>

#include "vsl/config/node.hpp"
#include "vsl/localization/localizer.hpp"

namespace vsl::localization {
namespace {

std::string error_of(const std::string& text) {
  try {
    localizer_options_from(config::Node::load_string(text, "l.yaml"));
  } catch (const config::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error for:\n" << text;
  return "";
}

TEST(LocalizerOptions, ShippedConfigLoads) {
  const LocalizerOptions options =
      localizer_options_from(config::Node::load_file("config/localizer.yaml"));
  EXPECT_GT(options.graph.link_threshold_m, 0.0);
  EXPECT_GT(options.noise.zeta_m, 0.0);
}

// The struct's defaults are the shipped file's values, so that a tool without --config
// localizes as the daemon does.
TEST(LocalizerOptions, DefaultsAreTheShippedConfig) {
  const LocalizerOptions shipped =
      localizer_options_from(config::Node::load_file("config/localizer.yaml"));
  const LocalizerOptions defaults;
  // Section by section, so that a failure names the section.
  EXPECT_TRUE(defaults.graph == shipped.graph);
  EXPECT_TRUE(defaults.noise == shipped.noise);
  EXPECT_TRUE(defaults.pruning == shipped.pruning);
  EXPECT_TRUE(defaults.hypotheses == shipped.hypotheses);
  EXPECT_TRUE(defaults.validation == shipped.validation);
  EXPECT_TRUE(defaults.refinement == shipped.refinement);
  EXPECT_TRUE(defaults == shipped);
  // And the comparison sees a difference.
  LocalizerOptions other = shipped;
  other.pruning.floor_heights_m.push_back(3.0);
  EXPECT_FALSE(other == shipped);
}

// A section that sets some keys keeps the defaults of the others (the robot upright, the edge
// nodes of doors).
TEST(LocalizerOptions, AbsentKeysKeepTheDefaults) {
  const LocalizerOptions options = localizer_options_from(config::Node::load_string(
      "world_graph: {link_threshold_m: 3.5}\nrefinement: {huber_sigmas: 2}\n", "l.yaml"));
  EXPECT_DOUBLE_EQ(options.graph.link_threshold_m, 3.5);
  EXPECT_EQ(options.graph.edge_node_types, LocalizerOptions{}.graph.edge_node_types);
  EXPECT_EQ(options.graph.node_types, LocalizerOptions{}.graph.node_types);
  EXPECT_DOUBLE_EQ(options.refinement.huber_sigmas, 2.0);
  EXPECT_TRUE(options.refinement.planar_prior);
}

TEST(LocalizerOptions, SegmentTypesAreReadAndMustBeNodeTypes) {
  const LocalizerOptions none = localizer_options_from(
      config::Node::load_string("validation: {segment_types: []}\n", "l.yaml"));
  EXPECT_TRUE(none.validation.segment_types.empty());
  EXPECT_EQ(LocalizerOptions{}.validation.segment_types, std::vector<std::string>{"handle"});
  EXPECT_NE(error_of("validation: {segment_types: [handle, handel]}\n")
                .find("l.yaml:1: validation.segment_types[1]: 'handel' is not one of "
                      "world_graph.node_types"),
            std::string::npos)
      << error_of("validation: {segment_types: [handle, handel]}\n");
}

TEST(LocalizerOptions, ReadsEverySection) {
  const LocalizerOptions options = localizer_options_from(config::Node::load_string(
      "world_graph: {link_threshold_m: 3.5, edge_node_types: [door]}\n"
      "percept_noise: {zeta_m: 100, ego_camera_position_m: [0.1, 0, 1.6], min_sigma_m: 0.002}\n"
      "pruning: {tau_sigmas: 2.5, mu_max_m: 0.1, kappa_max_rad: 0.15, floor_heights_m: [0, 3.2],\n"
      "          floor_tolerance_m: 0.03}\n"
      "hypotheses: {min_associations: 4, max_interpretations: 500}\n"
      "validation: {gate_sigmas: 4, ambiguity_margin: 0.25}\n"
      "refinement: {huber_sigmas: 2, planar_prior: true}\n",
      "l.yaml"));
  EXPECT_DOUBLE_EQ(options.graph.link_threshold_m, 3.5);
  EXPECT_EQ(options.graph.edge_node_types, std::vector<std::string>{"door"});
  EXPECT_DOUBLE_EQ(options.noise.zeta_m, 100);
  EXPECT_DOUBLE_EQ(options.noise.ego_camera_position_m.z(), 1.6);
  EXPECT_DOUBLE_EQ(options.pruning.tau_sigmas, 2.5);
  EXPECT_EQ(options.pruning.floor_heights_m, (std::vector<double>{0.0, 3.2}));
  EXPECT_DOUBLE_EQ(options.pruning.floor_tolerance_m, 0.03);
  EXPECT_EQ(options.hypotheses.min_associations, 4);
  EXPECT_EQ(options.hypotheses.max_interpretations, 500);
  EXPECT_DOUBLE_EQ(options.validation.gate_sigmas, 4);
  EXPECT_TRUE(options.refinement.planar_prior);
}

TEST(LocalizerOptions, BadValuesNameFileLineAndKey) {
  EXPECT_EQ(error_of("percept_noise: {zeta_m: 0}\n"),
            "l.yaml:1: percept_noise.zeta_m: must be in [1, 1e+06], got 0");
  EXPECT_EQ(error_of("pruning:\n  mu_max: 0.1\n"),
            "l.yaml:2: pruning.mu_max: unknown key (allowed: tau_sigmas, min_tau_m, mu_max_m, "
            "kappa_max_rad, max_unsupported_fraction, max_partners, max_filtered_percepts, "
            "max_percepts, max_link_set, use_gravity, max_tilt_rad, floor_heights_m, "
            "floor_tolerance_m)");
  EXPECT_EQ(error_of("pruning:\n  floor_heights_m: 0.0\n")
                .rfind("l.yaml:2: pruning.floor_heights_m: ", 0),
            0u);
  EXPECT_EQ(error_of("hypotheses: {min_associations: 3.5}\n"),
            "l.yaml:1: hypotheses.min_associations: expected an integer, got '3.5'");
  EXPECT_EQ(error_of("refinement: {planar_prior: maybe}\n"),
            "l.yaml:1: refinement.planar_prior: expected true or false, got 'maybe'");
  EXPECT_EQ(error_of("localiser: {}\n").rfind("l.yaml:1: localiser: unknown key", 0), 0u);
}

}  // namespace
}  // namespace vsl::localization
