// Training-side throughput of the walking task: raw mj_step of the same model, VecEnv steps
// with random actions (1 and 2 worker threads), and VecEnv steps with policy inference (the
// collection loop of PPO without the update), the last two also with the PGS solver. Prints
// JSON.
//   build/simhuman_learn_bench [envs] [seconds_per_case] [policy.pt]
#include <torch/torch.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/learn/walk_env.h"

using namespace simhuman;
using Clock = std::chrono::steady_clock;

namespace {

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// raw mj_step from standing states of the walk task, with random PD targets held for a policy
// step; restarts every 2 s like short training episodes
double RawStepsPerSecond(learn::WalkTask& task, double seconds) {
  const mjModel* m = task.model();
  mjData* d = mj_makeData(m);
  std::vector<float> obs(control::kWalkObsDim);
  task.Reset(0, 1, obs.data());
  const mjData* start = task.data(0);
  core::Rng rng(3);
  long steps = 0;
  // constraint rows per step by kind (what the solver works on)
  double rows_contact = 0, rows_limit = 0, rows_other = 0;
  auto t0 = Clock::now();
  while (Since(t0) < seconds) {
    mj_copyData(d, m, start);
    for (int k = 0; k < 240; ++k) {
      if (k % control::kWalkSubsteps == 0) {
        for (int j = 0; j < m->nu; ++j) d->ctrl[j] = start->ctrl[j] + rng.Normal(0.2);
      }
      mj_step(m, d);
      ++steps;
      for (int r = 0; r < d->nefc; ++r) {
        const int type = d->efc_type[r];
        if (type == mjCNSTR_LIMIT_JOINT) {
          ++rows_limit;
        } else if (type >= mjCNSTR_CONTACT_FRICTIONLESS) {
          ++rows_contact;
        } else {
          ++rows_other;
        }
      }
    }
  }
  double rate = steps / Since(t0);
  std::fprintf(stderr, "constraint rows per mj_step: contact %.1f, joint limit %.1f, other %.1f\n",
               rows_contact / steps, rows_limit / steps, rows_other / steps);
  // where the time of one mj_step goes (MuJoCo's own timers, on for this loop only)
  const std::pair<int, const char*> stages[] = {
      {mjTIMER_POS_KINEMATICS, "kinematics"},   {mjTIMER_POS_INERTIA, "inertia"},
      {mjTIMER_POS_COLLISION, "collision"},     {mjTIMER_POS_MAKE, "make_constraints"},
      {mjTIMER_POS_PROJECT, "project"},         {mjTIMER_VELOCITY, "velocity"},
      {mjTIMER_ACTUATION, "actuation"},         {mjTIMER_ACCELERATION, "acceleration"},
      {mjTIMER_CONSTRAINT, "constraint_solver"}};
  double total = d->timer[mjTIMER_STEP].duration;
  if (total > 0) {
    std::fprintf(stderr, "mj_step stages (share of step time, %d contacts at the end):", d->ncon);
    for (const auto& [id, name] : stages) {
      std::fprintf(stderr, " %s %.0f%%", name, 100.0 * d->timer[id].duration / total);
    }
    std::fprintf(stderr, "\n");
  }
  mj_deleteData(d);
  return rate;
}

double EnvStepsPerSecond(int envs, int threads, double seconds, control::GaussianActor* actor,
                         control::ObsNormalizer* norm,
                         learn::WalkPhysicsSolver solver = learn::WalkPhysicsSolver::kNewton) {
  auto task = learn::WalkTask::Create(envs, solver);
  if (!task.ok()) std::exit(2);
  learn::VecEnv env(std::move(*task), threads, 1);
  env.ResetAll();
  core::Rng rng(5);
  std::vector<float> act(static_cast<size_t>(envs) * control::kWalkActDim);
  long steps = 0;
  auto t0 = Clock::now();
  while (Since(t0) < seconds) {
    if (actor) {
      torch::NoGradGuard ng;
      torch::Tensor o =
          torch::from_blob(const_cast<float*>(env.obs().data()), {envs, control::kWalkObsDim});
      torch::Tensor a = (*actor)->forward(norm->Normalize(o)).contiguous();
      std::copy(a.data_ptr<float>(), a.data_ptr<float>() + act.size(), act.begin());
    } else {
      for (float& a : act) a = static_cast<float>(rng.Normal(0.3));
    }
    env.Step(act.data());
    steps += envs;
  }
  return steps / Since(t0);
}

}  // namespace

double NowMs() {
  return std::chrono::duration<double, std::milli>(Clock::now().time_since_epoch()).count();
}

int main(int argc, char** argv) {
  int envs = argc > 1 ? std::atoi(argv[1]) : 128;
  double secs = argc > 2 ? std::atof(argv[2]) : 10.0;
  torch::set_num_threads(1);
  control::GaussianActor actor(control::kWalkObsDim, control::kWalkActDim,
                               std::vector<int>{256, 256}, 0.5);
  control::ObsNormalizer norm(control::kWalkObsDim);
  if (argc > 3) {
    auto p = control::LoadPolicyFile(argv[3]);
    if (!p.ok()) {
      std::fprintf(stderr, "%s\n", std::string(p.status().message()).c_str());
      return 2;
    }
    actor = p->actor;
    norm = p->norm;
  }
  auto task = learn::WalkTask::Create(1);
  if (!task.ok()) return 2;
  mjcb_time = NowMs;
  RawStepsPerSecond(**task, secs / 2);  // timer breakdown only: the timers cost time
  mjcb_time = nullptr;
  double raw = RawStepsPerSecond(**task, secs);
  double env1 = EnvStepsPerSecond(envs, 1, secs, nullptr, nullptr);
  double env2 = EnvStepsPerSecond(envs, 2, secs, nullptr, nullptr);
  double pol1 = EnvStepsPerSecond(envs, 1, secs, &actor, &norm);
  double pol2 = EnvStepsPerSecond(envs, 2, secs, &actor, &norm);
  // the same with MuJoCo's PGS solver (PpoConfig::physics_solver "pgs")
  double pgs2 = EnvStepsPerSecond(envs, 2, secs, nullptr, nullptr, learn::WalkPhysicsSolver::kPgs);
  double pgs_pol2 = EnvStepsPerSecond(envs, 2, secs, &actor, &norm, learn::WalkPhysicsSolver::kPgs);
  const double sub = control::kWalkSubsteps;
  std::printf(
      "{\"envs\": %d, \"substeps\": %d, \"raw_mj_steps_per_s\": %.0f,\n"
      " \"env_steps_per_s_random_1thread\": %.0f, \"ratio_1thread\": %.3f,\n"
      " \"env_steps_per_s_random_2threads\": %.0f,\n"
      " \"env_steps_per_s_policy_1thread\": %.0f, \"env_steps_per_s_policy_2threads\": %.0f,\n"
      " \"pgs_env_steps_per_s_random_2threads\": %.0f, \"pgs_env_steps_per_s_policy_2threads\": "
      "%.0f}\n",
      envs, control::kWalkSubsteps, raw, env1, env1 * sub / raw, env2, pol1, pol2, pgs2, pgs_pol2);
  return 0;
}
