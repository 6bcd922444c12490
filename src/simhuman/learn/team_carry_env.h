#pragma once
/// A toy cooperative team task for fast MAPPO tests, a 2-D miniature of CooHOI's carrying: N
/// point-mass agents (unit mass, drag 1/s, pushed by a force in [-1, 1]^2 as in ReachTask)
/// must together bring a box to a goal. The box moves only while every agent holds it (is
/// within kGripM of it), with the agents' mean velocity; one agent cannot move it alone.
/// Box and goal start uniformly in [-0.8, 0.8]^2 and [-1, 1]^2, agents in [-1, 1]^2.
/// 100 steps of 0.05 s.
///
/// Reward of agent a per step: kApproachWeight exp(-|p_a - box| / kRewardScaleM), its own
/// share for reaching the box, plus the team's exp(-|box - goal| / kRewardScaleM) (dense: no
/// distance is out of reach of the gradient). Success: the box within kSuccessM of the goal.
///
/// Observation of agent a (8 + 2 (N - 1)): its position, its velocity, box - position,
/// goal - box, then every other agent's position minus its own (in agent order).
/// Action (2): force. Shared state (4 N + 4): every agent's position and velocity, box, goal.

#include <vector>

#include "simhuman/learn/multi_agent_env.h"

namespace simhuman::learn {

class TeamCarryTask : public MultiAgentVecTask {
 public:
  /// `num_agents` in [2, 8].
  TeamCarryTask(int num_envs, int num_agents);
  std::string name() const override { return "team_carry"; }
  int num_envs() const override { return static_cast<int>(envs_.size()); }
  int num_agents() const override { return agents_; }
  int obs_dim() const override { return 8 + 2 * (agents_ - 1); }
  int act_dim() const override { return 2; }
  int state_dim() const override { return 4 * agents_ + 4; }
  void Reset(int i, uint64_t seed, float* obs, float* state) override;
  void Step(int i, const float* actions, float* obs, float* state, float* rewards,
            TeamStepInfo* info) override;

  static constexpr int kMaxSteps = 100;
  static constexpr double kGripM = 0.25;
  static constexpr double kSuccessM = 0.15;
  static constexpr double kApproachWeight = 0.5;
  static constexpr double kRewardScaleM = 0.5;

 private:
  struct Agent {
    double p[2], v[2];
  };
  struct Env {
    std::vector<Agent> agents;
    double box[2], goal[2];
    int steps = 0;
  };
  void Observe(const Env& e, float* obs, float* state) const;
  int agents_;
  std::vector<Env> envs_;
};

}  // namespace simhuman::learn
