// Labels from the simulator's object-id buffer (libs/render: one world-object index per pixel, -1
// where nothing), for training the class models (paper §2.1: "trained from labelled images") and
// for evaluating recognition against ground truth (paper §2.1 requires the class-specific
// recognizers to solve data association up to the class, so errors are counted per class).
//
// Training: a blob lies on the object most of its pixels show (purity) and covers some fraction of
// that object's visible pixels (coverage). It is a positive sample of class c when that object is
// of type c, purity >= 0.9 and coverage >= 0.6 (a whole object, not a fragment of one); it is a
// negative sample when (almost) none of its pixels lie on objects of type c; otherwise it is not
// used (a fragment of a door is neither a good door nor a good non-door).
//
// Ground truth for evaluation: an object of an evaluated type whose reference point X_i lies
// within 4 m of the left camera and that is at least half visible in both images. "Half visible"
// compares its pixels in the rendering of the whole world with those in an unoccluded rendering of
// the recognizable objects alone (doors, handles, drawer fronts), made with a wider field of view
// so that objects cut by the image border count as partly hidden too.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "vsl/recognition/blob.hpp"

namespace cv {
class Mat;
}

namespace vsl::recognition {

// Number of pixels of each object in an id buffer (CV_32S, -1 = nothing): counts[i] for object
// index i < object_count. Ids outside [-1, object_count) throw std::invalid_argument.
std::vector<int> object_pixel_counts(const cv::Mat& object_ids, std::size_t object_count);

// The object a blob lies on.
struct BlobLabel {
  int object_index = -1;  // the id most of its pixels carry (-1: mostly background)
  double purity = 0.0;    // fraction of the blob's pixels on that object, 0 .. 1
  double coverage = 0.0;  // fraction of that object's visible pixels the blob covers, 0 .. 1
};

// Labels `blob` (from an image whose id buffer is `object_ids`, CV_32S of the image's size) with
// the majority object; `visible_px` are object_pixel_counts() of the same buffer. Throws
// std::invalid_argument when the blob leaves the buffer or the buffer has the wrong type.
BlobLabel label_blob(const Blob& blob, const cv::Mat& object_ids, std::span<const int> visible_px);

// Fraction of the blob's pixels on objects whose type is `type` (object_types[i] is the type of
// world object i).
double fraction_on_type(const Blob& blob, const cv::Mat& object_ids,
                        std::span<const std::string> object_types, const std::string& type);

struct SampleLabelOptions {
  double min_purity = 0.9;    // of a positive sample
  double min_coverage = 0.6;  // of a positive sample
  // A negative sample has less than this fraction of its pixels on objects of the class.
  double max_negative_fraction_on_class = 0.1;
};

enum class SampleRole { positive, negative, unused };

// The role of a blob as a training sample of class `type`.
SampleRole sample_role(const BlobLabel& label, double fraction_on_class, bool object_is_of_class,
                       const SampleLabelOptions& options = {});
// The same from the id buffer.
SampleRole sample_role(const Blob& blob, const cv::Mat& object_ids, std::span<const int> visible_px,
                       std::span<const std::string> object_types, const std::string& type,
                       const SampleLabelOptions& options = {});

// --- Ground truth for evaluation -------------------------------------------------------------

struct GroundTruthOptions {
  double max_distance_m = 4.0;        // of the reference point from the left camera centre
  double min_visible_fraction = 0.5;  // in each image, of the unoccluded pixel count
};

// One object of an evaluated type in one stereo frame.
struct GroundTruthObject {
  std::size_t object_index = 0;  // into WorldModel::objects
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();  // reference point X_i, ego frame
  // The object's frame's axes in the ego frame (world::ObjectModel::world_orientation seen from
  // the robot): an error in the ego frame e is R^T e in the object's own axes.
  Eigen::Matrix3d ego_R_object = Eigen::Matrix3d::Identity();
  double distance_m = 0.0;  // from the left camera centre
  int left_visible_px = 0;  // in the rendering of the whole world
  int right_visible_px = 0;
  int left_unoccluded_px = 0;  // in the rendering of the recognizable objects alone
  int right_unoccluded_px = 0;
  // Of the unoccluded pixels, those inside the image (the rest lie in the wider rendering's
  // margin, beyond the image border).
  int left_in_image_px = 0;
  int right_in_image_px = 0;
  // A flat object (a door: one extent under a tenth of the others) has a face; `facing_cosine`
  // is the cosine of the angle between the face's normal and the ray from the reference point to
  // the left camera centre: 1 seen head-on, 0 edge-on (its apparent width shrinks by this
  // factor). 1 for other objects.
  bool flat = false;
  double facing_cosine = 1.0;
  bool visible = false;  // set by mark_ground_truth_visible()
};

// True when the object's whole unoccluded outline lies inside both images (none of its pixels in
// the wider renderings' margin): not cut by the image border, whether or not it is occluded.
bool whole_in_both_images(const GroundTruthObject& object);

// Visible fraction in one image: visible / unoccluded (0 when the object is not in the unoccluded
// image at all; capped at 1, since distortion and pixel rounding can differ between renderings).
double visible_fraction(int visible_px, int unoccluded_px);

// Sets `visible` on every object: within max_distance_m and at least min_visible_fraction in
// both images.
void mark_ground_truth_visible(std::vector<GroundTruthObject>& objects,
                               const GroundTruthOptions& options = {});

// --- Matching percepts to ground truth -------------------------------------------------------

struct PerceptToMatch {
  std::string type;
  Eigen::Vector3d ego_position_m = Eigen::Vector3d::Zero();
  float confidence = 0.0f;
};

struct PerceptMatch {
  int ground_truth = -1;  // index into the ground-truth objects; -1: a false positive
  double error_m = 0.0;   // distance to that object's reference point
};

// Matches percepts to visible ground-truth objects: a percept is a true positive when it lies
// within `max_error_m` of the reference point of a visible object of its type that no other
// percept matched. Percepts are taken in order of decreasing confidence (ties: input order), each
// to its nearest free object, so the result does not depend on how the recognizer ordered them.
// Returns one entry per percept, in input order.
std::vector<PerceptMatch> match_percepts(std::span<const PerceptToMatch> percepts,
                                         std::span<const GroundTruthObject> ground_truth,
                                         double max_error_m = 0.10);

}  // namespace vsl::recognition
