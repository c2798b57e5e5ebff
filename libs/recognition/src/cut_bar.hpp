// A bar (a handle) that the same image border cuts at one end in both images (Detection::
// border_cut; StereoMatchOptions::CutBar): its centre from the end both images show and the
// class's typical length. Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>

#include <optional>

#include "triangulation.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// The bar's centre and the covariance its unknown length adds (left camera frame, visible
// surface; metres, m^2).
struct CutBarCentre {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d length_covariance_m2 = Eigen::Matrix3d::Zero();
};

// `span`: the union of the two views (Triangulator::bar_span), `border`: the image border that
// cuts both views (kTop, kBottom, kLeft or kRight). The end of the span that projects farther
// from that border in the left image is the bar's own; the centre lies typical_length_m / 2 from
// it along the span, towards the cut end. nullopt, with the refusal in `trace`, when the span's
// length is outside 0.4 .. 1.1 of the typical length (kExtent: a short piece places the centre
// from too little, a longer one is no such bar) or an end projects behind the left camera.
std::optional<CutBarCentre> place_cut_bar(const Triangulator::BarSpan& span, BorderCut border,
                                          const Triangulator& triangulator,
                                          const StereoMatchOptions::CutBar& bar,
                                          StereoPairTrace& trace);

}  // namespace vsl::recognition::detail
