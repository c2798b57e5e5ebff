// Per-class tallies of a recognition evaluation (docs/recognition.md): percepts matched to the
// ground truth (labelling.hpp: within 10 cm of a visible object of their type, one to one),
// precision over the true and false positives (percepts of real objects the ground truth leaves
// out are neither), recall over the visible objects, the 3D error of the matched
// percepts by distance band, and the time per stereo pair.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/labelling.hpp"

namespace vsl::tools {

// Distance bands of the 3D error, by the object's distance from the left camera: [0, 1), [1, 2),
// [2, 3), [3, 4] m.
inline constexpr int kDistanceBands = 4;
int distance_band(double distance_m);

// Viewing-angle bands of the recall of flat objects (GroundTruthObject::flat, doors), by the angle
// between the face's normal and the ray to the left camera: [0, 30), [30, 45), [45, 60), [60, 70),
// [70, 80), [80, 90] degrees. Where the recall is lost: a door seen 80 degrees off its normal is a
// sliver a twentieth of its width, merged with its neighbour along a run of cupboards.
// A false positive this near an object of its own type is counted as misplaced.
inline constexpr double kMisplacedDistanceM = 0.5;

inline constexpr int kViewingAngleBands = 6;
inline constexpr std::array<double, kViewingAngleBands> kViewingAngleBandStartsDeg{0,  30, 45,
                                                                                   60, 70, 80};
int viewing_angle_band(double facing_cosine);

struct ClassTally {
  std::string type;
  int ground_truth = 0;  // visible objects of the type, summed over the frames
  int percepts = 0;      // every percept of the type within range (see tally_frame)
  int out_of_range = 0;  // percepts farther away: outside the evaluated range, not counted
  int true_positives = 0;
  // The same over the ground-truth objects whose whole outline lies inside both images
  // (recognition::whole_in_both_images: not cut by the image border).
  int ground_truth_whole = 0;
  int true_positives_whole = 0;
  // Unmatched percepts within the match distance of a real object of the type that is not in
  // the ground truth (farther than the limit, or less than half visible): a correct percept of an
  // object the ground truth leaves out, neither a true nor a false positive (as detections of
  // "difficult" or "don't care" objects in the PASCAL VOC and KITTI benchmarks).
  int false_positives_on_other_objects = 0;
  // The false positives by what lies nearest them: an object of their type within
  // kMisplacedDistanceM (misplaced: a real object, its reference point off), else an object of
  // another type within the match distance (mistyped), else nothing (spurious).
  int false_misplaced = 0;
  int false_mistyped = 0;
  std::array<std::vector<double>, kDistanceBands> errors_m;  // matched percepts' 3D errors
  // And their squared Mahalanobis distances e^T Sigma^-1 e under the percept's own covariance:
  // for an honest covariance chi-square with 3 degrees of freedom (median 2.37, 97 % within 3
  // sigmas, the localizer's gate); much lower, the covariance is too wide, higher, too narrow.
  std::array<std::vector<double>, kDistanceBands> mahalanobis2;
  // Flat ground-truth objects and their true positives by viewing-angle band, all and whole.
  std::array<int, kViewingAngleBands> flat_ground_truth{}, flat_true_positives{};
  std::array<int, kViewingAngleBands> flat_ground_truth_whole{}, flat_true_positives_whole{};

  int false_positives() const {
    return percepts - true_positives - false_positives_on_other_objects;
  }
  // Over the percepts that are true or false positives (the others left out, as above).
  double precision() const {
    const int judged = true_positives + false_positives();
    return judged == 0 ? 1.0 : double(true_positives) / judged;
  }
  // Over every percept in range: the correct percepts of objects outside the ground truth count
  // as false positives.
  double precision_strict() const {
    return percepts == 0 ? 1.0 : double(true_positives) / percepts;
  }
  double recall() const { return ground_truth == 0 ? 1.0 : double(true_positives) / ground_truth; }
  double recall_whole() const {
    return ground_truth_whole == 0 ? 1.0 : double(true_positives_whole) / ground_truth_whole;
  }
};

struct EvaluationTally {
  std::vector<ClassTally> classes;  // one per evaluated type
  int frames = 0;
  std::vector<double> frame_ms, segmentation_ms, classification_ms, stereo_ms;
};

// Adds one frame: `ground_truth` marked (mark_ground_truth_visible), the recognizer's result and
// its wall time. Percepts farther than max_distance_m + max_error_m from the left camera lie
// outside the evaluated range (the ground truth stops at max_distance_m): they are counted apart,
// not as false positives. Returns the match of each percept (match_percepts).
std::vector<recognition::PerceptMatch> tally_frame(
    const std::vector<recognition::GroundTruthObject>& ground_truth,
    const recognition::FrameResult& result, double frame_ms, double max_distance_m,
    double max_error_m, EvaluationTally& tally);

// The q-quantile (0..1) of `values` by linear interpolation between order statistics; NaN when
// empty.
double quantile(std::vector<double> values, double q);

}  // namespace vsl::tools
