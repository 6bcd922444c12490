#pragma once
/// Building and running one episode from a scene and a plan, shared by `simhuman run` and
/// `simhuman eval`, and the records an episode leaves behind (result JSON, trajectory CSV).

#include <mujoco/mujoco.h>

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/control/mpc/mpc_config.h"
#include "simhuman/control/mpc/mpc_controller.h"
#include "simhuman/control/runner.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/model_builder.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

/// The seed stream controllers draw from: agent a of a run with seed s is seeded
/// core::DeriveSeed(s, kControllerStream, a).
inline constexpr uint64_t kControllerStream = 1;

/// The seed of agent `agent`'s controller in a run seeded `run_seed`.
uint64_t ControllerSeed(uint64_t run_seed, int agent);

/// Where each human of `spec` starts. Only standing humans can be placed yet: another posture
/// is InvalidArgument naming the human ("/humans/0") and the valid postures.
core::StatusOr<std::vector<world::AgentSpec>> AgentSpecs(const world::SceneSpec& spec);

/// The simulation of `spec`, whose catalog is `catalog` (BuildCatalog(spec)).
core::StatusOr<std::unique_ptr<world::SimWorld>> BuildWorld(const world::SceneSpec& spec,
                                                            const core::SceneCatalog& catalog);

/// One MPC controller per agent of `world` (which must outlive them), seeded by
/// ControllerSeed(run_seed, agent).
core::StatusOr<std::vector<std::unique_ptr<control::MpcController>>> MakeControllers(
    const world::SimWorld& world, const control::MpcConfig& config, uint64_t run_seed);

/// Runs `chain` (grounded against world.catalog()) with `controllers` (one per agent).
control::EpisodeResult RunWithControllers(
    world::SimWorld& world, const plan::ContactChain& chain,
    const std::vector<std::unique_ptr<control::MpcController>>& controllers,
    const control::RunOptions& options, control::Trajectory* trajectory);

/// As RunWithControllers, but when `walk_policy` names a file, get-close steps that start
/// standing are walked with that policy (control::WalkThenContactController) and the MPC does
/// the other steps; carry steps are carried by the carriers with `carry_policy`
/// (control::CarryPolicyController), and a plan with carry steps gets kCarryStepBudgetS per
/// step. Errors: a policy file (NotFound, DataLoss, InvalidArgument); a plan with carry steps
/// and no `carry_policy` (FailedPrecondition, naming the step and the flag).
core::StatusOr<control::EpisodeResult> RunWithWalkPolicy(
    world::SimWorld& world, const plan::ContactChain& chain,
    const std::vector<std::unique_ptr<control::MpcController>>& controllers,
    const std::string& walk_policy, const control::RunOptions& options,
    control::Trajectory* trajectory, const std::string& carry_policy = "");

/// Time budget of each step of a plan with carry steps (a 20 m carry takes about a minute).
inline constexpr double kCarryStepBudgetS = 120.0;

/// The carrying policy to use: `flag` when given, else assets/policies/carry.pt of the source
/// tree when that file exists, else "".
std::string DefaultCarryPolicy(const std::string& flag);

/// The walking policy to use: `flag` when given, else assets/policies/walk.pt of the source
/// tree when that file exists, else "" (no walking).
std::string DefaultWalkPolicy(const std::string& flag);

/// A short description of a step for progress lines and captions: its label, or one made from
/// its pairs ("pelvis on chair000 seat surface", "get close to bed000 (front)").
std::string StepText(const plan::ContactStep& step);

/// The episode's outcome as JSON: success, steps_completed, steps_total, contact_error_m (null
/// when nothing was recorded), fell, end_reason, sim_time_s, wall_time_s, wall_per_sim (null
/// for a zero-length episode), step_completion_s.
nlohmann::ordered_json EpisodeResultJson(const control::EpisodeResult& result);

/// Where the results came from: git_revision (core::GitRevision(), refreshed each build) and
/// mujoco_version (mj_versionString()).
nlohmann::ordered_json ProvenanceJson();

/// Column names of the model's qpos, in qpos order: one per hinge or slide joint ("<joint
/// name>"), and "<joint name>[k]" for the 7 entries of a free joint (x y z qw qx qy qz) and the
/// 4 of a ball joint. An unnamed joint is called "joint<id>".
std::vector<std::string> QposColumnNames(const mjModel* m);

/// Writes the trajectory as CSV: header "time_s,step," then QposColumnNames(m), one row per
/// recorded frame (step: 0-based index of the plan step being worked on). Errors name `path`.
absl::Status WriteTrajectoryCsv(const std::string& path, const mjModel* m,
                                const control::Trajectory& trajectory);

/// Writes `j` (pretty-printed, 2 spaces, keys in insertion order) atomically to `path`.
absl::Status WriteJsonFile(const std::string& path, const nlohmann::ordered_json& j);

}  // namespace simhuman::eval
