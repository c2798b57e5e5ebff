#include "stereo_assignment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace vsl::recognition::detail {
namespace {

// Leaving a left detection unmatched costs more than any set of admissible pairs can, so that the
// assignment first maximizes the number of matches, then minimizes their total cost.
double unmatched_cost(std::size_t pairs) {
  return 4.0 * static_cast<double>(pairs + 1);
}

// Minimum-cost assignment of rows to columns (rows <= columns), Hungarian method with potentials
// (Kuhn-Munkres, O(rows^2 columns)). cost is row-major rows x columns; returns the column of each
// row.
std::vector<int> hungarian(const std::vector<double>& cost, int rows, int columns) {
  const double inf = std::numeric_limits<double>::infinity();
  // 1-based as in the textbook formulation; column 0 is the virtual start.
  std::vector<double> u(rows + 1, 0.0), v(columns + 1, 0.0);
  std::vector<int> row_of(columns + 1, 0), way(columns + 1, 0);
  for (int i = 1; i <= rows; ++i) {
    row_of[0] = i;
    int j0 = 0;
    std::vector<double> min_slack(columns + 1, inf);
    std::vector<char> used(columns + 1, 0);
    do {
      used[j0] = 1;
      const int i0 = row_of[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= columns; ++j) {
        if (used[j]) continue;
        const double slack = cost[(i0 - 1) * columns + (j - 1)] - u[i0] - v[j];
        if (slack < min_slack[j]) {
          min_slack[j] = slack;
          way[j] = j0;
        }
        if (min_slack[j] < delta) {
          delta = min_slack[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= columns; ++j) {
        if (used[j]) {
          u[row_of[j]] += delta;
          v[j] -= delta;
        } else {
          min_slack[j] -= delta;
        }
      }
      j0 = j1;
    } while (row_of[j0] != 0);
    do {
      const int j1 = way[j0];
      row_of[j0] = row_of[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> column_of(rows, -1);
  for (int j = 1; j <= columns; ++j) {
    if (row_of[j] != 0) column_of[row_of[j] - 1] = j - 1;
  }
  return column_of;
}

}  // namespace

std::vector<Candidate> assign(const std::vector<Candidate>& candidates, int left_count,
                              int right_count) {
  // Components by union-find over left nodes 0..L-1 and right nodes L..L+R-1.
  std::vector<int> parent(left_count + right_count);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Candidate& c : candidates) parent[find(c.left)] = find(left_count + c.right);

  std::vector<std::vector<int>> by_component(left_count + right_count);
  for (int k = 0; k < static_cast<int>(candidates.size()); ++k) {
    by_component[find(candidates[k].left)].push_back(k);
  }
  std::vector<Candidate> out;
  for (const std::vector<int>& members : by_component) {
    if (members.empty()) continue;
    if (members.size() == 1) {
      out.push_back(candidates[members[0]]);
      continue;
    }
    // Local indices of the component's left and right detections.
    std::vector<int> lefts, rights;
    for (int k : members) {
      lefts.push_back(candidates[k].left);
      rights.push_back(candidates[k].right);
    }
    for (auto* v : {&lefts, &rights}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    const int rows = static_cast<int>(lefts.size());
    const int columns = static_cast<int>(rights.size()) + rows;
    const double unmatched = unmatched_cost(members.size());
    // Inadmissible pairs cost more than leaving every row unmatched.
    const double forbidden = 2.0 * unmatched * (rows + 1);
    std::vector<double> cost(static_cast<std::size_t>(rows) * columns, forbidden);
    for (int i = 0; i < rows; ++i) {
      for (int j = static_cast<int>(rights.size()); j < columns; ++j)
        cost[i * columns + j] = unmatched;
    }
    for (int k : members) {
      const int i = static_cast<int>(
          std::lower_bound(lefts.begin(), lefts.end(), candidates[k].left) - lefts.begin());
      const int j = static_cast<int>(
          std::lower_bound(rights.begin(), rights.end(), candidates[k].right) - rights.begin());
      cost[i * columns + j] = candidates[k].cost;
    }
    const std::vector<int> column_of = hungarian(cost, rows, columns);
    for (int k : members) {
      const int i = static_cast<int>(
          std::lower_bound(lefts.begin(), lefts.end(), candidates[k].left) - lefts.begin());
      const int j = column_of[i];
      if (j >= 0 && j < static_cast<int>(rights.size()) && rights[j] == candidates[k].right) {
        out.push_back(candidates[k]);
      }
    }
  }
  std::sort(out.begin(), out.end(),
            [](const Candidate& a, const Candidate& b) { return a.left < b.left; });
  return out;
}

namespace {

// The image rows a detection spans (its extents along the blob axes, projected on the vertical).
double vertical_extent_px(const Detection& d) {
  return std::abs(d.major_extent_px * std::sin(d.major_axis_angle_rad)) +
         std::abs(d.minor_extent_px * std::cos(d.major_axis_angle_rad));
}

}  // namespace

void uncross(std::vector<Candidate>& assigned, const std::vector<Candidate>& candidates,
             const std::vector<Detection>& left, const std::vector<IdealPixel>& left_ideal,
             const std::vector<IdealPixel>& right_ideal) {
  const auto candidate = [&](int l, int r) -> const Candidate* {
    for (const Candidate& c : candidates) {
      if (c.left == l && c.right == r) return &c;
    }
    return nullptr;
  };
  for (std::size_t i = 0; i < assigned.size(); ++i) {
    for (std::size_t j = i + 1; j < assigned.size(); ++j) {
      const int l1 = assigned[i].left, r1 = assigned[i].right;
      const int l2 = assigned[j].left, r2 = assigned[j].right;
      if (left[l1].type != left[l2].type) continue;
      const Eigen::Vector2d dl = left_ideal[l1].ideal_px - left_ideal[l2].ideal_px;
      const Eigen::Vector2d dr = right_ideal[r1].ideal_px - right_ideal[r2].ideal_px;
      const bool side_by_side =
          std::abs(dl.y()) < 0.5 * (vertical_extent_px(left[l1]) + vertical_extent_px(left[l2]));
      if (!side_by_side || !(dl.x() * dr.x() < 0.0)) continue;
      const Candidate* a = candidate(l1, r2);
      const Candidate* b = candidate(l2, r1);
      if (!a || !b) continue;
      assigned[i] = *a;
      assigned[j] = *b;
    }
  }
  std::sort(assigned.begin(), assigned.end(),
            [](const Candidate& a, const Candidate& b) { return a.left < b.left; });
}

}  // namespace vsl::recognition::detail
