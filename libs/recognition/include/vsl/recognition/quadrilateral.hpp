// The outline of a planar rectangle (a door's front face) seen through a pinhole camera is a
// convex quadrilateral, and the point where its diagonals cross is the image of the rectangle's
// centre: incidence is preserved by any projection, while the blob's centroid (the centre of the
// projected area) is not the projection of the face's centre under perspective. At 2 m, a door
// seen at 45 deg has its centroid a few centimetres off the centre of its face; worse, the
// centroid moves with every pixel segmentation adds or drops at the outline (a shaded strip at
// the bottom of the door in one image and not in the other), and each pixel of left-right
// difference is depth error (1 px of disparity is 20 cm at 3 m). The four sides fitted by least
// squares to hundreds of outline pixels each are sub-pixel and the same in both images.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

#include "vsl/recognition/blob.hpp"

namespace vsl::recognition {

struct BlobQuadrilateral {
  // Corners clockwise on the screen (v down) from the one of least u + v, so that the corners of
  // one rectangle seen by two cameras correspond (image coordinates, pixel centres at integers).
  std::array<Eigen::Vector2d, 4> corners;
  Eigen::Vector2d centre_px = Eigen::Vector2d::Zero();  // where the diagonals cross
  double area_px = 0.0;                                 // of the quadrilateral
  // Mean length of the two sides nearest the image vertical, pixels: the image of a door's
  // vertical edges (a length that a camera turning about the vertical does not foreshorten).
  double vertical_side_px = 0.0;
  // Fraction of the blob's outline pixels within the fit tolerance of a side (1 for a clean
  // quadrilateral; a blob of two doors in an L or a door with a big bite out of it scores low).
  double outline_fit = 0.0;
  // The least, over the four sides, of the fraction of the side's length that outline pixels
  // (not on the image border) lie along: near 1 when every side is seen; low for a side that is
  // only the hull's chord across a gap, or where the image border cuts the object.
  double min_side_support = 0.0;
  // The same per side: side k runs from corners[k] to corners[k + 1 mod 4] (0 the top, 2 the
  // bottom of an upright rectangle).
  std::array<double, 4> side_support{};
};

// Fits a convex quadrilateral to the outline of `blob`: the four-vertex simplification of the
// outline's convex hull, then each side refitted (total least squares, again without the pixels
// more than 1.5 px off) to the outline pixels near it, the corners from the intersections of
// neighbouring sides. Empty when the blob is too small (fewer than 8 px across), the hull does not
// simplify to four vertices, or the result is not a convex quadrilateral holding the blob's
// centroid.
//
// With the image's size, outline pixels on the image border are left out of the sides (and of
// outline_fit and min_side_support): where the border cuts off a corner of a rectangle, its two
// sides still meet at the corner outside the image; where it cuts off a whole side, the side
// along the border has no support.
std::optional<BlobQuadrilateral> fit_quadrilateral(const Blob& blob, int image_width = 0,
                                                   int image_height = 0);

}  // namespace vsl::recognition
