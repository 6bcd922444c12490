#pragma once
/// The `tabletop`, `place` and `stack` suites: DASH's benchmark (Appendix B) on our seated
/// human. Each episode is a generated scene (world/tabletop.h: DASH's objects, ranges and task
/// rules) run through the pick-and-place pipeline (control/manip/tabletop_pipeline.h) with a
/// grasp policy file or the scripted grasp. Success is DASH's rule plus ours (at rest 2 s after
/// the release); reported over all trials and excluding motion-planning failures, with a
/// per-stage failure table and the pipeline's simulation speed beside raw mj_step's.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "simhuman/control/manip/table_world.h"
#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/control/runner.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/sim_world.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::eval {

struct TabletopEvalOptions {
  std::string kind = "any";  ///< "place", "stack" or "any" (the tabletop suite: 50/50)
  int episodes = 200;
  /// The first episode's index: episodes first_episode .. first_episode + episodes - 1 of the
  /// seed run (each is seeded by its index, so 200 from 200 are the next 200 after the suite's)
  int first_episode = 0;
  uint64_t seed = 1;
  /// A grasp policy file (simhuman train --task grasp), or "scripted" for the training-free
  /// grasp.
  std::string grasp = "scripted";
  /// A place policy file (simhuman train --task place), or "scripted" for the scripted placing.
  std::string place = "scripted";
  /// "truth": the pipeline reads the objects' true state; "vision": the head camera and the
  /// vision model `vision_model` (eval/tabletop_vision.h).
  std::string perception = "truth";
  std::string vision_model;
  /// With "vision": the hand's touch also places the object it grasps and holds
  /// (VisionLoopOptions::touch); false: the camera and the grasp prior alone.
  bool touch = true;
  /// With "vision": the task planner's estimates fitted to the objects' outlines
  /// (VisionLoopOptions::silhouette); false: the network's estimates as they are.
  bool silhouette = true;
  /// Grasps tried on one object before a miss ends the episode
  /// (control::manip::TabletopOptions::grasp_attempts).
  int grasp_attempts = 2;
  /// The seed of every arm plan's RRTConnect search (control::manip::PlannerOptions::seed). The
  /// suite's outcome moves with it by a few episodes (docs/BENCHMARKS.md, issue 15, session 39).
  uint64_t planner_seed = 1;
  /// Zero-shot runs (world::MakeZeroShot): every episode's task object becomes this shape of
  /// world::ZeroShotShapes(); "" keeps the generator's box, cylinder or sphere. Ground truth
  /// only, as DASH's zero-shot demonstrations.
  std::string zero_shot;
  std::string zero_shot_mesh = world::kZeroShotMeshFile;  ///< the OBJ file of zero_shot "mesh"
  /// Episodes run at once, one thread each (its own world, grasp policy and renderer); the
  /// results are the same for any value (each episode is seeded by its index)
  int jobs = 1;
};

/// The --perception values.
const std::vector<std::string>& PerceptionNames();

struct TabletopEpisode {
  int index = 0;
  uint64_t seed = 0;
  std::string kind, object, shape;
  bool success = false, plan_failure = false;
  std::string failed_stage;  ///< "" on success
  std::string end_reason;
  int sim_steps = 0;
  int grasp_attempts = 0;  ///< grasps begun
  /// The object's tilt from upright (degrees) when the release began; -1: not reached
  double release_tilt_deg = -1;
  /// The object's base above the target (m) when the release began; -1: not reached
  double release_gap_m = -1;
  double wall_s = 0, cpu_s = 0;
};

struct TabletopEvalSummary {
  int episodes = 0, successes = 0, plan_failures = 0;
  double success_rate = 0;               ///< over all trials
  double success_rate_no_plan_fail = 0;  ///< excluding motion-planning failures (DASH reports it)
  std::map<std::string, int> failures_by_stage;
  /// Episodes that grasped more than once, and how many of those succeeded.
  int regrasped = 0, regrasped_successes = 0;
  /// Per task, keyed "<kind>/<shape of the object moved>" (e.g. "stack/cylinder").
  struct Tally {
    int episodes = 0, successes = 0, plan_failures = 0;
  };
  std::map<std::string, Tally> by_task;
  /// DASH's protocol beside ours: only episodes that move a box or a cylinder (DASH trained its
  /// sphere policy "for qualitative demonstrations only", Appendix A.3.5, so its 200-scene
  /// numbers move boxes and cylinders; spheres stay in its scenes as other objects).
  Tally DashTally(const std::string& kind) const;
  double steps_per_s = 0;        ///< the whole pipeline (planning, policy, physics, vision)
  double sim_s = 0, wall_s = 0;  ///< simulated and wall time of the pipelines (real-time factor)
  std::string perception = "truth";
  bool touch = false;           ///< vision with touch (TabletopEvalOptions::touch)
  bool silhouette = false;      ///< vision with the silhouette fit (TabletopEvalOptions)
  int perception_failures = 0;  ///< vision: the task's objects not seen at task planning
  int vision_frames = 0;
  double vision_ms_per_frame = 0, render_ms_per_frame = 0;
  double silhouette_fit_ms_per_episode = 0;  ///< task planning's silhouette fit (vision)
  /// mj_step alone on the same model, same run: 1000 steps from every episode's start
  double raw_steps_per_s = 0;
  /// The same two speeds per second of CPU time (the pipeline's thread): what a core of its own
  /// gives, which other processes sharing the machine change far less than the wall-clock ones.
  double cpu_steps_per_s = 0, raw_cpu_steps_per_s = 0;
  /// The run as a whole: episodes run at once (TabletopEvalOptions::jobs), its wall time from
  /// the first episode's start to the last one's end, and the pipeline's simulation steps over
  /// that time (with jobs = 2: what the 2 cores give together)
  int jobs = 1;
  double elapsed_s = 0, steps_per_elapsed_s = 0;
  nlohmann::json ToJson() const;
};

/// Runs the suite. Errors: a bad kind or episode count (InvalidArgument), a grasp policy file
/// that cannot be loaded (naming it). `on_episode` (optional) sees each episode as it ends.
core::StatusOr<TabletopEvalSummary> RunTabletopEval(
    const TabletopEvalOptions& options,
    const std::function<void(const TabletopEpisode&)>& on_episode = {});

nlohmann::json TabletopEpisodeJson(const TabletopEpisode& e);

// The generated table scenes and their goals (control/manip/table_world.h), as eval names them.
using control::manip::MakeTableWorld;
using control::manip::TabletopSceneGoal;
using control::manip::TableWorld;

/// The grasp policy to use: `flag` when given, else assets/policies/grasp.pt when the checkout
/// has it, else "scripted".
std::string DefaultGraspPolicy(const std::string& flag);

/// The pipeline's goal for a tabletop plan (the offline planner's form of "put the red box on
/// the blue cylinder": a step with the right hand on an object, then a step with that object on
/// top of another) in `world`. InvalidArgument naming the step and what the pipeline takes for
/// any other plan: the left hand, relations other than "on top of", more or fewer steps.
core::StatusOr<control::manip::TabletopGoal> TabletopGoalFromPlan(const plan::ContactChain& chain,
                                                                  const world::SimWorld& world);

/// Whether agent 0 of `world` sits at the table with a dexterous right hand and `chain` is a
/// tabletop plan (a first step that grasps an object with the right hand): what `simhuman run`
/// hands to the pipeline instead of the MPC.
bool IsTabletopRun(const plan::ContactChain& chain, const world::SimWorld& world);

/// Whether agent 0 of `world` sits at the table with a dexterous right hand, its trunk held
/// where it sits: only the tabletop pipeline can move it (it cannot stand up or walk).
bool IsSeatedTabletopWorld(const world::SimWorld& world);

/// OK unless `world` is a seated tabletop world (IsSeatedTabletopWorld) and `chain` is not a
/// tabletop plan: then InvalidArgument naming the plan's first step, the object it needed to
/// get close to, and what such a scene runs (e.g. an object beyond the seated arm's reach made
/// the planner stand the human up and walk it over).
core::Status CheckSeatedTabletopPlan(const plan::ContactChain& chain, const world::SimWorld& world);

/// Runs a tabletop plan through the pipeline (`grasp_policy`, `place_policy`: a file or
/// "scripted"; a non-empty `vision_model`: the head camera plans and watches,
/// eval/tabletop_vision.h), recording
/// `trajectory` at 30 frames/s (step 0 until the grasp holds, then step 1). The result reads as
/// an episode's: success, steps completed, the pipeline's end reason. Errors: the plan
/// (TabletopGoalFromPlan), an unloadable policy.
core::StatusOr<control::EpisodeResult> RunTabletopPlan(
    world::SimWorld& world, const plan::ContactChain& chain, const std::string& grasp_policy,
    control::Trajectory* trajectory, const std::string& vision_model = "",
    const std::string& place_policy = "scripted");

}  // namespace simhuman::eval
