// Class-specific blob descriptors (paper §2.1): the door descriptor V_d (Eq. 2) and the handle
// descriptor V_h (Eq. 3), computed from a Blob (blob.hpp). Every component is scale-invariant:
// the same object 20 px or 400 px across gives (up to pixel quantization) the same descriptor, so
// one Gaussian class model serves every distance.
//
// The paper is terse; this is our precise reading.
//
// Blob frame. Every pixel centre x is expressed in the blob's eigen frame,
//   a = (x - X_c) . e_1,  b = (x - X_c) . e_2,
// e_1, e_2 the unit eigenvectors of the pixel covariance (major, minor axis; eigenvalues
// rho_1 >= rho_2). The extents A = a_max - a_min + 1 and B = b_max - b_min + 1 (pixels; the +1 is
// the pixel's own footprint) span the blob's oriented bounding rectangle.
//
// Door, V_d (Eq. 2), seven components:
//  0 chord_ratio_major  d_max^rho1 / d_min^rho1: the pixels are binned by b in 1 px bins; each
//  bin's
//                       chord along e_1 is (max a - min a + 1). Ratio of the longest to the
//                       shortest chord, over the central 80% of the bins (the outer 10% at each end
//                       are pixel-quantization noise at the corners of a tilted outline). A
//                       rectangle gives 1; a door seen obliquely (a trapezoid whose vertical sides
//                       are h_near and h_far long) gives about h_near / h_far.
//  1 chord_ratio_minor  d_max^rho2 / d_min^rho2: the same with the roles of a and b exchanged.
//  2 elasticity         S_i / L_i normalized by the value of the blob's own oriented bounding
//                       rectangle: (S_i / L_i) / (S_R / L_R), S_R = A B and L_R its outline's
//                       crack length 2 (A + B)(|cos phi| + |sin phi|), phi the angle of e_1 from +u
//                       (L_i is a crack length too: a tilted straight edge is a staircase). S/L
//                       alone grows linearly with the blob's size; the ratio is 1 for a rectangle
//                       at any size and drops for concave (L-shaped, notched, merged) or ragged
//                       blobs.
//  3 theta_1_rad,       the angles of the blob's two long sides from the image vertical, in
//  4 theta_2_rad        [0, pi/2], smaller first. Each long side is the line fitted (least squares)
//                       to the extreme b (min, resp. max) of each 1 px bin of a, over the central
//                       80% of the bins. They restrict the skewness (a parallelogram tilts both)
//                       and the uprightness: door panels are taller than wide, so their long sides
//                       are verticals (both near 0; the neck pitch tilts them a few degrees), while
//                       drawer fronts and countertop edges are wide and short (both near pi/2).
//  5 log_aspect         ADDED (not in Eq. 2): 0.5 ln((rho_1 + 1/12) / (rho_2 + 1/12)), the log of
//                       the length-to-width ratio (exactly ln(A/B) for an axis-aligned A x B
//                       rectangle; the 1/12 is a pixel's own variance). The chord ratios and the
//                       elasticity are 1 for every rectangle, so without it a blob of two merged
//                       neighbouring doors (twice as wide) looks like one door.
//  6 colour_angle_rad   ADDED (not in Eq. 2): arccos(Q_d^ . K_mean^), the angle between the blob's
//                       mean colour and the door's ideal colour, as in Eq. 3. Eq. 2 is shape only,
//                       so an upright rectangular wall patch between two cupboards would pass; the
//                       angle (not the distance) is insensitive to shading and exposure.
//
// Handle, V_h (Eq. 3), three components:
//  0 log_eigenvalue_ratio  ln((rho_1 + 1/12) / (rho_2 + 1/12)): the axis compactness rho_1/rho_2
//                          in the log. A 16 cm x 12 mm bar is a ratio of (13.3)^2 = 178 in theory,
//                          but 2-4 px wide at 4 m the quantized width makes it 60-300: a spread by
//                          factors, which a Gaussian models in the log.
//  1 colour_angle_rad      arccos(Q^ . K_mean^), Q the handle's ideal colour (RGB in [0, 1]).
//  2 colour_distance       ||Q - K_mean|| (RGB in [0, 1]).
// All of them are scale-invariant as they stand.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

#include "vsl/recognition/blob.hpp"

namespace vsl::recognition {

inline constexpr int kDoorDescriptorSize = 7;
inline constexpr int kHandleDescriptorSize = 3;
// Indices of the components that depend on the ideal colour (door_descriptor_names(),
// handle_descriptor_names()).
inline constexpr int kDoorColourAngleComponent = 6;
inline constexpr int kHandleColourAngleComponent = 1;
inline constexpr int kHandleColourDistanceComponent = 2;

// Component names, as written in the model files (class_model.hpp) and checked on loading.
const std::vector<std::string>& door_descriptor_names();
const std::vector<std::string>& handle_descriptor_names();

// The blob in its eigen frame (see above): extents, chords and long sides.
struct BlobAxes {
  double a_min_px = 0.0, a_max_px = 0.0;  // pixel centres along e_1 (major axis), from X_c
  double b_min_px = 0.0, b_max_px = 0.0;  // and along e_2 (minor axis)
  double major_extent_px = 0.0;           // A = a_max - a_min + 1
  double minor_extent_px = 0.0;           // B = b_max - b_min + 1
  double chord_ratio_major = 1.0;         // d_max^rho1 / d_min^rho1
  double chord_ratio_minor = 1.0;         // d_max^rho2 / d_min^rho2
  double side_1_from_vertical_rad = 0.0;  // theta_1 <= theta_2, [0, pi/2]
  double side_2_from_vertical_rad = 0.0;
};

// Computes BlobAxes in two passes over the blob's pixels. Requires a non-empty blob.
BlobAxes blob_axes(const Blob& blob);

// Angle of the major axis from +u, in [0, pi) (Detection::major_axis_angle_rad).
double major_axis_angle_rad(const Blob& blob);

// arccos(Q^ . K^) in [0, pi]; pi/2 when either colour is black (no chromaticity).
double colour_angle_rad(const Eigen::Vector3d& ideal_rgb, const Eigen::Vector3d& colour_rgb);

// V_d (Eq. 2 plus the two added components), size kDoorDescriptorSize. `axes` = blob_axes(blob).
Eigen::VectorXd door_descriptor(const Blob& blob, const BlobAxes& axes,
                                const Eigen::Vector3d& ideal_colour_rgb);
Eigen::VectorXd door_descriptor(const Blob& blob, const Eigen::Vector3d& ideal_colour_rgb);

// V_h (Eq. 3), size kHandleDescriptorSize.
Eigen::VectorXd handle_descriptor(const Blob& blob, const Eigen::Vector3d& ideal_colour_rgb);

// The components of V_d (V_h) that depend on the ideal colour, set for a blob of mean colour
// `colour_rgb`: training that learns the class's ideal colour recomputes them without the blob.
void set_door_colour_components(Eigen::VectorXd& v, const Eigen::Vector3d& ideal_colour_rgb,
                                const Eigen::Vector3d& colour_rgb);
void set_handle_colour_components(Eigen::VectorXd& v, const Eigen::Vector3d& ideal_colour_rgb,
                                  const Eigen::Vector3d& colour_rgb);

}  // namespace vsl::recognition
