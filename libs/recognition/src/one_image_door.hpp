// A door outline of one image that no pair took, placed by the door's fit (partly_seen_door.hpp)
// with what the other image shows of its vertical sides. The other image's blob of the door is
// merged with a neighbour, cut away by that image's border, or off the class model, so there is
// no outline to pair with; its pixels still show where the door's sides are. Each side the caller
// names is swept into the other image over the whole depth range (side_correlation.hpp) and
// becomes that image's view of the side: its two ends on side (the sweep measures the side's
// horizontal position, not where it ends). The own image's outline gives its corners in the
// states its border cut gives them (corner_states_of). A side not swept gives nothing in the
// other image (CornerState::kAbsent); the fit places it from the own image's corners on the door's
// level edges, which must measure the door's width (not the class's guess), and the other image
// must then agree: the side so placed lies beyond that image's border on its side (or within
// kMaxInsideBorderPx of it), or that image shows it there. A swept side is
// held to two pixel sigmas of the fit, the outline's corners to the position gate of whole pairs;
// a door swept on both sides has no viewing-angle or least-width bound (limits_of).
//
// Which sides are swept:
//   kBoth    whole outlines (StereoMatchOptions::min_single_view_correlation);
//   kInner   the side the other image shows even near its border (the right side of a left
//            outline, the left side of a right one): whole outlines or outlines cut by the top or
//            bottom border whose other side the other image cannot show, or shows at one of two
//            peaks of a repeated edge;
//   kOuter   the other side of a whole outline, the inner one placed.
// A side whose sweep peaks twice within min_peak_margin gives both peaks (the second
// refined a pixel either way); exactly one combination of the sides' peaks must make a door, each
// of its peaks scoring min_single_view_correlation. Internal to vsl_recognition.
#pragma once

#include <optional>

#include "stereo_views.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

enum class SweptSides { kBoth, kInner, kOuter };

// The percept of detection `index` of image `image` (0 left, 1 right) placed from that image:
// the fit's centre (left camera frame, `reference_depth_offset_m` of its type behind the face
// along the ray) and covariance, the other image's pixel the centre's projection, and the
// confidence the detection's times the lowest swept side's score. nullopt unless the door is
// placed, its type has a door class (StereoMatchOptions::door_classes), the up direction is known
// and the images could be correlated.
std::optional<StereoPercept> place_one_image_door(const StereoViews& v, int image, int index,
                                                  SweptSides sides);

}  // namespace vsl::recognition::detail
