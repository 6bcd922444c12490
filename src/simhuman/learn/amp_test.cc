#include "simhuman/learn/amp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "simhuman/core/testing_temp.h"
#include "simhuman/learn/amp_features.h"
#include "simhuman/learn/gait_clip.h"
#include "simhuman/learn/motion_clip.h"
#include "simhuman/learn/ppo.h"
#include "simhuman/learn/reach_env.h"
#include "simhuman/learn/walk_env.h"

namespace simhuman::learn {
namespace {

namespace fs = std::filesystem;

std::string TempDir(const std::string& name) {
  fs::path p = core::testing::UniqueTempPath("amp_test_" + name);
  fs::remove_all(p);
  return p.string();
}

// feature blocks (amp_features.h)
bool IsVelocity(int k) { return (k >= 7 && k < 13) || (k >= 41 && k < 69); }

MotionClip Gait(double seconds) {
  GaitClipOptions o;
  o.seconds = seconds;
  auto c = GaitClip(o);
  EXPECT_TRUE(c.ok()) << c.status();
  return *c;
}

TEST(GaitClip, AdvancesAtTheCommandedSpeedWithAFootOnTheFloor) {
  MotionClip c = Gait(2.0);
  ASSERT_EQ(c.frames.size(), 61u);
  EXPECT_NEAR(c.frames.back().root_pos_m[0], 2.0, 1e-9);
  for (const ClipFrame& f : c.frames) {
    EXPECT_GT(f.root_pos_m[2], 0.85);
    EXPECT_LT(f.root_pos_m[2], 1.0);
  }
  // the knees alternate
  double max_l = 0, max_r = 0;
  for (const ClipFrame& f : c.frames) {
    max_l = std::max(max_l, f.q_rad[24]);
    max_r = std::max(max_r, f.q_rad[17]);
  }
  EXPECT_GT(max_l, 0.8);
  EXPECT_GT(max_r, 0.8);
}

// The same state gives the same features from the simulator and from a clip: the walk task
// is simulated, its states are recorded at the policy rate as a clip, and the clip's features
// (positions from the frames, velocities by finite differences) match the online ones.
TEST(AmpFeatures, SameFromSimulationAndFromClip) {
  constexpr float kPoseTol = 1e-4f;    // positions and angles: same qpos, float rounding
  constexpr double kVelRelTol = 0.25;  // finite differences at 30 Hz vs instantaneous
  auto task = WalkTask::Create(1);
  ASSERT_TRUE(task.ok()) << task.status();
  WalkTask& t = **task;
  ASSERT_EQ(t.amp_feature_dim(), kAmpFeatureDim);
  const mjModel* m = t.model();
  int root = m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "root")];
  std::vector<int> hinge;
  for (const std::string& n : world::HumanoidJointNames()) {
    hinge.push_back(m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, n.c_str())]);
  }
  std::vector<float> obs(control::kWalkObsDim), act(control::kWalkActDim);
  t.Reset(0, 11, obs.data());
  MotionClip clip;
  clip.fps = 1.0 / control::kWalkPolicyDt;
  std::vector<float> online;
  const int kSteps = 24;
  for (int s = 0; s <= kSteps; ++s) {
    if (s > 0) {
      for (int j = 0; j < control::kWalkActDim; ++j) act[j] = 0.6f * std::sin(0.3f * s + j);
      StepInfo info;
      t.Step(0, act.data(), obs.data(), &info);
      ASSERT_FALSE(info.terminated);
    }
    std::vector<float> f(kAmpFeatureDim);
    t.AmpFeatures(0, f.data());
    online.insert(online.end(), f.begin(), f.end());
    const mjData* d = t.data(0);
    ClipFrame fr;
    for (int k = 0; k < 3; ++k) fr.root_pos_m[k] = d->qpos[root + k];
    for (int k = 0; k < 4; ++k) fr.root_quat_wxyz[k] = d->qpos[root + 3 + k];
    for (int j = 0; j < world::kHumanoidDofs; ++j) fr.q_rad[j] = d->qpos[hinge[j]];
    clip.frames.push_back(fr);
  }
  auto from_clip = t.AmpClipFeatures(clip);
  ASSERT_TRUE(from_clip.ok()) << from_clip.status();
  ASSERT_EQ(from_clip->size(), online.size());
  double vel_err = 0, vel_mag = 0;
  for (int s = 1; s < kSteps; ++s) {  // interior frames (central differences)
    for (int k = 0; k < kAmpFeatureDim; ++k) {
      float a = online[s * kAmpFeatureDim + k], b = (*from_clip)[s * kAmpFeatureDim + k];
      if (IsVelocity(k)) {
        vel_err += std::abs(a - b);
        vel_mag += std::abs(a);
      } else {
        EXPECT_NEAR(a, b, kPoseTol) << "frame " << s << " feature " << k;
      }
    }
  }
  EXPECT_GT(vel_mag, 1.0);  // the body did move
  EXPECT_LT(vel_err / vel_mag, kVelRelTol);
}

// A state set from a clip frame (qpos, finite-difference qvel) gives exactly the clip's row.
TEST(AmpFeatures, StateSetFromClipMatchesClipRowIntegration) {
  auto task = WalkTask::Create(1);
  ASSERT_TRUE(task.ok()) << task.status();
  MotionClip clip = Gait(1.0);
  auto rows = (*task)->AmpClipFeatures(clip);
  ASSERT_TRUE(rows.ok()) << rows.status();
  auto sim = world::SimWorld::Create(core::SceneCatalog(), {world::AgentSpec()}, {});
  ASSERT_TRUE(sim.ok()) << sim.status();
  const mjModel* m = (*sim)->model();
  mjData* d = (*sim)->data();
  for (size_t f : {0, 7, 30}) {
    SetStateFromClip(m, (*sim)->agent(0), clip, f, d->qpos, d->qvel);
    mj_forward(m, d);
    std::vector<float> out(kAmpFeatureDim);
    AmpFeatures(m, d, (*sim)->agent(0), out.data());
    for (int k = 0; k < kAmpFeatureDim; ++k) {
      EXPECT_NEAR(out[k], (*rows)[f * kAmpFeatureDim + k], 1e-5) << f << " " << k;
    }
  }
}

TEST(AmpReplayBuffer, WrapsAround) {
  AmpReplayBuffer buf(5, 2);
  buf.Add(torch::arange(8, torch::kFloat32).reshape({4, 2}));
  EXPECT_EQ(buf.size(), 4);
  buf.Add(torch::full({3, 2}, -1.f));
  EXPECT_EQ(buf.size(), 5);
  core::Rng rng(1);
  torch::Tensor s = buf.Sample(200, rng);
  // rows 0 and 1 were overwritten by the second batch: only {4,5}, {6,7} and -1 rows remain
  EXPECT_EQ((s.select(1, 0) == 0).sum().item<int64_t>(), 0);
  EXPECT_GT((s.select(1, 0) == -1).sum().item<int64_t>(), 0);
  EXPECT_GT((s.select(1, 0) == 6).sum().item<int64_t>(), 0);
}

// The discriminator learns to tell clip pairs from noisy pairs within a fixed budget.
TEST(AmpDiscriminator, SeparatesClipPairsFromNoisePairsIntegration) {
  constexpr double kMinAccuracy = 0.9;
  constexpr int kUpdates = 150, kBatch = 128;
  auto task = WalkTask::Create(1);
  ASSERT_TRUE(task.ok()) << task.status();
  auto feats = (*task)->AmpClipFeatures(Gait(4.0));
  ASSERT_TRUE(feats.ok()) << feats.status();
  torch::manual_seed(3);
  torch::Tensor expert = AmpExpertPairs({*feats}, kAmpFeatureDim);
  AmpDiscriminator disc(kAmpFeatureDim, std::vector<int>{64, 64});
  disc->FitNormalizer(expert.slice(1, 0, kAmpFeatureDim));
  torch::optim::Adam opt(disc->parameters(), torch::optim::AdamOptions(1e-3));
  core::Rng rng(4);
  auto noisy = [&](int64_t n) {
    torch::Tensor e = SampleRows(expert, n, rng);
    return e + 0.3 * torch::randn(e.sizes());
  };
  AmpUpdateStats st;
  for (int k = 0; k < kUpdates; ++k) {
    ASSERT_TRUE(
        AmpUpdate(disc, opt, SampleRows(expert, kBatch, rng), noisy(kBatch), 5.0, 1.0, &st));
  }
  torch::Tensor d_e, d_n;
  torch::Tensor r_e = AmpStyleReward(disc, SampleRows(expert, 512, rng), &d_e);
  torch::Tensor r_n = AmpStyleReward(disc, noisy(512), &d_n);
  double acc = 0.5 * ((d_e > 0).to(torch::kFloat32).mean().item<double>() +
                      (d_n < 0).to(torch::kFloat32).mean().item<double>());
  EXPECT_GT(acc, kMinAccuracy) << "last loss " << st.loss;
  EXPECT_GT(r_e.mean().item<double>(), r_n.mean().item<double>() + 0.3);
  EXPECT_GE(r_n.min().item<double>(), 0.0);
  EXPECT_LE(r_e.max().item<double>(), 1.0);
}

PpoConfig TinyAmpConfig(const std::string& clip) {
  PpoConfig c;
  c.task = "walk";
  c.num_envs = 8;
  c.threads = 1;
  c.update_torch_threads = 1;
  c.seed = 5;
  c.rollout_steps = 8;
  c.epochs = 1;
  c.minibatches = 2;
  c.hidden = {32, 32};
  c.total_steps = 4 * 8 * 8;
  c.checkpoint_every_s = 1e9;
  c.amp_clips = {clip};
  c.amp_disc_hidden = {32, 32};
  c.amp_disc_batch = 32;
  c.amp_disc_updates = 2;
  c.amp_replay_size = 256;
  return c;
}

std::vector<torch::Tensor> DiscState(const std::string& checkpoint) {
  torch::serialize::InputArchive ar, d;
  ar.load_from(checkpoint);
  EXPECT_TRUE(ar.try_read("amp_disc", d));
  AmpDiscriminator disc(kAmpFeatureDim, std::vector<int>{32, 32});
  disc->load(d);
  std::vector<torch::Tensor> out;
  for (const auto& p : disc->named_parameters()) out.push_back(p.value().clone());
  for (const auto& b : disc->named_buffers()) out.push_back(b.value().clone());
  return out;
}

TEST(AmpPpo, RunsCheckpointsResumesAndLogsIntegration) {
  std::string dir = TempDir("run");
  fs::create_directories(dir);
  std::string clip_path = dir + "/gait.clip.json";
  ASSERT_TRUE(SaveMotionClip(Gait(3.0), clip_path).ok());
  PpoConfig c = TinyAmpConfig(clip_path);
  {
    auto tr = PpoTrainer::Create(c, dir + "/run");
    ASSERT_TRUE(tr.ok()) << tr.status();
    for (int i = 0; i < 2; ++i) {
      auto st = (*tr)->Iterate();
      ASSERT_TRUE(st.ok()) << st.status();
      EXPECT_TRUE(st->amp);
      EXPECT_GE(st->amp_style_reward, 0.0);
      EXPECT_LE(st->amp_style_reward, 1.0);
      EXPECT_GT(st->amp_disc_loss, 0.0);
    }
    ASSERT_TRUE((*tr)->Checkpoint().ok());
  }
  fs::copy_file(dir + "/run/checkpoint.pt", dir + "/saved.pt");
  auto r = PpoTrainer::Resume(dir + "/run");
  ASSERT_TRUE(r.ok()) << r.status();
  // the resumed discriminator is bit for bit the saved one
  ASSERT_TRUE((*r)->Checkpoint().ok());
  std::vector<torch::Tensor> saved = DiscState(dir + "/saved.pt");
  std::vector<torch::Tensor> loaded = DiscState(dir + "/run/checkpoint.pt");
  ASSERT_EQ(saved.size(), loaded.size());
  for (size_t k = 0; k < saved.size(); ++k) EXPECT_TRUE(torch::equal(saved[k], loaded[k])) << k;
  while (!(*r)->done()) ASSERT_TRUE((*r)->Iterate().ok());
  std::ifstream log(dir + "/run/log.jsonl");
  std::string line;
  int lines = 0;
  while (std::getline(log, line)) {
    nlohmann::json j = nlohmann::json::parse(line);
    for (const char* k : {"amp_disc_loss", "amp_expert_acc", "amp_agent_acc", "amp_d_expert",
                          "amp_d_agent", "amp_style_reward", "amp_task_reward"}) {
      EXPECT_TRUE(j.contains(k)) << k << " missing in " << line;
    }
    ++lines;
  }
  EXPECT_EQ(lines, 4);
  fs::remove_all(dir);
}

TEST(AmpPpo, ConfigErrors) {
  std::string dir = TempDir("bad");
  PpoConfig c = TinyAmpConfig(dir + "/no_such.clip.json");
  auto missing = PpoTrainer::Create(c, dir + "/a");
  EXPECT_EQ(missing.status().code(), absl::StatusCode::kNotFound) << missing.status();
  EXPECT_NE(missing.status().message().find("no_such.clip.json"), std::string::npos);
  // a task without AMP features
  auto reach = PpoTrainer::CreateWithTask(c, dir + "/b", std::make_unique<ReachTask>(4));
  EXPECT_EQ(reach.status().code(), absl::StatusCode::kInvalidArgument) << reach.status();
  EXPECT_NE(reach.status().message().find("no AMP features"), std::string::npos);
  // strict JSON
  EXPECT_FALSE(PpoConfig::FromJson(nlohmann::json{{"amp_clip", {"x"}}}).ok());
  EXPECT_FALSE(PpoConfig::FromJson(nlohmann::json{{"amp_style_weight", -1}}).ok());
  auto ok = PpoConfig::FromJson(nlohmann::json{{"amp_clips", {"a.bvh"}}, {"amp_grad_penalty", 10}});
  ASSERT_TRUE(ok.ok()) << ok.status();
  EXPECT_EQ(ok->amp_grad_penalty, 10);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace simhuman::learn
