#include "simhuman/control/runner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>

#include "simhuman/control/mpc/mpc_controller.h"
#include "simhuman/plan/validate.h"
#include "simhuman/world/scene.h"

namespace simhuman::control {
namespace {

constexpr double kSeatTolM = 0.06;
// a head point above this is a standing adult's (1.6 m at the start), below it a seated one's
// (about 1.2 m on a chair)
constexpr double kStandingHeadM = 1.3;
constexpr double kGripTolRad = 0.15;

// holds the agent's standing servo targets from the start; asks for its own physics timestep
// and records the timesteps it saw
class HoldController : public Controller {
 public:
  HoldController(const world::SimWorld* world, int agent, double dt_s)
      : world_(world), agent_(agent), dt_s_(dt_s) {}
  std::string name() const override { return "hold"; }
  absl::Status Act(const Observation& obs) override {
    last_step_index_ = obs.step_index;
    if (hold_.empty()) {
      const world::AgentIndex& ix = world_->agent(agent_);
      for (int j = 0; j < ix.num_actuators(); ++j) hold_.push_back(obs.data->ctrl[ix.actuator[j]]);
    }
    return absl::OkStatus();
  }
  void Targets(double time_s, core::Span<double> ctrl) const override {
    if (last_time_s_ >= 0) steps_seen_.insert(std::round((time_s - last_time_s_) * 1e6) / 1e6);
    last_time_s_ = time_s;
    for (int j = 0; j < ctrl.size() && j < static_cast<int>(hold_.size()); ++j) ctrl[j] = hold_[j];
  }
  double control_period_s() const override { return 0.03; }
  double physics_timestep_s() const override { return dt_s_; }
  const std::set<double>& steps_seen() const { return steps_seen_; }
  int last_step_index() const { return last_step_index_; }

 private:
  const world::SimWorld* world_;
  int agent_;
  double dt_s_;
  std::vector<double> hold_;
  int last_step_index_ = -1;
  mutable double last_time_s_ = -1;
  mutable std::set<double> steps_seen_;
};

// a body controller for the humanoid body, and a grip that closes a placeholder hand: each
// writes its own part of the agent's actuator span
class BodyAndGrip : public Controller {
 public:
  BodyAndGrip(Controller* body, std::vector<double> grip_rad)
      : body_(body), grip_rad_(std::move(grip_rad)) {}
  std::string name() const override { return body_->name() + "+grip"; }
  absl::Status Act(const Observation& obs) override { return body_->Act(obs); }
  void Targets(double time_s, core::Span<double> ctrl) const override {
    body_->Targets(time_s, ctrl);
    for (int j = world::kHumanoidDofs; j < ctrl.size(); ++j) {
      ctrl[j] = grip_rad_[j - world::kHumanoidDofs];
    }
  }
  double control_period_s() const override { return body_->control_period_s(); }

 private:
  Controller* body_;
  std::vector<double> grip_rad_;
};

struct Scene {
  world::SceneSpec spec;
  core::SceneCatalog catalog;
  std::unique_ptr<world::SimWorld> world;
};

// sit_demo's chair and its human, plus `extra` more humans
Scene SitDemo(const std::string& kind, const std::vector<world::AgentSpec>& extra) {
  Scene s;
  s.spec = *world::LoadScene("sit_demo");
  s.spec.humans[0].kind = kind;
  auto cat = world::BuildCatalog(s.spec);
  EXPECT_TRUE(cat.ok()) << cat.status();
  s.catalog = *cat;
  const world::HumanSpec& h = s.spec.humans[0];
  std::vector<world::AgentSpec> agents = {{h.pos_xy.x(), h.pos_xy.y(), h.yaw_rad, h.scale, kind}};
  agents.insert(agents.end(), extra.begin(), extra.end());
  auto w = world::SimWorld::Create(s.catalog, agents);
  EXPECT_TRUE(w.ok()) << w.status();
  s.world = std::move(w).value();
  s.catalog = s.world->catalog();
  return s;
}

plan::ContactChain Ground(const std::string& text, const core::SceneCatalog& catalog) {
  auto chain = plan::ParseAndGround(text, "<test>", catalog);
  EXPECT_TRUE(chain.ok()) << chain.status();
  return *chain;
}

double HeadZ(const world::SimWorld& w, int agent) {
  return w.BodyPoints(w.data(), agent)[static_cast<int>(core::BodyJoint::kHead)].z();
}

class FixedStep : public HoldController {
 public:
  explicit FixedStep(double dt) : HoldController(nullptr, 0, dt) {}
};

TEST(RunnerTest, CommonTimestepIsTheFinestAsked) {
  FixedStep any(0.0), coarse(1.0 / 120), fine(0.004);
  EXPECT_DOUBLE_EQ(CommonTimestep({&any}, 0.005), 0.005);
  EXPECT_DOUBLE_EQ(CommonTimestep({&coarse}, 0.005), 1.0 / 120);
  EXPECT_DOUBLE_EQ(CommonTimestep({&any, &coarse}, 0.005), 1.0 / 120);
  EXPECT_DOUBLE_EQ(CommonTimestep({&coarse, &fine}, 0.005), 0.004);
  EXPECT_DOUBLE_EQ(CommonTimestep({&fine, &coarse, &any}, 0.005), 0.004);
}

TEST(RunnerTest, EachAgentFallsByItsOwnPosture) {
  RunOptions o;
  // a head at 0.35 m: fallen for a standing or seated step, fine on a bed
  EXPECT_TRUE(IsFall(Posture::kStand, 0.35, 1.0, o));
  EXPECT_TRUE(IsFall(Posture::kSit, 0.35, 1.0, o));
  EXPECT_FALSE(IsFall(Posture::kLieBack, 0.35, 1.0, o));
  EXPECT_FALSE(IsFall(Posture::kLieSide, 0.35, 1.0, o));
  EXPECT_TRUE(IsFall(Posture::kLieBack, 0.2, 1.0, o));
  // the standing limit scales with the body: a child's head at 0.35 m is above 0.45 x 0.7
  EXPECT_FALSE(IsFall(Posture::kStand, 0.35, 0.7, o));
}

TEST(RunnerTest, OnFrameInterruptsAndTheNextEpisodeContinuesFromThatState) {
  Scene s = SitDemo("humanoid", {});
  HoldController hold(s.world.get(), 0, 0.005);
  const std::string chair = s.catalog.objects[0].id;
  plan::ContactChain chain = Ground(
      "[[[\"" + chair + "\", \"seat surface\", \"pelvis\", \"contact\", \"up\"]]]", s.catalog);
  RunOptions ro;
  ro.record = false;
  std::vector<double> frames_s;
  ro.on_frame = [&](double t, int step) {
    EXPECT_EQ(step, 0);
    frames_s.push_back(t);
    return t < 0.2;
  };
  EpisodeResult first = RunEpisode(*s.world, chain, {&hold}, ro, nullptr);
  EXPECT_EQ(first.end_reason, "interrupted");
  // frames every 1/30 s of simulated time, the last one the interrupting one
  ASSERT_GE(frames_s.size(), 2u);
  EXPECT_NEAR(frames_s[1] - frames_s[0], 1.0 / ro.record_fps, 0.01);
  EXPECT_GE(frames_s.back(), 0.2);
  EXPECT_LT(frames_s.back(), 0.2 + 2.0 / ro.record_fps);
  const double world_time_s = s.world->data()->time;
  // the next episode starts at the world's current time, from the state left behind
  frames_s.clear();
  EpisodeResult second = RunEpisode(*s.world, chain, {&hold}, ro, nullptr);
  EXPECT_EQ(second.end_reason, "interrupted");
  ASSERT_FALSE(frames_s.empty());
  EXPECT_NEAR(frames_s.front(), 0.0, 1e-9);
  EXPECT_GT(s.world->data()->time, world_time_s + 0.19);
  // controllers kept across episodes see the second one's steps as new ones
  ro.controller_step_offset = 1;
  EXPECT_EQ(RunEpisode(*s.world, chain, {&hold}, ro, nullptr).end_reason, "interrupted");
  EXPECT_EQ(hold.last_step_index(), 1);
}

TEST(RunnerTest, TwoHumansWithDifferentControllersAndPosturesIntegration) {
  // human 0 sits on the chair with the MPC; human 1 stands 2 m to its side with a hold
  // controller that asks for a 4 ms physics step
  Scene s = SitDemo("humanoid", {{0.6, 2.0, 0.0, 1.0}});
  ASSERT_EQ(s.world->num_agents(), 2);
  MpcConfig cfg = *MpcConfig::Preset("fast");
  auto mpc = MpcController::Create(s.world.get(), 0, cfg, 7);
  ASSERT_TRUE(mpc.ok()) << mpc.status();
  HoldController hold(s.world.get(), 1, 0.004);
  const std::string chair = s.catalog.objects[0].id;
  plan::ContactChain chain = Ground(
      "[[[\"" + chair + "\", \"seat surface\", \"pelvis\", \"contact\", \"up\"]]]", s.catalog);
  RunOptions ro;
  ro.tracker.budget_s_per_step = 8.0;
  ro.settle_s = 1.0;
  ro.record = false;
  EpisodeResult r = RunEpisode(*s.world, chain, {mpc->get(), &hold}, ro, nullptr);
  EXPECT_TRUE(r.success) << r.end_reason;
  EXPECT_FALSE(r.fell);
  // the seated human's pelvis is on the seat, the other still stands
  const core::CatalogObject& c = s.catalog.objects[0];
  const Eigen::Vector3d pelvis =
      s.world->BodyPoints(s.world->data(), 0)[static_cast<int>(core::BodyJoint::kPelvis)];
  EXPECT_LT((pelvis.head<2>() - c.pose.pos.head<2>()).norm(), 0.35);
  EXPECT_LT(HeadZ(*s.world, 0), kStandingHeadM);  // seated: the head is lower
  EXPECT_GT(HeadZ(*s.world, 1), kStandingHeadM);
  // one model, one timestep: the finest asked for
  ASSERT_EQ(hold.steps_seen().size(), 1u);
  EXPECT_NEAR(*hold.steps_seen().begin(), 0.004, 1e-9);
  EXPECT_DOUBLE_EQ(s.world->model()->opt.timestep, 0.005);  // restored after the episode
}

TEST(RunnerTest, HumanoidWithADexterousHandRunsABodyControllerAndAGripIntegration) {
  Scene s = SitDemo("humanoid_right_hand", {});
  const world::AgentIndex& ix = s.world->agent(0);
  ASSERT_EQ(ix.num_actuators(), world::kHumanoidDofs + world::kHandDofs);
  ASSERT_EQ(ix.num_body_points(), core::kNumBodyJoints + 3);
  ASSERT_EQ(s.world->model()->nu, ix.num_actuators());
  const core::BodyPointCatalog& points = s.catalog.agents[0].body_points;
  ASSERT_TRUE(points.Find("right palm").has_value());
  EXPECT_EQ(static_cast<int>(*points.Find("right palm")), core::kNumBodyJoints);

  MpcConfig cfg = *MpcConfig::Preset("fast");
  auto mpc = MpcController::Create(s.world.get(), 0, cfg, 7);
  ASSERT_TRUE(mpc.ok()) << mpc.status();
  // every hand hinge to 40 % of its range (a half-closed hand)
  std::vector<double> grip;
  for (const world::HandJoint& h : world::HandJoints()) {
    grip.push_back((h.lo_deg + 0.4 * (h.hi_deg - h.lo_deg)) * M_PI / 180);
  }
  BodyAndGrip ctl(mpc->get(), grip);
  const std::string chair = s.catalog.objects[0].id;
  plan::ContactChain chain = Ground(
      "[[[\"" + chair + "\", \"seat surface\", \"pelvis\", \"contact\", \"up\"]]]", s.catalog);
  RunOptions ro;
  ro.tracker.budget_s_per_step = 8.0;
  ro.record = false;
  EpisodeResult r = RunEpisode(*s.world, chain, {&ctl}, ro, nullptr);
  EXPECT_TRUE(r.success) << r.end_reason;
  EXPECT_FALSE(r.fell);
  // the hand's hinges followed the grip
  for (int j = world::kHumanoidDofs; j < ix.num_actuators(); ++j) {
    EXPECT_NEAR(s.world->data()->qpos[ix.hinge_qpos[j]], grip[j - world::kHumanoidDofs],
                kGripTolRad)
        << "hand hinge " << j;
  }
  // the hand's body points exist in the plan language; the MPC says it does not drive them
  plan::ContactChain palm = Ground(
      "{\"steps\": [{\"pairs\": [{\"object\": \"" + chair +
          "\", \"part\": \"seat surface\", \"joint\": \"right palm\", \"contact\": \"contact\", "
          "\"direction\": \"up\"}]}]}",
      s.catalog);
  ASSERT_EQ(palm.steps[0].pairs[0].joint, points.Find("right palm"));
  s.world->Reset();
  auto mpc2 = MpcController::Create(s.world.get(), 0, cfg, 7);
  ASSERT_TRUE(mpc2.ok());
  EpisodeResult refused = RunEpisode(*s.world, palm, {mpc2->get()}, ro, nullptr);
  EXPECT_FALSE(refused.success);
  EXPECT_NE(refused.end_reason.find("'right palm'"), std::string::npos) << refused.end_reason;
}

}  // namespace
}  // namespace simhuman::control

namespace simhuman::control {
namespace {

TEST(RunnerTest, JointCentrePelvisIsTheMiddleOfTheHips) {
  std::vector<Eigen::Vector3d> pts(core::kNumBodyJoints, Eigen::Vector3d::Zero());
  pts[static_cast<int>(core::BodyJoint::kPelvis)] = Eigen::Vector3d(0, 0, 0.40);
  pts[static_cast<int>(core::BodyJoint::kLeftHip)] = Eigen::Vector3d(0.02, 0.09, 0.50);
  pts[static_cast<int>(core::BodyJoint::kRightHip)] = Eigen::Vector3d(0.0, -0.09, 0.48);
  std::vector<Eigen::Vector3d> jc = JointCentrePelvis(pts);
  EXPECT_TRUE(
      jc[static_cast<int>(core::BodyJoint::kPelvis)].isApprox(Eigen::Vector3d(0.01, 0.0, 0.49)));
  EXPECT_EQ(jc[static_cast<int>(core::BodyJoint::kHead)],
            pts[static_cast<int>(core::BodyJoint::kHead)]);
}

}  // namespace
}  // namespace simhuman::control
