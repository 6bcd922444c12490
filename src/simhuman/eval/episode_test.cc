#include "simhuman/eval/episode.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "simhuman/control/runner.h"
#include "simhuman/core/rng.h"
#include "simhuman/eval/eval_runner.h"
#include "simhuman/world/humanoid.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {
namespace {

using ::testing::HasSubstr;

constexpr double kTol = 1e-12;

// sit_demo plus a second human and a movable box
world::SceneSpec TwoHumansAndABox() {
  world::SceneSpec spec = *world::BuiltinScene("sit_demo");
  world::ObjectSpec box;
  box.id = "box001";
  box.type = "box";
  box.pos = Eigen::Vector3d(-1.5, 1.5, 0);
  box.mass_kg = 3.0;
  spec.objects.push_back(box);
  world::HumanSpec h;
  h.pos_xy = Eigen::Vector2d(-1.5, -1.5);
  spec.humans.push_back(h);
  return spec;
}

TEST(EpisodeTest, QposColumnsNameEveryEntry) {
  world::SceneSpec spec = TwoHumansAndABox();
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(spec);
  ASSERT_TRUE(catalog.ok());
  core::StatusOr<std::unique_ptr<world::SimWorld>> sim = BuildWorld(spec, *catalog);
  ASSERT_TRUE(sim.ok()) << sim.status();
  const mjModel* m = (*sim)->model();
  std::vector<std::string> names = QposColumnNames(m);
  ASSERT_EQ(static_cast<int>(names.size()), m->nq);
  for (const std::string& n : names) EXPECT_FALSE(n.empty());
  const world::AgentIndex& a0 = (*sim)->agent(0);
  EXPECT_EQ(names[a0.root_qpos], "root[0]");
  EXPECT_EQ(names[a0.root_qpos + 6], "root[6]");
  EXPECT_EQ(names[a0.hinge_qpos[0]], world::HumanoidJointNames()[0]);
  const world::AgentIndex& a1 = (*sim)->agent(1);
  EXPECT_EQ(names[a1.root_qpos + 3], "h1/root[3]");
  EXPECT_EQ(names[a1.hinge_qpos[5]], "h1/" + world::HumanoidJointNames()[5]);
  EXPECT_NE(std::find(names.begin(), names.end(), "obj/box001/root[0]"), names.end());

  // a two-frame trajectory round trip
  control::Trajectory t;
  t.nq = m->nq;
  t.time_s = {0.0, 1.0 / 30};
  t.qpos = {std::vector<double>(m->nq, 0.5), std::vector<double>(m->nq, -0.25)};
  t.step_index = {0, 1};
  std::string path = (std::filesystem::temp_directory_path() /
                      ("simhuman_traj_test_" + std::to_string(getpid()) + ".csv"))
                         .string();
  ASSERT_TRUE(WriteTrajectoryCsv(path, m, t).ok());
  std::ifstream in(path);
  std::string header, row1, row2, extra;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header.rfind("time_s,step,root[0],root[1],root[2],root[3]", 0), 0u) << header;
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), m->nq + 1);
  EXPECT_EQ(std::count(row2.begin(), row2.end(), ','), m->nq + 1);
  EXPECT_EQ(row1.rfind("0.0000,0,0.5,0.5", 0), 0u) << row1;
  EXPECT_EQ(row2.rfind("0.0333,1,-0.25,", 0), 0u) << row2;
  std::filesystem::remove(path);
  EXPECT_FALSE(WriteTrajectoryCsv("/nonexistent_dir/x.csv", m, t).ok());
}

TEST(EpisodeTest, StandingAndSeatedStarts) {
  world::SceneSpec spec = *world::BuiltinScene("sit_demo");
  core::StatusOr<std::vector<world::AgentSpec>> p = AgentSpecs(spec);
  ASSERT_TRUE(p.ok());
  ASSERT_EQ(p->size(), 1u);
  EXPECT_NEAR((*p)[0].x, spec.humans[0].pos_xy.x(), kTol);
  EXPECT_NEAR((*p)[0].yaw_rad, spec.humans[0].yaw_rad, kTol);
  spec.humans[0].posture = "lie";
  p = AgentSpecs(spec);
  ASSERT_FALSE(p.ok());
  EXPECT_THAT(p.status().message(), HasSubstr("/humans/0/posture: 'lie'"));
  EXPECT_THAT(p.status().message(), HasSubstr("valid postures to start in: stand, sit"));
  // seated on sit_demo's chair: the pelvis on the seat; held only with a dexterous hand
  spec.humans[0].posture = "sit";
  spec.humans[0].pos_xy = spec.humans[0].pos_xy.Zero();
  p = AgentSpecs(spec);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_NEAR((*p)[0].seated_pelvis_z,
              world::DefaultSizes("chair").at("seat_height") + world::SeatedPelvisAboveSeat(1.0),
              1e-9);
  EXPECT_FALSE((*p)[0].hold_pelvis);
  spec.humans[0].kind = "humanoid_right_hand";
  EXPECT_TRUE((*AgentSpecs(spec))[0].hold_pelvis);
  // sitting on thin air is refused by name
  spec.humans[0].pos_xy = Eigen::Vector2d(3, 3);
  p = AgentSpecs(spec);
  ASSERT_FALSE(p.ok());
  EXPECT_THAT(p.status().message(), HasSubstr("/humans/0/posture: 'sit' needs a seat"));
  // a bed's mattress seats too: on the front edge of bedroom's bed (x 1.75-3.25, top 0.5 m)
  world::SceneSpec bedroom = *world::BuiltinScene("bedroom");
  bedroom.humans[0].posture = "sit";
  bedroom.humans[0].pos_xy = Eigen::Vector2d(1.93, 0.1);
  p = AgentSpecs(bedroom);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_NEAR((*p)[0].seated_pelvis_z,
              world::DefaultSizes("bed").at("mattress_height") + world::SeatedPelvisAboveSeat(1.0),
              1e-9);
  bedroom.humans[0].pos_xy = Eigen::Vector2d(1.7, 0.1);  // just off the edge
  EXPECT_FALSE(AgentSpecs(bedroom).ok());
}

TEST(EpisodeTest, ControllerSeedsAreDistinctAndStable) {
  EXPECT_EQ(ControllerSeed(5, 0), ControllerSeed(5, 0));
  EXPECT_NE(ControllerSeed(5, 0), ControllerSeed(5, 1));
  EXPECT_NE(ControllerSeed(5, 0), ControllerSeed(6, 0));
  EXPECT_EQ(ControllerSeed(5, 1), core::DeriveSeed(5, kControllerStream, 1));
}

TEST(EpisodeTest, StepTextUsesLabelOrPairs) {
  plan::ContactStep step;
  step.label = "sit down";
  EXPECT_EQ(StepText(step), "sit down");
  step.label.clear();
  plan::ContactPair seat;
  seat.object = "chair000";
  seat.part = "seat surface";
  seat.joint = core::BodyJoint::kPelvis;
  plan::ContactPair head = seat;
  head.part = "back surface";
  head.joint = core::BodyJoint::kHead;
  head.type = plan::ContactType::kNotContact;
  plan::ContactPair ignored = seat;
  ignored.type = plan::ContactType::kNotCare;
  step.pairs = {seat, head, ignored};
  EXPECT_EQ(StepText(step), "pelvis on chair000 seat surface, head off chair000 back surface");
  plan::ContactPair close;
  close.object = "bed000";
  close.part = "none";
  close.direction = plan::Direction::kFront;
  step.pairs = {close};
  EXPECT_EQ(StepText(step), "get close to bed000 (front)");
}

TEST(EpisodeTest, ResultJsonUsesNullForMissingValues) {
  control::EpisodeResult r;
  r.steps_total = 2;
  r.end_reason = "unstable: bad qacc at t=1.000 s";
  nlohmann::ordered_json j = EpisodeResultJson(r);
  for (const char* key :
       {"success", "steps_completed", "steps_total", "contact_error_m", "fell", "end_reason",
        "sim_time_s", "wall_time_s", "wall_per_sim", "step_completion_s", "pair_errors_m"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_TRUE(j["contact_error_m"].is_null());
  EXPECT_TRUE(j["wall_per_sim"].is_null());
  EXPECT_EQ(j["end_reason"], r.end_reason);
  r.contact_error_m = 0.04;
  r.pair_errors_m = {{0.03, 0.0}, {0.09}};
  r.sim_time_s = 2.0;
  r.wall_time_s = 1.0;
  j = EpisodeResultJson(r);
  EXPECT_DOUBLE_EQ(j["contact_error_m"].get<double>(), 0.04);
  EXPECT_DOUBLE_EQ(j["wall_per_sim"].get<double>(), 0.5);
  ASSERT_EQ(j["pair_errors_m"].size(), 2u);
  EXPECT_DOUBLE_EQ(j["pair_errors_m"][1][0].get<double>(), 0.09);
  nlohmann::ordered_json p = ProvenanceJson();
  EXPECT_FALSE(p["git_revision"].get<std::string>().empty());
  EXPECT_EQ(p["mujoco_version"], mj_versionString());
}

EpisodeRecord Record(bool plan_success, bool extra_pass, double error_m, bool fell, int steps,
                     double sim_s, double wall_s) {
  EpisodeRecord r;
  r.result.success = plan_success;
  r.result.steps_completed = steps;
  r.result.steps_total = 2;
  r.result.contact_error_m = error_m;
  r.result.fell = fell;
  r.result.sim_time_s = sim_s;
  r.result.wall_time_s = wall_s;
  r.extra.pass = extra_pass;
  r.extra.metric = "lie_axis_error_deg";
  r.extra.value = extra_pass ? 10.0 : std::nan("");
  r.success = plan_success && extra_pass;
  return r;
}

TEST(EvalRunnerTest, SuccessNeedsThePlanThenTheHoldThenTheExtraCheck) {
  // every way to loosen the rule flips one of these cases
  struct Case {
    bool plan, holds, fell, extra, held, success;
  };
  const Case cases[] = {
      {true, true, false, true, true, true},     // all three
      {false, true, false, true, false, false},  // the plan failed: a later pose counts for nothing
      {true, false, false, true, false, false},  // completed, but no longer held 3 s later
      {true, true, true, true, false, false},    // held at the end, but fell in between
      {true, true, false, false, true, false},   // held, but the suite's extra check fails
  };
  for (const Case& c : cases) {
    EpisodeRecord r;
    r.result.success = c.plan;
    r.result.fell = c.fell;
    r.extra.pass = c.extra;
    JudgeEpisode(c.holds, &r);
    EXPECT_EQ(r.held, c.held) << c.plan << c.holds << c.fell << c.extra;
    EXPECT_EQ(r.success, c.success) << c.plan << c.holds << c.fell << c.extra;
  }
  EXPECT_DOUBLE_EQ(kEvalSettleS, 3.0);
}

// the hold check's posture for stand-up and walk-to steps (ours, beside UniHSI's position rule)
TEST(EvalRunnerTest, AGetCloseStepHoldsOnlyWithTheHumanOnItsFeetIntegration) {
  using J = core::BodyJoint;
  auto body = [](double hip_z, Eigen::Vector3d knee, Eigen::Vector3d foot, Eigen::Vector3d head) {
    plan::BodyPoints b;
    for (double side : {-0.1, 0.1}) {
      const Eigen::Vector3d y(0, side, 0);
      b.at(side < 0 ? J::kRightHip : J::kLeftHip) = Eigen::Vector3d(0, side, hip_z);
      b.at(side < 0 ? J::kRightKnee : J::kLeftKnee) = knee + y;
      b.at(side < 0 ? J::kRightFoot : J::kLeftFoot) = foot + y;
    }
    b.at(J::kHead) = head;
    return b;
  };
  const plan::BodyPoints standing = body(0.92, {0.02, 0, 0.5}, {0, 0, 0.08}, {0, 0, 1.6});
  const plan::BodyPoints seated = body(0.5, {0.45, 0, 0.52}, {0.45, 0, 0.08}, {-0.05, 0, 1.15});
  const plan::BodyPoints slumped = body(0.15, {0.4, 0, 0.25}, {0.8, 0, 0.08}, {-0.2, 0, 0.6});
  const plan::BodyPoints lying = body(0.6, {0.42, 0, 0.6}, {0.84, 0, 0.6}, {-0.62, 0, 0.62});
  const plan::BodyPoints bent = body(0.9, {0.02, 0, 0.5}, {0, 0, 0.08}, {0.7, 0, 1.0});
  EXPECT_TRUE(StandsOnItsFeet(standing));
  EXPECT_FALSE(StandsOnItsFeet(seated));
  EXPECT_FALSE(StandsOnItsFeet(slumped));  // beside a bed, the pelvis at its stand point
  EXPECT_FALSE(StandsOnItsFeet(lying));
  EXPECT_FALSE(StandsOnItsFeet(bent));  // the trunk folded forward past 45 degrees
  plan::ContactStep stand_up;
  plan::ContactPair get_close;
  get_close.part = "none";
  get_close.agent = 1;
  ASSERT_TRUE(get_close.IsGetClose());
  stand_up.pairs = {get_close};
  EXPECT_TRUE(GetCloseHumansStand(stand_up, {slumped, standing}));
  EXPECT_FALSE(GetCloseHumansStand(stand_up, {standing, slumped}));
  EXPECT_FALSE(GetCloseHumansStand(stand_up, {standing}));  // no such human
  // a step without get-close pairs is not judged by posture
  plan::ContactPair sit;
  sit.joint = J::kPelvis;
  sit.part = "seat surface";
  ASSERT_FALSE(sit.IsGetClose());
  EXPECT_TRUE(GetCloseHumansStand(plan::ContactStep{{sit}, std::nullopt, "", ""}, {lying}));
  // our humanoid as it starts, standing, and at a child's and a tall adult's scale
  for (double scale : {0.6, 1.0, 1.2}) {
    world::AgentSpec human;
    human.scale = scale;
    auto w = world::SimWorld::Create(core::SceneCatalog{}, {human});
    ASSERT_TRUE(w.ok()) << w.status();
    mj_forward((*w)->model(), (*w)->data());
    EXPECT_TRUE(StandsOnItsFeet(control::AllBodyPoints(**w, (*w)->data())[0])) << scale;
  }
}

TEST(EvalRunnerTest, SummaryByHand) {
  std::vector<EpisodeRecord> recs = {
      Record(true, true, 0.02, false, 2, 10, 5), Record(true, false, 0.04, false, 2, 10, 5),
      Record(false, true, -1, true, 0, 5, 10), Record(false, true, 0.06, false, 1, 15, 10)};
  Summary s = Summarize("lie", recs, 10);
  EXPECT_EQ(s.suite, "lie");
  EXPECT_EQ(s.episodes, 4);
  EXPECT_EQ(s.episodes_requested, 10);
  EXPECT_DOUBLE_EQ(s.success_rate, 0.25);
  ASSERT_TRUE(s.contact_error_m.has_value());
  EXPECT_NEAR(*s.contact_error_m, 0.04, kTol);  // the episode without one is left out
  EXPECT_DOUBLE_EQ(s.success_steps, 1.25);
  EXPECT_DOUBLE_EQ(s.fall_rate, 0.25);
  EXPECT_DOUBLE_EQ(s.extra_pass_rate, 0.75);
  EXPECT_DOUBLE_EQ(s.wall_per_sim, 30.0 / 40.0);

  // UniHSI's body points: only the succeeding episode that also met them counts, and
  // journals without the field (before session 31) are left out
  ASSERT_TRUE(s.success_rate_unihsi_points.has_value());
  EXPECT_DOUBLE_EQ(*s.success_rate_unihsi_points, 0.0);
  recs[0].result.success_unihsi_points = true;
  recs[1].result.success_unihsi_points = true;  // its episode failed the hold: no success
  recs[2].unihsi_recorded = false;
  EXPECT_DOUBLE_EQ(*Summarize("lie", recs, 10).success_rate_unihsi_points, 1.0 / 3.0);
  auto reread = EpisodeRecordFromJson(EpisodeRecordJson(recs[0]));
  ASSERT_TRUE(reread.ok()) << reread.status();
  EXPECT_TRUE(reread->unihsi_recorded && reread->result.success_unihsi_points);
  nlohmann::json old_line = EpisodeRecordJson(recs[0]);
  old_line.erase("success_unihsi_points");
  reread = EpisodeRecordFromJson(old_line);
  ASSERT_TRUE(reread.ok()) << reread.status();
  EXPECT_FALSE(reread->unihsi_recorded);
  // the pair distances at the hold check round-trip, and are empty in older journals
  recs[1].held_pair_errors_m = {0.04, 0.12};
  reread = EpisodeRecordFromJson(EpisodeRecordJson(recs[1]));
  ASSERT_TRUE(reread.ok()) << reread.status();
  EXPECT_EQ(reread->held_pair_errors_m, (std::vector<double>{0.04, 0.12}));
  old_line = EpisodeRecordJson(recs[1]);
  old_line.erase("held_pair_errors_m");
  reread = EpisodeRecordFromJson(old_line);
  ASSERT_TRUE(reread.ok()) << reread.status();
  EXPECT_TRUE(reread->held_pair_errors_m.empty());

  Summary empty = Summarize("sit", {}, 3);
  EXPECT_EQ(empty.episodes, 0);
  EXPECT_FALSE(empty.contact_error_m.has_value());
  EXPECT_FALSE(empty.success_rate_unihsi_points.has_value());

  EvalOptions options;
  options.seed = 9;
  nlohmann::ordered_json j = SummaryJson(s, options);
  for (const char* key :
       {"suite", "episodes", "episodes_requested", "success_rate", "success_rate_unihsi_points",
        "contact_error_m", "success_steps", "fall_rate", "wall_per_sim", "seed", "preset", "config",
        "git_revision", "mujoco_version"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_TRUE(SummaryJson(empty, options)["contact_error_m"].is_null());

  nlohmann::ordered_json line = EpisodeRecordJson(recs[1]);
  EXPECT_EQ(line["success"], false);
  EXPECT_EQ(line["plan_success"], true);
  EXPECT_EQ(line["extra_check"], "lie_axis_error_deg");
  EXPECT_TRUE(EpisodeRecordJson(recs[1])["lie_axis_error_deg"].is_null());  // NaN
  EXPECT_EQ(line.dump().find('\n'), std::string::npos);
}

}  // namespace
}  // namespace simhuman::eval
