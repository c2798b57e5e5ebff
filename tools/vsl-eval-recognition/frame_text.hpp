// The text dump of an evaluated frame (vsl-eval-recognition --dump DIR, docs/recognition.md):
// DIR/frame_NNNN.txt beside the pictures of frame_dump.hpp, for people to read where each
// ground-truth object was lost and how each percept was made.
#pragma once

#include <string>
#include <vector>

// Declared only, so that this header pulls in neither OpenCV nor the renderer's or the world
// model's headers (frame_text.cpp includes them).
namespace vsl::head {
class HeadKinematics;
struct JointState;
}  // namespace vsl::head

namespace vsl::recognition {
struct FrameResult;
struct GroundTruthObject;
struct PerceptMatch;
struct RecognizerFile;
struct StereoMatchOptions;
}  // namespace vsl::recognition

namespace vsl::world {
class WorldModel;
}

namespace vsl::tools {

class FunnelTally;
struct StereoRender;

// What one frame's text is made of: the evaluation loop's objects of that frame, not copied.
struct FrameTextInput {
  const world::WorldModel& world;
  const StereoRender& frame;       // the rendered pair with its id buffers
  const head::JointState& joints;  // the view's, to place the cameras for the stereo trace
  const head::HeadKinematics& head;
  const recognition::StereoMatchOptions& stereo_options;  // the recognizer's
  const recognition::FrameResult& result;
  const std::vector<recognition::GroundTruthObject>& ground_truth;
  const std::vector<recognition::PerceptMatch>& matches;  // per percept of `result`
  // The model files' contents, for the Mahalanobis distance of each object's blob.
  const std::vector<recognition::RecognizerFile>& model_contents;
};

// Writes the frame's text dump: the objects in view (pixel counts, distance, whether they count as
// ground truth), a funnel line per visible ground-truth object (per image its blob, whether it was
// detected, the stereo gate of its pair, and the stage where it was lost), and how each percept was
// made; adds each visible ground-truth object's stage to `funnel`. False when `path` cannot be
// written.
bool write_frame_text(const std::string& path, const FrameTextInput& input, FunnelTally& funnel);

}  // namespace vsl::tools
