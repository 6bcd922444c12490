#include "simhuman/control/policy/policy_controller.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/testing_temp.h"
#include "simhuman/world/model_builder.h"
#include "simhuman/world/objects.h"

namespace simhuman::control {
namespace {

std::string WritePolicy(const std::string& name, const std::string& task, int obs_dim,
                        const std::string& variant = "") {
  std::string path = core::testing::UniqueTempPath("policy_test_" + name);
  torch::manual_seed(1);
  GaussianActor actor(obs_dim, kWalkActDim, std::vector<int>{16, 16}, 0.5);
  ObsNormalizer norm(obs_dim);
  torch::serialize::OutputArchive ar;
  SavePolicyKeys(ar, PolicyMeta{task, obs_dim, kWalkActDim, {16, 16}, variant}, actor, norm);
  ar.save_to(path);
  return path;
}

// one human at the origin facing +x among `scene`'s objects, at the walker's physics step
// (nullptr, with a test failure, if the world cannot be built)
std::unique_ptr<world::SimWorld> World(const core::SceneCatalog& scene = {}) {
  world::ModelOptions o;
  o.timestep_s = kWalkPhysicsDt;
  auto w = world::SimWorld::Create(scene, {world::AgentSpec()}, o);
  EXPECT_TRUE(w.ok()) << w.status();
  return w.ok() ? *std::move(w) : nullptr;
}

TEST(WalkPolicyController, ActsWithFiniteTargetsAtItsOwnRate) {
  auto world = World();
  auto c = WalkPolicyController::Load(WritePolicy("ok", "walk", kWalkObsDim), world.get(), 0);
  ASSERT_TRUE(c.ok()) << c.status();
  EXPECT_DOUBLE_EQ((*c)->physics_timestep_s(), kWalkPhysicsDt);
  EXPECT_DOUBLE_EQ((*c)->control_period_s(), kWalkPolicyDt);
  (*c)->SetTarget(0, 0, 0);
  Observation obs;
  obs.world = world.get();
  obs.data = world->data();
  ASSERT_TRUE((*c)->Act(obs).ok());
  std::array<double, kWalkActDim> ctrl{};
  (*c)->Targets(0, ctrl);
  for (double v : ctrl) EXPECT_TRUE(std::isfinite(v));
  // standing on the target facing its heading, nearly untrained: not stepping
  EXPECT_FALSE((*c)->state().stepping);
}

TEST(WalkPolicyController, RunsWithTheGaitItsFileRecords) {
  auto world = World();
  const std::string human = WritePolicy("human", "walk", kWalkObsDim, "human");
  auto meta = LoadPolicyFile(human);
  ASSERT_TRUE(meta.ok()) << meta.status();
  EXPECT_EQ(meta->meta.variant, "human");
  EXPECT_EQ(LoadPolicyFile(WritePolicy("plain", "walk", kWalkObsDim))->meta.variant, "");
  // the human gait's clock runs slower (1.05 s cycles against 0.9 s)
  double advance[2];
  int k = 0;
  for (const std::string& path : {WritePolicy("plain2", "walk", kWalkObsDim), human}) {
    auto c = WalkPolicyController::Load(path, world.get(), 0);
    ASSERT_TRUE(c.ok()) << c.status();
    (*c)->SetTarget(3, 0, 0);
    Observation obs;
    obs.world = world.get();
    obs.data = world->data();
    ASSERT_TRUE((*c)->Act(obs).ok());
    const double p0 = (*c)->state().phase;
    obs.time_s = kWalkPolicyDt;
    ASSERT_TRUE((*c)->Act(obs).ok());
    advance[k++] = std::fmod((*c)->state().phase - p0 + 1.0, 1.0);
  }
  EXPECT_NEAR(advance[0] / advance[1], 1.05 / 0.9, 1e-6);
  auto bad = WalkPolicyController::Load(WritePolicy("bad", "walk", kWalkObsDim, "moonwalk"),
                                        world.get(), 0);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(std::string(bad.status().message()).find("unknown walking gait 'moonwalk'"),
            std::string::npos);
  // the default gait is the original's parameters
  auto plain = WalkGait("");
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain->gait_period_s, WalkParams().gait_period_s);
  EXPECT_EQ(plain->hip_swing_rad, WalkParams().hip_swing_rad);
}

TEST(WalkCommand, ShortStepsKeepTheHeadingLongWalksTurnFirst) {
  auto world = World();
  auto ix = MakeWalkIndex(*world, 0);
  ASSERT_TRUE(ix.ok()) << ix.status();
  mj_forward(world->model(), world->data());
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(world->data(), *ix, &pos, &yaw);
  const Eigen::Vector2d back(-std::cos(yaw), -std::sin(yaw)), left(-std::sin(yaw), std::cos(yaw));
  WalkParams p;
  auto command = [&](const Eigen::Vector2d& offset) {
    WalkState s;
    s.target_xy = pos.head<2>() + offset;
    s.target_yaw_rad = yaw;
    UpdateWalkCommand(p, world->data(), *ix, &s);
    EXPECT_TRUE(s.stepping);
    return s;
  };
  // 1.2 and 1.45 m behind, same heading: steps backwards without turning
  for (double dist : {1.2, 1.45}) {
    WalkState b = command(dist * back);
    EXPECT_TRUE(b.short_step) << dist;
    EXPECT_LT(b.cmd.vx, -0.2) << dist;
    EXPECT_NEAR(b.cmd.yaw_rate, 0.0, 0.05) << dist;
  }
  // 1.2 m to the left: a side step
  WalkState l = command(1.2 * left);
  EXPECT_GT(l.cmd.vy, 0.2);
  EXPECT_NEAR(l.cmd.yaw_rate, 0.0, 0.05);
  // 5 m behind: turn round first (no backward walking), at the top yaw rate
  WalkState f = command(5.0 * back);
  EXPECT_FALSE(f.short_step);
  EXPECT_GT(f.cmd.vx, -0.05);
  EXPECT_NEAR(std::abs(f.cmd.yaw_rate), p.max_yaw_rate, 1e-9);
  // with short steps off, 1.2 m behind turns as a long walk does
  p.short_step_m = 0;
  WalkState off = command(1.2 * back);
  EXPECT_FALSE(off.short_step);
  EXPECT_GT(std::abs(off.cmd.yaw_rate), 0.5);
}

TEST(WalkTargets, ArmsFollowTheReferenceLegsTheAction) {
  auto world = World();
  auto ix = MakeWalkIndex(*world, 0);
  ASSERT_TRUE(ix.ok()) << ix.status();
  WalkParams p;
  WalkState s;
  s.phase = 0.3;
  s.amplitude = 1.0;
  s.cmd.vx = 0.8;
  double ref[kWalkActDim], ctrl[kWalkActDim];
  WalkReference(p, s.phase, s.amplitude, s.cmd, ref);
  std::vector<float> action(kWalkActDim, 1.0f);
  WalkTargets(p, *ix, s, action.data(), ctrl);
  const auto& names = world::HumanoidJointNames();
  int arms = 0, moved = 0;
  for (int j = 0; j < kWalkActDim; ++j) {
    bool arm = names[j].find("shoulder") != std::string::npos ||
               names[j].find("elbow") != std::string::npos;
    EXPECT_EQ(WalkActionUsed(j), !arm) << names[j];  // training leaves out what is ignored
    if (arm) {
      ++arms;
      EXPECT_DOUBLE_EQ(ctrl[j], ref[j]) << names[j];
    } else if (std::abs(ctrl[j] - ref[j]) > 0.1) {
      ++moved;
    }
  }
  EXPECT_EQ(arms, 8);
  EXPECT_GE(moved, 15);  // the other 20 joints follow the action (a few clip at their limits)
}

TEST(WalkPolicyController, WalksAroundATableOnTheWayToTheStandPoint) {
  world::ObjectSpec spec;
  spec.id = "table000";
  spec.type = "table";
  spec.pos = Eigen::Vector3d(1.6, 0, 0);
  auto table = world::BuildObject(spec);
  ASSERT_TRUE(table.ok()) << table.status();
  core::SceneCatalog scene;
  scene.objects.push_back(*table);
  auto world = World(scene);
  ASSERT_NE(world, nullptr);
  auto c = WalkPolicyController::Load(WritePolicy("route", "walk", kWalkObsDim), world.get(), 0);
  ASSERT_TRUE(c.ok()) << c.status();
  StepTask task;
  task.get_close = true;
  task.walk_point = Eigen::Vector3d(3.4, 0, 0);
  Observation obs;
  obs.world = world.get();
  obs.data = world->data();
  obs.task = &task;
  ASSERT_TRUE((*c)->Act(obs).ok());
  const NavPath* route = (*c)->route();
  ASSERT_NE(route, nullptr);
  EXPECT_GT(route->points.size(), 2u);
  EXPECT_EQ(route->blocked_m, 0);
  // the policy steers to a point on the route 1.2 m ahead, beside the table, not through it
  const Eigen::Vector2d carrot = (*c)->state().target_xy;
  EXPECT_GT(std::abs(carrot.y()), 0.3);
  EXPECT_NEAR(carrot.norm(), kRouteLookaheadM, 0.15);
  // without navigation it steers straight at the walk point
  (*c)->Restart();
  (*c)->set_navigation(false);
  ASSERT_TRUE((*c)->Act(obs).ok());
  EXPECT_EQ((*c)->route(), nullptr);
  EXPECT_NEAR(((*c)->state().target_xy - Eigen::Vector2d(3.4, 0)).norm(), 0, 1e-12);
}

// stood up 0.35 m in front of a bed, facing away from it: a route that leaves to the side first
// steps out, heading kept, to where there is room to turn (turning on the spot there swung a
// foot into the bed's edge); a route straight ahead, or the same route with the bed far behind,
// does not
TEST(WalkPolicyController, StepsAwayFromABedBeforeTurningBesideIt) {
  auto walk_to = [](double bed_gap_m, Eigen::Vector2d goal, Eigen::Vector2d* target,
                    double* target_yaw, double* room) {
    world::ObjectSpec spec;
    spec.id = "bed000";
    spec.type = "bed";
    auto bed = world::BuildObject(spec);
    ASSERT_TRUE(bed.ok()) << bed.status();
    spec.pos = Eigen::Vector3d(-bed_gap_m - bed->LocalBounds().second.x(), 0, 0);
    bed = world::BuildObject(spec);
    ASSERT_TRUE(bed.ok()) << bed.status();
    core::SceneCatalog scene;
    scene.objects.push_back(*bed);
    auto world = World(scene);
    ASSERT_NE(world, nullptr);
    auto c = WalkPolicyController::Load(WritePolicy("bed", "walk", kWalkObsDim), world.get(), 0);
    ASSERT_TRUE(c.ok()) << c.status();
    StepTask task;
    task.get_close = true;
    task.walk_point = Eigen::Vector3d(goal.x(), goal.y(), 0);
    Observation obs;
    obs.world = world.get();
    obs.data = world->data();
    obs.task = &task;
    ASSERT_TRUE((*c)->Act(obs).ok());
    *target = (*c)->state().target_xy;
    *target_yaw = (*c)->state().target_yaw_rad;
    *room = PointClearance(scene, *target, NavConfig());
  };
  Eigen::Vector2d target;
  double yaw = 1, room = 0;
  const double start_room = 0.35;
  walk_to(start_room, {1.0, 2.5}, &target, &yaw, &room);
  EXPECT_GE(room, WalkPolicyController::kTurnRoomM);
  EXPECT_GT(target.norm(), 0.05);
  EXPECT_LT(target.norm(), WalkPolicyController::kMaxExitM);
  EXPECT_NEAR(yaw, 0, 0.05);  // the heading kept: a step, not a turn
  // straight ahead: no exit, the carrot on the route
  walk_to(start_room, {3.0, 0.0}, &target, &yaw, &room);
  EXPECT_NEAR(target.norm(), kRouteLookaheadM, 0.15);
  // the bed 1 m behind: the walker turns on its spot
  walk_to(1.0, {1.0, 2.5}, &target, &yaw, &room);
  EXPECT_LT(target.norm(), 0.05);
  EXPECT_GT(yaw, 0.8);
}

TEST(WalkPolicyController, NoTargetIsAnError) {
  auto world = World();
  auto c = WalkPolicyController::Load(WritePolicy("nt", "walk", kWalkObsDim), world.get(), 0);
  ASSERT_TRUE(c.ok());
  Observation obs;
  obs.world = world.get();
  obs.data = world->data();
  EXPECT_EQ((*c)->Act(obs).code(), absl::StatusCode::kFailedPrecondition);
}

TEST(WalkPolicyController, WrongTaskMissingAndCorruptFilesAreErrors) {
  auto world = World();
  auto reach = WalkPolicyController::Load(WritePolicy("reach", "reach", 6), world.get(), 0);
  EXPECT_EQ(reach.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(reach.status().message().find("reach"), std::string::npos);
  auto missing = WalkPolicyController::Load("/nonexistent/walk.pt", world.get(), 0);
  EXPECT_EQ(missing.status().code(), absl::StatusCode::kNotFound);
  std::string bad = core::testing::UniqueTempPath("policy_test_malformed.pt");
  std::ofstream(bad) << "not a torch archive";
  auto corrupt = WalkPolicyController::Load(bad, world.get(), 0);
  EXPECT_EQ(corrupt.status().code(), absl::StatusCode::kDataLoss);
  EXPECT_NE(corrupt.status().message().find(bad), std::string::npos);
}

}  // namespace
}  // namespace simhuman::control

namespace simhuman::control {
namespace {

class FakeContact : public Controller {
 public:
  std::string name() const override { return "fake"; }
  absl::Status Act(const Observation&) override {
    ++acts;
    return absl::OkStatus();
  }
  void Targets(double, core::Span<double> ctrl) const override {
    std::fill(ctrl.begin(), ctrl.end(), 0.0);
  }
  double control_period_s() const override { return 0.04; }
  int acts = 0;
};

// a walker (a policy file named `name`) and a fake contact controller behind one
// WalkThenContactController, and a get-close step to (x, 0, 0)
struct Handover {
  std::unique_ptr<world::SimWorld> world;
  std::unique_ptr<WalkPolicyController> walker;
  FakeContact mpc;
  std::unique_ptr<WalkThenContactController> c;
  StepTask get_close;

  Handover(const std::string& name, double x) : world(World()) {
    auto w = WalkPolicyController::Load(WritePolicy(name, "walk", kWalkObsDim), world.get(), 0);
    EXPECT_TRUE(w.ok()) << w.status();
    if (w.ok()) walker = std::move(w).value();
    c = std::make_unique<WalkThenContactController>(walker.get(), &mpc);
    get_close.get_close = true;
    get_close.stand_point = get_close.walk_point = Eigen::Vector3d(x, 0, 0);
  }
};

TEST(WalkThenContactController, WalksGetCloseStepsAndHandsOverOnlyWhenStopped) {
  Handover h("hand", 3);
  auto& world = h.world;
  FakeContact& mpc = h.mpc;
  WalkThenContactController& c = *h.c;
  StepTask& walk_task = h.get_close;
  StepTask sit_task;
  Observation obs;
  obs.world = world.get();
  obs.data = world->data();
  obs.task = &walk_task;
  obs.step_index = 0;
  ASSERT_TRUE(c.Act(obs).ok());
  EXPECT_TRUE(c.walking());
  EXPECT_DOUBLE_EQ(c.physics_timestep_s(), kWalkPhysicsDt);
  EXPECT_EQ(mpc.acts, 0);
  // the plan moves on while the human is 3 m from the stand point: keep walking
  obs.task = &sit_task;
  obs.step_index = 1;
  obs.time_s = 1.0;
  ASSERT_TRUE(c.Act(obs).ok());
  EXPECT_TRUE(c.walking());
  EXPECT_EQ(mpc.acts, 0);
  // ... but not forever
  obs.time_s = 1.0 + WalkThenContactController::kMaxFinishS + 0.1;
  ASSERT_TRUE(c.Act(obs).ok());
  EXPECT_FALSE(c.walking());
  EXPECT_EQ(mpc.acts, 1);
  EXPECT_DOUBLE_EQ(c.physics_timestep_s(), 0.0);
}

TEST(WalkThenContactController, StandUpIsTheContactControllersThenTheWalkerTakesOver) {
  Handover h("stand", 2);
  auto& world = h.world;
  FakeContact& mpc = h.mpc;
  WalkThenContactController& c = *h.c;
  StepTask& stand_up = h.get_close;
  mjData* d = world->data();
  const int root = world->agent(0).root_qpos;
  const double stand_z = d->qpos[root + 2];
  Observation obs;
  obs.world = world.get();
  obs.data = d;
  obs.task = &stand_up;
  // seated: the pelvis is low, the contact controller stands the human up
  d->qpos[root + 2] = 0.5;
  mj_kinematics(world->model(), d);
  ASSERT_TRUE(c.Act(obs).ok());
  EXPECT_FALSE(c.walking());
  EXPECT_EQ(mpc.acts, 1);
  // standing, but not yet for kStoodS
  d->qpos[root + 2] = stand_z;
  mj_kinematics(world->model(), d);
  obs.time_s = 1.0;
  ASSERT_TRUE(c.Act(obs).ok());
  obs.time_s = 1.0 + 0.5 * WalkThenContactController::kStoodS;
  ASSERT_TRUE(c.Act(obs).ok());
  EXPECT_FALSE(c.walking());
  EXPECT_EQ(mpc.acts, 3);
  // stood long enough, 2 m from the walk point: the walker takes the rest of the way
  obs.time_s = 1.0 + WalkThenContactController::kStoodS + 0.01;
  ASSERT_TRUE(c.Act(obs).ok());
  EXPECT_TRUE(c.walking());
  EXPECT_EQ(mpc.acts, 3);
}

// perched as high as a standing pelvis (a high stool), the thighs level: not standing, so a
// stand-up step starts with the contact controller, not the walker
TEST(WalkThenContactController, APelvisAsHighAsStandingWithLevelThighsIsNotStanding) {
  std::vector<Eigen::Vector3d> pts(core::kNumBodyJoints, Eigen::Vector3d(0, 0, 0.9));
  EXPECT_FALSE(ThighsDown(pts, 1.0));
  pts[static_cast<int>(core::BodyJoint::kLeftKnee)].z() = 0.48;
  pts[static_cast<int>(core::BodyJoint::kRightKnee)].z() = 0.48;
  EXPECT_TRUE(ThighsDown(pts, 1.0));
  EXPECT_FALSE(ThighsDown(pts, 1.5));  // a tall human's thighs hang farther
  EXPECT_TRUE(ThighsDown(std::vector<Eigen::Vector3d>{}, 1.0));

  Handover h("perch", 2);
  auto& world = h.world;
  FakeContact& mpc = h.mpc;
  WalkThenContactController& c = *h.c;
  StepTask& stand_up = h.get_close;
  stand_up.posture = Posture::kStand;
  mjData* d = world->data();
  const mjModel* m = world->model();
  for (const auto& [name, angle] : world::SeatedHinges()) {
    const int j = mj_name2id(m, mjOBJ_JOINT, (world::AgentPrefix(0) + name).c_str());
    ASSERT_GE(j, 0) << name;
    d->qpos[m->jnt_qposadr[j]] = angle;
  }
  mj_kinematics(m, d);  // the pelvis stays at standing height
  Observation obs;
  obs.world = world.get();
  obs.data = d;
  obs.task = &stand_up;
  world->AllBodyPoints(d, 0, &obs.body_points);
  ASSERT_TRUE(c.Act(obs).ok());
  EXPECT_FALSE(c.walking());
  EXPECT_EQ(mpc.acts, 1);
}

}  // namespace
}  // namespace simhuman::control
