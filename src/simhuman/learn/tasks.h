#pragma once
/// The registry of single-agent training tasks (`simhuman train --task NAME`): a new task is an
/// entry here, not a branch in the trainer.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/learn/vec_env.h"

namespace simhuman::learn {

/// How a task's environments are built (from the training config).
struct TaskOptions {
  std::string solver = "newton";            ///< "newton" or "pgs"
  std::vector<double> body_scales = {1.0};  ///< humans' length scales, spread over the envs
  std::string walk_gait;                    ///< walk, carry: control::WalkGait name
  bool carry_grip = false;                  ///< carry: the hands grip (CarryTask::Create)
  double carry_held_start_frac = 0.35;      ///< carry: share of Reset()s that start holding
  double carry_put_down_start_frac = 0.0;   ///< carry: share that start inside the put-down
  /// walk: reward weights of the leg gait term and foot slip, and the leg term's width (rad^2);
  /// the defaults are WalkRewardWeights'
  double walk_gait_weight = 1.0, walk_gait_width = 0.5, walk_foot_slip_weight = 0.5;
  double walk_route_share = 0.0;  ///< walk: WalkTask::set_route_share
};

struct TaskDef {
  std::string name;
  std::string description;  ///< one line for --help and errors
  /// Builds the task with `envs` environments and `options` (a task without a solver choice
  /// or body scales ignores them; the config's checks refuse them first).
  std::function<core::StatusOr<std::unique_ptr<VecTask>>(int envs, const TaskOptions& options)>
      make;
  /// A task whose policy may initialise this one (`--init-from`): same actions, and this task's
  /// observation starts with that task's whole observation; the input layer is widened with
  /// zero weights for the new entries. Empty: only a policy of the same task.
  std::string init_parent;
  /// Whether the task accepts the "pgs" solver.
  bool solver_choice = false;
  /// Tasks of the same observation and actions whose policies may initialise this one as they
  /// are (e.g. the carry policy starts the lift stage's training).
  std::vector<std::string> init_peers = {};
};

const std::vector<TaskDef>& Tasks();
/// The task named `name`; an error lists the valid names.
core::StatusOr<const TaskDef*> FindTask(std::string_view name);

// Names and solver choice without the environments (learn/task_names.cc), for config parsing
// in builds that do not link the environments (the fuzz targets); a test checks they agree
// with Tasks().

/// The registry's task names, in its order.
std::vector<std::string> TaskNames();
/// Whether `name` accepts body scales other than 1 (the walk task).
bool TaskHasBodyScales(std::string_view name);
/// Whether `name` walks to a reference gait that `walk_gait` chooses (walk and the carry tasks).
bool TaskHasWalkGait(std::string_view name);
/// Whether `name` is one of the carrying tasks (carry, carry-lift, carry-deliver).
bool TaskIsCarry(std::string_view name);
/// InvalidArgument naming both when a non-empty walk gait `gait` is given for a task without one.
absl::Status CheckWalkGaitTask(std::string_view task, std::string_view gait);
/// Whether `name` accepts the "pgs" solver (TaskDef::solver_choice).
bool TaskHasSolverChoice(std::string_view name);

}  // namespace simhuman::learn
