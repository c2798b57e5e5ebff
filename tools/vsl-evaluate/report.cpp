#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>

#include "json_writer.hpp"

namespace vsl::evaluate {
namespace {

using scenario::Distribution;

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

std::string format(const char* pattern, auto... values) {
  char line[512];
  std::snprintf(line, sizeof line, pattern, values...);
  return line;
}

std::string count_line(const char* label, std::size_t n, std::size_t of, const char* note) {
  return format("%-17s %5zu / %zu  %6.1f%%  %s\n", label, n, of,
                of ? 100.0 * static_cast<double>(n) / static_cast<double>(of) : 0.0, note);
}

std::string distribution_line(const char* label, const Distribution& d, double scale,
                              const char* unit, int decimals) {
  if (d.count == 0) return format("%-27s n/a (none)\n", label);
  const std::string u = *unit ? std::string(" ") + unit : "";
  return format("%-27s median %.*f%s, 95%% %.*f%s, max %.*f%s (of %zu)\n", label, decimals,
                d.median * scale, u.c_str(), decimals, d.p95 * scale, u.c_str(), decimals,
                d.max * scale, u.c_str(), d.count);
}

void write_distribution(tools::JsonWriter& json, const Distribution& d, double scale = 1.0) {
  json.begin_object();
  json.key("count").number(static_cast<double>(d.count));
  json.key("median").number(d.median * scale);
  json.key("p95").number(d.p95 * scale);
  json.key("max").number(d.max * scale);
  json.end_object();
}

// "93.5 %", the share of `n` in `s`'s scenarios.
std::string percent(const scenario::Summary& s, std::size_t n) {
  return format("%.1f %%", 100.0 * s.rate(n));
}

// One value of a distribution (`Distribution::median` or `::p95`) with its unit, or "n/a".
std::string value(const Distribution& d, double Distribution::*which, double scale,
                  const char* unit, int decimals) {
  if (d.count == 0) return "n/a";
  return format("%.*f %s", decimals, d.*which * scale, unit);
}

// vsl and the peer in two columns over the same cases (--peer).
void print_side_by_side(const Report& r, std::ostream& out) {
  const scenario::Summary& v = r.summary;
  const PeerReport& peer = *r.peer;
  const scenario::Summary& p = peer.summary;
  const auto row = [&](const char* label, const std::string& vsl, const std::string& other) {
    out << format("  %-23s %14s %14s\n", label, vsl.c_str(), other.c_str());
  };
  out << format("localizer vs peer on the same %zu scenarios (one thread each):\n", v.scenarios);
  row("", "vsl", peer.name.c_str());
  row("correct-localized", percent(v, v.correct), percent(p, p.correct));
  row("wrong-confident", percent(v, v.wrong_confident), percent(p, p.wrong_confident));
  row("ambiguous", percent(v, v.ambiguous), percent(p, p.ambiguous));
  row("failed", percent(v, v.failed), percent(p, p.failed));
  row("position error median", value(v.position_error_m, &Distribution::median, 100, "cm", 2),
      value(p.position_error_m, &Distribution::median, 100, "cm", 2));
  row("position error 95%", value(v.position_error_m, &Distribution::p95, 100, "cm", 2),
      value(p.position_error_m, &Distribution::p95, 100, "cm", 2));
  row("time median", value(v.wall_ms, &Distribution::median, 1, "ms", 3),
      value(p.wall_ms, &Distribution::median, 1, "ms", 3));
  row("time 95%", value(v.wall_ms, &Distribution::p95, 1, "ms", 3),
      value(p.wall_ms, &Distribution::p95, 1, "ms", 3));
  const PeerOptions& o = peer.options;
  out << format(
      "  (position errors over localized results; time: wall time around each call. %s: "
      "Open3D RANSAC over every same-type percept-object pair, inlier distance %g m, ransac_n 3, "
      "edge-length check %g, at most %d iterations, confidence %g, least-squares refit on its "
      "inliers, localized with at least %d inlier percepts)\n",
      peer.name.c_str(), o.max_correspondence_distance_m, o.edge_length_similarity,
      o.max_iterations, o.confidence, o.min_inlier_percepts);
}

void write_peer(tools::JsonWriter& json, const PeerReport& peer) {
  const scenario::Summary& s = peer.summary;
  const PeerOptions& o = peer.options;
  json.begin_object();
  json.key("name").string(peer.name);
  json.key("settings").begin_object();
  json.key("correspondences").string("all same-type percept-object pairs");
  json.key("max_correspondence_distance_m").number(o.max_correspondence_distance_m);
  json.key("ransac_n").number(3);
  json.key("edge_length_similarity").number(o.edge_length_similarity);
  json.key("max_iterations").number(o.max_iterations);
  json.key("confidence").number(o.confidence);
  json.key("min_inlier_percepts").number(o.min_inlier_percepts);
  json.key("threads").number(1);
  json.end_object();
  json.key("counts").begin_object();
  json.key("correct_localized").number(static_cast<double>(s.correct));
  json.key("wrong_confident").number(static_cast<double>(s.wrong_confident));
  json.key("ambiguous").number(static_cast<double>(s.ambiguous));
  json.key("failed").number(static_cast<double>(s.failed));
  json.end_object();
  json.key("rates").begin_object();
  json.key("correct_localized").number(s.rate(s.correct));
  json.key("wrong_confident").number(s.rate(s.wrong_confident));
  json.key("ambiguous").number(s.rate(s.ambiguous));
  json.key("failed").number(s.rate(s.failed));
  json.end_object();
  json.key("position_error_m");
  write_distribution(json, s.position_error_m);
  json.key("heading_error_deg");
  write_distribution(json, s.heading_error_deg);
  json.key("wall_ms");
  write_distribution(json, s.wall_ms);
  json.end_object();
}

}  // namespace

void print_text(const Report& r, bool details, std::ostream& out) {
  const scenario::Summary& s = r.summary;
  const RunInfo& i = r.info;
  if (i.source == "generated") {
    out << format(
        "vsl-evaluate: %zu scenarios generated in '%s' (%s, %zu objects), seed %llu, "
        "%.0f%% false positives, %.0f%% misses; localizer config: %s\n",
        s.scenarios, i.world_name.c_str(), i.world.c_str(), i.world_objects,
        static_cast<unsigned long long>(i.seed), 100 * i.false_positive_rate, 100 * i.miss_rate,
        i.localizer_config.c_str());
  } else {
    out << format(
        "vsl-evaluate: %zu scenarios from %s in '%s' (%s, %zu objects); localizer "
        "config: %s\n",
        s.scenarios, i.source.c_str(), i.world_name.c_str(), i.world.c_str(), i.world_objects,
        i.localizer_config.c_str());
  }
  if (i.active_rounds > 0) {
    out << format("active validation: up to %d look(s) per ambiguous result, %zu looks in all\n",
                  i.active_rounds, r.active_looks);
  }
  out << distribution_line("percepts per scenario:", s.percepts, 1.0, "", 0);
  const std::string correct_note =
      format("localized within %.0f cm and %.1f deg of the truth", i.thresholds.position_m * 100,
             i.thresholds.heading_rad * kRadToDeg);
  out << count_line("correct-localized", s.correct, s.scenarios, correct_note.c_str());
  out << count_line("wrong-confident", s.wrong_confident, s.scenarios,
                    "localized, but not within the thresholds");
  const std::string ambiguous_note =
      format("truth among the hypotheses in %zu of %zu", s.ambiguous_with_truth, s.ambiguous);
  out << count_line("ambiguous", s.ambiguous, s.scenarios, ambiguous_note.c_str());
  out << count_line("failed", s.failed, s.scenarios, "no pose");
  out << distribution_line("position error (localized):", s.position_error_m, 100.0, "cm", 2);
  out << distribution_line("heading error (localized):", s.heading_error_deg, 1.0, "deg", 3);
  out << distribution_line("localizer total time:", s.total_ms, 1.0, "ms", 3);
  out << distribution_line("wall time per scenario:", s.wall_ms, 1.0, "ms", 3);
  const auto& m = s.median_stage_ms;
  out << format(
      "median stage times (ms): proximity %.3f, orientation %.3f, hypotheses %.3f, "
      "validation %.3f, refinement %.3f\n",
      m.proximity_filter_ms, m.orientation_filter_ms, m.hypothesis_generation_ms, m.validation_ms,
      m.refinement_ms);
  if (r.peer) print_side_by_side(r, out);
  if (!details) return;
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    const scenario::Outcome& o = r.cases[k].outcome;
    out << format("  %-24s %-10s %s %3zu percepts %2zu hyp. %8.3f ms", r.names[k].c_str(),
                  localization::to_string(o.status), o.correct ? "ok   " : "     ", o.percepts,
                  o.hypotheses, o.timing.total_ms);
    if (o.error) {
      out << format("  error %.2f cm, heading %.3f deg, rotation %.3f deg",
                    o.error->position_m * 100, o.error->heading_rad * kRadToDeg,
                    o.error->rotation_rad * kRadToDeg);
    }
    if (r.cases[k].active_looks > 0) out << format("  %d active look(s)", r.cases[k].active_looks);
    if (!r.cases[k].message.empty()) out << "  (" << r.cases[k].message << ")";
    if (r.peer) {
      const scenario::Outcome& p = r.peer->cases[k].outcome;
      out << format("  | %s: %s %s %8.3f ms", r.peer->name.c_str(),
                    localization::to_string(p.status), p.correct ? "ok" : "  ", p.wall_ms);
      if (p.error) out << format("  error %.2f cm", p.error->position_m * 100);
    }
    out << "\n";
  }
}

void print_json(const Report& r, bool details, std::ostream& out) {
  const scenario::Summary& s = r.summary;
  const RunInfo& i = r.info;
  tools::JsonWriter json(out);
  json.begin_object();
  json.key("world").string(i.world);
  json.key("localizer_config").string(i.localizer_config);
  json.key("source").string(i.source);
  if (i.source == "generated") {
    json.key("seed").number(static_cast<double>(i.seed));
    json.key("false_positive_rate").number(i.false_positive_rate);
    json.key("miss_rate").number(i.miss_rate);
  }
  json.key("active_rounds").number(i.active_rounds);
  json.key("thresholds").begin_object();
  json.key("position_m").number(i.thresholds.position_m);
  json.key("heading_deg").number(i.thresholds.heading_rad * kRadToDeg);
  json.end_object();
  json.key("scenarios").number(static_cast<double>(s.scenarios));
  json.key("counts").begin_object();
  json.key("correct_localized").number(static_cast<double>(s.correct));
  json.key("wrong_confident").number(static_cast<double>(s.wrong_confident));
  json.key("ambiguous").number(static_cast<double>(s.ambiguous));
  json.key("ambiguous_with_truth").number(static_cast<double>(s.ambiguous_with_truth));
  json.key("failed").number(static_cast<double>(s.failed));
  json.key("active_looks").number(static_cast<double>(r.active_looks));
  json.end_object();
  json.key("rates").begin_object();
  json.key("correct_localized").number(s.rate(s.correct));
  json.key("wrong_confident").number(s.rate(s.wrong_confident));
  json.key("ambiguous").number(s.rate(s.ambiguous));
  json.key("failed").number(s.rate(s.failed));
  json.key("truth_among_ambiguous_hypotheses")
      .number(s.ambiguous
                  ? static_cast<double>(s.ambiguous_with_truth) / static_cast<double>(s.ambiguous)
                  : 1.0);
  json.end_object();
  json.key("position_error_m");
  write_distribution(json, s.position_error_m);
  json.key("heading_error_deg");
  write_distribution(json, s.heading_error_deg);
  json.key("total_ms");
  write_distribution(json, s.total_ms);
  json.key("wall_ms");
  write_distribution(json, s.wall_ms);
  const auto& m = s.median_stage_ms;
  json.key("median_stage_ms").begin_object();
  json.key("proximity_filter").number(m.proximity_filter_ms);
  json.key("orientation_filter").number(m.orientation_filter_ms);
  json.key("hypothesis_generation").number(m.hypothesis_generation_ms);
  json.key("validation").number(m.validation_ms);
  json.key("refinement").number(m.refinement_ms);
  json.key("total").number(m.total_ms);
  json.end_object();
  json.key("percepts");
  write_distribution(json, s.percepts);
  if (r.peer) {
    json.key("peer");
    write_peer(json, *r.peer);
  }
  if (details) {
    json.key("cases").begin_array();
    for (std::size_t k = 0; k < r.cases.size(); ++k) {
      const scenario::Outcome& o = r.cases[k].outcome;
      json.begin_object();
      json.key("name").string(r.names[k]);
      json.key("status").string(localization::to_string(o.status));
      json.key("correct").boolean(o.correct);
      json.key("truth_among_hypotheses").boolean(o.truth_among_hypotheses);
      json.key("percepts").number(static_cast<double>(o.percepts));
      json.key("hypotheses").number(static_cast<double>(o.hypotheses));
      json.key("total_ms").number(o.timing.total_ms);
      json.key("wall_ms").number(o.wall_ms);
      if (o.error) {
        json.key("position_error_m").number(o.error->position_m);
        json.key("heading_error_deg").number(o.error->heading_rad * kRadToDeg);
        json.key("rotation_error_deg").number(o.error->rotation_rad * kRadToDeg);
      }
      json.key("active_looks").number(r.cases[k].active_looks);
      json.key("message").string(r.cases[k].message);
      if (r.peer) {
        const CaseResult& p = r.peer->cases[k];
        json.key("peer").begin_object();
        json.key("status").string(localization::to_string(p.outcome.status));
        json.key("correct").boolean(p.outcome.correct);
        json.key("wall_ms").number(p.outcome.wall_ms);
        if (p.outcome.error) {
          json.key("position_error_m").number(p.outcome.error->position_m);
          json.key("heading_error_deg").number(p.outcome.error->heading_rad * kRadToDeg);
        }
        json.key("message").string(p.message);
        json.end_object();
      }
      json.end_object();
    }
    json.end_array();
  }
  json.end_object();
  out << "\n";
}

}  // namespace vsl::evaluate
