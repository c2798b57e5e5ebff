#include "vsl/localization/seeds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vsl::localization {
namespace {

// Below this conditioning (smallest altitude, and with gravity the first edge's horizontal
// extent, over the largest sigma) a seed's pose is off by more than a tenth of a radian and its
// subgraphs are mostly noise: such seeds come after all others. Below the floor (a quarter
// radian) they are not tried.
constexpr double kMinConditioning = 8.0;
constexpr double kFloorConditioning = 4.0;
// Percepts considered for seeds: the most precise ones.
constexpr std::size_t kPool = 16;
// A percept of a seed that gave no subgraph counts as used this many times.
constexpr int kSuspectUses = 4;

double altitude(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a;
  const double n = ab.norm();
  if (n == 0.0) return (c - a).norm();
  return ab.cross(c - a).norm() / n;
}

double horizontal_extent(const Eigen::Vector3d& d) {
  return std::sqrt(d.x() * d.x() + d.y() * d.y());
}

}  // namespace

SeedChooser::SeedChooser(const world::WorldGraph& graph, const std::vector<FusedPercept>& percepts,
                         const std::vector<PerceptNoise>& noise, const CandidateSets& candidates,
                         const PruningOptions& options)
    : uses_(percepts.size(), 0) {
  std::vector<int> pool;
  for (std::size_t a = 0; a < percepts.size(); ++a) {
    if (!candidates.outlier[a] && candidates.types[a]) pool.push_back(static_cast<int>(a));
  }
  std::stable_sort(pool.begin(), pool.end(),
                   [&](int a, int b) { return noise[a].sigma_m < noise[b].sigma_m; });
  if (pool.size() > kPool) pool.resize(kPool);

  const auto link_ok = [&](int a, int b) {
    const double d = (percepts[a].ego_position_m - percepts[b].ego_position_m).norm();
    const double sa = noise[a].sigma_m, sb = noise[b].sigma_m;
    const double mu = std::max(options.mu_max_m, options.tau_sigmas * std::sqrt(sa * sa + sb * sb));
    return d + mu < graph.link_threshold_m();
  };
  const auto candidate_count = [&](int x) {
    return static_cast<double>(std::max<std::size_t>(
        1, candidates.constrained[x] ? candidates.nodes[x].size()
                                     : graph.count_of_type(*candidates.types[x])));
  };
  for (std::size_t p = 0; p < pool.size(); ++p) {
    for (std::size_t q = p + 1; q < pool.size(); ++q) {
      for (std::size_t r = q + 1; r < pool.size(); ++r) {
        std::array<int, 3> t{pool[p], pool[q], pool[r]};
        if (!link_ok(t[0], t[1]) || !link_ok(t[0], t[2]) || !link_ok(t[1], t[2])) continue;
        const Eigen::Vector3d& a = percepts[t[0]].ego_position_m;
        const Eigen::Vector3d& b = percepts[t[1]].ego_position_m;
        const Eigen::Vector3d& c = percepts[t[2]].ego_position_m;
        const double sigma =
            std::max({noise[t[0]].sigma_m, noise[t[1]].sigma_m, noise[t[2]].sigma_m});
        double conditioning = std::min({altitude(a, b, c), altitude(b, c, a), altitude(c, a, b)});
        if (options.use_gravity) {
          // Origin and first axis: the pair with the largest horizontal extent, which fixes yaw.
          const std::array<std::array<int, 3>, 3> orders{
              {{t[0], t[1], t[2]}, {t[0], t[2], t[1]}, {t[1], t[2], t[0]}}};
          double best = -1.0;
          for (const auto& o : orders) {
            const double h =
                horizontal_extent(percepts[o[1]].ego_position_m - percepts[o[0]].ego_position_m);
            if (h > best) {
              best = h;
              t = o;
            }
          }
          conditioning = std::min(conditioning, best);
        }
        conditioning /= sigma;
        if (conditioning < kFloorConditioning) continue;
        // The orientation filter visits the origin's candidates and, for each, its neighbours of
        // the other two types: the product of the three counts is a fair proxy of its work.
        const double cost = candidate_count(t[0]) * candidate_count(t[1]) * candidate_count(t[2]);
        const double penalty = conditioning < kMinConditioning ? 1e-6 : 1.0;
        scored_.push_back({{t}, penalty * std::min(conditioning, 50.0) / std::cbrt(cost)});
      }
    }
  }
  std::stable_sort(scored_.begin(), scored_.end(),
                   [](const Scored& x, const Scored& y) { return x.score > y.score; });
  taken_.assign(scored_.size(), false);
}

std::optional<PerceptTriple> SeedChooser::next() {
  // The best-scored triple among those whose percepts were used least.
  int best = -1;
  int best_uses = std::numeric_limits<int>::max();
  for (std::size_t s = 0; s < scored_.size(); ++s) {
    if (taken_[s]) continue;
    int used = 0;
    for (const int x : scored_[s].triple.percepts) used += uses_[x];
    if (used < best_uses) {
      best_uses = used;
      best = static_cast<int>(s);
      if (used == 0) break;
    }
  }
  if (best < 0) return std::nullopt;
  taken_[best] = true;
  for (const int x : scored_[best].triple.percepts) ++uses_[x];
  return scored_[best].triple;
}

void SeedChooser::report_empty(const PerceptTriple& seed) {
  for (const int x : seed.percepts) uses_[x] += kSuspectUses;
}

std::vector<PerceptTriple> choose_seed_triples(const world::WorldGraph& graph,
                                               const std::vector<FusedPercept>& percepts,
                                               const std::vector<PerceptNoise>& noise,
                                               const CandidateSets& candidates,
                                               const PruningOptions& options,
                                               std::size_t max_seeds) {
  SeedChooser chooser(graph, percepts, noise, candidates, options);
  std::vector<PerceptTriple> seeds;
  while (seeds.size() < max_seeds) {
    const auto seed = chooser.next();
    if (!seed) break;
    seeds.push_back(*seed);
  }
  return seeds;
}

}  // namespace vsl::localization
