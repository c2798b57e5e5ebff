// Where the ground-truth objects were lost (vsl-eval-recognition --dump): per visible ground-truth
// object, the first stage of the pipeline it did not pass, tallied per class and per whole / cut
// (recognition::whole_in_both_images), with the stereo gate that refused the pairs detected in both
// images. The figures behind docs/recognition.md's "what still limits" paragraphs.
#pragma once

#include <array>
#include <map>
#include <ostream>
#include <string>
#include <utility>

namespace vsl::tools {

// The object in one image: the blob holding most of its pixels (purity: the object's share of the
// blob; coverage: the blob's share of the object's visible pixels, labelling.hpp), whether a
// recognizer of the object's type detected that blob, and whether the blob touches the image
// border.
struct FunnelSide {
  int blob = -1;  // -1: no blob holds any of its pixels
  double purity = 0.0;
  double coverage = 0.0;
  bool detected = false;
  bool at_border = false;
};

enum class FunnelStage {
  kPercept,             // a true percept matched it
  kNoBlob,              // no blob in one image
  kMerged,              // its blob is under 90% this object in one image (joined to another)
  kFragment,            // its blob holds under 60% of it in one image
  kStereo,              // detected in both images, no true percept (see the stereo gate)
  kUndetectedAtBorder,  // not detected in one image, its blob touching the image border
  kUndetected,          // not detected in one image
};
inline constexpr int kFunnelStages = 7;
const char* funnel_stage_name(FunnelStage stage);

// In the order of the enum: the first that applies.
FunnelStage funnel_stage(const FunnelSide& left, const FunnelSide& right, bool matched);

class FunnelTally {
 public:
  // `stereo`: for kStereo, the gate that refused the pair of the two detections
  // (recognition::stereo_gate_name), or "assigned" (kept, but more than the match distance off),
  // "not_assigned" (admissible, the assignment kept another pair), "no_pair".
  void add(const std::string& type, bool whole, FunnelStage stage, const std::string& stereo);
  // A table, one row per class and whole / cut, then the stereo gates of each row's kStereo.
  void print(std::ostream& out) const;

 private:
  struct Row {
    std::array<int, kFunnelStages> stages{};
    std::map<std::string, int> stereo;
  };
  std::map<std::pair<std::string, bool>, Row> rows_;  // (type, whole)
};

}  // namespace vsl::tools
