#pragma once
/// Solves a whole-body reference pose for a step from its contacts: a Levenberg-Marquardt pose
/// optimization (root pose + 28 hinges) that starts from a base posture (stand, sit, lie on
/// back/side) placed relative to the step's object, pulls each contact joint to its part at
/// touching distance from the given direction, pushes not-contact joints away, keeps feet on
/// the floor (stand, sit), the centre of mass over the feet (stand), and stays close to the
/// base posture. Nothing here is written per task: the posture is chosen from the contacts.

#include <mujoco/mujoco.h>

#include <array>
#include <string>
#include <vector>

#include "simhuman/control/task.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control {

/// A solved pose for one agent.
struct ReferencePose {
  std::array<double, 7> root{};  ///< pos (3) + quat wxyz (4)
  std::array<double, world::kHumanoidDofs> hinges{};
  double residual = 0;         ///< final weighted residual norm (diagnostic)
  double contact_error_m = 0;  ///< mean distance of contact joints to touching position
};

/// The hinge angles of a base posture.
std::array<double, world::kHumanoidDofs> BasePostureHinges(Posture p);

/// Solver settings.
struct ReferencePoseOptions {
  int iterations = 40;
  double w_contact = 10.0;
  double w_not_contact = 5.0;
  double w_posture = 0.6;
  double w_root_orientation = 2.0;
  double w_feet = 8.0;
  double w_balance = 6.0;
  double w_penetration = 10.0;
  /// Solve a pose of getting up from a seat instead of the step's goal: 1 = still seated,
  /// trunk leaning forward and feet drawn back under the knees; 2 = seat-off, pelvis just off
  /// the seat with the centre of mass over the feet (drawn back as in 1). 0 = the step's goal.
  int rise = 0;
  /// Start the optimization from this pose instead of the base posture (which still anchors
  /// the posture term); for small corrections of an already solved pose. Not owned.
  const ReferencePose* warm_start = nullptr;
};

/// Solves the reference pose of `task` for agent `agent` of `world`. `d_now` is the current
/// state (used for the start pose, feet anchoring and the agent's heading); `scratch` is an
/// mjData of the same model that the solver may overwrite. Deterministic.
ReferencePose SolveReferencePose(const world::SimWorld& world, int agent, const StepTask& task,
                                 const mjData* d_now, mjData* scratch,
                                 const ReferencePoseOptions& options = {});

/// Writes `pose` into agent `agent`'s qpos of `d` (other entries untouched).
void SetAgentPose(const world::AgentIndex& a, const ReferencePose& pose, mjData* d);

/// Reads agent `agent`'s pose from `d`.
ReferencePose GetAgentPose(const world::AgentIndex& a, const mjData* d);

}  // namespace simhuman::control
