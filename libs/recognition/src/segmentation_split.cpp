// split_at_slits (segmentation.hpp): a blob of two flush doors, joined where the line barrier
// along their reveal breaks, is cut along the straight slit the reveal leaves in it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "vsl/recognition/segmentation.hpp"

namespace vsl::recognition {
namespace {

// A slit point: the centre of a gap between two runs of one row.
struct SlitPoint {
  int v = 0;
  double u = 0.0;
};

// u = u_ref + slope (v - v_ref).
struct SlitLine {
  double v_ref = 0.0;
  double u_ref = 0.0;
  double slope = 0.0;
  double at(double v) const { return u_ref + slope * (v - v_ref); }
};

constexpr double kMaxSlope = 0.6;      // |du/dv|: within 31 deg of the image vertical
constexpr double kInlierPx = 1.5;      // a slit point on the line
constexpr int kMinSlitRows = 24;       // rows in which the line crosses the blob
constexpr int kCandidatesPerEnd = 12;  // slit points tried at each end of the blob
constexpr int kMaxLevels = 3;          // splits of splits
constexpr int kMaxSlitsTried = 4;      // slits tried per blob when the best cuts off a strip

// The slit points within kInlierPx of `line`, counted once per row.
template <typename Visit>
int count_on_line(const std::vector<SlitPoint>& points, const SlitLine& line, Visit&& visit) {
  int count = 0;
  int last_v = -1;
  for (const SlitPoint& p : points) {
    if (p.v == last_v || std::abs(p.u - line.at(p.v)) > kInlierPx) continue;
    last_v = p.v;
    ++count;
    visit(p);
  }
  return count;
}

// Whether `line` is (about) one of `rejected`: within kInlierPx of it at the blob's top and
// bottom rows.
bool among(const SlitLine& line, const std::vector<SlitLine>& rejected, int v_min, int v_max) {
  return std::any_of(rejected.begin(), rejected.end(), [&](const SlitLine& r) {
    return std::abs(line.at(v_min) - r.at(v_min)) <= 2.0 * kInlierPx &&
           std::abs(line.at(v_max) - r.at(v_max)) <= 2.0 * kInlierPx;
  });
}

// What the slit search looks at: per row (v_min + k) the blob's first column and one past its
// last (0: no pixel in the row), and the slit points, sorted by (v, u).
struct SlitEvidence {
  int v_min = 0;
  int rows = 0;
  std::vector<int> row_first;
  std::vector<int> row_end;
  std::vector<SlitPoint> points;
};

// Vertical slits: gaps of 1..max_slit_width_px between two runs of one row.
SlitEvidence vertical_slit_evidence(const std::vector<PixelRun>& runs,
                                    const SegmentationOptions& options) {
  SlitEvidence e;
  e.v_min = runs.front().v;
  e.rows = runs.back().v - e.v_min + 1;
  e.row_first.assign(static_cast<std::size_t>(e.rows), 0);
  e.row_end.assign(static_cast<std::size_t>(e.rows), 0);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const PixelRun& r = runs[i];
    const auto row = static_cast<std::size_t>(r.v - e.v_min);
    if (e.row_end[row] == 0) e.row_first[row] = r.u_begin;
    e.row_end[row] = r.u_end;
    if (i + 1 < runs.size() && runs[i + 1].v == r.v) {
      const int gap = runs[i + 1].u_begin - r.u_end;
      if (gap >= 1 && gap <= options.max_slit_width_px) {
        e.points.push_back({r.v, 0.5 * (r.u_end + runs[i + 1].u_begin - 1)});
      }
    }
  }
  return e;
}

// The slit lines, best first (through the most slit points), up to kMaxSlitsTried: each the
// best candidate line that is not (about) one already found, refitted; the search stops at the
// first that fails the support test.
std::vector<SlitLine> find_slits(const SlitEvidence& evidence, const SegmentationOptions& options) {
  const int v_min = evidence.v_min;
  const int rows = evidence.rows;
  const int v_max = v_min + rows - 1;
  if (rows < kMinSlitRows) return {};
  const std::vector<int>& row_first = evidence.row_first;
  const std::vector<int>& row_end = evidence.row_end;
  const std::vector<SlitPoint>& points = evidence.points;
  const double min_support = options.min_slit_support;
  // A line needs two points (and the index arithmetic below n >= 2).
  if (points.size() < 2 || static_cast<double>(points.size()) < min_support * kMinSlitRows) {
    return {};
  }

  // Candidate lines through pairs of slit points from the two ends of the blob (a slit along
  // most of the blob has points near both ends), with the number of points on each.
  const std::size_t n = points.size();
  const std::size_t third = std::max<std::size_t>(1, n / 3);
  const std::size_t step = std::max<std::size_t>(1, third / kCandidatesPerEnd);
  std::vector<std::pair<int, SlitLine>> candidates;
  for (std::size_t i = 0; i < third; i += step) {
    for (std::size_t k = 0; k < third; k += step) {
      const std::size_t j = n - 1 - k;
      if (j <= i) break;
      const SlitPoint& a = points[i];
      const SlitPoint& b = points[j];
      if (4 * (b.v - a.v) < rows) continue;
      const SlitLine line{double(a.v), a.u, (b.u - a.u) / double(b.v - a.v)};
      if (std::abs(line.slope) > kMaxSlope) continue;
      candidates.emplace_back(count_on_line(points, line, [](const SlitPoint&) {}), line);
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });

  std::vector<SlitLine> found;
  for (const auto& [count, candidate] : candidates) {
    if (static_cast<int>(found.size()) >= kMaxSlitsTried) break;
    if (among(candidate, found, v_min, v_max)) continue;
    if (count < min_support * kMinSlitRows) break;
    // Least-squares refit to the points on it.
    double sv = 0.0, su = 0.0, svv = 0.0, svu = 0.0;
    int m = 0;
    count_on_line(points, candidate, [&](const SlitPoint& p) {
      sv += p.v;
      su += p.u;
      ++m;
    });
    const double mv = sv / m, mu = su / m;
    count_on_line(points, candidate, [&](const SlitPoint& p) {
      svv += (p.v - mv) * (p.v - mv);
      svu += (p.v - mv) * (p.u - mu);
    });
    const SlitLine line{mv, mu, svv > 0.0 ? svu / svv : 0.0};
    if (std::abs(line.slope) > kMaxSlope) break;
    const int on_line = count_on_line(points, line, [](const SlitPoint&) {});
    int crossing = 0;
    for (int row = 0; row < rows; ++row) {
      const double u = line.at(v_min + row);
      if (row_end[static_cast<std::size_t>(row)] > 0 &&
          u > row_first[static_cast<std::size_t>(row)] &&
          u < row_end[static_cast<std::size_t>(row)] - 1) {
        ++crossing;
      }
    }
    if (crossing < kMinSlitRows || on_line < min_support * crossing) break;
    found.push_back(line);
  }
  return found;
}

// The blob cut in two along its best slit whose pieces are both fronts (below), trying up to
// kMaxSlitsTried lines: the groove of a shaker door's stile often has more support than the
// reveal beside it, which a handle interrupts. Nothing when no slit gives two fronts.
std::optional<std::pair<std::vector<PixelRun>, std::vector<PixelRun>>> cut_at_slit(
    const std::vector<PixelRun>& runs, const std::vector<SlitLine>& slits, long area,
    const SegmentationOptions& options) {
  for (const SlitLine& slit : slits) {
    const SlitLine* const line = &slit;
    std::vector<PixelRun> left, right;
    long left_area = 0, right_area = 0;
    for (const PixelRun& r : runs) {
      // Pixel centres at integers: left of the line are the columns u < line(v).
      const int cut = static_cast<int>(std::ceil(line->at(r.v)));
      if (r.u_begin < cut) {
        left.push_back({r.v, r.u_begin, std::min(r.u_end, cut)});
        left_area += left.back().u_end - left.back().u_begin;
      }
      if (r.u_end > cut) {
        right.push_back({r.v, std::max(r.u_begin, cut), r.u_end});
        right_area += right.back().u_end - right.back().u_begin;
      }
    }
    // Each piece a front of its own: not a strip such as a shaker door's stile, which the groove
    // between the stile and the recessed panel (a slit too) would cut off.
    if (left_area < options.min_blob_px || right_area < options.min_blob_px ||
        static_cast<double>(std::min(left_area, right_area)) <
            options.min_split_piece_fraction * static_cast<double>(area)) {
      continue;
    }
    return std::make_pair(std::move(left), std::move(right));
  }
  return std::nullopt;
}

void split(std::vector<PixelRun> runs, const SegmentationOptions& options, int level,
           std::vector<std::vector<PixelRun>>& out) {
  long area = 0;
  for (const PixelRun& r : runs) area += r.u_end - r.u_begin;
  if (level >= kMaxLevels || area < options.min_split_blob_px || runs.empty()) {
    out.push_back(std::move(runs));
    return;
  }
  auto pieces =
      cut_at_slit(runs, find_slits(vertical_slit_evidence(runs, options), options), area, options);
  if (!pieces) {
    out.push_back(std::move(runs));
    return;
  }
  split(std::move(pieces->first), options, level + 1, out);
  split(std::move(pieces->second), options, level + 1, out);
}

}  // namespace

std::vector<std::vector<PixelRun>> split_at_slits(std::vector<PixelRun> runs,
                                                  const SegmentationOptions& options) {
  std::vector<std::vector<PixelRun>> out;
  if (options.min_split_blob_px <= 0) {
    out.push_back(std::move(runs));
    return out;
  }
  split(std::move(runs), options, 0, out);
  return out;
}

}  // namespace vsl::recognition
