#pragma once
/// The controller interface the episode runner drives.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "simhuman/control/task.h"
#include "simhuman/core/span.h"
#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control {

/// What a controller sees at a control tick. Learned policies read only proprioception
/// (`data` restricted to their agent), the contact targets of the current step and the height
/// map; model-based planners (the sampling MPC) also read the full simulator state through
/// `world`/`data`, because they roll the model forward.
struct Observation {
  double time_s = 0;
  int agent = 0;
  const world::SimWorld* world = nullptr;
  const mjData* data = nullptr;
  int step_index = 0;              ///< index of the current plan step
  const StepTask* task = nullptr;  ///< the current step in controller terms
  /// World positions of the agent's body points, by id (its catalog's: the 15 standard ones
  /// first).
  std::vector<Eigen::Vector3d> body_points;
  /// Per term of `task`: target point minus joint (UniHSI's v_np - v_j).
  std::vector<Eigen::Vector3d> contact_offsets;
  /// Ego-centric height map (row-major, `heightmap_size` x `heightmap_size` cells of
  /// `heightmap_cell_m`, centred on the pelvis, x forward): heights above the floor.
  std::vector<float> heightmap;
  int heightmap_size = 0;
  double heightmap_cell_m = 0;
  /// The caller runs against the wall clock and is behind it (RunOptions::behind_real_time):
  /// a controller may skip optional work this tick (the MPC skips replans, up to a limit).
  bool behind_real_time = false;
};

/// A controller of one agent. Not thread-safe; one instance per agent.
class Controller {
 public:
  virtual ~Controller() = default;
  virtual std::string name() const = 0;
  /// Called at the control rate. Plans or infers; must not step `obs.data`.
  virtual absl::Status Act(const Observation& obs) = 0;
  /// Called every physics step: writes the agent's actuator targets for time `time_s` into
  /// `ctrl`, one entry per actuator of the agent (world::AgentIndex::actuator order: the
  /// humanoid body's kHumanoidDofs first, then a hand's). `ctrl` holds the current targets on
  /// entry: entries a controller does not drive (a hand, for a body controller) keep them.
  virtual void Targets(double time_s, core::Span<double> ctrl) const = 0;
  /// Control period (s) at which the runner calls Act().
  virtual double control_period_s() const = 0;
  /// Physics timestep (s) the controller needs while it is in control (learned policies run
  /// at the rate they were trained at); 0: the world's own timestep.
  virtual double physics_timestep_s() const { return 0.0; }
};

}  // namespace simhuman::control
