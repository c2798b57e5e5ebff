// Rejection of isolated percepts (paper §2.1.1): a percept of frame t is kept when a percept of
// the same type from another frame within t's frame range [varsigma_0(t), varsigma_1(t)] lies
// closer than varpi.
//
// The frame range is the frames that share visual space with t. A percept q of frame u lies in
// u's field of view by construction, so when |p - q| < varpi frame u looked at p's neighbourhood:
// it is in t's frame range there. The test therefore compares with every other frame of the scan
// and needs no camera model; a uniform grid of cell size varpi keeps it linear in the percepts.
#pragma once

#include <vector>

#include "vsl/fusion/percept.hpp"

namespace vsl::fusion {

// keep[f][i] for percept i of frames[f].
std::vector<std::vector<bool>> non_isolated(const std::vector<Frame>& frames,
                                            double isolation_distance_m);

}  // namespace vsl::fusion
