#pragma once
/// Runs one episode: steps the simulation, calls each agent's controller at its control rate,
/// tracks the plan with UniHSI's Task Parser rules (plan::StepTracker), watches health and
/// falls, and records the trajectory.

#include <functional>
#include <string>
#include <vector>

#include "simhuman/control/controller.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/plan/metrics.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control {

/// Per-frame joint positions of the whole model (all humans and movable objects).
struct Trajectory {
  double fps = 30;
  int nq = 0;
  std::vector<double> time_s;
  std::vector<std::vector<double>> qpos;
  std::vector<int> step_index;  ///< plan step being worked on at each frame
};

/// One progress event (a step completed, or the episode ended).
struct ProgressEvent {
  int step = 0;  ///< step index the event is about
  int steps_total = 0;
  double time_s = 0;
  double distance_m = 0;  ///< mean distance of the step's contact pairs to their targets
  bool completed = false;
  bool ended = false;
  std::string label;
};

/// The one fall rule of every suite (docs/EVAL_PROTOCOLS.md): a human has fallen when its head
/// point is below kFallHeadHeightM x its scale, or below kLyingFallHeadHeightM while its step
/// asks it to lie. The walk suite applies the same rule to its standing walker.
inline constexpr double kFallHeadHeightM = 0.5;

struct RunOptions {
  plan::PairParams pair;
  /// Our default asks a step to hold for 0.5 s before it counts (UniHSI counts the first
  /// instant), so passing through a contact on the way down is not a success.
  plan::TrackerParams tracker = [] {
    plan::TrackerParams p;
    p.hold_s = 0.5;
    return p;
  }();
  double record_fps = 30;
  /// Ego-centric height map handed to controllers (UniHSI's scene awareness): cells per side
  /// and cell size. 0 cells turns it off.
  int heightmap_size = 16;
  double heightmap_cell_m = 0.1;
  bool record = true;
  double fall_head_height_m = kFallHeadHeightM;  ///< head below this (x scale) while not lying
  /// After the last step completes, keep simulating (controllers keep the last step) for this
  /// long, so a video shows the final pose held. Falls in this span are reported (`fell`) but
  /// do not change `success`, which is decided by the plan alone.
  double settle_s = 0.0;
  std::function<void(const ProgressEvent&)> progress;  ///< optional
  /// Optional: called on the simulating thread every 1/record_fps s of simulated time (whether
  /// or not `record`), between physics steps, with the episode time (s) and the current step
  /// index; world.data() then holds a consistent state. Returning false ends the episode there
  /// with end_reason "interrupted", and a later RunEpisode on the same world continues from that
  /// state (the live server, web/, ends a plan this way when a new command arrives).
  std::function<bool(double time_s, int step)> on_frame;
  /// Added to the step index controllers observe (Observation::step_index). Controllers tell a
  /// new step from the last one by its index, so a caller that runs several episodes on the
  /// same controllers (the live server) starts each past the steps of the episodes before.
  int controller_step_offset = 0;
  /// Optional, for callers paced by the wall clock (the live server): whether the simulation
  /// at episode time `time_s` is behind real time. Controllers see it in
  /// Observation::behind_real_time, and the MPC then replans less often (MpcConfig::
  /// max_replan_s) instead of letting the simulation fall further behind.
  std::function<bool(double time_s)> behind_real_time;
};

/// `points` (one agent's standard body points, BodyJoint order) with the pelvis point moved to
/// UniHSI's pelvis joint centre: the middle of the two hip points.
std::vector<Eigen::Vector3d> JointCentrePelvis(std::vector<Eigen::Vector3d> points);

struct EpisodeResult {
  bool success = false;
  int steps_completed = 0;
  int steps_total = 0;
  double contact_error_m = -1;  ///< Eq. 10; -1 when nothing was recorded
  /// Eq. 10 with UniHSI's pelvis point, the joint centre between the hips (JointCentrePelvis),
  /// in place of ours at the sitting bones, at the same step completions; -1 as above
  double contact_error_joint_centre_m = -1;
  /// The plan's success on UniHSI's body points: `success`, and every step's pairs also met at
  /// some tick while that step ran with the joint-centre pelvis point and a hand on the pelvis
  /// measured to that point (plan::PairParams::hand_on_pelvis_at_belly false), not our belly
  /// point. Steps still complete by our points; this column only reads them the paper's way.
  bool success_unihsi_points = false;
  bool fell = false;
  /// "completed", "timeout", "fell", "interrupted" (on_frame), "unstable: ...", "controller: ..."
  std::string end_reason;
  double sim_time_s = 0;
  double wall_time_s = 0;
  std::vector<double> step_completion_s;
  /// Per step, the er_i (Eq. 11) recorded for its contact and not-contact pairs, in pair order
  /// (not-care and get-close pairs have none); empty for a step never reached.
  std::vector<std::vector<double>> pair_errors_m;
};

/// Runs `chain` (grounded against world.catalog()) with one controller per agent.
EpisodeResult RunEpisode(world::SimWorld& world, const plan::ContactChain& chain,
                         const std::vector<Controller*>& controllers, const RunOptions& options,
                         Trajectory* trajectory);

/// Head height (m) below which a human whose step lies down has fallen (off the bed).
inline constexpr double kLyingFallHeadHeightM = 0.25;

/// The fall rule, per agent: its head (z of the head point, m) below
/// options.fall_head_height_m x its scale, or below kLyingFallHeadHeightM while its own step
/// lies down (`posture` of its StepTask).
bool IsFall(Posture posture, double head_z_m, double scale, const RunOptions& options);

/// The physics timestep shared by `controllers`: the finest any of them asks for
/// (Controller::physics_timestep_s), else `world_dt`. One model has one timestep; a controller
/// that asks for none accepts any, and one that asks for a coarser step than another gets the
/// finer one (its Act() still runs at its own control period).
double CommonTimestep(const std::vector<Controller*>& controllers, double world_dt);

/// Body points of every agent in plan terms.
std::vector<plan::BodyPoints> AllBodyPoints(const world::SimWorld& world, const mjData* d);

}  // namespace simhuman::control
