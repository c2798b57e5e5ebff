// Encode/decode round trip of every vsl LCM type, and decoding of truncated and garbled buffers.
//
// Every lcmtypes/*.lcm file must appear in AllTypes below (EveryLcmFileIsTested checks it), with a
// Sample() that sets every field to a non-trivial value and an ExpectEq() that compares every
// field.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "vsl/association_t.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/fused_percept_list_t.hpp"
#include "vsl/fused_percept_t.hpp"
#include "vsl/gaze_command_t.hpp"
#include "vsl/ground_truth_pose_t.hpp"
#include "vsl/head_state_t.hpp"
#include "vsl/image_t.hpp"
#include "vsl/localize_request_t.hpp"
#include "vsl/localizer_status_t.hpp"
#include "vsl/percept_list_t.hpp"
#include "vsl/percept_t.hpp"
#include "vsl/pose_estimate_t.hpp"
#include "vsl/pose_hypothesis_t.hpp"
#include "vsl/pose_t.hpp"
#include "vsl/stereo_frame_t.hpp"

namespace {

template <class... Ts>
struct TypeList {
  using Gtest = ::testing::Types<Ts...>;
  static std::set<std::string> Names() { return {Ts::getTypeName()...}; }
  static std::vector<int64_t> Hashes() { return {Ts::getHash()...}; }
};

using AllTypes =
    TypeList<vsl::association_t, vsl::daemon_heartbeat_t, vsl::fused_percept_list_t,
             vsl::fused_percept_t, vsl::gaze_command_t, vsl::ground_truth_pose_t, vsl::head_state_t,
             vsl::image_t, vsl::localize_request_t, vsl::localizer_status_t, vsl::percept_list_t,
             vsl::percept_t, vsl::pose_estimate_t, vsl::pose_hypothesis_t, vsl::pose_t,
             vsl::stereo_frame_t>;

using Bytes = std::vector<uint8_t>;

// ---------------------------------------------------------------------------------------------
// Samples: every field set, arrays non-empty, values that would show byte-order, truncation or
// sign mistakes (negative, fractional, > 32 bit), strings with spaces, UTF-8 and an empty one.

template <size_t N>
void Fill(double (&a)[N], double first, double step) {
  for (size_t i = 0; i < N; ++i) a[i] = first + step * static_cast<double>(i);
}

vsl::pose_t SamplePose(double s) {
  vsl::pose_t p{};
  p.position_m[0] = 12.5 * s;
  p.position_m[1] = -3.25 * s;
  p.position_m[2] = 0.875;
  p.orientation_wxyz[0] = 0.5;
  p.orientation_wxyz[1] = -0.5;
  p.orientation_wxyz[2] = 0.5 * s;
  p.orientation_wxyz[3] = -0.5 * s;
  return p;
}

vsl::image_t SampleImage(int8_t format, int seed) {
  vsl::image_t im{};
  im.utime = 1'700'000'000'123'456 + seed;
  im.width = 5;
  im.height = 3;
  const int bytes_per_pixel = format == vsl::image_t::GRAY8 ? 1 : 3;
  im.row_stride = im.width * bytes_per_pixel + 1;  // padded rows
  im.pixel_format = format;
  im.size = im.row_stride * im.height;
  im.data.resize(im.size);
  for (int i = 0; i < im.size; ++i) im.data[i] = static_cast<uint8_t>((i * 37 + seed) & 0xff);
  return im;
}

vsl::head_state_t SampleHeadState() {
  vsl::head_state_t h{};
  h.utime = 1'700'000'000'000'001;
  h.num_joints = 3;
  h.joint_names = {"neck_pan", "neck_tilt", "eyes vergence"};
  h.joint_positions_rad = {0.25, -0.125, 1.0e-9};
  h.joint_velocities_rad_s = {-0.5, 0.0, 3.5};
  return h;
}

vsl::association_t SampleAssociation(int i) {
  vsl::association_t a{};
  a.percept_index = 7 + i;
  a.model_object_id = "kitchen/door_" + std::to_string(i);
  return a;
}

vsl::percept_t SamplePercept(int i) {
  vsl::percept_t p{};
  p.utime = 1'700'000'000'500'000 + i;
  p.frame_id = 5'000'000'000LL + i;
  p.type = i % 2 == 0 ? "door" : "handle";
  Fill(p.ego_position_m, 1.5 + i, -0.75);
  Fill(p.ego_covariance_m2, 1e-4, 2.5e-5);
  p.shared_sigma_m = 0.0125;
  p.shared_ray_sigma_m = 0.0375;
  Fill(p.ego_camera_position_m, 0.05, 0.1);
  p.left_pixel_uv[0] = 320.25 + i;
  p.left_pixel_uv[1] = 240.5;
  p.right_pixel_uv[0] = 300.75 + i;
  p.right_pixel_uv[1] = 240.25;
  p.confidence = 0.875f;
  return p;
}

vsl::fused_percept_t SampleFusedPercept(int i) {
  vsl::fused_percept_t f{};
  f.type = i == 0 ? "door" : "Tür-Griff";  // UTF-8
  Fill(f.ego_position_m, -2.0 + i, 0.5);
  Fill(f.ego_covariance_m2, 4e-4, -1e-5);
  Fill(f.ego_camera_position_m, 0.01 * i, 0.02);
  f.support = 9 + i;
  f.expected = 12;
  f.confidence = static_cast<double>(f.support) / f.expected;
  return f;
}

vsl::pose_hypothesis_t SampleHypothesis(int i) {
  vsl::pose_hypothesis_t h{};
  h.world_T_ego = SamplePose(1.0 + i);
  h.score = 0.9 - 0.25 * i;
  h.num_associations = 2 + i;
  for (int k = 0; k < h.num_associations; ++k) h.associations.push_back(SampleAssociation(k + i));
  return h;
}

template <class T>
T Sample();

template <>
vsl::pose_t Sample() {
  return SamplePose(1.0);
}

template <>
vsl::image_t Sample() {
  return SampleImage(vsl::image_t::BGR8, 1);
}

template <>
vsl::head_state_t Sample() {
  return SampleHeadState();
}

template <>
vsl::stereo_frame_t Sample() {
  vsl::stereo_frame_t f{};
  f.utime = 1'700'000'000'123'456;
  f.frame_id = 4'294'967'301LL;  // > 32 bit
  f.head_name = "sim head";
  f.gaze_request_id = -1;
  f.gaze_reached = 1;
  f.left = SampleImage(vsl::image_t::BGR8, 2);
  f.right = SampleImage(vsl::image_t::GRAY8, 3);
  f.head = SampleHeadState();
  return f;
}

template <>
vsl::gaze_command_t Sample() {
  vsl::gaze_command_t g{};
  g.utime = 1'700'000'000'000'777;
  g.request_id = 42;
  g.mode = vsl::gaze_command_t::JOINT_TARGETS;
  Fill(g.ego_target_m, 2.5, -1.25);
  g.num_joints = 2;
  g.joint_names = {"neck_pan", "neck_tilt"};
  g.joint_targets_rad = {-0.75, 0.3125};
  return g;
}

template <>
vsl::percept_t Sample() {
  return SamplePercept(1);
}

template <>
vsl::percept_list_t Sample() {
  vsl::percept_list_t l{};
  l.utime = 1'700'000'000'600'000;
  l.frame_id = 77;
  l.frame_utime = 1'700'000'000'500'000;
  l.ego_T_left_camera = SamplePose(-0.5);
  l.num_percepts = 3;
  for (int i = 0; i < l.num_percepts; ++i) l.percepts.push_back(SamplePercept(i));
  return l;
}

template <>
vsl::fused_percept_t Sample() {
  return SampleFusedPercept(1);
}

template <>
vsl::fused_percept_list_t Sample() {
  vsl::fused_percept_list_t l{};
  l.utime = 1'700'000'020'000'000;
  l.request_id = 3;
  l.num_frames = 20;
  l.num_percepts = 2;
  l.percepts = {SampleFusedPercept(0), SampleFusedPercept(1)};
  return l;
}

template <>
vsl::association_t Sample() {
  return SampleAssociation(3);
}

template <>
vsl::pose_hypothesis_t Sample() {
  return SampleHypothesis(1);
}

template <>
vsl::pose_estimate_t Sample() {
  vsl::pose_estimate_t e{};
  e.utime = 1'700'000'021'000'000;
  e.request_id = 3;
  e.status = vsl::pose_estimate_t::AMBIGUOUS;
  e.world_T_ego = SamplePose(2.0);
  for (int i = 0; i < 36; ++i) e.covariance[i] = (i % 7 == 0 ? 1e-3 : -1e-6) * (i + 1);
  e.num_hypotheses = 2;
  e.hypotheses = {SampleHypothesis(0), SampleHypothesis(1)};
  e.num_associations = 3;
  e.associations = {SampleAssociation(0), SampleAssociation(1), SampleAssociation(2)};
  e.message = "two hypotheses remain after active validation";
  return e;
}

template <>
vsl::localizer_status_t Sample() {
  vsl::localizer_status_t s{};
  s.utime = 1'700'000'010'000'000;
  s.request_id = 3;
  s.state = vsl::localizer_status_t::ACTIVE_VALIDATION;
  s.progress = 0.8125;
  s.message = "looking at kitchen/door_2";
  s.num_fused_percepts = 11;
  s.num_hypotheses = 2;
  return s;
}

template <>
vsl::localize_request_t Sample() {
  vsl::localize_request_t r{};
  r.utime = 1'700'000'000'000'000;
  r.request_id = 3;
  r.source = "vsl-localize";
  r.reason = "";  // empty strings must survive too
  return r;
}

template <>
vsl::ground_truth_pose_t Sample() {
  vsl::ground_truth_pose_t g{};
  g.utime = 1'700'000'000'000'000;
  g.world_T_ego = SamplePose(-1.0);
  g.world_name = "kitchen.yaml";
  return g;
}

template <>
vsl::daemon_heartbeat_t Sample() {
  vsl::daemon_heartbeat_t h{};
  h.utime = 1'700'000'000'999'999;
  h.process = "vsl-recognition";
  h.pid = 31337;
  h.state = "running";
  h.uptime_s = 3600.25;
  h.messages_received = 9'000'000'001LL;
  h.messages_published = 123;
  h.messages_dropped = 4;
  h.decode_errors = 1;
  return h;
}

// ---------------------------------------------------------------------------------------------
// Field-by-field equality.

template <size_t N, class V>
void ExpectArrayEq(const V (&a)[N], const V (&b)[N], const char* name) {
  for (size_t i = 0; i < N; ++i) EXPECT_EQ(a[i], b[i]) << name << "[" << i << "]";
}

#define EXPECT_FIELD(f) EXPECT_EQ(a.f, b.f) << #f
#define EXPECT_ARRAY(f) ExpectArrayEq(a.f, b.f, #f)

void ExpectEq(const vsl::pose_t& a, const vsl::pose_t& b) {
  EXPECT_ARRAY(position_m);
  EXPECT_ARRAY(orientation_wxyz);
}

void ExpectEq(const vsl::image_t& a, const vsl::image_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(width);
  EXPECT_FIELD(height);
  EXPECT_FIELD(row_stride);
  EXPECT_FIELD(pixel_format);
  EXPECT_FIELD(size);
  EXPECT_FIELD(data);
}

void ExpectEq(const vsl::head_state_t& a, const vsl::head_state_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(num_joints);
  EXPECT_FIELD(joint_names);
  EXPECT_FIELD(joint_positions_rad);
  EXPECT_FIELD(joint_velocities_rad_s);
}

void ExpectEq(const vsl::stereo_frame_t& a, const vsl::stereo_frame_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(frame_id);
  EXPECT_FIELD(head_name);
  EXPECT_FIELD(gaze_request_id);
  EXPECT_FIELD(gaze_reached);
  {
    SCOPED_TRACE("left");
    ExpectEq(a.left, b.left);
  }
  {
    SCOPED_TRACE("right");
    ExpectEq(a.right, b.right);
  }
  {
    SCOPED_TRACE("head");
    ExpectEq(a.head, b.head);
  }
}

void ExpectEq(const vsl::gaze_command_t& a, const vsl::gaze_command_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(request_id);
  EXPECT_FIELD(mode);
  EXPECT_ARRAY(ego_target_m);
  EXPECT_FIELD(num_joints);
  EXPECT_FIELD(joint_names);
  EXPECT_FIELD(joint_targets_rad);
}

void ExpectEq(const vsl::percept_t& a, const vsl::percept_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(frame_id);
  EXPECT_FIELD(type);
  EXPECT_ARRAY(ego_position_m);
  EXPECT_ARRAY(ego_covariance_m2);
  EXPECT_FIELD(shared_sigma_m);
  EXPECT_FIELD(shared_ray_sigma_m);
  EXPECT_ARRAY(ego_camera_position_m);
  EXPECT_ARRAY(left_pixel_uv);
  EXPECT_ARRAY(right_pixel_uv);
  EXPECT_FIELD(confidence);
}

void ExpectEq(const vsl::percept_list_t& a, const vsl::percept_list_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(frame_id);
  EXPECT_FIELD(frame_utime);
  {
    SCOPED_TRACE("ego_T_left_camera");
    ExpectEq(a.ego_T_left_camera, b.ego_T_left_camera);
  }
  EXPECT_FIELD(num_percepts);
  ASSERT_EQ(a.percepts.size(), b.percepts.size());
  for (size_t i = 0; i < a.percepts.size(); ++i) {
    SCOPED_TRACE("percepts[" + std::to_string(i) + "]");
    ExpectEq(a.percepts[i], b.percepts[i]);
  }
}

void ExpectEq(const vsl::fused_percept_t& a, const vsl::fused_percept_t& b) {
  EXPECT_FIELD(type);
  EXPECT_ARRAY(ego_position_m);
  EXPECT_ARRAY(ego_covariance_m2);
  EXPECT_ARRAY(ego_camera_position_m);
  EXPECT_FIELD(support);
  EXPECT_FIELD(expected);
  EXPECT_FIELD(confidence);
}

void ExpectEq(const vsl::fused_percept_list_t& a, const vsl::fused_percept_list_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(request_id);
  EXPECT_FIELD(num_frames);
  EXPECT_FIELD(num_percepts);
  ASSERT_EQ(a.percepts.size(), b.percepts.size());
  for (size_t i = 0; i < a.percepts.size(); ++i) {
    SCOPED_TRACE("percepts[" + std::to_string(i) + "]");
    ExpectEq(a.percepts[i], b.percepts[i]);
  }
}

void ExpectEq(const vsl::association_t& a, const vsl::association_t& b) {
  EXPECT_FIELD(percept_index);
  EXPECT_FIELD(model_object_id);
}

void ExpectEq(const std::vector<vsl::association_t>& a, const std::vector<vsl::association_t>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE("associations[" + std::to_string(i) + "]");
    ExpectEq(a[i], b[i]);
  }
}

void ExpectEq(const vsl::pose_hypothesis_t& a, const vsl::pose_hypothesis_t& b) {
  {
    SCOPED_TRACE("world_T_ego");
    ExpectEq(a.world_T_ego, b.world_T_ego);
  }
  EXPECT_FIELD(score);
  EXPECT_FIELD(num_associations);
  ExpectEq(a.associations, b.associations);
}

void ExpectEq(const vsl::pose_estimate_t& a, const vsl::pose_estimate_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(request_id);
  EXPECT_FIELD(status);
  {
    SCOPED_TRACE("world_T_ego");
    ExpectEq(a.world_T_ego, b.world_T_ego);
  }
  EXPECT_ARRAY(covariance);
  EXPECT_FIELD(num_hypotheses);
  ASSERT_EQ(a.hypotheses.size(), b.hypotheses.size());
  for (size_t i = 0; i < a.hypotheses.size(); ++i) {
    SCOPED_TRACE("hypotheses[" + std::to_string(i) + "]");
    ExpectEq(a.hypotheses[i], b.hypotheses[i]);
  }
  EXPECT_FIELD(num_associations);
  ExpectEq(a.associations, b.associations);
  EXPECT_FIELD(message);
}

void ExpectEq(const vsl::localizer_status_t& a, const vsl::localizer_status_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(request_id);
  EXPECT_FIELD(state);
  EXPECT_FIELD(progress);
  EXPECT_FIELD(message);
  EXPECT_FIELD(num_fused_percepts);
  EXPECT_FIELD(num_hypotheses);
}

void ExpectEq(const vsl::localize_request_t& a, const vsl::localize_request_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(request_id);
  EXPECT_FIELD(source);
  EXPECT_FIELD(reason);
}

void ExpectEq(const vsl::ground_truth_pose_t& a, const vsl::ground_truth_pose_t& b) {
  EXPECT_FIELD(utime);
  {
    SCOPED_TRACE("world_T_ego");
    ExpectEq(a.world_T_ego, b.world_T_ego);
  }
  EXPECT_FIELD(world_name);
}

void ExpectEq(const vsl::daemon_heartbeat_t& a, const vsl::daemon_heartbeat_t& b) {
  EXPECT_FIELD(utime);
  EXPECT_FIELD(process);
  EXPECT_FIELD(pid);
  EXPECT_FIELD(state);
  EXPECT_FIELD(uptime_s);
  EXPECT_FIELD(messages_received);
  EXPECT_FIELD(messages_published);
  EXPECT_FIELD(messages_dropped);
  EXPECT_FIELD(decode_errors);
}

#undef EXPECT_FIELD
#undef EXPECT_ARRAY

// ---------------------------------------------------------------------------------------------
// Helpers.

template <class T>
Bytes Encode(const T& msg) {
  Bytes buf(static_cast<size_t>(msg.getEncodedSize()));
  const int n = msg.encode(buf.data(), 0, static_cast<int>(buf.size()));
  EXPECT_EQ(n, static_cast<int>(buf.size())) << T::getTypeName();
  return buf;
}

// Decodes buf[0, len) into msg; returns decode()'s result, or INT_MIN if decode() threw.
template <class T>
int Decode(const Bytes& buf, size_t len, T& msg) {
  try {
    return msg.decode(buf.data(), 0, static_cast<int>(len));
  } catch (const std::exception& e) {
    ADD_FAILURE() << T::getTypeName() << "::decode threw " << e.what() << " for " << len
                  << " bytes";
    return std::numeric_limits<int>::min();
  }
}

void PutInt32BigEndian(Bytes& buf, size_t offset, int32_t value) {
  const auto u = static_cast<uint32_t>(value);
  for (int i = 0; i < 4; ++i) buf.at(offset + i) = static_cast<uint8_t>(u >> (24 - 8 * i));
}

int32_t GetInt32BigEndian(const Bytes& buf, size_t offset) {
  uint32_t u = 0;
  for (int i = 0; i < 4; ++i) u = (u << 8) | buf.at(offset + i);
  return static_cast<int32_t>(u);
}

constexpr size_t kHashBytes = 8;  // every encoded message starts with its 64-bit fingerprint

// ---------------------------------------------------------------------------------------------
// Tests run for every type.

template <class T>
class LcmTypes : public ::testing::Test {};

struct TypeName {
  template <class T>
  static std::string GetName(int) {
    return T::getTypeName();
  }
};

TYPED_TEST_SUITE(LcmTypes, AllTypes::Gtest, TypeName);

TYPED_TEST(LcmTypes, RoundTripKeepsEveryField) {
  const TypeParam in = Sample<TypeParam>();
  const Bytes buf = Encode(in);
  TypeParam out{};
  ASSERT_EQ(Decode(buf, buf.size(), out), static_cast<int>(buf.size()));
  ExpectEq(in, out);
  EXPECT_EQ(Encode(out), buf) << "re-encoding the decoded message changes the bytes";
}

TYPED_TEST(LcmTypes, EncodeIntoShortBufferFails) {
  const TypeParam in = Sample<TypeParam>();
  Bytes buf(static_cast<size_t>(in.getEncodedSize()) - 1);
  EXPECT_LT(in.encode(buf.data(), 0, static_cast<int>(buf.size())), 0);
}

TYPED_TEST(LcmTypes, EveryTruncationIsAnError) {
  const Bytes buf = Encode(Sample<TypeParam>());
  for (size_t len = 0; len < buf.size(); ++len) {
    TypeParam out{};
    EXPECT_LT(Decode(buf, len, out), 0) << "truncated to " << len << " of " << buf.size();
  }
}

TYPED_TEST(LcmTypes, WrongFingerprintIsAnError) {
  Bytes buf = Encode(Sample<TypeParam>());
  for (size_t i = 0; i < kHashBytes; ++i) {
    Bytes bad = buf;
    bad[i] ^= 0x10;
    TypeParam out{};
    EXPECT_LT(Decode(bad, bad.size(), out), 0) << "fingerprint byte " << i;
  }
}

// Random corruption after the fingerprint (the fingerprint alone rejects most foreign data):
// decode() must return an error or a length within the buffer, never throw or crash. Run under
// VSL_SANITIZE=ON to also catch out-of-bounds reads.
TYPED_TEST(LcmTypes, GarbledPayloadNeverThrows) {
  const Bytes buf = Encode(Sample<TypeParam>());
  std::mt19937 rng(20240611u);
  std::uniform_int_distribution<size_t> pos(kHashBytes, buf.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<int> count(1, 4);
  for (int trial = 0; trial < 2000; ++trial) {
    Bytes bad = buf;
    const int n = count(rng);
    for (int k = 0; k < n; ++k) {
      const size_t p = pos(rng);
      // Mostly 0xff / 0x7f / 0x80 (large and negative lengths), sometimes any byte.
      static constexpr uint8_t kNasty[] = {0xff, 0x7f, 0x80, 0x00};
      bad[p] = trial % 2 == 0 ? kNasty[k % 4] : static_cast<uint8_t>(byte(rng));
    }
    const size_t len = trial % 5 == 0 ? pos(rng) : bad.size();
    TypeParam out{};
    const int r = Decode(bad, len, out);
    EXPECT_LE(r, static_cast<int>(len));
    if (r == std::numeric_limits<int>::min()) return;  // already reported; stop the flood
  }
}

// ---------------------------------------------------------------------------------------------
// Whole-set checks.

TEST(LcmTypesSet, EveryLcmFileIsTested) {
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(VSL_SOURCE_DIR "/lcmtypes")) {
    if (entry.path().extension() == ".lcm") files.insert(entry.path().stem().string());
  }
  EXPECT_EQ(files, AllTypes::Names())
      << "lcmtypes/*.lcm and the types tested here differ: add the new type to AllTypes, "
         "Sample() and ExpectEq() in tests/lcmtypes/lcmtypes_test.cpp";
}

TEST(LcmTypesSet, FingerprintsAreDistinct) {
  std::vector<int64_t> hashes = AllTypes::Hashes();
  std::sort(hashes.begin(), hashes.end());
  EXPECT_EQ(std::adjacent_find(hashes.begin(), hashes.end()), hashes.end())
      << "two vsl types have the same fingerprint: lcm-spy could not tell them apart";
}

// ---------------------------------------------------------------------------------------------
// Specific garbled length fields. The generated decoders are bounds-checked by
// lcmtypes/harden_cpp.cmake; stock lcm-gen 1.3.1 code throws std::length_error on a negative
// count and allocates gigabytes for a huge one.

TEST(LcmTypesGarbled, BadArrayCountIsAnError) {
  const Bytes buf = Encode(Sample<vsl::head_state_t>());
  constexpr size_t kNumJoints = kHashBytes + 8;  // after utime
  ASSERT_EQ(GetInt32BigEndian(buf, kNumJoints), 3);
  for (int32_t bad_count :
       {-1, std::numeric_limits<int32_t>::min(), 4, std::numeric_limits<int32_t>::max()}) {
    Bytes bad = buf;
    PutInt32BigEndian(bad, kNumJoints, bad_count);
    vsl::head_state_t out{};
    EXPECT_LT(Decode(bad, bad.size(), out), 0) << "num_joints = " << bad_count;
  }
}

TEST(LcmTypesGarbled, BadByteArraySizeIsAnError) {
  const Bytes buf = Encode(Sample<vsl::image_t>());
  constexpr size_t kSize = kHashBytes + 8 + 4 + 4 + 4 + 1;  // utime width height stride format
  ASSERT_EQ(GetInt32BigEndian(buf, kSize), Sample<vsl::image_t>().size);
  for (int32_t bad_size : {-1, std::numeric_limits<int32_t>::min(), Sample<vsl::image_t>().size + 1,
                           std::numeric_limits<int32_t>::max()}) {
    Bytes bad = buf;
    PutInt32BigEndian(bad, kSize, bad_size);
    vsl::image_t out{};
    EXPECT_LT(Decode(bad, bad.size(), out), 0) << "size = " << bad_size;
  }
}

TEST(LcmTypesGarbled, BadStructArrayCountIsAnError) {
  const Bytes buf = Encode(Sample<vsl::fused_percept_list_t>());
  constexpr size_t kNumPercepts = kHashBytes + 8 + 8 + 4;  // utime request_id num_frames
  ASSERT_EQ(GetInt32BigEndian(buf, kNumPercepts), 2);
  for (int32_t bad_count : {-1, 3, std::numeric_limits<int32_t>::max()}) {
    Bytes bad = buf;
    PutInt32BigEndian(bad, kNumPercepts, bad_count);
    vsl::fused_percept_list_t out{};
    EXPECT_LT(Decode(bad, bad.size(), out), 0) << "num_percepts = " << bad_count;
  }
}

TEST(LcmTypesGarbled, BadStringLengthIsAnError) {
  const Bytes buf = Encode(Sample<vsl::localize_request_t>());
  constexpr size_t kSourceLength = kHashBytes + 8 + 8;  // utime request_id
  ASSERT_EQ(GetInt32BigEndian(buf, kSourceLength),
            static_cast<int32_t>(Sample<vsl::localize_request_t>().source.size() + 1));
  for (int32_t bad_length :
       {0, -1, std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max()}) {
    Bytes bad = buf;
    PutInt32BigEndian(bad, kSourceLength, bad_length);
    vsl::localize_request_t out{};
    EXPECT_LT(Decode(bad, bad.size(), out), 0) << "string length = " << bad_length;
  }
}

// Stock lcm-gen 1.3.1 code skips the resize of a primitive array whose count is 0, so decoding
// into a reused message kept the previous message's elements.
TEST(LcmTypesGarbled, DecodingIntoAReusedMessageLeavesNoStaleElements) {
  vsl::head_state_t reused{};
  const Bytes three = Encode(Sample<vsl::head_state_t>());
  ASSERT_GT(Decode(three, three.size(), reused), 0);
  ASSERT_EQ(reused.joint_positions_rad.size(), 3u);

  vsl::head_state_t empty{};
  empty.utime = 5;
  empty.num_joints = 0;
  const Bytes none = Encode(empty);
  ASSERT_GT(Decode(none, none.size(), reused), 0);
  EXPECT_EQ(reused.num_joints, 0);
  EXPECT_TRUE(reused.joint_names.empty());
  EXPECT_TRUE(reused.joint_positions_rad.empty());
  EXPECT_TRUE(reused.joint_velocities_rad_s.empty());
}

}  // namespace
