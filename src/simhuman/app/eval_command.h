#pragma once
/// `simhuman eval`: a benchmark suite of seeded, independent episodes with a results table.

#include <cstdint>
#include <ostream>
#include <string>

#include "simhuman/app/llm_flags.h"
#include "simhuman/core/communicator.h"

namespace simhuman::app {

/// The flags of `simhuman eval`.
struct EvalFlags {
  std::string suite;  ///< one of eval::SuiteNames(), or "language"
  int episodes = 10;
  uint64_t seed = 1;
  std::string out;  ///< output folder; empty: out/eval_<suite>
  std::string preset = "fast";
  bool preset_given = false;
  std::string config;               ///< MpcConfig JSON file; empty: the preset
  int video_every = 0;              ///< contact sheet of every K-th episode; 0: none
  std::string corpus;               ///< language suite: corpus file; empty: the one in the sources
  std::string planner = "offline";  ///< language suite: the planner
  LlmFlags llm;                     ///< --llm-* flags (with --planner llm)
  /// Walking policy file: required by the `walk` suite; other suites walk their get-close
  /// steps with it when given (default assets/policies/walk.pt when that file exists).
  std::string policy;
  bool video = false;                     ///< walk suite: also write MP4s of rendered episodes
  std::string physics_solver = "newton";  ///< walk suites: world::ModelOptions::solver
  /// walk suites: the humans' length scales, one run of the suite each (empty: scale 1)
  std::vector<double> scales;
  /// Plan suites: continue the run in --out, running only its missing episodes.
  bool resume = false;
  /// Tabletop suites: a grasp policy file, or "scripted"; empty: assets/policies/grasp.pt when
  /// it exists, else "scripted".
  std::string grasp_policy;
  /// Tabletop suites: a place policy file (simhuman train --task place), or "scripted".
  std::string place_policy = "scripted";
  /// Tabletop suites: grasps tried on one object (control::manip::TabletopOptions).
  int grasp_attempts = 2;
  /// Tabletop suites: the arm planner's seed (eval::TabletopEvalOptions::planner_seed).
  int planner_seed = 1;
  std::string zero_shot;       ///< tabletop, place, stack: eval::TabletopEvalOptions::zero_shot
  std::string zero_shot_mesh;  ///< its OBJ file for "mesh" (empty: world::kZeroShotMeshFile)
  int jobs = 1;                ///< tabletop, place, stack: episodes run at once (threads)
  /// Tabletop suites: the first episode's index (eval::TabletopEvalOptions::first_episode)
  int first_episode = 0;
  std::string approach_policy;  ///< carry: a walking policy for the approach phase
  std::string walker;           ///< carry: a walking policy for every walking phase
  std::string lift_policy;      ///< carry: a carry-lift policy for the lift
  std::string deliver_policy;   ///< carry: a carry-deliver policy for the carry and put-down
  bool model_squats = false;    ///< carry: the lift and put-down by the model-based controller
  /// Tabletop suites: "truth" or "vision" (the head camera and the vision model).
  std::string perception = "truth";
  bool no_touch = false;  ///< --perception vision without the hand's touch (an ablation)
  /// vision without the silhouette fit of the planning estimates (an ablation)
  bool no_silhouette = false;
  /// The vision suite and --perception vision: a model file (simhuman train --task vision); empty:
  /// the shipped one.
  std::string vision_model;
};

/// Runs the suite: a table row per finished episode and a summary table on `out`, files as
/// eval::RunEval() (eval/eval_job.h) writes them. kExitOk when every episode ran, kExitBadInput for
/// bad flags or files, kExitInternal when an episode could not be set up or a file not written
/// (what finished stays written). The "language" suite instead runs the command corpus through
/// --planner and writes DIR/summary.json (eval::LanguageSummaryJson); episode flags are
/// ignored there. Plan suites run as a job over the ranks of `comm` (eval/eval_job.h); only
/// rank 0 should be given real `out` and `err` streams (every rank returns the same code).
int EvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err,
                core::Communicator& comm);

}  // namespace simhuman::app
