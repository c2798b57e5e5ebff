// config/localizer.yaml -> LocalizerOptions. Every key is optional (the defaults are the struct's)
// and validated: a wrong value or an unknown key stops the program with file:line: key: what.
#include <algorithm>

#include "vsl/config/node.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/world/world_graph_options.hpp"

namespace vsl::localization {
namespace {

using config::Node;

int int_in(const Node& node, std::int64_t min, std::int64_t max) {
  const std::int64_t value = node.as_int();
  if (value < min || value > max) {
    node.fail("must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
              "], got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

// Absent keys keep their value in `out` (LocalizerOptions' defaults).
PerceptNoiseOptions percept_noise(const Node& section, PerceptNoiseOptions out) {
  section.expect_keys({"zeta_m", "ego_camera_position_m", "min_sigma_m"});
  if (const auto zeta = section.find("zeta_m")) out.zeta_m = zeta->as_double_in(1.0, 1e6);
  if (const auto camera = section.find("ego_camera_position_m")) {
    const auto c = camera->as_array<3>();
    out.ego_camera_position_m = {c[0], c[1], c[2]};
  }
  if (const auto floor = section.find("min_sigma_m"))
    out.min_sigma_m = floor->as_double_in(1e-6, 1.0);
  return out;
}

// Absent keys keep their value in `out` (LocalizerOptions' defaults).
PruningOptions pruning(const Node& section, PruningOptions out) {
  section.expect_keys({"tau_sigmas", "min_tau_m", "mu_max_m", "kappa_max_rad",
                       "max_unsupported_fraction", "max_partners", "max_filtered_percepts",
                       "max_percepts", "max_link_set", "use_gravity", "max_tilt_rad",
                       "floor_heights_m", "floor_tolerance_m"});
  if (const auto v = section.find("tau_sigmas")) out.tau_sigmas = v->as_double_in(0.5, 20.0);
  if (const auto v = section.find("min_tau_m")) out.min_tau_m = v->as_double_in(0.0, 1.0);
  if (const auto v = section.find("mu_max_m")) out.mu_max_m = v->as_double_in(0.001, 2.0);
  if (const auto v = section.find("kappa_max_rad"))
    out.kappa_max_rad = v->as_double_in(0.001, 3.1416);
  if (const auto v = section.find("max_unsupported_fraction")) {
    out.max_unsupported_fraction = v->as_double_in(0.0, 0.9);
  }
  if (const auto v = section.find("max_partners")) out.max_partners = int_in(*v, 1, 1000);
  if (const auto v = section.find("max_filtered_percepts")) {
    out.max_filtered_percepts = int_in(*v, 3, 100000);
  }
  if (const auto v = section.find("max_percepts")) out.max_percepts = int_in(*v, 3, 100000);
  if (const auto v = section.find("max_link_set")) out.max_link_set = int_in(*v, 1, 100000000);
  if (const auto v = section.find("use_gravity")) out.use_gravity = v->as_bool();
  if (const auto v = section.find("max_tilt_rad")) out.max_tilt_rad = v->as_double_in(0.0, 1.5);
  if (const auto v = section.find("floor_heights_m")) out.floor_heights_m = v->as_doubles();
  if (const auto v = section.find("floor_tolerance_m")) {
    out.floor_tolerance_m = v->as_double_in(0.0, 10.0);
  }
  return out;
}

// Absent keys keep their value in `out` (LocalizerOptions' defaults).
HypothesisOptions hypotheses(const Node& section, HypothesisOptions out) {
  section.expect_keys({"min_associations", "same_position_m", "same_angle_rad",
                       "max_interpretations", "max_seeds", "confirming_seeds",
                       "single_seed_explained_fraction"});
  if (const auto v = section.find("min_associations")) {
    out.min_associations = int_in(*v, 3, 50);
  }
  if (const auto v = section.find("same_position_m"))
    out.same_position_m = v->as_double_in(1e-4, 1.0);
  if (const auto v = section.find("same_angle_rad"))
    out.same_angle_rad = v->as_double_in(1e-4, 1.0);
  if (const auto v = section.find("max_interpretations")) {
    out.max_interpretations = int_in(*v, 1, 10000000);
  }
  if (const auto v = section.find("max_seeds")) out.max_seeds = int_in(*v, 1, 100000);
  if (const auto v = section.find("confirming_seeds")) out.confirming_seeds = int_in(*v, 1, 100000);
  if (const auto v = section.find("single_seed_explained_fraction")) {
    out.single_seed_explained_fraction = v->as_double_in(0.0, 1.0);
  }
  return out;
}

// Absent keys keep their value in `out` (LocalizerOptions' defaults).
ValidationOptions validation(const Node& section, ValidationOptions out) {
  section.expect_keys({"gate_sigmas", "ambiguity_margin", "clutter_density_per_m3",
                       "min_explained_fraction", "precision_sigmas", "required_position_m",
                       "required_angle_rad", "outlier_test_alpha", "segment_types"});
  if (const auto v = section.find("gate_sigmas")) out.gate_sigmas = v->as_double_in(0.5, 20.0);
  if (const auto v = section.find("ambiguity_margin"))
    out.ambiguity_margin = v->as_double_in(0.0, 100.0);
  if (const auto v = section.find("min_explained_fraction")) {
    out.min_explained_fraction = v->as_double_in(0.0, 1.0);
  }
  if (const auto v = section.find("clutter_density_per_m3")) {
    out.clutter_density_per_m3 = v->as_double_in(1e-9, 1e6);
  }
  if (const auto v = section.find("outlier_test_alpha")) {
    out.outlier_test_alpha = v->as_double_in(0.0, 0.5);
  }
  if (const auto v = section.find("precision_sigmas"))
    out.precision_sigmas = v->as_double_in(0.0, 20.0);
  if (const auto v = section.find("required_position_m")) {
    out.required_position_m = v->as_double_in(1e-4, 100.0);
  }
  if (const auto v = section.find("required_angle_rad")) {
    out.required_angle_rad = v->as_double_in(1e-4, 3.1416);
  }
  if (const auto v = section.find("segment_types")) {
    out.segment_types.clear();
    for (std::size_t i = 0; i < v->size(); ++i) out.segment_types.push_back((*v)[i].as_string());
  }
  return out;
}

// Absent keys keep their value in `out` (LocalizerOptions' defaults).
RefinementOptions refinement(const Node& section, RefinementOptions out) {
  section.expect_keys({"huber_sigmas", "planar_prior", "max_iterations"});
  if (const auto v = section.find("huber_sigmas")) out.huber_sigmas = v->as_double_in(0.1, 100.0);
  if (const auto v = section.find("planar_prior")) out.planar_prior = v->as_bool();
  if (const auto v = section.find("max_iterations")) out.max_iterations = int_in(*v, 1, 1000);
  return out;
}

}  // namespace

LocalizerOptions localizer_options_from(const Node& root) {
  LocalizerOptions options;
  if (root.is_null()) return options;
  root.expect_keys({"runtime", "world_graph", "percept_noise", "pruning", "hypotheses",
                    "validation", "refinement"});
  if (const auto s = root.find("world_graph")) {
    options.graph = world::world_graph_options_from(*s, options.graph);
  }
  if (const auto s = root.find("percept_noise")) options.noise = percept_noise(*s, options.noise);
  if (const auto s = root.find("pruning")) options.pruning = pruning(*s, options.pruning);
  if (const auto s = root.find("hypotheses")) {
    options.hypotheses = hypotheses(*s, options.hypotheses);
  }
  if (const auto s = root.find("validation")) {
    options.validation = validation(*s, options.validation);
  }
  if (const auto s = root.find("refinement")) {
    options.refinement = refinement(*s, options.refinement);
  }
  // A bar type given that is no node type would never match a piece: a typo, not a choice.
  const std::vector<std::string>& node_types = options.graph.node_types;
  const std::vector<std::string>& segment_types = options.validation.segment_types;
  const auto validation_section = root.find("validation");
  const auto given = validation_section ? validation_section->find("segment_types") : std::nullopt;
  for (std::size_t i = 0; given && i < segment_types.size() && !node_types.empty(); ++i) {
    if (std::find(node_types.begin(), node_types.end(), segment_types[i]) == node_types.end()) {
      (*given)[i].fail("'" + segment_types[i] + "' is not one of world_graph.node_types");
    }
  }
  return options;
}

}  // namespace vsl::localization
