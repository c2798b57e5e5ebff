#include "vsl/localization/proximity_filter.hpp"

#include "vsl/localization/localization_context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace vsl::localization {
namespace {

using world::NodeIndex;
using world::TypeId;

// One percept's view of a constraining pair.
struct Partner {
  int percept;        // the other percept
  TypeId type;        // its type
  double lo_m, hi_m;  // Eq. 8: link lengths within phi +- tau
  std::size_t band;   // |psi|: size of the link set, the cost of reading it
};

// Pass 1 scratch, one entry per node, reused for every percept without clearing: an entry
// belongs to the percept whose `epoch` it carries.
struct Tally {
  std::uint32_t epoch = 0;
  std::uint32_t last_partner = 0;  // so that a node counts once per partner
  std::uint32_t count = 0;         // partners whose link set holds the node
};

// Dense membership of nodes in candidate sets: bit b of node n is set while n is a candidate of
// percept b.
class Membership {
 public:
  Membership(std::size_t nodes, std::size_t percepts)
      : words_((percepts + 63) / 64), bits_(nodes * words_, 0) {}
  bool test(NodeIndex node, int percept) const {
    return (bits_[node * words_ + percept / 64] >> (percept % 64)) & 1u;
  }
  void set(NodeIndex node, int percept) {
    bits_[node * words_ + percept / 64] |= std::uint64_t{1} << (percept % 64);
  }
  void reset(NodeIndex node, int percept) {
    bits_[node * words_ + percept / 64] &= ~(std::uint64_t{1} << (percept % 64));
  }

 private:
  std::size_t words_;
  std::vector<std::uint64_t> bits_;
};

// f_a: partners allowed to give no support.
int allowed_unsupported(std::size_t partners, double fraction) {
  if (partners <= 1) return 0;
  const int f = std::max(1, static_cast<int>(std::floor(fraction * static_cast<double>(partners))));
  return std::min(f, static_cast<int>(partners) - 1);
}

using PartnerLists = std::vector<std::vector<Partner>>;

// Each percept's partners: the linkable pairs with the percepts not excluded.
PartnerLists choose_partners(const world::WorldGraph& graph,
                             const std::vector<PerceptPair>& linkable,
                             const std::vector<bool>& excluded, const PruningOptions& options,
                             const CandidateSets& out) {
  const std::size_t m = out.types.size();
  // Each percept is filtered against its max_partners most precise partners (smallest tau), not
  // the smallest link sets: an empty link set is the mark of a false positive, and choosing by it
  // would hand every percept the false positives first.
  std::vector<std::vector<const PerceptPair*>> mine(m);
  for (const PerceptPair& pair : linkable) {
    if (!excluded[pair.b]) mine[pair.a].push_back(&pair);
    if (!excluded[pair.a]) mine[pair.b].push_back(&pair);
  }
  const auto per_percept = static_cast<std::size_t>(std::max(options.max_partners, 1));
  PartnerLists partners(m);
  for (std::size_t a = 0; a < m; ++a) {
    std::stable_sort(
        mine[a].begin(), mine[a].end(),
        [](const PerceptPair* x, const PerceptPair* y) { return x->tau_m < y->tau_m; });
    if (mine[a].size() > per_percept) mine[a].resize(per_percept);
    for (const PerceptPair* pair : mine[a]) {
      const int b = pair->a == static_cast<int>(a) ? pair->b : pair->a;
      const TypeId ta = *out.types[a];
      const TypeId tb = *out.types[b];
      const double lo = pair->distance_m - pair->tau_m;
      const double hi = pair->distance_m + pair->tau_m;
      partners[a].push_back({b, tb, lo, hi, graph.links(ta, tb, lo, hi).size()});
    }
  }

  return partners;
}

void drop_unselective(PartnerLists& partners, const PruningOptions& options) {
  const std::size_t m = partners.size();
  // Unselective percepts (a link set of theirs above max_link_set: reading it costs more than the
  // pruning saves) are left unconstrained and constrain nobody; dropping them as partners can
  // change others' lists, so repeat until stable.
  const auto limit = static_cast<std::size_t>(std::max(options.max_link_set, 0));
  for (bool dropped = true; dropped;) {
    dropped = false;
    std::vector<bool> unselective(m, false);
    for (std::size_t a = 0; a < m; ++a) {
      const auto& list = partners[a];
      unselective[a] =
          std::any_of(list.begin(), list.end(), [&](const Partner& p) { return p.band > limit; });
    }
    for (std::size_t a = 0; a < m; ++a) {
      auto& list = partners[a];
      const std::size_t before = list.size();
      if (unselective[a]) {
        list.clear();
      } else {
        list.erase(std::remove_if(list.begin(), list.end(),
                                  [&](const Partner& p) { return unselective[p.percept]; }),
                   list.end());
      }
      dropped = dropped || list.size() != before;
    }
  }
}

// Fills out.nodes and out.constrained; returns required_a per percept.
std::vector<int> collect_candidates(const world::WorldGraph& graph, PartnerLists& partners,
                                    const PruningOptions& options, CandidateSets& out) {
  const std::size_t m = out.types.size();
  // Pass 1: a node of percept a's type is a candidate when the link sets of at least
  // required_a = |partners| - f_a partners contain it. Such a node lies in at least one of any
  // f_a + 1 of those link sets, so collecting from the f_a + 1 smallest sees every candidate.
  std::vector<Tally> tally;
  std::vector<int> required(m, 0);
  for (std::size_t a = 0; a < m; ++a) {
    out.nodes[a].clear();
    out.constrained[a] = false;
    std::vector<Partner>& list = partners[a];
    if (!out.types[a] || list.empty()) continue;
    std::sort(list.begin(), list.end(),
              [](const Partner& x, const Partner& y) { return x.band < y.band; });
    out.constrained[a] = true;
    if (tally.empty()) tally.resize(graph.node_count());
    const int f = allowed_unsupported(list.size(), options.max_unsupported_fraction);
    required[a] = static_cast<int>(list.size()) - f;
    const auto epoch = static_cast<std::uint32_t>(a + 1);
    const TypeId ta = *out.types[a];
    for (std::size_t p = 0; p < list.size(); ++p) {
      for (const world::TypedLink& link :
           graph.links(ta, list[p].type, list[p].lo_m, list[p].hi_m)) {
        Tally& t = tally[link.from];
        if (t.epoch != epoch) {
          t = {epoch, static_cast<std::uint32_t>(p), 1};
        } else if (t.last_partner != p) {
          t.last_partner = static_cast<std::uint32_t>(p);
          ++t.count;
        }
      }
    }
    constexpr std::uint32_t kCollected = 0xffffffffu;
    for (int p = 0; p <= f; ++p) {
      for (const world::TypedLink& link :
           graph.links(ta, list[p].type, list[p].lo_m, list[p].hi_m)) {
        Tally& t = tally[link.from];
        if (t.last_partner == kCollected || t.count < static_cast<std::uint32_t>(required[a])) {
          continue;
        }
        t.last_partner = kCollected;
        out.nodes[a].push_back(link.from);
      }
    }
    std::sort(out.nodes[a].begin(), out.nodes[a].end());
  }

  return required;
}

// Removes the candidates that lose their support and fills out.outlier.
void arc_consistency(const world::WorldGraph& graph, const TypedAdjacency& adjacency,
                     const PartnerLists& partners, const std::vector<int>& required,
                     CandidateSets& out) {
  const std::size_t m = out.types.size();
  // Arc consistency (AC-4): a candidate u of a keeps the support of partner b while some
  // candidate of b is linked to u with a length in their band. Supports are counted once; then
  // every removed candidate decrements the counts of the candidates it supported (found among its
  // graph neighbours), so the whole fixed point costs O(candidates x degree), not a sweep per
  // change.
  bool any = false;
  for (std::size_t a = 0; a < m; ++a) any = any || out.constrained[a];
  if (!any) {
    for (std::size_t a = 0; a < m; ++a) out.outlier[a] = !out.types[a];
    return;
  }
  Membership member(graph.node_count(), m);
  for (std::size_t a = 0; a < m; ++a) {
    for (const NodeIndex u : out.nodes[a]) member.set(u, static_cast<int>(a));
  }
  struct Dependent {
    int percept;  // a, which has b as its partner number `slot`
    std::size_t slot;
  };
  std::vector<std::vector<Dependent>> dependents(m);
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t k = 0; k < partners[a].size(); ++k) {
      dependents[partners[a][k].percept].push_back({static_cast<int>(a), k});
    }
  }
  // support[a][i * K_a + k]: candidates of a's partner k linked to a's i-th candidate in band.
  std::vector<std::vector<std::uint16_t>> support(m);
  std::vector<std::vector<std::uint8_t>> supported_partners(m);
  std::vector<std::pair<int, NodeIndex>> removed;
  for (std::size_t a = 0; a < m; ++a) {
    const std::vector<Partner>& list = partners[a];
    const std::size_t k_count = list.size();
    const std::vector<NodeIndex>& nodes = out.nodes[a];
    support[a].assign(nodes.size() * k_count, 0);
    supported_partners[a].assign(nodes.size(), 0);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      std::uint16_t* counts = support[a].data() + i * k_count;
      for (std::size_t k = 0; k < k_count; ++k) {
        const Partner& p = list[k];
        for (const world::Neighbour& n : adjacency.within(nodes[i], p.type, p.lo_m, p.hi_m)) {
          if (member.test(n.node, p.percept) && counts[k]++ == 0) ++supported_partners[a][i];
        }
      }
      if (supported_partners[a][i] < required[a])
        removed.emplace_back(static_cast<int>(a), nodes[i]);
    }
  }
  for (const auto& [a, u] : removed) member.reset(u, a);
  const auto slot_of = [&](int a, NodeIndex u) {
    const auto& nodes = out.nodes[a];
    return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), u) -
                                    nodes.begin());
  };
  for (std::size_t next = 0; next < removed.size(); ++next) {
    const auto [b, v] = removed[next];
    ++out.passes;
    for (const Dependent& d : dependents[b]) {
      const Partner& p = partners[d.percept][d.slot];
      for (const world::Neighbour& n : adjacency.within(v, *out.types[d.percept], p.lo_m, p.hi_m)) {
        if (!member.test(n.node, d.percept)) continue;
        const std::size_t i = slot_of(d.percept, n.node);
        std::uint16_t& count = support[d.percept][i * partners[d.percept].size() + d.slot];
        if (--count > 0) continue;
        if (--supported_partners[d.percept][i] < required[d.percept]) {
          member.reset(n.node, d.percept);
          removed.emplace_back(d.percept, n.node);
        }
      }
    }
  }
  for (std::size_t a = 0; a < m; ++a) {
    std::vector<NodeIndex>& nodes = out.nodes[a];
    nodes.erase(std::remove_if(nodes.begin(), nodes.end(),
                               [&](NodeIndex u) { return !member.test(u, static_cast<int>(a)); }),
                nodes.end());
  }
  for (std::size_t a = 0; a < m; ++a) {
    out.outlier[a] = !out.types[a] || (out.constrained[a] && out.nodes[a].empty());
  }
}

// One run of the filter with the percepts in `excluded` passive: they constrain nobody, but their
// own candidates are still filtered against the others, so that a true percept excluded in an
// earlier round (its partners then included false positives) gets its candidates back. Fills
// out.nodes, out.constrained, out.outlier.
void filter_round(const world::WorldGraph& graph, const TypedAdjacency& adjacency,
                  const std::vector<PerceptPair>& linkable, const std::vector<bool>& excluded,
                  const PruningOptions& options, CandidateSets& out) {
  PartnerLists partners = choose_partners(graph, linkable, excluded, options, out);
  drop_unselective(partners, options);
  const std::vector<int> required = collect_candidates(graph, partners, options, out);
  arc_consistency(graph, adjacency, partners, required, out);
}

}  // namespace

PerceptPair make_percept_pair(int a, int b, const std::vector<FusedPercept>& percepts,
                              const std::vector<PerceptNoise>& noise,
                              const PruningOptions& options) {
  PerceptPair pair;
  pair.a = std::min(a, b);
  pair.b = std::max(a, b);
  const Eigen::Vector3d d = percepts[pair.b].ego_position_m - percepts[pair.a].ego_position_m;
  pair.distance_m = d.norm();
  const Eigen::Vector3d direction =
      pair.distance_m > 0.0 ? Eigen::Vector3d(d / pair.distance_m) : Eigen::Vector3d::UnitX();
  const double sa = noise[pair.a].sigma_along_m(direction);
  const double sb = noise[pair.b].sigma_along_m(direction);
  pair.tau_m = std::max(options.min_tau_m, options.tau_sigmas * std::sqrt(sa * sa + sb * sb));
  return pair;
}

std::vector<PerceptPair> percept_pair_table(const std::vector<FusedPercept>& percepts,
                                            const std::vector<PerceptNoise>& noise,
                                            const PruningOptions& options) {
  const std::size_t n = percepts.size();
  std::vector<PerceptPair> table(n * n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      table[a * n + b] = table[b * n + a] =
          make_percept_pair(static_cast<int>(a), static_cast<int>(b), percepts, noise, options);
    }
  }
  return table;
}

std::vector<std::optional<world::TypeId>> percept_types(const world::WorldGraph& graph,
                                                        const std::vector<FusedPercept>& percepts) {
  std::vector<std::optional<world::TypeId>> types;
  types.reserve(percepts.size());
  for (const FusedPercept& p : percepts) types.push_back(graph.find_type(p.type));
  return types;
}

bool CandidateSets::is_candidate(int percept, world::NodeIndex node) const {
  const auto& list = nodes[percept];
  return std::binary_search(list.begin(), list.end(), node);
}

std::size_t CandidateSets::candidate_count() const {
  std::size_t total = 0;
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    if (constrained[a] && !outlier[a]) total += nodes[a].size();
  }
  return total;
}

CandidateSets proximity_filter(const world::WorldGraph& graph, const TypedAdjacency& adjacency,
                               const std::vector<FusedPercept>& percepts,
                               const std::vector<PerceptNoise>& noise,
                               const PruningOptions& options) {
  return proximity_filter(graph, adjacency, percepts, noise, options,
                          percept_types(graph, percepts));
}

CandidateSets proximity_filter(const world::WorldGraph& graph, const TypedAdjacency& adjacency,
                               const std::vector<FusedPercept>& percepts,
                               const std::vector<PerceptNoise>& noise,
                               const PruningOptions& options,
                               std::vector<std::optional<world::TypeId>> types) {
  const std::size_t m = percepts.size();
  CandidateSets out;
  out.types = std::move(types);
  out.types.resize(m);
  out.nodes.assign(m, {});
  out.constrained.assign(m, false);
  out.outlier.assign(m, false);
  for (std::size_t a = 0; a < m; ++a) out.outlier[a] = !out.types[a].has_value();

  // Pairs that the link set can constrain: both types known, and close enough that the true
  // objects are surely linked (phi + tau < varpi).
  // The percepts filtered: the max_filtered_percepts most precise ones.
  std::vector<int> by_precision;
  for (std::size_t a = 0; a < m; ++a) {
    if (!out.outlier[a]) by_precision.push_back(static_cast<int>(a));
  }
  std::stable_sort(by_precision.begin(), by_precision.end(),
                   [&](int a, int b) { return noise[a].sigma_m < noise[b].sigma_m; });
  std::vector<bool> filtered(m, false);
  for (std::size_t r = 0; r < by_precision.size(); ++r) {
    filtered[by_precision[r]] =
        r < static_cast<std::size_t>(std::max(options.max_filtered_percepts, 0));
  }
  std::vector<PerceptPair> linkable;
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = a + 1; b < m; ++b) {
      if (!filtered[a] || !filtered[b]) continue;
      const PerceptPair pair =
          make_percept_pair(static_cast<int>(a), static_cast<int>(b), percepts, noise, options);
      if (pair.distance_m + pair.tau_m < graph.link_threshold_m()) linkable.push_back(pair);
    }
  }

  // Rounds: an outlier found in one round gave (or withheld) support to its partners; run again
  // without it so that it neither props up nor pulls down anybody. Each round removes at least
  // one percept, so there are at most m rounds; in practice one or two.
  std::vector<bool> excluded = out.outlier;
  for (;;) {
    ++out.rounds;
    filter_round(graph, adjacency, linkable, excluded, options, out);
    bool grown = false;
    for (std::size_t a = 0; a < m; ++a) {
      if (out.outlier[a] && !excluded[a]) excluded[a] = grown = true;
    }
    if (!grown) break;
  }
  for (const PerceptPair& pair : linkable) {
    if (!out.outlier[pair.a] && !out.outlier[pair.b]) out.pairs.push_back(pair);
  }
  return out;
}

}  // namespace vsl::localization
