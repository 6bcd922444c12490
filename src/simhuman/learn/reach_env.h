#pragma once
/// A toy task for fast learning tests: a 2-D point mass (unit mass, drag 1/s) pushed by a
/// force in [-1, 1]^2 must reach and stay at a random target in [-1, 1]^2. 100 steps of
/// 0.05 s, reward 1 - min(|p - target|, 1) per step (a random policy scores ~30-45, a good
/// one > 80). Observation: position, velocity, target - position (6). Action: force (2).

#include <vector>

#include "simhuman/core/rng.h"
#include "simhuman/learn/vec_env.h"

namespace simhuman::learn {

class ReachTask : public VecTask {
 public:
  explicit ReachTask(int num_envs);
  std::string name() const override { return "reach"; }
  int num_envs() const override { return static_cast<int>(envs_.size()); }
  int obs_dim() const override { return 6; }
  int act_dim() const override { return 2; }
  double action_limit() const override { return 1.0; }  ///< forces are clipped to +-1
  void Reset(int i, uint64_t seed, float* obs) override;
  void Step(int i, const float* action, float* obs, StepInfo* info) override;
  static constexpr int kMaxSteps = 100;

 private:
  struct Env {
    double p[2], v[2], t[2];
    int steps = 0;
  };
  void Observe(const Env& e, float* obs) const;
  std::vector<Env> envs_;
};

}  // namespace simhuman::learn
