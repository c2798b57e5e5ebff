// vsl-eval-recognition --images: the learned detector on labelled photographs (a YOLO folder
// pair), per class precision and recall at the detector's thresholds, AP50, the precision-recall
// curve as JSON and a picture grid of labels and detections.
#pragma once

namespace vsl::tools {

// Runs the mode on the command line (which holds --images); returns the exit code.
int run_image_evaluation(int argc, char** argv);

}  // namespace vsl::tools
