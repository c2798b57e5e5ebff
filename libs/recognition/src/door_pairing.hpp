// The door pairs of the cross match placed by the door's fit (partly_seen_door.hpp): the sides'
// correlation into the fit, the pre-gates on the outlines, the pairs the image border cuts, and
// the whole pairs an occluder explains after the assignment. Internal to vsl_recognition.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "partly_seen_door.hpp"
#include "stereo_assignment.hpp"
#include "stereo_views.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// What a fit of a door explains: the outlines as they are (whole, or cut by the image border), an
// occluder hiding the door's lower part, or one hiding a corner.
enum class Explanation { kOutlines, kLowerPartHidden, kCornerHidden };

// The pair (l, r) judged as one door (partly_seen_door.hpp), each view's corners in the states
// given; an outline corner beyond the image is where the outline's sides would meet, not a corner
// the image shows, so the door's own corner there is hidden.
std::optional<Candidate> judge_door(const StereoViews& v, int l, int r,
                                    const std::array<CornerState, 4>& left,
                                    const std::array<CornerState, 4>& right, StereoPairTrace& trace,
                                    Explanation explanation = Explanation::kOutlines);

// Whether a pair of views is a pair of door outlines, judged by the door's fit: their class has
// sizes (door_classes), both have four corners, the up direction is known, and cut views can be
// of one door (cuts_of_one_door).
bool is_door_pair(const StereoViews& v, int l, int r);

// The detections no pair took, paired by an occluder's explanation (explain_by_occluder) of
// their pair's refusal in `occluded`, one to one; the pairs so placed are added to `assigned`
// and their traces in `traces` (when given) replaced. After the cross match's assignment, so that
// an occluder explains only what the whole views could not pair.
void explain_unpaired_by_occluder(const StereoViews& v, std::vector<StereoPairTrace> occluded,
                                  std::vector<Candidate>& assigned,
                                  std::vector<StereoPairTrace>* traces);

}  // namespace vsl::recognition::detail
