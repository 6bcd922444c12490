#pragma once
/// What the sampling controllers' rollouts share (the contact MPC, control/mpc, and the carry
/// MPC, control/policy/carry_mpc): the copy of the state a rollout starts from, and the smooth
/// L1 penalty their costs use.

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstring>

namespace simhuman::control {

/// Copies what a rollout starts from: time, positions, velocities, the solver's warm start,
/// controls and actuator activations (`to` then steps as `from` would).
inline void CopyRolloutStart(const mjModel* m, const mjData* from, mjData* to) {
  to->time = from->time;
  std::memcpy(to->qpos, from->qpos, sizeof(mjtNum) * m->nq);
  std::memcpy(to->qvel, from->qvel, sizeof(mjtNum) * m->nv);
  std::memcpy(to->qacc_warmstart, from->qacc_warmstart, sizeof(mjtNum) * m->nv);
  std::memcpy(to->ctrl, from->ctrl, sizeof(mjtNum) * m->nu);
  if (m->na) std::memcpy(to->act, from->act, sizeof(mjtNum) * m->na);
}

/// Quadratic below `delta`, linear above (of |x|), continuous with its slope.
inline double SmoothL1(double x, double delta) {
  const double a = std::abs(x);
  return a < delta ? 0.5 * a * a / delta : a - 0.5 * delta;
}

}  // namespace simhuman::control
