// The request state machine driven with fake time, fake messages and a fake localization engine.
#include <gtest/gtest.h>

#include <deque>

#include "localizer_core.hpp"

namespace vsl::localizer_daemon {
namespace {

using localization::FusedPercept;
using localization::LocalizationResult;
using localization::Status;

constexpr std::int64_t kSecond = 1'000'000;

struct Recorder : LocalizerOutputs {
  void gaze(const GazeCommand& c) override { gazes.push_back(c); }
  void status(const StatusReport& r) override { statuses.push_back(r); }
  void pose(const PoseReport& r) override { poses.push_back(r); }
  // The states in order, repeats (periodic statuses) folded.
  std::vector<State> states() const {
    std::vector<State> out;
    for (const auto& s : statuses) {
      if (out.empty() || out.back() != s.state) out.push_back(s.state);
    }
    return out;
  }
  std::vector<GazeCommand> gazes;
  std::vector<StatusReport> statuses;
  std::vector<PoseReport> poses;
};

// Answers from a script: one result per localize() call.
struct FakeEngine : LocalizationEngine {
  // Reports the stages a real localization reaches for its result: pruning, generating and
  // validating always, refining only for a pose.
  LocalizationResult localize(const std::vector<FusedPercept>& percepts,
                              const vsl::localization::StageObserver& on_stage) const override {
    seen.push_back(percepts.size());
    LocalizationResult r = results.empty() ? LocalizationResult{} : results.front();
    if (!results.empty()) results.pop_front();
    using vsl::localization::LocalizationStage;
    on_stage(LocalizationStage::kPruning);
    on_stage(LocalizationStage::kGenerating);
    on_stage(LocalizationStage::kValidating);
    if (r.status == Status::kLocalized) on_stage(LocalizationStage::kRefining);
    return r;
  }
  std::optional<Eigen::Vector3d> discriminator_target(
      const LocalizationResult&, const std::vector<Eigen::Vector3d>&) const override {
    return discriminator;
  }
  std::optional<Eigen::Vector3d> precision_target(
      const LocalizationResult&, const std::vector<Eigen::Vector3d>& looked) const override {
    precision_looked.push_back(looked);
    return precision;
  }
  mutable std::deque<LocalizationResult> results;
  mutable std::vector<std::vector<Eigen::Vector3d>> precision_looked;  // per precision_target call
  std::optional<Eigen::Vector3d> precision = Eigen::Vector3d(2.0, -1.5, 1.0);
  mutable std::vector<std::size_t> seen;
  std::optional<Eigen::Vector3d> discriminator = Eigen::Vector3d(1.0, 2.0, 0.5);
};

LocalizationResult result(Status status, double x = 1.0) {
  LocalizationResult r;
  r.status = status;
  r.world_T_ego.translation() = Eigen::Vector3d(x, 2.0, 0.0);
  r.covariance = localization::PoseCovariance::Identity() * 1e-4;
  r.hypotheses.resize(status == Status::kAmbiguous ? 2 : 1);
  r.message = localization::to_string(status);
  return r;
}

// FAILED only as too uncertain: one hypothesis, refined, but imprecise.
LocalizationResult too_uncertain() {
  LocalizationResult r = result(Status::kFailed);
  r.too_uncertain = true;
  r.message = "explains 5 of 5 percepts; pose too uncertain (sigma 2.1 cm, 0.3 deg)";
  return r;
}

CoreOptions options() {
  CoreOptions o;
  o.ego_gaze_targets_m = {Eigen::Vector3d(2, -1, 1), Eigen::Vector3d(2, 0, 1),
                          Eigen::Vector3d(2, 1, 1)};
  o.frames_per_target = 2;
  o.settle_timeout_s = 5;
  o.recognition_timeout_s = 5;
  o.fusing_timeout_s = 2;
  o.fusing_attempts = 2;
  o.max_active_looks = 2;
  o.status_period_s = 0.5;
  o.first_gaze_id = 100;
  return o;
}

struct Harness {
  explicit Harness(CoreOptions o = options()) : core(std::move(o), engine, out) {}
  // The head reaches the last gaze target and frames there are recognized.
  void settle_and_recognize(int frames = 2) {
    const std::int64_t gaze_id = out.gazes.back().gaze_id;
    // A moving frame for the same command does not count.
    core.frame({next_frame, gaze_id, false}, now += 100'000);
    core.percepts(next_frame++, now += 10'000);
    for (int i = 0; i < frames; ++i) {
      core.frame({next_frame, gaze_id, true}, now += 100'000);
      core.percepts(next_frame++, now += 10'000);
    }
  }
  void fused(std::size_t n = 6) {
    core.fused(core.request_id(), std::vector<FusedPercept>(n, FusedPercept{}), now += 10'000);
  }
  FakeEngine engine;
  Recorder out;
  LocalizerCore core;
  std::int64_t now = 1000 * kSecond;
  std::int64_t next_frame = 0;
};

TEST(LocalizerCore, ScanFuseLocalize) {
  Harness h;
  h.engine.results.push_back(result(Status::kLocalized));
  h.core.request(7, h.now);
  ASSERT_EQ(h.out.gazes.size(), 1u);
  EXPECT_EQ(h.out.gazes[0].gaze_id, 100);
  EXPECT_EQ(h.out.gazes[0].ego_target_m, Eigen::Vector3d(2, -1, 1));
  h.settle_and_recognize();
  ASSERT_EQ(h.out.gazes.size(), 2u);
  EXPECT_EQ(h.out.gazes[1].gaze_id, 101);
  h.settle_and_recognize();
  h.settle_and_recognize();
  EXPECT_EQ(h.out.gazes.size(), 3u);
  EXPECT_EQ(h.core.state(), State::kFusing);
  h.fused(6);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].request_id, 7);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_EQ(h.engine.seen, std::vector<std::size_t>{6});
  EXPECT_EQ(h.out.states(), (std::vector<State>{State::kScanning, State::kFusing, State::kPruning,
                                                State::kGenerating, State::kValidating,
                                                State::kRefining, State::kDone}));
  EXPECT_DOUBLE_EQ(h.out.statuses.back().progress, 1.0);
  EXPECT_EQ(h.out.statuses.back().num_fused_percepts, 6);
  // "step k of N" while in progress.
  bool saw_step = false;
  for (const auto& s : h.out.statuses) {
    if (s.message.find("step 2 of 4: gaze target 2 of 3") == 0) saw_step = true;
  }
  EXPECT_TRUE(saw_step);
}

TEST(LocalizerCore, FramesOfOtherCommandsOrInMotionDoNotCount) {
  Harness h;
  h.core.request(7, h.now);
  h.core.frame({1, 99, true}, h.now += 1000);  // an older command's frame at rest
  h.core.percepts(1, h.now += 1000);
  h.core.frame({2, 100, false}, h.now += 1000);  // ours, still moving
  h.core.percepts(2, h.now += 1000);
  h.core.percepts(3, h.now += 1000);  // a frame never seen at rest
  EXPECT_EQ(h.out.gazes.size(), 1u);
  h.core.frame({4, 100, true}, h.now += 1000);
  h.core.percepts(4, h.now += 1000);
  h.core.percepts(4, h.now += 1000);  // a duplicate counts once
  EXPECT_EQ(h.out.gazes.size(), 1u);
  h.core.frame({5, 100, true}, h.now += 1000);
  h.core.percepts(5, h.now += 1000);
  EXPECT_EQ(h.out.gazes.size(), 2u);
}

TEST(LocalizerCore, GazeCommandRepeatsUntilTheHeadIsAtRest) {
  Harness h;
  h.core.request(7, h.now);
  ASSERT_EQ(h.out.gazes.size(), 1u);
  h.core.tick(h.now += kSecond / 2);
  EXPECT_EQ(h.out.gazes.size(), 1u);  // not yet due
  h.core.tick(h.now += kSecond / 2);
  ASSERT_EQ(h.out.gazes.size(), 2u);  // the driver may have missed it: same id, same target
  EXPECT_EQ(h.out.gazes[1].gaze_id, h.out.gazes[0].gaze_id);
  EXPECT_EQ(h.out.gazes[1].ego_target_m, h.out.gazes[0].ego_target_m);
  h.core.frame({1, h.out.gazes[0].gaze_id, true}, h.now += 1000);  // at rest now
  h.core.tick(h.now += 2 * kSecond);
  EXPECT_EQ(h.out.gazes.size(), 2u);  // no more repeats once the head is at rest
}

TEST(LocalizerCore, AmbiguousRunsActiveValidationUntilLocalized) {
  Harness h;
  h.engine.results = {result(Status::kAmbiguous), result(Status::kLocalized, 3.0)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused(5);
  EXPECT_EQ(h.core.state(), State::kActiveValidation);
  ASSERT_EQ(h.out.gazes.size(), 4u);
  EXPECT_EQ(h.out.gazes[3].ego_target_m, Eigen::Vector3d(1.0, 2.0, 0.5));
  EXPECT_TRUE(h.out.poses.empty());
  h.settle_and_recognize();
  EXPECT_EQ(h.core.state(), State::kFusing);
  h.fused(7);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_DOUBLE_EQ(h.out.poses[0].result.world_T_ego.translation().x(), 3.0);
  EXPECT_EQ(h.out.states(),
            (std::vector<State>{State::kScanning, State::kFusing, State::kPruning,
                                State::kGenerating, State::kValidating, State::kActiveValidation,
                                State::kFusing, State::kPruning, State::kGenerating,
                                State::kValidating, State::kRefining, State::kDone}));
}

TEST(LocalizerCore, AmbiguousAfterTheLookLimit) {
  Harness h;
  h.engine.results = {result(Status::kAmbiguous), result(Status::kAmbiguous),
                      result(Status::kAmbiguous)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  h.settle_and_recognize();
  h.fused();
  h.settle_and_recognize();
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.gazes.size(), 5u);  // 3 scan + 2 active looks
  EXPECT_EQ(h.out.poses[0].result.status, Status::kAmbiguous);
  EXPECT_NE(h.out.poses[0].message.find("after 2 active looks"), std::string::npos);
  EXPECT_EQ(h.core.state(), State::kDone);
}

// A look that cannot complete ends the request with what was known before it: AMBIGUOUS after
// an ambiguous result, FAILED (no pose) after a precision look for a result too uncertain.
TEST(LocalizerCore, ActiveLookThatNeverSettlesEndsWithWhatWasKnown) {
  for (const bool precision : {false, true}) {
    SCOPED_TRACE(precision ? "precision look" : "discriminating look");
    Harness h;
    h.engine.results = {precision ? too_uncertain() : result(Status::kAmbiguous)};
    h.core.request(7, h.now);
    for (int i = 0; i < 3; ++i) h.settle_and_recognize();
    h.fused();
    ASSERT_EQ(h.core.state(), State::kActiveValidation);
    h.core.tick(h.now += 6 * kSecond);  // settle_timeout_s is 5 s
    ASSERT_EQ(h.out.poses.size(), 1u);
    EXPECT_EQ(h.out.poses[0].result.status, precision ? Status::kFailed : Status::kAmbiguous);
    EXPECT_NE(h.out.poses[0].message.find("did not complete"), std::string::npos)
        << h.out.poses[0].message;
    EXPECT_EQ(h.out.poses[0].result.covariance.isZero(), precision);
    EXPECT_EQ(h.core.state(), precision ? State::kFailed : State::kDone);
  }
}

TEST(LocalizerCore, FailedResultCarriesNoPose) {
  Harness h;
  h.engine.results = {result(Status::kFailed)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_TRUE(h.out.poses[0].result.world_T_ego.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(h.out.poses[0].result.covariance.isZero());
  EXPECT_EQ(h.core.state(), State::kFailed);
}

// `o` with the look agreement test on (shipped off).
CoreOptions testing_agreement(CoreOptions o) {
  o.look_agreement_alpha = 0.01;
  return o;
}

CoreOptions looking_around() {
  CoreOptions o = options();
  o.ego_look_around_targets_m = {Eigen::Vector3d(-0.4, 2.5, 1), Eigen::Vector3d(-0.4, -2.5, 1)};
  return o;
}

// A scan that gives no pose for want of evidence (facing a bare wall): the head looks around
// once, further round than the scan, and fusion and localization run again with what it saw.
TEST(LocalizerCore, NoPoseFromTheScanLooksAroundOnceThenLocalizes) {
  Harness h(looking_around());
  LocalizationResult too_few = result(Status::kFailed);
  too_few.message = "fewer than three percepts";
  h.engine.results = {too_few, result(Status::kLocalized, 1.5)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused(2);
  EXPECT_TRUE(h.out.poses.empty());
  EXPECT_EQ(h.core.state(), State::kScanning);
  ASSERT_EQ(h.out.gazes.size(), 4u);
  EXPECT_EQ(h.out.gazes[3].ego_target_m, Eigen::Vector3d(-0.4, 2.5, 1));
  EXPECT_NE(h.out.statuses.back().message.find("look-around target 1 of 2"), std::string::npos)
      << h.out.statuses.back().message;
  h.settle_and_recognize();
  ASSERT_EQ(h.out.gazes.size(), 5u);
  EXPECT_EQ(h.out.gazes[4].ego_target_m, Eigen::Vector3d(-0.4, -2.5, 1));
  h.settle_and_recognize();
  EXPECT_EQ(h.core.state(), State::kFusing);
  h.fused(7);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_EQ(h.engine.seen, (std::vector<std::size_t>{2, 7}));
  EXPECT_EQ(h.out.states().front(), State::kScanning);
  EXPECT_EQ(h.core.state(), State::kDone);
}

// Once per request: failing again after the look around is the answer, and a result that is
// only too uncertain takes a precision look instead.
TEST(LocalizerCore, LooksAroundOnlyOnceAndNotWhenOnlyTooUncertain) {
  Harness h(looking_around());
  h.engine.results = {result(Status::kFailed), result(Status::kFailed)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  for (int i = 0; i < 2; ++i) h.settle_and_recognize();
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_EQ(h.out.gazes.size(), 5u);
  EXPECT_EQ(h.core.state(), State::kFailed);

  Harness u(looking_around());
  u.engine.results = {too_uncertain(), result(Status::kLocalized, 1.01)};
  u.core.request(7, u.now);
  for (int i = 0; i < 3; ++i) u.settle_and_recognize();
  u.fused();
  ASSERT_EQ(u.out.gazes.size(), 4u);
  EXPECT_EQ(u.out.gazes[3].ego_target_m, Eigen::Vector3d(2.0, -1.5, 1.0));  // for precision
  EXPECT_EQ(u.core.state(), State::kActiveValidation);
}

// The robot has not moved all request: a pose localized after looking around must agree with
// a pose too uncertain before it, even with a look between them that found too little.
TEST(LocalizerCore, APoseAfterLookingAroundMustAgreeWithAnEarlierImprecisePose) {
  Harness h(testing_agreement(looking_around()));
  h.engine.results = {too_uncertain(), result(Status::kFailed), result(Status::kLocalized, 1.2)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  h.settle_and_recognize();  // the precision look
  h.fused();
  ASSERT_EQ(h.out.gazes.size(), 5u);  // then the look around
  for (int i = 0; i < 2; ++i) h.settle_and_recognize();
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_NE(h.out.poses[0].message.find("20.0 cm"), std::string::npos) << h.out.poses[0].message;
}

// Before a request would end without a pose (too uncertain with nothing new in reach or the
// looks spent; ambiguous with nothing to discriminate or the looks spent), the head looks around
// once, and what it sees is localized with the rest.
TEST(LocalizerCore, LooksAroundBeforeGivingUpOnAnImpreciseOrAmbiguousPose) {
  struct Case {
    const char* name;
    std::vector<LocalizationResult> results;
    bool no_precision_target;
    bool no_discriminator;
    std::size_t gazes_before_looking_around;
  };
  const std::vector<Case> cases = {
      {"too uncertain, nothing new in reach", {too_uncertain()}, true, false, 3},
      {"too uncertain after the look limit",
       {too_uncertain(), too_uncertain(), too_uncertain()},
       false,
       false,
       5},
      {"ambiguous, nothing discriminates", {result(Status::kAmbiguous)}, false, true, 3},
      {"ambiguous after the look limit",
       {result(Status::kAmbiguous), result(Status::kAmbiguous), result(Status::kAmbiguous)},
       false,
       false,
       5},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Harness h(looking_around());
    h.engine.results.assign(c.results.begin(), c.results.end());
    h.engine.results.push_back(result(Status::kLocalized, 1.001));
    if (c.no_precision_target) h.engine.precision.reset();
    if (c.no_discriminator) h.engine.discriminator.reset();
    h.core.request(7, h.now);
    for (int i = 0; i < 3; ++i) h.settle_and_recognize();
    h.fused();
    while (h.out.gazes.size() < c.gazes_before_looking_around + 1 && h.out.poses.empty()) {
      h.settle_and_recognize();  // an active look
      h.fused();
    }
    ASSERT_TRUE(h.out.poses.empty());
    ASSERT_EQ(h.out.gazes.size(), c.gazes_before_looking_around + 1);
    EXPECT_EQ(h.out.gazes.back().ego_target_m, Eigen::Vector3d(-0.4, 2.5, 1));
    EXPECT_EQ(h.core.state(), State::kScanning);
    for (int i = 0; i < 2; ++i) h.settle_and_recognize();
    h.fused(9);
    ASSERT_EQ(h.out.poses.size(), 1u);
    EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
    EXPECT_EQ(h.engine.seen.back(), 9u);
  }
}

// Without look-around targets the request ends as before.
TEST(LocalizerCore, WithoutLookAroundTargetsAnAmbiguousPoseIsTheAnswer) {
  Harness h;
  h.engine.results = {result(Status::kAmbiguous)};
  h.engine.discriminator.reset();
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kAmbiguous);
  EXPECT_NE(h.out.poses[0].message.find("nothing discriminates"), std::string::npos);
}

// A look-around target the head never settles on: the scan's answer stands, with why.
TEST(LocalizerCore, ALookAroundThatNeverSettlesEndsWithTheScansAnswer) {
  Harness h(looking_around());
  LocalizationResult none = result(Status::kFailed);
  none.message = "no hypothesis is consistent with the percepts";
  h.engine.results = {none};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  h.core.tick(h.now += 6 * kSecond);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_EQ(h.out.poses[0].message.rfind("no hypothesis is consistent with the percepts; "
                                         "look-around target 1 of 2 at",
                                         0),
            0u)
      << h.out.poses[0].message;
  EXPECT_TRUE(h.out.poses[0].result.world_T_ego.isApprox(Eigen::Isometry3d::Identity()));
}

// A pose too uncertain is not the end: a precision look away from every earlier gaze, then
// fusion and localization again with what it saw.
TEST(LocalizerCore, TooUncertainTakesAPrecisionLookThenLocalizes) {
  Harness h;
  h.engine.results = {too_uncertain(), result(Status::kLocalized, 1.02)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused(5);
  EXPECT_TRUE(h.out.poses.empty());
  EXPECT_EQ(h.core.state(), State::kActiveValidation);
  ASSERT_EQ(h.out.gazes.size(), 4u);
  EXPECT_EQ(h.out.gazes[3].ego_target_m, Eigen::Vector3d(2.0, -1.5, 1.0));
  EXPECT_NE(h.out.statuses.back().message.find("for precision"), std::string::npos)
      << h.out.statuses.back().message;
  // The engine was told every gaze so far: the three scan targets.
  ASSERT_EQ(h.engine.precision_looked.size(), 1u);
  EXPECT_EQ(h.engine.precision_looked[0], options().ego_gaze_targets_m);
  h.settle_and_recognize();
  h.fused(9);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_DOUBLE_EQ(h.out.poses[0].result.world_T_ego.translation().x(), 1.02);
  EXPECT_EQ(h.engine.seen, (std::vector<std::size_t>{5, 9}));
  EXPECT_EQ(h.core.state(), State::kDone);
}

// A scan too uncertain at x = 1.0 m, then a precision look that localizes at x = 1.2 m.
void precision_look_moves_the_pose_20_cm(Harness& h) {
  h.engine.results = {too_uncertain(), result(Status::kLocalized, 1.2)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused(5);
  h.settle_and_recognize();
  h.fused(9);
}

// Without the agreement test (the shipped default) the pose after the look is the answer.
TEST(LocalizerCore, WithoutTheAgreementTestThePoseAfterTheLookStands) {
  Harness h;
  precision_look_moves_the_pose_20_cm(h);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_DOUBLE_EQ(h.out.poses[0].result.world_T_ego.translation().x(), 1.2);
}

// The robot has not moved while its head looked again: a pose localized after the precision look
// 20 cm from the one before it (1 cm sigmas each) is not to be trusted.
TEST(LocalizerCore, APoseThatDisagreesWithTheOneBeforeThePrecisionLookFails) {
  Harness h(testing_agreement(options()));
  precision_look_moves_the_pose_20_cm(h);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_EQ(h.core.state(), State::kFailed);
  EXPECT_NE(h.out.statuses.back().message.find("20.0 cm"), std::string::npos)
      << h.out.statuses.back().message;
}

TEST(LocalizerCore, TooUncertainAfterTheLookLimitFailsWithoutAPose) {
  Harness h;
  h.engine.results = {too_uncertain(), too_uncertain(), too_uncertain()};
  h.engine.precision = Eigen::Vector3d(2.0, -1.5, 1.0);
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  h.settle_and_recognize();
  h.fused();
  h.settle_and_recognize();
  h.fused();
  EXPECT_EQ(h.out.gazes.size(), 5u);  // 3 scan + 2 precision looks (max_active_looks)
  // The second look was told of the first.
  ASSERT_EQ(h.engine.precision_looked.size(), 2u);
  EXPECT_EQ(h.engine.precision_looked[1].size(), 4u);
  EXPECT_EQ(h.engine.precision_looked[1].back(), Eigen::Vector3d(2.0, -1.5, 1.0));
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_NE(h.out.poses[0].message.find("too uncertain"), std::string::npos);
  EXPECT_NE(h.out.poses[0].message.find("after 2 active looks"), std::string::npos)
      << h.out.poses[0].message;
  EXPECT_TRUE(h.out.poses[0].result.world_T_ego.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(h.out.poses[0].result.covariance.isZero());
  EXPECT_EQ(h.core.state(), State::kFailed);
}

TEST(LocalizerCore, TooUncertainWithNothingToLookAtFails) {
  Harness h;
  h.engine.results = {too_uncertain()};
  h.engine.precision.reset();
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.gazes.size(), 3u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_NE(h.out.poses[0].message.find("nothing new in reach"), std::string::npos);
}

TEST(LocalizerCore, HeadThatNeverSettlesFails) {
  Harness h;
  h.core.request(7, h.now);
  h.core.tick(h.now += 4 * kSecond);
  EXPECT_TRUE(h.out.poses.empty());
  h.core.tick(h.now += 2 * kSecond);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_NE(h.out.poses[0].message.find("did not settle on gaze target 1"), std::string::npos);
  EXPECT_EQ(h.out.statuses.back().state, State::kFailed);
  EXPECT_NE(h.out.statuses.back().message.find("timeout"), std::string::npos);
}

TEST(LocalizerCore, RecognitionThatNeverAnswersFails) {
  Harness h;
  h.core.request(7, h.now);
  h.core.frame({1, 100, true}, h.now += kSecond);
  h.core.tick(h.now += 4 * kSecond);  // 4 s after settling: still waiting
  EXPECT_TRUE(h.out.poses.empty());
  h.core.tick(h.now += 2 * kSecond);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_NE(h.out.poses[0].message.find("0 of 2 frames"), std::string::npos);
}

TEST(LocalizerCore, FusingTimesOutReEntersFusingThenFails) {
  Harness h;
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  ASSERT_EQ(h.core.state(), State::kFusing);
  h.out.statuses.clear();
  h.core.tick(h.now += 2 * kSecond + 1);
  // A new ENTRY into FUSING: one SCANNING status in between.
  EXPECT_EQ(h.out.states(), (std::vector<State>{State::kScanning, State::kFusing}));
  EXPECT_EQ(h.core.state(), State::kFusing);
  h.core.tick(h.now += 2 * kSecond + 1);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_NE(h.out.poses[0].message.find("no FUSED_PERCEPTS"), std::string::npos);
}

TEST(LocalizerCore, FusedPerceptsOfAnotherRequestAreIgnored) {
  Harness h;
  h.engine.results = {result(Status::kLocalized)};
  h.core.request(7, h.now);
  for (int i = 0; i < 3; ++i) h.settle_and_recognize();
  h.core.fused(6, {FusedPercept{}}, h.now);
  EXPECT_TRUE(h.out.poses.empty());
  h.fused();
  EXPECT_EQ(h.out.poses.size(), 1u);
}

TEST(LocalizerCore, NewRequestAbortsTheOneInProgress) {
  Harness h;
  h.core.request(7, h.now);
  h.settle_and_recognize();
  h.core.request(7, h.now += 1000);  // the same request again: a duplicate
  EXPECT_TRUE(h.out.poses.empty());
  h.core.request(8, h.now += 1000);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].request_id, 7);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_NE(h.out.poses[0].message.find("aborted by request 8"), std::string::npos);
  EXPECT_EQ(h.core.request_id(), 8);
  EXPECT_EQ(h.core.state(), State::kScanning);
  EXPECT_EQ(h.out.gazes.back().ego_target_m, Eigen::Vector3d(2, -1, 1));  // the scan restarts
}

TEST(LocalizerCore, PeriodicStatus) {
  Harness h;
  h.core.tick(h.now);
  ASSERT_EQ(h.out.statuses.size(), 1u);
  EXPECT_EQ(h.out.statuses[0].state, State::kIdle);
  EXPECT_EQ(h.out.statuses[0].request_id, -1);
  h.core.tick(h.now += 100'000);
  EXPECT_EQ(h.out.statuses.size(), 1u);
  h.core.tick(h.now += 500'000);
  EXPECT_EQ(h.out.statuses.size(), 2u);
}

TEST(LocalizerCore, PassiveFollowsTheRecordedRun) {
  CoreOptions o = options();
  o.passive = true;
  Harness h(o);
  h.engine.results = {result(Status::kAmbiguous), result(Status::kLocalized, 4.0)};
  h.core.request(7, h.now);
  h.core.followed_status(7, State::kScanning, h.now += 1000);
  h.core.frame({1, 5, true}, h.now += 1000);  // ignored in passive mode
  EXPECT_EQ(h.core.state(), State::kScanning);
  h.core.followed_status(7, State::kFusing, h.now += 1000);
  EXPECT_EQ(h.core.state(), State::kFusing);
  h.fused();
  EXPECT_EQ(h.core.state(), State::kActiveValidation);
  h.core.followed_status(7, State::kValidating, h.now += 1000);
  h.core.followed_status(7, State::kActiveValidation, h.now += 1000);
  h.core.followed_status(7, State::kFusing, h.now += 1000);
  EXPECT_EQ(h.core.state(), State::kFusing);
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_TRUE(h.out.gazes.empty());
}

TEST(LocalizerCore, PassiveReportsAmbiguousWhenTheRecordedRunEnds) {
  CoreOptions o = options();
  o.passive = true;
  Harness h(o);
  h.engine.results = {result(Status::kAmbiguous)};
  // No request in the log: the recorded status starts the run.
  h.core.followed_status(9, State::kScanning, h.now);
  EXPECT_EQ(h.core.request_id(), 9);
  h.core.followed_status(9, State::kFusing, h.now += 1000);
  h.fused();
  h.core.followed_status(9, State::kDone, h.now += 1000);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kAmbiguous);
  EXPECT_EQ(h.out.poses[0].request_id, 9);
}

TEST(LocalizerCore, PassiveFollowsARecordedPrecisionLook) {
  CoreOptions o = options();
  o.passive = true;
  Harness h(o);
  h.engine.results = {too_uncertain(), result(Status::kLocalized, 1.01)};
  h.core.request(7, h.now);
  h.core.followed_status(7, State::kFusing, h.now += 1000);
  h.fused();
  EXPECT_EQ(h.core.state(), State::kActiveValidation);
  EXPECT_TRUE(h.out.poses.empty());
  h.core.followed_status(7, State::kActiveValidation, h.now += 1000);
  h.core.followed_status(7, State::kFusing, h.now += 1000);
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_TRUE(h.out.gazes.empty());
  EXPECT_TRUE(h.engine.precision_looked.empty());  // the recorded run chose its looks
}

// Replays follow a recorded look around (its FUSING entry), and a recorded run that did not
// look around ends with the scan's answer.
TEST(LocalizerCore, PassiveFollowsARecordedLookAround) {
  CoreOptions o = looking_around();
  o.passive = true;
  Harness h(o);
  h.engine.results = {result(Status::kFailed), result(Status::kLocalized, 1.5)};
  h.core.request(7, h.now);
  h.core.followed_status(7, State::kFusing, h.now += 1000);
  h.fused();
  EXPECT_EQ(h.core.state(), State::kScanning);
  h.core.followed_status(7, State::kScanning, h.now += 1000);
  h.core.followed_status(7, State::kFusing, h.now += 1000);
  h.fused();
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kLocalized);
  EXPECT_TRUE(h.out.gazes.empty());

  Harness ended(o);
  LocalizationResult too_few = result(Status::kFailed);
  too_few.message = "fewer than three percepts";
  ended.engine.results = {too_few};
  ended.core.request(7, ended.now);
  ended.core.followed_status(7, State::kFusing, ended.now += 1000);
  ended.fused();
  ended.core.followed_status(7, State::kFailed, ended.now += 1000);
  ASSERT_EQ(ended.out.poses.size(), 1u);
  EXPECT_EQ(ended.out.poses[0].result.status, Status::kFailed);
  EXPECT_EQ(ended.out.poses[0].message, "fewer than three percepts (the recorded run ended)");
}

TEST(LocalizerCore, PassiveReportsTooUncertainWhenTheRecordedRunEnds) {
  CoreOptions o = options();
  o.passive = true;
  Harness h(o);
  h.engine.results = {too_uncertain()};
  h.core.request(7, h.now);
  h.core.followed_status(7, State::kFusing, h.now += 1000);
  h.fused();
  h.core.followed_status(7, State::kFailed, h.now += 1000);
  ASSERT_EQ(h.out.poses.size(), 1u);
  EXPECT_EQ(h.out.poses[0].result.status, Status::kFailed);
  EXPECT_NE(h.out.poses[0].message.find("too uncertain"), std::string::npos);
  EXPECT_EQ(h.core.state(), State::kFailed);
}

}  // namespace
}  // namespace vsl::localizer_daemon
