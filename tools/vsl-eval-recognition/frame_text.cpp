// The text dump of an evaluated frame (frame_text.hpp).
#include "frame_text.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <fstream>
#include <map>

#include "funnel.hpp"
#include "recognition_views.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/head/joint_state.hpp"
#include "vsl/recognition/frame_recognizer.hpp"
#include "vsl/recognition/labelling.hpp"
#include "vsl/recognition/recognizer_factory.hpp"
#include "vsl/recognition/stereo_match.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::tools {

bool write_frame_text(const std::string& path, const FrameTextInput& input, FunnelTally& funnel) {
  const world::WorldModel& world = input.world;
  const StereoRender& frame = input.frame;
  const head::HeadKinematics& head = input.head;
  const recognition::FrameResult& result = input.result;
  const std::vector<recognition::GroundTruthObject>& truth = input.ground_truth;
  const std::vector<recognition::PerceptMatch>& matches = input.matches;
  const std::vector<recognition::RecognizerFile>& model_contents = input.model_contents;
  std::ofstream text(path);
  if (!text) return false;
  text << "# object type distance_m left_visible/in_image/unoccluded_px "
          "right_visible/in_image/unoccluded_px ground_truth facing_cosine\n";
  for (const recognition::GroundTruthObject& object : truth) {
    text << world.objects[object.object_index].id << " " << object.type << " " << object.distance_m
         << " " << object.left_visible_px << "/" << object.left_in_image_px << "/"
         << object.left_unoccluded_px << " " << object.right_visible_px << "/"
         << object.right_in_image_px << "/" << object.right_unoccluded_px << " "
         << (object.visible ? "yes" : "no") << " "
         << (object.flat ? std::to_string(object.facing_cosine) : std::string("-")) << "\n";
  }
  // Where each ground-truth object was lost: per image, the blob holding most of its
  // pixels (purity, coverage: labelling.hpp), whether a recognizer of its type detected that
  // blob, and whether a percept matched the object.
  text << "# funnel: object type whole|cut | left: blob purity coverage detected | right: "
          "... | "
          "percept\n";
  std::vector<char> object_matched(truth.size(), 0);
  for (const recognition::PerceptMatch& m : matches) {
    if (m.ground_truth >= 0) object_matched[static_cast<std::size_t>(m.ground_truth)] = 1;
  }
  // The stereo match again, with its trace: which gate refused the pair of the object's
  // two detections, or whether the assignment kept it.
  std::vector<recognition::StereoPairTrace> pair_trace;
  {
    Eigen::Isometry3d ego_T_left, ego_T_right;
    head.ego_T_cameras(input.joints.positions_rad, ego_T_left, ego_T_right);
    cv::Mat left_grey, right_grey;
    cv::cvtColor(frame.left.image, left_grey, cv::COLOR_BGR2GRAY);
    cv::cvtColor(frame.right.image, right_grey, cv::COLOR_BGR2GRAY);
    recognition::match_and_triangulate(result.left_detections, result.right_detections,
                                       head.calibration().left, head.calibration().right,
                                       ego_T_left.inverse() * ego_T_right, input.stereo_options,
                                       ego_T_left.linear().transpose() * Eigen::Vector3d::UnitZ(),
                                       &pair_trace, {&left_grey, &right_grey});
  }
  for (std::size_t t = 0; t < truth.size(); ++t) {
    const recognition::GroundTruthObject& object = truth[t];
    if (!object.visible) continue;
    text << "funnel " << world.objects[object.object_index].id << " " << object.type
         << (recognition::whole_in_both_images(object) ? " whole" : " cut");
    int left_best = -1;
    std::array<int, 2> detection_index{-1, -1};
    std::array<FunnelSide, 2> funnel_sides;
    for (int side = 0; side < 2; ++side) {
      const auto& blobs = side == 0 ? result.left_blobs : result.right_blobs;
      const auto& detections = side == 0 ? result.left_detections : result.right_detections;
      const cv::Mat& ids = side == 0 ? frame.left.object_ids : frame.right.object_ids;
      const int id = static_cast<int>(object.object_index);
      int best = -1, best_on = 0, best_area = 0, total = 0;
      for (int r = 0; r < ids.rows; ++r) {
        const int* row = ids.ptr<int>(r);
        for (int c = 0; c < ids.cols; ++c) total += row[c] == id;
      }
      for (std::size_t b = 0; b < blobs.size(); ++b) {
        int on = 0;
        for (const recognition::PixelRun& run : blobs[b].runs) {
          const int* row = ids.ptr<int>(run.v);
          for (int c = run.u_begin; c < run.u_end; ++c) on += row[c] == id;
        }
        if (on > best_on) {
          best_on = on;
          best = static_cast<int>(b);
          best_area = static_cast<int>(blobs[b].area_px);
        }
      }
      bool detected = false;
      Eigen::Vector2d reference = Eigen::Vector2d::Zero();
      std::vector<Eigen::Vector2d> corners;
      for (std::size_t i = 0; i < detections.size(); ++i) {
        const recognition::Detection& d = detections[i];
        if (d.blob_index == best && d.type == object.type) {
          detected = true;
          detection_index[static_cast<std::size_t>(side)] = static_cast<int>(i);
          reference = d.reference_px;
          corners = d.corners_px;
        }
      }
      double d2 = -1.0;
      for (const recognition::RecognizerFile& file : model_contents) {
        if (best >= 0 && file.model.type() == object.type) {
          d2 = file.model.mahalanobis2(
              recognition::descriptor_of(file, blobs[static_cast<std::size_t>(best)]));
        }
      }
      if (side == 0) left_best = best;
      FunnelSide& funnel_side = funnel_sides[static_cast<std::size_t>(side)];
      funnel_side.blob = best;
      funnel_side.purity = best_area > 0 ? double(best_on) / best_area : 0.0;
      funnel_side.coverage = total > 0 ? double(best_on) / total : 0.0;
      funnel_side.detected = detected;
      if (best >= 0) {
        const recognition::Blob& blob = blobs[static_cast<std::size_t>(best)];
        funnel_side.at_border = blob.u_min <= 1 || blob.v_min <= 1 || blob.u_max >= ids.cols - 2 ||
                                blob.v_max >= ids.rows - 2;
      }
      text << " | " << best << " " << (best_area > 0 ? double(best_on) / best_area : 0.0) << " "
           << (total > 0 ? double(best_on) / total : 0.0) << " " << (detected ? "det" : "-") << " "
           << d2;
      if (best >= 0) {
        const recognition::Blob& blob = blobs[static_cast<std::size_t>(best)];
        text << " @" << reference.x() << "," << reference.y() << " A" << blob.area_px << " bb"
             << blob.u_min << "," << blob.v_min << "," << blob.u_max << "," << blob.v_max << " q";
        for (const Eigen::Vector2d& c : corners) text << c.x() << "," << c.y() << ";";
        // The other object the blob lies on most, with its share of the blob.
        std::map<int, int> others;
        for (const recognition::PixelRun& run : blob.runs) {
          const int* row = ids.ptr<int>(run.v);
          for (int c = run.u_begin; c < run.u_end; ++c) {
            if (row[c] != id) ++others[row[c]];
          }
        }
        int other = -2, other_px = 0;
        for (const auto& [o, n] : others) {
          if (n > other_px) {
            other = o;
            other_px = n;
          }
        }
        text << " with "
             << (other >= 0 ? world.objects[static_cast<std::size_t>(other)].id
                            : std::string(other == -1 ? "nothing" : "-"))
             << " " << other_px / blob.area_px;
      }
    }
    text << " | " << (object_matched[t] ? "percept" : "-");
    // The percept made from the left blob, if any, and its distance from this object.
    for (const recognition::FramePercept& p : result.percepts) {
      if (p.left_detection < 0) continue;  // a single-view percept from the right image
      const recognition::Detection& d =
          result.left_detections[static_cast<std::size_t>(p.left_detection)];
      if (d.type == object.type && d.blob_index == left_best) {
        text << " " << (p.ego_position_m - object.ego_position_m).norm();
      }
    }
    std::string stereo = "no_pair";
    for (const recognition::StereoPairTrace& trace : pair_trace) {
      if (trace.left_detection == detection_index[0] &&
          trace.right_detection == detection_index[1]) {
        text << " | stereo " << recognition::stereo_gate_name(trace.refused_by);
        if (trace.refused_by != recognition::StereoGate::kNone) {
          text << " " << trace.value << " limit " << trace.limit;
          stereo = recognition::stereo_gate_name(trace.refused_by);
        } else {
          text << (trace.assigned ? " assigned" : " not_assigned")
               << (trace.occluded_corner ? " occluded_corner" : "");
          stereo = trace.assigned ? "assigned" : "not_assigned";
        }
      }
    }
    const FunnelStage stage =
        funnel_stage(funnel_sides[0], funnel_sides[1], object_matched[t] != 0);
    text << " | stage " << funnel_stage_name(stage) << "\n";
    funnel.add(object.type, recognition::whole_in_both_images(object), stage, stereo);
  }
  // How each percept was made: a pair, one image alone (single_view), a pair cut by the
  // top, bottom, left or right border (cut_top, cut_bottom, cut_left, cut_right) or by two in
  // one image (cut_corner), or a pair with one corner hidden
  // (occluded_corner).
  text << "# percept type left_px right_px distance_m made_by matched_object error_m\n";
  for (std::size_t i = 0; i < result.percepts.size(); ++i) {
    const recognition::FramePercept& p = result.percepts[i];
    const char* made_by = "pair";
    if (p.left_detection < 0 || p.right_detection < 0) {
      made_by = "single_view";
    } else {
      const recognition::BorderCut cut =
          result.left_detections[static_cast<std::size_t>(p.left_detection)].border_cut;
      if (cut == recognition::BorderCut::kTop) made_by = "cut_top";
      if (cut == recognition::BorderCut::kBottom) made_by = "cut_bottom";
      if (cut == recognition::BorderCut::kLeft) made_by = "cut_left";
      if (cut == recognition::BorderCut::kRight) made_by = "cut_right";
      // A corner cut in the right image (its left border), or in the left image (its right one).
      const recognition::BorderCut right_cut =
          result.right_detections[static_cast<std::size_t>(p.right_detection)].border_cut;
      if (right_cut == recognition::BorderCut::kTopLeft ||
          right_cut == recognition::BorderCut::kBottomLeft ||
          cut == recognition::BorderCut::kTopRight || cut == recognition::BorderCut::kBottomRight) {
        made_by = "cut_corner";
      }
      for (const recognition::StereoPairTrace& trace : pair_trace) {
        if (trace.occluded_corner && trace.left_detection == p.left_detection &&
            trace.right_detection == p.right_detection) {
          made_by = "occluded_corner";
        }
      }
    }
    text << "percept " << p.type << " " << p.left_px.x() << "," << p.left_px.y() << " "
         << p.right_px.x() << "," << p.right_px.y() << " "
         << (p.ego_position_m - result.ego_T_left_camera.translation()).norm() << " " << made_by
         << " ";
    if (matches[i].ground_truth >= 0) {
      const auto& object = truth[static_cast<std::size_t>(matches[i].ground_truth)];
      text << world.objects[object.object_index].id << " " << matches[i].error_m << "\n";
    } else {
      text << "- -";
      // What the false positive's blob lies on (labelling.hpp): its left blob, or its
      // right one for a single-view percept from the right image.
      const bool from_left = p.left_detection >= 0;
      const recognition::Detection& d =
          from_left ? result.left_detections[static_cast<std::size_t>(p.left_detection)]
                    : result.right_detections[static_cast<std::size_t>(p.right_detection)];
      const recognition::Blob& blob =
          (from_left ? result.left_blobs
                     : result.right_blobs)[static_cast<std::size_t>(d.blob_index)];
      const cv::Mat& ids = from_left ? frame.left.object_ids : frame.right.object_ids;
      const std::vector<int> visible = recognition::object_pixel_counts(ids, world.objects.size());
      const recognition::BlobLabel label = recognition::label_blob(blob, ids, visible);
      text << " on "
           << (label.object_index >= 0
                   ? world.objects[static_cast<std::size_t>(label.object_index)].id
                   : std::string("background"))
           << " purity " << label.purity << " coverage " << label.coverage;
      // How far the percept is from that object's reference point, when it is one of the
      // evaluated objects of the frame.
      for (const recognition::GroundTruthObject& object : truth) {
        if (static_cast<int>(object.object_index) == label.object_index) {
          text << " off " << (p.ego_position_m - object.ego_position_m).norm();
        }
      }
      text << "\n";
    }
  }
  text.close();
  return !text.fail();
}

}  // namespace vsl::tools
