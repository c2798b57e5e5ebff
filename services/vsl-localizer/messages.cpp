#include "messages.hpp"

#include <cmath>

#include "vsl/stereo_frame_t.hpp"

namespace vsl::localizer_daemon {
namespace {

static_assert(static_cast<int>(State::kIdle) == vsl::localizer_status_t::IDLE);
static_assert(static_cast<int>(State::kScanning) == vsl::localizer_status_t::SCANNING);
static_assert(static_cast<int>(State::kFusing) == vsl::localizer_status_t::FUSING);
static_assert(static_cast<int>(State::kValidating) == vsl::localizer_status_t::VALIDATING);
static_assert(static_cast<int>(State::kActiveValidation) ==
              vsl::localizer_status_t::ACTIVE_VALIDATION);
static_assert(static_cast<int>(State::kDone) == vsl::localizer_status_t::DONE);
static_assert(static_cast<int>(State::kFailed) == vsl::localizer_status_t::FAILED);

bool finite(const double* values, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(values[i])) return false;
  }
  return true;
}

vsl::pose_t pose_of(const Eigen::Isometry3d& world_T_ego) {
  vsl::pose_t pose{};
  const Eigen::Vector3d t = world_T_ego.translation();
  Eigen::Quaterniond q(world_T_ego.rotation());
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;  // one sign for one rotation
  for (int i = 0; i < 3; ++i) pose.position_m[i] = t[i];
  pose.orientation_wxyz[0] = q.w();
  pose.orientation_wxyz[1] = q.x();
  pose.orientation_wxyz[2] = q.y();
  pose.orientation_wxyz[3] = q.z();
  return pose;
}

std::vector<vsl::association_t> associations_of(
    const std::vector<localization::Association>& associations) {
  std::vector<vsl::association_t> out;
  out.reserve(associations.size());
  for (const auto& a : associations) {
    vsl::association_t m{};
    m.percept_index = a.percept_index;
    m.model_object_id = a.object_id;
    out.push_back(m);
  }
  return out;
}

// Big-endian readers of the LCM wire format.
struct Reader {
  std::span<const std::uint8_t> bytes;
  std::size_t at = 0;
  bool ok = true;

  std::uint64_t u64() {
    if (bytes.size() - at < 8 || at > bytes.size()) return fail();
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | bytes[at++];
    return v;
  }
  std::uint32_t u32() {
    if (bytes.size() - at < 4 || at > bytes.size()) return static_cast<std::uint32_t>(fail());
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | bytes[at++];
    return v;
  }
  std::uint8_t u8() {
    if (at >= bytes.size()) return static_cast<std::uint8_t>(fail());
    return bytes[at++];
  }
  void skip(std::size_t n) {
    if (bytes.size() - at < n) {
      fail();
      return;
    }
    at += n;
  }
  std::uint64_t fail() {
    ok = false;
    at = bytes.size();
    return 0;
  }
};

}  // namespace

std::variant<std::vector<localization::FusedPercept>, std::string> fused_percepts_from(
    const vsl::fused_percept_list_t& message) {
  if (message.num_percepts < 0 ||
      static_cast<std::size_t>(message.num_percepts) != message.percepts.size()) {
    return std::string("num_percepts disagrees with the percepts");
  }
  std::vector<localization::FusedPercept> out;
  out.reserve(message.percepts.size());
  for (std::size_t i = 0; i < message.percepts.size(); ++i) {
    const vsl::fused_percept_t& m = message.percepts[i];
    if (m.type.empty()) return "percept " + std::to_string(i) + ": empty type";
    if (!finite(m.ego_position_m, 3)) {
      return "percept " + std::to_string(i) + ": position not finite";
    }
    localization::FusedPercept p;
    p.type = m.type;
    p.ego_position_m =
        Eigen::Vector3d(m.ego_position_m[0], m.ego_position_m[1], m.ego_position_m[2]);
    p.support = std::max(1, m.support);
    if (finite(m.ego_covariance_m2, 9)) {
      Eigen::Matrix3d c;
      for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) c(r, k) = m.ego_covariance_m2[3 * r + k];
      }
      const bool usable = c.diagonal().minCoeff() > 0.0 &&
                          (c - c.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * c.norm();
      if (usable) p.ego_covariance_m2 = c;
    }
    out.push_back(std::move(p));
  }
  return out;
}

vsl::gaze_command_t gaze_message(const GazeCommand& command, std::int64_t utime) {
  vsl::gaze_command_t m{};
  m.utime = utime;
  m.request_id = command.gaze_id;
  m.mode = vsl::gaze_command_t::TARGET_POINT;
  for (int i = 0; i < 3; ++i) m.ego_target_m[i] = command.ego_target_m[i];
  m.num_joints = 0;
  return m;
}

vsl::localizer_status_t status_message(const StatusReport& report, std::int64_t utime) {
  vsl::localizer_status_t m{};
  m.utime = utime;
  m.request_id = report.request_id;
  m.state = static_cast<std::int8_t>(report.state);
  m.progress = report.progress;
  m.message = report.message;
  m.num_fused_percepts = report.num_fused_percepts;
  m.num_hypotheses = report.num_hypotheses;
  return m;
}

vsl::pose_estimate_t pose_message(const PoseReport& report, std::int64_t utime) {
  const localization::LocalizationResult& r = report.result;
  vsl::pose_estimate_t m{};
  m.utime = utime;
  m.request_id = report.request_id;
  switch (r.status) {
    case localization::Status::kLocalized:
      m.status = vsl::pose_estimate_t::LOCALIZED;
      break;
    case localization::Status::kAmbiguous:
      m.status = vsl::pose_estimate_t::AMBIGUOUS;
      break;
    case localization::Status::kFailed:
      m.status = vsl::pose_estimate_t::FAILED;
      break;
  }
  m.world_T_ego = pose_of(r.world_T_ego);
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 6; ++k) m.covariance[6 * i + k] = r.covariance(i, k);
  }
  for (const auto& h : r.hypotheses) {
    vsl::pose_hypothesis_t mh{};
    mh.world_T_ego = pose_of(h.world_T_ego);
    mh.score = h.score;
    mh.associations = associations_of(h.associations);
    mh.num_associations = static_cast<std::int32_t>(mh.associations.size());
    m.hypotheses.push_back(std::move(mh));
  }
  m.num_hypotheses = static_cast<std::int32_t>(m.hypotheses.size());
  m.associations = associations_of(r.associations);
  m.num_associations = static_cast<std::int32_t>(m.associations.size());
  m.message = report.message;
  return m;
}

std::optional<FrameHeader> parse_frame_header(std::span<const std::uint8_t> bytes) {
  Reader in{bytes};
  const std::uint64_t hash = in.u64();
  if (!in.ok || hash != static_cast<std::uint64_t>(vsl::stereo_frame_t::getHash())) {
    return std::nullopt;
  }
  FrameHeader header;
  in.u64();  // utime
  header.frame_id = static_cast<std::int64_t>(in.u64());
  const std::uint32_t name_size = in.u32();  // with its terminating NUL
  if (!in.ok || name_size == 0 || name_size > bytes.size()) return std::nullopt;
  in.skip(name_size);
  header.gaze_request_id = static_cast<std::int64_t>(in.u64());
  header.gaze_reached = in.u8() != 0;
  if (!in.ok) return std::nullopt;
  return header;
}

}  // namespace vsl::localizer_daemon
