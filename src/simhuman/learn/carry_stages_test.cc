// The carry's stages as training tasks of their own (carry-lift, carry-deliver), the verdicts
// that end them, and the geometry that steers a walking policy through the carry
// (docs/BENCHMARKS.md, issue 17, session 46).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "simhuman/learn/carry_env.h"
#include "simhuman/learn/tasks.h"

namespace simhuman::learn {
namespace {

using control::CarryPhase;

// a reset of `stage`'s task, env 0, seed `seed`
std::unique_ptr<CarryTask> ResetStage(CarryStage stage, uint64_t seed, std::vector<float>* obs) {
  auto t = CarryTask::Create(1, "human", true, stage);
  if (!t.ok()) return nullptr;
  obs->resize((*t)->obs_dim());
  (*t)->Reset(0, seed, obs->data());
  return std::move(*t);
}

TEST(CarryStages, TheRegistryNamesEachStageAndItsTaskNames) {
  EXPECT_STREQ(CarryStageTask(CarryStage::kAll), "carry");
  EXPECT_STREQ(CarryStageTask(CarryStage::kLift), "carry-lift");
  EXPECT_STREQ(CarryStageTask(CarryStage::kDeliver), "carry-deliver");
  for (CarryStage stage : {CarryStage::kLift, CarryStage::kDeliver}) {
    auto def = FindTask(CarryStageTask(stage));
    ASSERT_TRUE(def.ok()) << def.status();
    // the whole-carry policy starts a stage's training as it is; the walker widened
    EXPECT_EQ((*def)->init_parent, "walk");
    ASSERT_EQ((*def)->init_peers.size(), 1u);
    EXPECT_EQ((*def)->init_peers[0], "carry");
    auto made = (*def)->make(1, TaskOptions());
    ASSERT_TRUE(made.ok()) << made.status();
    EXPECT_EQ((*made)->name(), CarryStageTask(stage));
    EXPECT_TRUE(TaskIsCarry((*made)->name()));
    EXPECT_TRUE(TaskHasWalkGait((*made)->name()));
  }
  EXPECT_FALSE(TaskIsCarry("walk"));
}

// every lift-stage reset starts at the box, lifting; every delivery-stage reset holds the box
// at the lift's last instant (the next step carries)
TEST(CarryStages, EveryStageResetStartsWhereItsStageBeginsIntegration) {
  std::vector<float> obs;
  auto lift = ResetStage(CarryStage::kLift, 1, &obs);
  auto deliver = ResetStage(CarryStage::kDeliver, 1, &obs);
  ASSERT_NE(lift, nullptr);
  ASSERT_NE(deliver, nullptr);
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    lift->Reset(0, seed, obs.data());
    EXPECT_EQ(lift->state(0).phase, CarryPhase::kLift) << "seed " << seed;
    deliver->Reset(0, seed, obs.data());
    EXPECT_EQ(deliver->state(0).phase, CarryPhase::kLift) << "seed " << seed;
    EXPECT_GT(deliver->state(0).phase_time_s, control::kLiftSeconds - 0.01) << "seed " << seed;
    const control::CarryBox box =
        control::ReadCarryBox(deliver->model(0), deliver->data(0), deliver->box_geom());
    EXPECT_GT(control::BoxLowestZ(box), 0.3) << "seed " << seed;
  }
}

// the hand-over verdict: a held start hands the box over; the same box put on the floor, or
// tipped 45 degrees in the hands, does not
TEST(CarryStages, TheLiftHandsOverABoxHeldUpAndLevelOnly) {
  std::vector<float> obs;
  auto t = ResetStage(CarryStage::kDeliver, 3, &obs);
  ASSERT_NE(t, nullptr);
  mjData* d = mj_makeData(t->model(0));
  mj_copyData(d, t->model(0), t->data(0));
  mj_forward(t->model(0), d);
  control::CarryBox box = control::ReadCarryBox(t->model(0), d, t->box_geom());
  EXPECT_TRUE(LiftHandedOver(d, t->index(), box));
  control::CarryBox on_floor = box;
  on_floor.pos.z() = box.half.z();
  EXPECT_FALSE(LiftHandedOver(d, t->index(), on_floor));
  control::CarryBox tipped = box;
  tipped.rot = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()) * box.rot;
  EXPECT_FALSE(LiftHandedOver(d, t->index(), tipped));
  mj_deleteData(d);
}

// the delivery verdict: the box resting on the floor within 0.2 m of the destination, the
// human standing
TEST(CarryStages, DeliveredIsTheBoxRestingAtTheDestination) {
  std::vector<float> obs;
  auto t = ResetStage(CarryStage::kDeliver, 4, &obs);
  ASSERT_NE(t, nullptr);
  control::CarryBox box = control::ReadCarryBox(t->model(0), t->data(0), t->box_geom());
  box.pos.z() = box.half.z();  // on the floor
  box.linvel.setZero();
  const Eigen::Vector2d at = box.pos.head<2>();
  EXPECT_TRUE(Delivered(t->data(0), t->index(), box, at + Eigen::Vector2d(0.15, 0)));
  EXPECT_FALSE(Delivered(t->data(0), t->index(), box, at + Eigen::Vector2d(0.25, 0)));
  control::CarryBox moving = box;
  moving.linvel = Eigen::Vector3d(0.3, 0, 0);
  EXPECT_FALSE(Delivered(t->data(0), t->index(), moving, at));
  control::CarryBox held = box;
  held.pos.z() += 0.2;
  EXPECT_FALSE(Delivered(t->data(0), t->index(), held, at));
}

// a lift-stage episode ends when its lift does, whatever the action: a success exactly when the
// box is handed over held, else "not lifted" (or an earlier failure)
TEST(CarryStages, ALiftEpisodeEndsWithItsLiftIntegration) {
  std::vector<float> obs;
  auto t = ResetStage(CarryStage::kLift, 7, &obs);
  ASSERT_NE(t, nullptr);
  std::vector<float> act(t->act_dim(), 0.f);
  int ends = 0;
  for (uint64_t seed = 7; seed < 10; ++seed) {
    t->Reset(0, seed, obs.data());
    StepInfo info;
    int steps = 0;
    const int max_steps = static_cast<int>(control::kLiftSeconds / control::kWalkPolicyDt) + 3;
    for (; steps < max_steps; ++steps) {
      t->Step(0, act.data(), obs.data(), &info);
      if (info.terminated || info.truncated) break;
    }
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    ASSERT_TRUE(info.terminated || info.truncated);
    ++ends;
    const control::CarryBox box = control::ReadCarryBox(t->model(0), t->data(0), t->box_geom());
    if (info.success) {
      EXPECT_FALSE(info.terminated);
      EXPECT_TRUE(LiftHandedOver(t->data(0), t->index(), box));
    } else {
      EXPECT_TRUE(info.terminated);
      EXPECT_NE(t->last_failure(0), CarryFailure::kNone);
    }
  }
  EXPECT_EQ(ends, 3);
}

// the holding pose leans back by hold_lean_rad_per_kg per kilogram held, in the carry only: the
// trunk's pitch (abdomen_y, actuator 1) of the carry reference is the hold keyframe's less the lean
TEST(CarryStages, TheCarryLeansBackByTheLoad) {
  std::vector<float> obs;
  auto t = ResetStage(CarryStage::kDeliver, 5, &obs);
  ASSERT_NE(t, nullptr);
  const control::CarryState& s = t->state(0);
  const double mass = t->model(0)->body_mass[t->model(0)->geom_bodyid[t->box_geom()]];
  EXPECT_NEAR(s.poses.hold_lean_rad, t->params().hold_lean_rad_per_kg * mass, 1e-9);
  EXPECT_GT(s.poses.hold_lean_rad, 0.03);
  control::CarryState carrying = s;
  carrying.phase = CarryPhase::kCarry;
  double q[control::kWalkActDim];
  control::CarryReference(carrying, q);
  constexpr int kAbdY = 1;
  EXPECT_NEAR(q[kAbdY], s.poses.hold[kAbdY] - s.poses.hold_lean_rad, 1e-9);
}

// The approach's last stretch is walked straight at the box: a human 0.4 m beside the stand
// point is sent to the approach line 0.6 m short of it; on that line, past the stand point
TEST(CarryStages, TheApproachWalksTheLineIntoTheStandPoint) {
  auto made = CarryTask::Create(1, "human", true);
  ASSERT_TRUE(made.ok()) << made.status();
  CarryTask& t = **made;
  t.SetEvaluation(100);
  std::vector<float> obs(t.obs_dim());
  t.Reset(0, 2, obs.data());
  ASSERT_EQ(t.state(0).phase, CarryPhase::kApproach);
  const mjModel* m = t.model(0);
  mjData* d = mj_makeData(m);
  mjData* scratch = mj_makeData(m);
  mj_copyData(d, m, t.data(0));
  mj_forward(m, d);
  Eigen::Vector3d pelvis;
  double yaw;
  control::PelvisPose(d, t.index().walk, &pelvis, &yaw);
  const control::CarryBox box = control::ReadCarryBox(m, d, t.box_geom());
  const double lead = t.params().approach_lead_m;
  for (double beside : {0.4, 0.0}) {
    control::CarryState s = t.state(0);
    const Eigen::Vector2d f = s.face_dir, left(-f.y(), f.x());
    // the stand point 0.5 m ahead of the pelvis along f, and `beside` to its left
    s.stand_xy = pelvis.head<2>() + 0.5 * f - beside * left;
    control::UpdateCarry(t.params(), m, scratch, d, t.index(), box, &s);
    SCOPED_TRACE(testing::Message() << beside << " m beside");
    ASSERT_EQ(s.phase, CarryPhase::kApproach);
    if (beside > 0) {
      const Eigen::Vector2d line_start = s.stand_xy - 0.6 * f;
      EXPECT_NEAR((s.walk.target_xy - line_start).norm(), lead, 1e-6);
      EXPECT_FALSE(s.approach_on_line);
    } else {
      EXPECT_LT((s.walk.target_xy - (s.stand_xy + lead * f)).norm(), 1e-6);
      EXPECT_TRUE(s.approach_on_line);
    }
  }
  mj_deleteData(scratch);
  mj_deleteData(d);
}

}  // namespace
}  // namespace simhuman::learn
