#include "simhuman/eval/vision_eval.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>

#include "simhuman/eval/tabletop_eval.h"
#include "simhuman/eval/tabletop_vision.h"
#include "simhuman/eval/vision_frames.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::eval {
namespace {

using ::testing::HasSubstr;

std::string ShippedModel() { return std::string(SIMHUMAN_SOURCE_DIR) + "/assets/vision/vision.pt"; }

TEST(VisionTrainConfigTest, ErrorsNameTheKeyAndTheRange) {
  auto unknown = VisionTrainConfig::FromJson({{"epochz", 3}});
  ASSERT_FALSE(unknown.ok());
  EXPECT_THAT(std::string(unknown.status().message()), HasSubstr("epochz"));
  auto bad = VisionTrainConfig::FromJson({{"fovy_deg", 5}});
  ASSERT_FALSE(bad.ok());
  EXPECT_THAT(std::string(bad.status().message()), HasSubstr("fovy_deg"));
  auto ok = VisionTrainConfig::FromJson({{"epochs", 3}});
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok->epochs, 3);
  EXPECT_EQ(ok->ToJson()["epochs"], 3);
}

// the pinhole model the network reads rays from is the camera MuJoCo renders: each visible
// object's true centre projects onto a pixel that shows that object
TEST(VisionFramesTest, TrueCentresProjectOntoTheirObjectsIntegration) {
  VisionFrameOptions o;
  o.planning_scenes = 2;
  o.placing_episodes = 0;
  int frames = 0, checked = 0;
  const core::Status s = CollectVisionFrames(o, [&](VisionFrame& f) {
    ++frames;
    EXPECT_EQ(f.stage, "planning");
    EXPECT_GE(f.task_object, 0);
    for (const perceive::ObjectTruth& t : f.truth) {
      if (t.pixels < 60) continue;  // mostly hidden or out of view
      double u, v;
      ASSERT_TRUE(f.camera.Project(t.centre, &u, &v));
      const int x = static_cast<int>(u), y = static_cast<int>(v);
      ASSERT_TRUE(x >= 0 && y >= 0 && x < f.camera.width && y < f.camera.height);
      EXPECT_EQ(f.body_ids[static_cast<size_t>(y) * f.camera.width + x], t.body) << t.id;
      ++checked;
    }
  });
  if (absl::IsUnavailable(s)) GTEST_SKIP() << s;
  ASSERT_TRUE(s.ok()) << s;
  EXPECT_EQ(frames, 2);
  EXPECT_GE(checked, 4);
}

// training frames of a held object tipped in the grip: its true up axis is the tilted one, the
// object stays at the hand, and without the share the same episode's frames are as they were
TEST(VisionFramesTest, HeldObjectsTiltedInTheHandAreShownAndLabelledTiltedIntegration) {
  VisionFrameOptions o;
  o.planning_scenes = 0;
  o.placing_episodes = 1;
  o.placing_frames = 4;
  o.placing_near_m = 1.0;
  o.seed = 3;
  auto tilts = [&](double share, std::vector<double>* out) {
    o.held_tilt_share = share;
    return CollectVisionFrames(o, [&](VisionFrame& f) {
      if (f.task_object < 0 || f.truth[f.task_object].shape == 2) return;  // a sphere: no up
      const perceive::ObjectTruth& t = f.truth[f.task_object];
      out->push_back(std::acos(std::clamp(t.up.z(), -1.0, 1.0)) * 180 / M_PI);
      if (share > 0) {
        EXPECT_GT(t.pixels, 30) << "the tilted object is in view";
      }
    });
  };
  std::vector<double> plain, tilted;
  for (o.seed = 3; o.seed < 10 && plain.empty(); ++o.seed) {  // the first box or cylinder
    const core::Status s = tilts(0, &plain);
    if (absl::IsUnavailable(s)) GTEST_SKIP() << s;
    ASSERT_TRUE(s.ok()) << s;
  }
  --o.seed;
  ASSERT_TRUE(tilts(1, &tilted).ok());
  ASSERT_EQ(plain.size(), 4u);
  ASSERT_EQ(tilted.size(), plain.size());
  double most = 0;
  for (size_t i = 0; i < plain.size(); ++i) {
    most = std::max(most, std::abs(tilted[i] - plain[i]));
    EXPECT_LE(tilted[i], plain[i] + o.held_tilt_max_deg + 0.1);
  }
  EXPECT_GT(most, 3.0) << "some frame shows a tilt the grasp did not make";
}

TEST(VisionEvalTest, TheShippedModelSeesThePlanningTablesIntegration) {
  if (!std::filesystem::exists(ShippedModel())) GTEST_SKIP() << "no " << ShippedModel();
  VisionEvalOptions o;
  o.model = ShippedModel();
  o.planning_scenes = 3;
  o.placing_episodes = 0;
  o.seed = 7;
  auto m = RunVisionEval(o);
  if (absl::IsUnavailable(m.status())) GTEST_SKIP() << m.status();
  ASSERT_TRUE(m.ok()) << m.status();
  const VisionStageMetrics& p = m->at("planning");
  EXPECT_EQ(p.frames, 3);
  ASSERT_GE(p.objects, 8);
  EXPECT_GE(p.matched, p.objects - 1);
  EXPECT_GE(p.colour_ok, p.matched - 1);
  EXPECT_GE(p.shape_ok, p.matched - 1);
  for (int k = 0; k < 3; ++k) EXPECT_LT(p.abs_err_cm[k] / p.matched, 2.5) << "axis " << k;
  // the silhouette fit brings the network's sizes closer to the truth (over 60 scenes: width
  // 0.58 -> 0.10 cm, height 0.56 -> 0.14 cm; docs/BENCHMARKS.md, issue 16 session 49)
  const VisionStageMetrics& net = m->at("planning-network");
  EXPECT_EQ(net.matched, p.matched);
  EXPECT_LT(p.width_err_cm, 0.5 * net.width_err_cm);
  EXPECT_LT(p.height_err_cm, 0.5 * net.height_err_cm);
}

TEST(VisionEvalTest, AMissingOrWrongModelIsNamed) {
  VisionEvalOptions o;
  o.model = "/nonexistent/vision.pt";
  auto m = RunVisionEval(o);
  ASSERT_FALSE(m.ok());
  EXPECT_TRUE(absl::IsNotFound(m.status()));
  EXPECT_THAT(std::string(m.status().message()), HasSubstr("/nonexistent/vision.pt"));
  TabletopEvalOptions t;
  t.episodes = 1;
  t.perception = "eyes";
  auto r = RunTabletopEval(t);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("truth, vision"));
}

TEST(TabletopVisionTest, TheGoalIsPlannedFromTheFirstFrameIntegration) {
  if (!std::filesystem::exists(ShippedModel())) GTEST_SKIP() << "no " << ShippedModel();
  auto tw = MakeTableWorld(11, "stack");
  ASSERT_TRUE(tw.ok()) << tw.status();
  const world::TabletopScene* ts = &tw->ts;
  const core::SceneCatalog* catalog = &tw->catalog;
  std::unique_ptr<world::SimWorld>* w = &tw->world;
  auto truth = TabletopSceneGoal(tw->ts, *tw->world);
  ASSERT_TRUE(truth.ok()) << truth.status();
  auto vision = TabletopVision::Create(ShippedModel(), (*w)->model());
  if (absl::IsUnavailable(vision.status())) GTEST_SKIP() << vision.status();
  ASSERT_TRUE(vision.ok()) << vision.status();
  control::manip::TabletopGoal goal = *truth;
  ASSERT_TRUE((*vision)->Begin(**w, *catalog, ts->task.object_id, ts->task.target_id, &goal).ok());
  EXPECT_LT((goal.planned_pos - truth->planned_pos).norm(), 0.02);
  EXPECT_LT((goal.target - truth->target).norm(), 0.02);
  EXPECT_NEAR(goal.height_m, truth->height_m, 0.02);
  EXPECT_NEAR(goal.half_width_m, truth->half_width_m, 0.01);
  ASSERT_TRUE(static_cast<bool>(goal.observe));
  // before the object is held the controllers see the plan
  const control::manip::ObjectView v = goal.observe((*w)->data(), false);
  EXPECT_LT((v.base - goal.planned_pos).norm(), 1e-9);
  EXPECT_EQ((*vision)->frames(), 1);
  // an object the scene does not hold is named, with what was seen
  control::manip::TabletopGoal other = *truth;
  const core::Status missing = (*vision)->Begin(**w, *catalog, "chair001", "", &other);
  EXPECT_TRUE(absl::IsNotFound(missing)) << missing;
  EXPECT_THAT(std::string(missing.message()), HasSubstr("seen:"));
}

// An object near the human's left hand, where the planning frame's edge cuts it (tabletop suite
// episode 192: "not seen at task planning"), is found by the second look at it.
TEST(TabletopVisionTest, AnObjectTheFramesEdgeCutsIsSeenByASecondLookIntegration) {
  if (!std::filesystem::exists(ShippedModel())) GTEST_SKIP() << "no " << ShippedModel();
  auto tw = MakeTableWorld(11, "place");
  ASSERT_TRUE(tw.ok()) << tw.status();
  auto truth = TabletopSceneGoal(tw->ts, *tw->world);
  ASSERT_TRUE(truth.ok()) << truth.status();
  const mjModel* m = tw->world->model();
  mjData* d = tw->world->data();
  const int adr = m->jnt_qposadr[m->body_jntadr[truth->object_body]];
  Eigen::Vector3d planned = Eigen::Vector3d::Zero();  // the moved object's base as planned
  auto begin = [&](bool again, int* frames) {
    VisionLoopOptions lo;
    lo.second_look = again;
    auto vision = TabletopVision::Create(ShippedModel(), m, lo);
    if (!vision.ok()) return vision.status();
    control::manip::TabletopGoal goal = *truth;
    SH_RETURN_IF_ERROR((*vision)->Begin(*tw->world, tw->catalog, tw->ts.task.object_id, "", &goal));
    *frames = (*vision)->frames();
    planned = goal.planned_pos;
    return absl::OkStatus();
  };
  // the near left corner of the objects' region, and beyond it toward the human's left
  int cut = 0;
  for (double y = 0.50; y < 0.66; y += 0.03) {
    const Eigen::Vector3d at = world::TableToWorld(Eigen::Vector3d(-0.10, y, 0));
    d->qpos[adr] = at.x();
    d->qpos[adr + 1] = at.y();
    mj_forward(m, d);
    int frames = 0;
    const core::Status first = begin(false, &frames);
    if (absl::IsUnavailable(first)) GTEST_SKIP() << first;
    if (first.ok()) continue;  // seen whole from the planning gaze
    ASSERT_TRUE(absl::IsNotFound(first)) << first;
    ++cut;
    const core::Status s = begin(true, &frames);
    ASSERT_TRUE(s.ok()) << "at table y " << y << ": " << s;
    EXPECT_GE(frames, 2);
    const Eigen::Vector3d base(d->xpos + 3 * truth->object_body);
    EXPECT_LT((planned - base).norm(), 0.01) << "at table y " << y;
  }
  EXPECT_GT(cut, 0) << "the planning frame cut the object nowhere";
}

// Once held, the object is kept in the hand's frame: when the hand moves, the estimate moves
// with it at once (before any new frame arrives). The "hand" here is the object's own body, so
// the object sits still in it; with the in-hand estimate off, the estimate stays behind.
TEST(TabletopVisionTest, TheHeldObjectsEstimateMovesWithTheHandIntegration) {
  if (!std::filesystem::exists(ShippedModel())) GTEST_SKIP() << "no " << ShippedModel();
  auto tw = MakeTableWorld(11, "place");
  ASSERT_TRUE(tw.ok()) << tw.status();
  const world::TabletopScene* ts = &tw->ts;
  const core::SceneCatalog* catalog = &tw->catalog;
  std::unique_ptr<world::SimWorld>* w = &tw->world;
  auto truth = TabletopSceneGoal(tw->ts, *tw->world);
  ASSERT_TRUE(truth.ok()) << truth.status();
  const mjModel* m = (*w)->model();
  mjData* d = (*w)->data();
  const int body = truth->object_body;
  const int adr = m->jnt_qposadr[m->body_jntadr[body]];
  for (int in_hand : {20, 0}) {
    VisionLoopOptions lo;
    lo.in_hand_frames = in_hand;
    auto vision = TabletopVision::Create(ShippedModel(), m, lo);
    if (absl::IsUnavailable(vision.status())) GTEST_SKIP() << vision.status();
    ASSERT_TRUE(vision.ok()) << vision.status();
    control::manip::TabletopGoal goal = *truth;
    ASSERT_TRUE(
        (*vision)->Begin(**w, *catalog, ts->task.object_id, "", &goal, /*hand_body=*/body).ok());
    // a second of frames, then the controllers take the object as held
    for (int k = 0; k < 20; ++k) {
      d->time += 0.05;
      ASSERT_TRUE((*vision)->OnStep(d).ok());
    }
    const control::manip::ObjectView before = goal.observe(d, true);
    const Eigen::Vector3d c0(d->xipos + 3 * body);
    EXPECT_LT((before.centre - c0).norm(), 0.03) << "in_hand_frames " << in_hand;
    // the hand (the object's body) lifts by 10 cm and turns 30 degrees about the vertical
    const double q0[7] = {d->qpos[adr],     d->qpos[adr + 1], d->qpos[adr + 2], d->qpos[adr + 3],
                          d->qpos[adr + 4], d->qpos[adr + 5], d->qpos[adr + 6]};
    d->qpos[adr + 2] += 0.1;
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()));
    const Eigen::Quaterniond q = turn * Eigen::Quaterniond(d->qpos[adr + 3], d->qpos[adr + 4],
                                                           d->qpos[adr + 5], d->qpos[adr + 6]);
    d->qpos[adr + 3] = q.w();
    d->qpos[adr + 4] = q.x();
    d->qpos[adr + 5] = q.y();
    d->qpos[adr + 6] = q.z();
    mj_forward(m, d);
    const Eigen::Vector3d c1(d->xipos + 3 * body);
    const control::manip::ObjectView after = goal.observe(d, true);
    if (in_hand > 0) {
      EXPECT_LT((after.centre - c1).norm(), 0.03);
      // the same error as before, turned with the hand
      EXPECT_LT(((after.centre - c1) - turn * (before.centre - c0)).norm(), 0.001);
    } else {
      EXPECT_LT((after.centre - before.centre).norm(), 1e-9);  // no new frame yet
    }
    mju_copy(d->qpos + adr, q0, 7);
    mj_forward(m, d);
    d->time = 0;
  }
}

// With touch_grasp, what the hand touches corrects the object the grasp sees: the "hand" is
// another object of the scene pressed against the moved one's side (its face square to the line
// between them); with touch the estimate's centre lies the object's half width behind the
// touched face, without it the estimate stays the first frame's.
TEST(TabletopVisionTest, TouchMovesTheGraspedObjectsEstimateOntoTheTouchedFaceIntegration) {
  if (!std::filesystem::exists(ShippedModel())) GTEST_SKIP() << "no " << ShippedModel();
  // the first generated place scene that moves a box and holds a second box
  core::StatusOr<control::manip::TableWorld> tw = absl::NotFoundError("none");
  core::StatusOr<control::manip::TabletopGoal> truth = absl::NotFoundError("none");
  int pusher = -1;
  for (uint64_t seed = 1; seed < 40 && pusher < 0; ++seed) {
    tw = MakeTableWorld(seed, "place");
    ASSERT_TRUE(tw.ok()) << tw.status();
    truth = TabletopSceneGoal(tw->ts, *tw->world);
    ASSERT_TRUE(truth.ok()) << truth.status();
    if (truth->shape != control::manip::GraspShape::kBox) continue;
    for (const core::CatalogObject& o : tw->catalog.objects) {
      if (o.type != "box" || o.id == tw->ts.task.object_id) continue;
      pusher = mj_name2id(tw->world->model(), mjOBJ_BODY, world::ObjectBodyName(o.id).c_str());
      if (pusher >= 0) break;
    }
  }
  ASSERT_GE(pusher, 0) << "no place scene of seeds 1-39 moves a box beside a second box";
  const mjModel* m = tw->world->model();
  mjData* d = tw->world->data();
  double pusher_half = 0;
  for (int g = 0; g < m->ngeom; ++g) {
    // a box is a shell of box geoms: its half width is the furthest reach of one along x
    if (m->geom_bodyid[g] == pusher) {
      pusher_half = std::max(pusher_half, std::abs(m->geom_pos[3 * g]) + m->geom_size[3 * g]);
    }
  }
  // the object's face toward the human (-x): the pusher turned as the object is
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rot(d->xmat +
                                                                           9 * truth->object_body);
  Eigen::Vector3d side = -rot.col(0);
  if (side.x() > 0) side = -side;
  const Eigen::Vector3d base(d->xpos + 3 * truth->object_body);
  const int adr = m->jnt_qposadr[m->body_jntadr[pusher]];
  std::array<double, 7> home;
  std::copy(d->qpos + adr, d->qpos + adr + 7, home.begin());
  const double depth = 0.0005;
  const Eigen::Vector3d at = base + (truth->half_width_m + pusher_half - depth) * side;
  for (bool touch : {true, false}) {
    std::copy(home.begin(), home.end(), d->qpos + adr);
    mj_forward(m, d);
    VisionLoopOptions lo;
    lo.touch = touch;
    lo.touch_grasp = true;
    auto vision = TabletopVision::Create(ShippedModel(), m, lo);
    if (absl::IsUnavailable(vision.status())) GTEST_SKIP() << vision.status();
    ASSERT_TRUE(vision.ok()) << vision.status();
    control::manip::TabletopGoal goal = *truth;
    ASSERT_TRUE(
        (*vision)->Begin(*tw->world, tw->catalog, tw->ts.task.object_id, "", &goal, pusher).ok());
    const control::manip::ObjectView planned = goal.observe(d, false);
    // the "hand" closes on the object's side
    d->qpos[adr] = at.x();
    d->qpos[adr + 1] = at.y();
    d->qpos[adr + 2] = base.z() + 0.001;  // its base on the table, as the object's
    std::copy(d->xquat + 4 * truth->object_body, d->xquat + 4 * truth->object_body + 4,
              d->qpos + adr + 3);
    mj_forward(m, d);
    for (int k = 0; k < 4; ++k) {
      d->time += 0.05;
      ASSERT_TRUE((*vision)->OnStep(d).ok());
    }
    const control::manip::ObjectView felt = goal.observe(d, false);
    if (touch) {
      // (the first frame's estimate lies 1.2 mm off this) the estimate's centre lies a half width
      // (as estimated) behind the touched face
      const double face = (at - pusher_half * side).dot(side) + 0.5 * depth;
      EXPECT_NEAR(face - felt.centre.dot(side), 0.5 * (*vision)->planned_width_m(), 0.0005);
    } else {
      EXPECT_LT((felt.centre - planned.centre).norm(), 1e-12);
    }
    d->time = 0;
  }
  std::copy(home.begin(), home.end(), d->qpos + adr);
  mj_forward(m, d);
}

TEST(TabletopVisionTest, APlaceTaskRunsOnTheCamerasEstimatesSlow) {
  if (!std::filesystem::exists(ShippedModel())) GTEST_SKIP() << "no " << ShippedModel();
  TabletopEvalOptions o;
  o.episodes = 1;
  o.kind = "place";
  o.perception = "vision";
  o.vision_model = ShippedModel();
  auto s = RunTabletopEval(o);
  if (absl::IsUnavailable(s.status())) GTEST_SKIP() << s.status();
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(s->episodes, 1);
  EXPECT_EQ(s->perception, "vision");
  // the camera ran at 20 Hz through the episode (one planning frame, then every 50 ms)
  EXPECT_GE(s->vision_frames, static_cast<int>(s->sim_s * 20) - 1);
  EXPECT_LE(s->vision_frames, static_cast<int>(s->sim_s * 20) + 2);
}

}  // namespace
}  // namespace simhuman::eval
