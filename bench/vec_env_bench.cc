// The C++ side of the Python throughput comparison (bench/py_env_bench.py): the walk task's
// VecEnv stepped with uniformly random actions in the action bounds, as a Python loop does with
// action_space.sample(). Prints one JSON line.
//   build/simhuman_vec_env_bench [envs] [threads] [seconds] [physics_solver newton|pgs]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/control/policy/walk_task.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/learn/walk_env.h"

using namespace simhuman;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  const int envs = argc > 1 ? std::atoi(argv[1]) : 128;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  const double seconds = argc > 3 ? std::atof(argv[3]) : 10.0;
  const std::string solver = argc > 4 ? argv[4] : "newton";
  if (envs < 1 || threads < 1 || !(seconds > 0) || (solver != "newton" && solver != "pgs")) {
    std::fprintf(stderr,
                 "usage: simhuman_vec_env_bench [envs >= 1] [threads >= 1] [seconds > 0] "
                 "[newton|pgs]\n");
    return 2;
  }
  auto task = learn::WalkTask::Create(
      envs, solver == "pgs" ? learn::WalkPhysicsSolver::kPgs : learn::WalkPhysicsSolver::kNewton);
  if (!task.ok()) {
    std::fprintf(stderr, "simhuman_vec_env_bench: %s\n", task.status().ToString().c_str());
    return 1;
  }
  learn::VecEnv env(std::move(*task), threads, 1);
  env.ResetAll();
  const int a = env.act_dim();
  std::vector<float> actions(static_cast<size_t>(envs) * a);
  core::Rng rng(7);
  auto random_step = [&] {
    for (float& x : actions) {
      x = static_cast<float>(rng.Uniform(-control::kWalkActionClip, control::kWalkActionClip));
    }
    env.Step(actions.data());
  };
  for (int k = 0; k < 5; ++k) random_step();  // warm-up
  long steps = 0;
  const Clock::time_point t0 = Clock::now();
  double elapsed = 0;
  while (elapsed < seconds) {
    random_step();
    ++steps;
    elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  std::printf(
      "{\"envs\": %d, \"threads\": %d, \"physics_solver\": \"%s\", \"vec_steps\": %ld, "
      "\"seconds\": %.3f, \"env_steps_per_s\": %.1f}\n",
      envs, threads, solver.c_str(), steps, elapsed, steps * envs / elapsed);
  return 0;
}
