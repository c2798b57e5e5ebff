// Colours and strokes shared by the map and the camera picture, so that a door is the same colour
// in both and in the legend. BGR (OpenCV order), 0-255.
#pragma once

#include <opencv2/core/types.hpp>

#include <string>

namespace vsl::view {

namespace colour {
inline const cv::Scalar kBackground{248, 246, 244};
inline const cv::Scalar kFloor{236, 233, 229};
inline const cv::Scalar kWall{70, 70, 70};
inline const cv::Scalar kText{40, 40, 40};
inline const cv::Scalar kEstimate{40, 150, 20};    // green: the localizer's pose
inline const cv::Scalar kTruth{200, 40, 160};      // purple: the simulator's ground truth
inline const cv::Scalar kHypothesis{0, 140, 255};  // orange: other live hypotheses
inline const cv::Scalar kGaze{30, 30, 220};        // red: where the head is told to look
inline const cv::Scalar kCovariance{40, 150, 20};
}  // namespace colour

// BGR colour of an object or percept type: doors steel blue, handles brass (as the kitchen's
// materials), drawer fronts teal, windows sky blue; any other type a stable colour from its name.
cv::Scalar type_colour(const std::string& type);

// Short label drawn beside a percept ("door" -> "door", "drawer_front" -> "drawer").
std::string type_label(const std::string& type);

}  // namespace vsl::view
