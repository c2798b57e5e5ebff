// The one-to-one assignment of the stereo cross match (stereo_match.hpp): the Hungarian method
// over the admissible pairs, then the ordering constraint. Internal to vsl_recognition.
#pragma once

#include <vector>

#include "epipolar.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/detection.hpp"

namespace vsl::recognition::detail {

// An admissible left-right pair.
struct Candidate {
  int left = -1;
  int right = -1;
  double cost = 0.0;  // normalized: sum of (gate quantity / its limit)^2, each term <= 1
  Triangulation triangulation;
};

// One-to-one assignment over the candidate pairs (left detections 0..left_count-1, right
// 0..right_count-1): as many matches as possible and, among those, the least total cost; per
// connected component of the candidate graph (components are independent and usually small), the
// Hungarian method on the component's admissible costs plus one "unmatched" column per left
// detection. Sorted by left detection.
std::vector<Candidate> assign(const std::vector<Candidate>& candidates, int left_count,
                              int right_count);

// The ordering constraint of stereo: two objects side by side (the two handles of a double door)
// appear in the same left-to-right order in both images; crossed matches put one of them far in
// front of the other, where nothing is. The assignment's costs (area, orientation; the position
// gate of bars is 0 for every pair within the other) cannot tell two such twins apart, so two
// assigned pairs of one type whose detections overlap in rows in the left image and that cross
// are replaced by the uncrossed pairs, when both of those are candidates too.
void uncross(std::vector<Candidate>& assigned, const std::vector<Candidate>& candidates,
             const std::vector<Detection>& left, const std::vector<IdealPixel>& left_ideal,
             const std::vector<IdealPixel>& right_ideal);

}  // namespace vsl::recognition::detail
