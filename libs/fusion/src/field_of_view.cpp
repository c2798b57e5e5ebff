#include "vsl/fusion/field_of_view.hpp"

#include "vsl/fusion/fusion_options.hpp"

namespace vsl::fusion {

FieldOfView::FieldOfView(const head::CameraIntrinsics& left, double image_margin_px,
                         double min_depth_m, double max_range_m)
    : left_(left),
      margin_px_(image_margin_px),
      min_depth_m_(min_depth_m),
      max_range_m_(max_range_m) {}

FieldOfView::FieldOfView(const head::CameraIntrinsics& left, const FusionOptions& options)
    : FieldOfView(left, options.image_margin_px, options.min_depth_m, options.max_range_m) {}

bool FieldOfView::sees(const Eigen::Isometry3d& ego_T_left_camera,
                       const Eigen::Vector3d& ego_point_m) const {
  // Camera frame: x right, y down, z forward.
  const Eigen::Vector3d camera_point_m = ego_T_left_camera.inverse() * ego_point_m;
  const double z = camera_point_m.z();
  if (z < min_depth_m_ || z <= 0.0) return false;
  if (camera_point_m.norm() > max_range_m_) return false;
  const double u_px = left_.fx_px * camera_point_m.x() / z + left_.cx_px;
  const double v_px = left_.fy_px * camera_point_m.y() / z + left_.cy_px;
  // Pixel centres at integer coordinates (OpenCV): the image spans [-0.5, size - 0.5].
  return u_px >= margin_px_ - 0.5 && u_px <= left_.width_px - 0.5 - margin_px_ &&
         v_px >= margin_px_ - 0.5 && v_px <= left_.height_px - 0.5 - margin_px_;
}

}  // namespace vsl::fusion
