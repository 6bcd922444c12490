#include "simhuman/plan/metrics.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "simhuman/plan/test_scene.h"
#include "simhuman/plan/validate.h"

namespace simhuman::plan {
namespace {

using core::BodyJoint;
using fixtures::MakeChair;
using fixtures::MakeTestScene;

// hand-computed values are written to 1e-12 or better; geometry is exact up to rounding
constexpr double kTol = 1e-9;

void ExpectVec(const Eigen::Vector3d& got, const Eigen::Vector3d& want) {
  EXPECT_NEAR((got - want).norm(), 0.0, kTol)
      << "got " << got.transpose() << ", want " << want.transpose();
}

ContactPair Pair(const std::string& object, const std::string& part, BodyJoint joint,
                 ContactType type, Direction direction) {
  ContactPair p;
  p.object = object;
  p.part = part;
  p.joint = joint;
  p.type = type;
  p.direction = direction;
  return p;
}

ContactPair GetClose(const std::string& object, Direction side) {
  ContactPair p;
  p.object = object;
  p.part = std::string(kNoneName);
  p.direction = side;
  return p;
}

// one agent with every body point at `default_pos`, and some points moved
std::vector<BodyPoints> Agent(std::initializer_list<std::pair<BodyJoint, Eigen::Vector3d>> moved,
                              const Eigen::Vector3d& facing = Eigen::Vector3d::UnitX()) {
  BodyPoints b;
  std::fill(b.pos_world.begin(), b.pos_world.end(), Eigen::Vector3d(10, 10, 10));  // far away
  for (const auto& [joint, pos] : moved) b.at(joint) = pos;
  b.facing_world = facing;
  return {b};
}

// pelvis on the seat of chair000 (seat top z = 0.47 over |x|, |y| <= 0.25), direction `dir`
PairEval Seat(const Eigen::Vector3d& pelvis, Direction dir = Direction::kUp) {
  static const core::SceneCatalog scene = MakeTestScene();
  return EvaluatePair(
      Pair("chair000", "seat surface", BodyJoint::kPelvis, ContactType::kContact, dir), scene,
      Agent({{BodyJoint::kPelvis, pelvis}}), PairParams{});
}

TEST(PlanMetricsTest, DefaultParamsAreValid) {
  EXPECT_TRUE(PairParams{}.Validate().ok());
  EXPECT_TRUE(TrackerParams{}.Validate().ok());
  PairParams p;
  p.direction_dot_min = 1.5;
  EXPECT_THAT(std::string(p.Validate().message()), ::testing::HasSubstr("direction_dot_min"));
  p = PairParams{};
  p.w_dk_per_m = std::nan("");
  EXPECT_FALSE(p.Validate().ok());
  TrackerParams t;
  t.budget_s_per_step = 0;
  EXPECT_THAT(std::string(t.Validate().message()), ::testing::HasSubstr("budget_s_per_step"));
}

TEST(PlanMetricsTest, DirectionVectorFollowsObjectYaw) {
  const core::Pose turned = core::Pose::FromYaw({3, 0, 0}, M_PI / 2);
  ExpectVec(DirectionVector(Direction::kUp, turned), {0, 0, 1});
  ExpectVec(DirectionVector(Direction::kDown, turned), {0, 0, -1});
  ExpectVec(DirectionVector(Direction::kFront, turned), {0, 1, 0});
  ExpectVec(DirectionVector(Direction::kBack, turned), {0, -1, 0});
  ExpectVec(DirectionVector(Direction::kLeft, turned), {-1, 0, 0});
  ExpectVec(DirectionVector(Direction::kRight, turned), {1, 0, 0});
  ExpectVec(DirectionVector(Direction::kNone, turned), {0, 0, 0});

  // a tilted object: the sides stay horizontal and follow the heading of +x
  core::Pose tilted = core::Pose::FromYaw({0, 0, 0}, M_PI / 6);
  tilted.quat = tilted.quat * Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(ObjectYaw(tilted), M_PI / 6, kTol);
  ExpectVec(DirectionVector(Direction::kFront, tilted), {std::cos(M_PI / 6), 0.5, 0});
}

TEST(PlanMetricsTest, ContactJointAboveSeat) {
  // nearest point (0, 0, 0.47); d = (0, 0, -0.08)
  PairEval e = Seat({0, 0, 0.55});
  EXPECT_NEAR(e.distance_m, 0.08, kTol);
  ExpectVec(e.d_vec, {0, 0, -0.08});
  ExpectVec(e.target_world, {0, 0, 0.47});
  EXPECT_NEAR(e.direction_dot, 1.0, kTol);
  EXPECT_TRUE(e.satisfied);
  EXPECT_NEAR(e.reward, 0.6703200460356393, kTol);  // exp(-5 * 0.08)
  EXPECT_TRUE(e.has_error);
  EXPECT_NEAR(e.error_m, 0.08, kTol);
  // "down" on a joint above the surface disagrees: not satisfied, penalised by w_dir
  PairEval down = Seat({0, 0, 0.55}, Direction::kDown);
  EXPECT_NEAR(down.direction_dot, -1.0, kTol);
  EXPECT_FALSE(down.satisfied);
  EXPECT_NEAR(down.reward, 0.6703200460356393 - 0.5, kTol);
}

TEST(PlanMetricsTest, ContactJointBesideSeat) {
  // nearest point (0.25, 0, 0.45); d = (-0.15, 0, 0): too far, and sideways
  PairEval far = Seat({0.40, 0, 0.45});
  EXPECT_NEAR(far.distance_m, 0.15, kTol);
  ExpectVec(far.d_vec, {-0.15, 0, 0});
  EXPECT_NEAR(far.direction_dot, 0.0, kTol);
  EXPECT_FALSE(far.satisfied);
  EXPECT_NEAR(far.reward, 0.4723665527410147, kTol);  // exp(-0.75), no direction penalty at 0

  // close enough but beside, not above: fails "up", passes "front" (chair +x)
  PairEval near_up = Seat({0.30, 0, 0.45});
  EXPECT_NEAR(near_up.distance_m, 0.05, kTol);
  EXPECT_FALSE(near_up.satisfied);
  EXPECT_NEAR(near_up.reward, 0.7788007830714049, kTol);  // exp(-0.25)
  PairEval near_front = Seat({0.30, 0, 0.45}, Direction::kFront);
  EXPECT_NEAR(near_front.direction_dot, 1.0, kTol);
  EXPECT_TRUE(near_front.satisfied);
  PairEval near_none = Seat({0.30, 0, 0.45}, Direction::kNone);
  EXPECT_TRUE(near_none.satisfied);
}

TEST(PlanMetricsTest, ContactDirectionThreshold) {
  // d = (-0.02, 0, -0.05): dot = 0.05 / sqrt(0.0029) = 0.9285 > 0.8
  PairEval steep = Seat({0.27, 0, 0.52});
  EXPECT_NEAR(steep.distance_m, 0.053851648071345036, kTol);
  EXPECT_NEAR(steep.direction_dot, 0.9284766908852594, kTol);
  EXPECT_TRUE(steep.satisfied);
  // d = (-0.05, 0, -0.04): dot = 0.04 / sqrt(0.0041) = 0.6247 < 0.8
  PairEval shallow = Seat({0.30, 0, 0.51});
  EXPECT_NEAR(shallow.direction_dot, 0.6246950475544243, kTol);
  EXPECT_FALSE(shallow.satisfied);
}

TEST(PlanMetricsTest, ContactJointBelowSeatIsPenalised) {
  // under the seat: nearest (0, 0, 0.43), joint lies below -> dot -1 with "up"
  PairEval e = Seat({0, 0, 0.38});
  EXPECT_NEAR(e.distance_m, 0.05, kTol);
  EXPECT_NEAR(e.direction_dot, -1.0, kTol);
  EXPECT_FALSE(e.satisfied);
  EXPECT_NEAR(e.reward, 0.2788007830714049, kTol);  // exp(-0.25) - 0.5
}

TEST(PlanMetricsTest, ContactAtOrInsideSurfaceAgrees) {
  // 0.01 m beside the seat edge: below the 0.02 m epsilon, direction counts as agreeing
  PairEval edge = Seat({0.26, 0, 0.45});
  EXPECT_NEAR(edge.distance_m, 0.01, kTol);
  EXPECT_NEAR(edge.direction_dot, 1.0, kTol);
  EXPECT_TRUE(edge.satisfied);
  EXPECT_NEAR(edge.reward, 0.951229424500714, kTol);  // exp(-0.05)
  // inside the solid: d = 0
  PairEval inside = Seat({0.1, 0.1, 0.45});
  EXPECT_NEAR(inside.distance_m, 0.0, kTol);
  EXPECT_TRUE(inside.satisfied);
  EXPECT_NEAR(inside.reward, 1.0, kTol);
  EXPECT_NEAR(inside.error_m, 0.0, kTol);
}

TEST(PlanMetricsTest, NotContact) {
  const core::SceneCatalog scene = MakeTestScene();
  const ContactPair pair = Pair("chair000", "seat surface", BodyJoint::kLeftHand,
                                ContactType::kNotContact, Direction::kNone);
  PairEval away = EvaluatePair(pair, scene, Agent({{BodyJoint::kLeftHand, {0, 0, 0.67}}}), {});
  EXPECT_NEAR(away.distance_m, 0.2, kTol);
  EXPECT_TRUE(away.satisfied);
  EXPECT_NEAR(away.reward, 0.6321205588285577, kTol);  // 1 - exp(-1)
  EXPECT_TRUE(away.has_error);
  EXPECT_NEAR(away.error_m, 0.1, kTol);  // max(0.3 - 0.2, 0)

  PairEval close = EvaluatePair(pair, scene, Agent({{BodyJoint::kLeftHand, {0, 0, 0.52}}}), {});
  EXPECT_NEAR(close.distance_m, 0.05, kTol);
  EXPECT_FALSE(close.satisfied);
  EXPECT_NEAR(close.reward, 0.22119921692859512, kTol);  // 1 - exp(-0.25)
  EXPECT_NEAR(close.error_m, 0.25, kTol);

  PairEval far = EvaluatePair(pair, scene, Agent({{BodyJoint::kLeftHand, {0, 0, 1.0}}}), {});
  EXPECT_NEAR(far.error_m, 0.0, kTol);  // farther than 0.3 m: no error
}

TEST(PlanMetricsTest, NotCare) {
  const core::SceneCatalog scene = MakeTestScene();
  PairEval e = EvaluatePair(
      Pair("chair000", "left arm", BodyJoint::kLeftHand, ContactType::kNotCare, Direction::kNone),
      scene, Agent({}), {});
  EXPECT_TRUE(e.satisfied);
  EXPECT_NEAR(e.reward, 1.0, kTol);
  EXPECT_FALSE(e.has_error);
}

TEST(PlanMetricsTest, PartJointTargetsTheSameAgentsBodyPoint) {
  const core::SceneCatalog scene = MakeTestScene();
  ContactPair pair =
      Pair("chair000", "left knee", BodyJoint::kRightFoot, ContactType::kContact, Direction::kNone);
  pair.part_joint = BodyJoint::kLeftKnee;
  PairEval e = EvaluatePair(
      pair, scene,
      Agent({{BodyJoint::kLeftKnee, {0.3, 0.1, 0.5}}, {BodyJoint::kRightFoot, {0.3, 0.1, 0.55}}}),
      {});
  ExpectVec(e.target_world, {0.3, 0.1, 0.5});
  ExpectVec(e.d_vec, {0, 0, -0.05});
  EXPECT_TRUE(e.satisfied);
  EXPECT_NEAR(e.reward, 0.7788007830714049, kTol);
}

// a seated pelvis turned 90 degrees (facing world +y): sitting bones at (1, 2, 0.5), the hips
// 4 cm above them, 0.17 m apart
std::vector<BodyPoints> SeatedFacingY(double scale) {
  return Agent({{BodyJoint::kPelvis, {1, 2, 0.5}},
                {BodyJoint::kLeftHip, {1 - 0.085 * scale, 2, 0.5 + 0.04 * scale}},
                {BodyJoint::kRightHip, {1 + 0.085 * scale, 2, 0.5 + 0.04 * scale}}},
               Eigen::Vector3d::UnitY());
}

TEST(PlanMetricsTest, TheBellyPointIsInFrontOfTheLowerTrunk) {
  for (double scale : {1.0, 0.7}) {
    const BellyTouch b = BellyPoint(SeatedFacingY(scale)[0].pos_world);
    ExpectVec(b.normal, {0, 1, 0});
    ExpectVec(b.pos, {1, 2 + 0.085 * scale, 0.5 + 0.04 * scale + 0.18 * scale});
  }
}

TEST(PlanMetricsTest, AHandOnThePelvisTouchesTheBellyInOurConventionOnly) {
  const core::SceneCatalog scene = MakeTestScene();
  ContactPair pair =
      Pair("chair000", "pelvis", BodyJoint::kRightHand, ContactType::kContact, Direction::kNone);
  pair.part_joint = BodyJoint::kPelvis;
  std::vector<BodyPoints> body = SeatedFacingY(1.0);
  // the hand's centre resting on the belly, its 0.045 m radius in front of the skin
  body[0].at(BodyJoint::kRightHand) = {1, 2 + 0.085 + 0.045, 0.72};
  PairParams ours;
  EXPECT_TRUE(TouchesBelly(pair, ours));
  PairEval e = EvaluatePair(pair, scene, body, ours);
  EXPECT_NEAR(e.distance_m, 0.045, kTol);
  EXPECT_TRUE(e.satisfied);
  // UniHSI's reading: the pelvis point itself, 0.27 m below and behind the hand
  PairParams unihsi;
  unihsi.hand_on_pelvis_at_belly = false;
  EXPECT_FALSE(TouchesBelly(pair, unihsi));
  e = EvaluatePair(pair, scene, body, unihsi);
  ExpectVec(e.target_world, {1, 2, 0.5});
  EXPECT_FALSE(e.satisfied);
  // only hands: a foot on the pelvis (not a plan anyone writes) keeps the point
  pair.joint = BodyJoint::kRightFoot;
  EXPECT_FALSE(TouchesBelly(pair, ours));
}

TEST(PlanMetricsTest, RotatedObjectSides) {
  // bed001 at (3, 0, 0) turned 90 degrees: mattress spans x in [2.5, 3.5], y in [-1, 1], top
  // z = 0.45; its "right" (-y local) is world +x
  const core::SceneCatalog scene = MakeTestScene();
  auto eval = [&](Direction dir) {
    return EvaluatePair(Pair("bed001", "mattress", BodyJoint::kHead, ContactType::kContact, dir),
                        scene, Agent({{BodyJoint::kHead, {3.55, 0.2, 0.45}}}), {});
  };
  PairEval right = eval(Direction::kRight);
  ExpectVec(right.target_world, {3.5, 0.2, 0.45});
  EXPECT_NEAR(right.distance_m, 0.05, kTol);
  EXPECT_TRUE(right.satisfied);
  PairEval left = eval(Direction::kLeft);
  EXPECT_NEAR(left.direction_dot, -1.0, kTol);
  EXPECT_FALSE(left.satisfied);
  EXPECT_NEAR(left.reward, 0.2788007830714049, kTol);
}

TEST(PlanMetricsTest, StandPointAndFacing) {
  // chair bounds: x in [-0.25, 0.25], y in [-0.29, 0.29]
  const core::CatalogObject chair = MakeChair(core::Pose::FromYaw({1, 2, 0}, 0.0));
  ExpectVec(StandPoint(chair, Direction::kFront, 0.45), {1.7, 2, 0});
  ExpectVec(StandPoint(chair, Direction::kBack, 0.45), {0.3, 2, 0});
  ExpectVec(StandPoint(chair, Direction::kLeft, 0.45), {1, 2.74, 0});
  ExpectVec(StandPoint(chair, Direction::kRight, 0.45), {1, 1.26, 0});
  EXPECT_NEAR(std::abs(StandFacingYaw(chair, Direction::kFront)), M_PI, kTol);
  EXPECT_NEAR(StandFacingYaw(chair, Direction::kLeft), -M_PI / 2, kTol);

  // bed: bounds x in [-1, 1], y in [-0.5, 0.5]; turned 90 degrees, its front is world +y
  const core::SceneCatalog scene = MakeTestScene();
  const core::CatalogObject& bed = *scene.Find("bed001");
  ExpectVec(StandPoint(bed, Direction::kFront, 0.45), {3, 1.45, 0});
  ExpectVec(StandPoint(bed, Direction::kRight, 0.45), {3.95, 0, 0});
  EXPECT_NEAR(StandFacingYaw(bed, Direction::kFront), -M_PI / 2, kTol);
}

TEST(PlanMetricsTest, GetClose) {
  core::SceneCatalog scene;
  scene.objects.push_back(MakeChair(core::Pose::FromYaw({1, 2, 0}, 0.0)));
  const ContactPair pair = GetClose("chair000", Direction::kFront);  // stand at (1.7, 2)
  const Eigen::Vector3d pelvis(1.8, 2.1, 0.9);
  auto facing = [](double yaw) { return Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0); };

  PairEval e = EvaluatePair(pair, scene, Agent({{BodyJoint::kPelvis, pelvis}}, facing(M_PI)), {});
  EXPECT_NEAR(e.distance_m, std::sqrt(0.02), kTol);
  ExpectVec(e.d_vec, {-0.1, -0.1, 0});
  ExpectVec(e.target_world, {1.7, 2, 0});
  EXPECT_NEAR(e.direction_dot, 1.0, kTol);
  EXPECT_TRUE(e.satisfied);
  EXPECT_NEAR(e.reward, 0.49306869139523984, kTol);  // exp(-5 sqrt(0.02))
  EXPECT_FALSE(e.has_error);

  // by default facing is not required ("stand up" is written as get close, facing away)
  EXPECT_TRUE(
      EvaluatePair(pair, scene, Agent({{BodyJoint::kPelvis, pelvis}}, facing(0)), {}).satisfied);
  // with a 45 degree tolerance: within passes, beyond fails; facing away is penalised to 0
  PairParams p45;
  p45.get_close_facing_tol_rad = M_PI / 4;
  EXPECT_TRUE(
      EvaluatePair(pair, scene, Agent({{BodyJoint::kPelvis, pelvis}}, facing(M_PI + M_PI / 6)), p45)
          .satisfied);
  EXPECT_FALSE(
      EvaluatePair(pair, scene, Agent({{BodyJoint::kPelvis, pelvis}}, facing(M_PI - M_PI / 3)), p45)
          .satisfied);
  PairEval away = EvaluatePair(pair, scene, Agent({{BodyJoint::kPelvis, pelvis}}, facing(0)), p45);
  EXPECT_FALSE(away.satisfied);
  EXPECT_NEAR(away.reward, 0.0, kTol);
  // too far: 0.4 m from the stand point
  EXPECT_FALSE(
      EvaluatePair(pair, scene, Agent({{BodyJoint::kPelvis, {2.1, 2, 0.9}}}, facing(M_PI)), {})
          .satisfied);
}

TEST(PlanMetricsTest, AdaptiveWeights) {
  std::vector<double> w = AdaptiveWeights({1.0, 0.5, 0.0}, 1e-3);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NEAR(w[0], 0.0, kTol);
  EXPECT_NEAR(w[1], 0.33311125916055967, kTol);              // 0.5 / 1.501
  EXPECT_NEAR(w[2], 0.6662225183211193, kTol);               // 1 / 1.501
  EXPECT_NEAR(w[0] + w[1] + w[2], 0.999333777481679, kTol);  // 1.5 / 1.501
  for (double x : AdaptiveWeights({1.0, 1.0}, 1e-3)) EXPECT_EQ(x, 0.0);
}

TEST(PlanMetricsTest, EvaluateStepCombinesPairs) {
  const core::SceneCatalog scene = MakeTestScene();
  ContactStep step;
  step.pairs.push_back(
      Pair("chair000", "seat surface", BodyJoint::kPelvis, ContactType::kContact, Direction::kUp));
  step.pairs.push_back(
      Pair("chair000", "left arm", BodyJoint::kRightHand, ContactType::kNotCare, Direction::kNone));
  step.pairs.push_back(Pair("chair000", "seat surface", BodyJoint::kLeftHand,
                            ContactType::kNotContact, Direction::kNone));
  const std::vector<BodyPoints> agents =
      Agent({{BodyJoint::kPelvis, {0, 0, 0.55}}, {BodyJoint::kLeftHand, {0, 0, 0.67}}});
  StepEval e = EvaluateStep(step, scene, agents, {});
  ASSERT_EQ(e.pairs.size(), 3u);
  EXPECT_TRUE(e.complete);
  // R = {exp(-0.4), 1, 1 - exp(-1)}
  EXPECT_NEAR(e.weights[0], 0.4719426240058934, kTol);
  EXPECT_NEAR(e.weights[1], 0.0, kTol);
  EXPECT_NEAR(e.weights[2], 0.5266258584925694, kTol);
  EXPECT_NEAR(e.reward, 0.6492436334137027, kTol);

  // moving the hand close breaks the not-contact pair and the step
  const std::vector<BodyPoints> close =
      Agent({{BodyJoint::kPelvis, {0, 0, 0.55}}, {BodyJoint::kLeftHand, {0, 0, 0.52}}});
  EXPECT_FALSE(EvaluateStep(step, scene, close, {}).complete);
}

TEST(PlanMetricsTest, EvaluatesAGroundedScenePlan) {
  const core::SceneCatalog scene = MakeTestScene();
  absl::StatusOr<ContactChain> chain =
      LoadAndGroundFile(fixtures::PlanDataPath("chain_tuple.json"), scene);
  ASSERT_TRUE(chain.ok()) << chain.status();
  // step 1: pelvis on the mattress (top z = 0.45), head not on it
  StepEval e =
      EvaluateStep(chain->steps[1], scene,
                   Agent({{BodyJoint::kPelvis, {3, 0, 0.5}}, {BodyJoint::kHead, {3, 0, 1}}}), {});
  EXPECT_TRUE(e.complete);
  EXPECT_NEAR(e.pairs[0].distance_m, 0.05, kTol);
  EXPECT_NEAR(e.pairs[1].distance_m, 0.55, kTol);
}

// ---- StepTracker ----

PairEval Eval(bool satisfied, bool has_error, double error_m) {
  PairEval p;
  p.satisfied = satisfied;
  p.has_error = has_error;
  p.error_m = error_m;
  return p;
}

StepEval StepOf(std::vector<PairEval> pairs) {
  StepEval s;
  s.complete = true;
  for (const PairEval& p : pairs) s.complete = s.complete && p.satisfied;
  s.pairs = std::move(pairs);
  return s;
}

// a chain of `sizes.size()` steps with the given numbers of pairs
ContactChain ChainOf(std::vector<int> sizes) {
  ContactChain chain;
  for (int n : sizes) {
    ContactStep step;
    step.pairs.resize(n);
    chain.steps.push_back(step);
  }
  return chain;
}

TEST(PlanTrackerTest, AdvancesWithHoldAndTimesOut) {
  TrackerParams params;
  params.hold_s = 0.5;
  StepTracker tracker(ChainOf({2, 1}), params);
  EXPECT_NEAR(tracker.time_budget_s(), 20.0, kTol);

  const StepEval s0_bad = StepOf({Eval(false, true, 0.3), Eval(true, true, 0.0)});
  const StepEval s0_good = StepOf({Eval(true, true, 0.08), Eval(true, true, 0.1)});
  for (int k = 0; k <= 9; ++k) tracker.Update(k / 10.0, s0_bad);
  // complete over 1.0 .. 1.2, broken at 1.3, complete again from 1.4: done at 1.9
  for (int k = 10; k <= 12; ++k) tracker.Update(k / 10.0, s0_good);
  tracker.Update(1.3, s0_bad);
  for (int k = 14; k <= 18; ++k) {
    tracker.Update(k / 10.0, s0_good);
    EXPECT_EQ(tracker.current_step(), 0) << k;
  }
  tracker.Update(1.9, s0_good);
  EXPECT_EQ(tracker.current_step(), 1);
  EXPECT_EQ(tracker.steps_completed(), 1);
  ASSERT_EQ(tracker.completion_times_s().size(), 1u);
  EXPECT_NEAR(tracker.completion_times_s()[0], 1.9, kTol);

  // step 1 never completes; its error comes from the last tick within the budget (t = 20)
  for (int k = 20; k <= 199; ++k) tracker.Update(k / 10.0, StepOf({Eval(false, true, 0.5)}));
  tracker.Update(20.0, StepOf({Eval(false, true, 0.15)}));
  EXPECT_FALSE(tracker.finished());
  tracker.Update(20.1, StepOf({Eval(false, true, 0.9)}));
  EXPECT_TRUE(tracker.finished());
  EXPECT_TRUE(tracker.timed_out());
  EXPECT_FALSE(tracker.succeeded());
  EXPECT_FALSE(tracker.done());
  EXPECT_EQ(tracker.steps_completed(), 1);
  EXPECT_TRUE(tracker.records()[1].errors_recorded);
  EXPECT_FALSE(tracker.records()[1].completed);

  // Eq. 10: mean of {0.08, 0.1} (step 0 at completion) and {0.15} (step 1 at the end)
  EXPECT_EQ(tracker.num_error_pairs(), 3);
  ASSERT_TRUE(tracker.contact_error_m().has_value());
  EXPECT_NEAR(*tracker.contact_error_m(), 0.11, kTol);

  // further ticks are ignored
  tracker.Update(30.0, StepOf({Eval(true, true, 0.0)}));
  EXPECT_EQ(tracker.steps_completed(), 1);
}

TEST(PlanTrackerTest, SucceedsWithinBudgetAndIgnoresLaterTicks) {
  StepTracker tracker(ChainOf({1, 1, 1}));  // hold 0: the first complete tick completes
  EXPECT_NEAR(tracker.time_budget_s(), 30.0, kTol);
  tracker.Update(0.0, StepOf({Eval(false, false, 0.0)}));
  tracker.Update(5.0, StepOf({Eval(true, false, 0.0)}));  // not care / get close: no error
  tracker.Update(6.0, StepOf({Eval(true, true, 0.02)}));
  EXPECT_EQ(tracker.current_step(), 2);
  tracker.Update(30.0, StepOf({Eval(true, true, 0.04)}));  // exactly at the budget counts
  EXPECT_TRUE(tracker.done());
  EXPECT_TRUE(tracker.succeeded());
  EXPECT_TRUE(tracker.finished());
  EXPECT_FALSE(tracker.timed_out());
  EXPECT_EQ(tracker.steps_completed(), 3);
  EXPECT_EQ(tracker.completion_times_s(), (std::vector<double>{5.0, 6.0, 30.0}));
  EXPECT_NEAR(*tracker.contact_error_m(), 0.03, kTol);
  tracker.Update(31.0, StepOf({Eval(true, true, 0.04)}));  // ignored, no abort
  EXPECT_EQ(tracker.steps_completed(), 3);
}

TEST(PlanTrackerTest, FinishRecordsTheCurrentStep) {
  StepTracker tracker(ChainOf({1, 2}));
  tracker.Update(0.5, StepOf({Eval(true, false, 0.0)}));
  tracker.Update(1.0, StepOf({Eval(false, true, 0.2), Eval(true, true, 0.0)}));
  tracker.Update(1.5, StepOf({Eval(false, true, 0.3), Eval(true, true, 0.1)}));
  tracker.Finish();  // e.g. the agent fell
  EXPECT_TRUE(tracker.finished());
  EXPECT_FALSE(tracker.timed_out());
  EXPECT_FALSE(tracker.succeeded());
  EXPECT_EQ(tracker.steps_completed(), 1);
  EXPECT_EQ(tracker.num_error_pairs(), 2);
  EXPECT_NEAR(*tracker.contact_error_m(), 0.2, kTol);
  tracker.Finish();  // idempotent
  EXPECT_EQ(tracker.num_error_pairs(), 2);
}

TEST(PlanTrackerTest, NoErrorsWithoutContactPairs) {
  StepTracker tracker(ChainOf({1}));
  tracker.Update(0.0, StepOf({Eval(true, false, 0.0)}));
  EXPECT_TRUE(tracker.succeeded());
  EXPECT_FALSE(tracker.contact_error_m().has_value());
}

TEST(PlanTrackerDeathTest, MisuseAborts) {
  StepTracker tracker(ChainOf({1}));
  tracker.Update(1.0, StepOf({Eval(false, true, 0.1)}));
  EXPECT_DEATH(tracker.Update(0.5, StepOf({Eval(false, true, 0.1)})), "time went backwards");
  EXPECT_DEATH(tracker.Update(2.0, StepOf({})), "not of the current step");
}

}  // namespace
}  // namespace simhuman::plan
