#pragma once
/// The pieces of `simhuman eval` for plan suites: one seeded, independent episode
/// (RunSuiteEpisode), its JSON line, and the summary. eval/eval_job.h runs them as a job over
/// one or more ranks. Formats in docs/FORMATS.md, protocols in docs/EVAL_PROTOCOLS.md.

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "simhuman/control/mpc/mpc_config.h"
#include "simhuman/control/runner.h"
#include "simhuman/core/status.h"
#include "simhuman/eval/motion_metrics.h"
#include "simhuman/eval/suites.h"

namespace simhuman::eval {

/// One finished episode.
/// Seconds an episode goes on after its plan completed; the final pose must still satisfy the
/// last step (and the suite's extra check) at the end.
inline constexpr double kEvalSettleS = 3.0;

struct EpisodeRecord {
  int index = 0;                  ///< 0-based episode number
  uint64_t seed = 0;              ///< episode seed: DeriveSeed(eval seed, index)
  std::string variant;            ///< EpisodeSpec::variant
  control::EpisodeResult result;  ///< result.success is the plan's own success
  ExtraResult extra;
  /// The last step's pairs still hold kEvalSettleS after the plan completed, without a fall.
  bool held = false;
  /// The last step's pair distances (PairEval::distance_m, m) when `held` was judged: which
  /// pair drifted when a completed plan did not hold. Empty in journals before session 33.
  std::vector<double> held_pair_errors_m;
  bool success = false;  ///< plan success, held, and the extra check
  /// result.success_unihsi_points was measured (false for journals before session 31)
  bool unihsi_recorded = true;
  std::string sheet_path;    ///< contact sheet written for this episode, if any
  std::string render_error;  ///< why the contact sheet could not be written, if it failed
  nlohmann::json scene;      ///< world::SceneToJson of the episode's scene
  nlohmann::json plan;       ///< the episode's plan
  /// The acting human's human-norm motion metrics (eval/motion_metrics.h); absent (nullopt)
  /// in journals written before session 19.
  std::optional<MotionMetrics> motion;
};

/// Whether a human stands on its feet at `body`: its hips at least 0.7 of its leg length (hip to
/// knee to foot, from the same points) above its lower foot, and its head above its hips within
/// 45 degrees of vertical. A seated human has its hips about half its leg length up, one slumped
/// on the floor or against a bed almost none.
bool StandsOnItsFeet(const plan::BodyPoints& body);

/// Our convention beside UniHSI's position-only get-close rule, for the hold check: every
/// get-close pair of `last` (a stand-up or walk-to step) also needs its human standing
/// (StandsOnItsFeet of `agents[pair.agent]`). True for a step without get-close pairs.
bool GetCloseHumansStand(const plan::ContactStep& last,
                         const std::vector<plan::BodyPoints>& agents);

/// The final success rule of every plan suite, on a record whose `result` and `extra` are set:
/// the plan succeeded (every step completed in order within its budget), then its last step
/// still holds `kEvalSettleS` later (`last_step_holds`, evaluated at the end of the episode)
/// without a fall in between, then the suite's extra check passes. Sets `held` and `success`.
void JudgeEpisode(bool last_step_holds, EpisodeRecord* record);

/// Aggregates over finished episodes.
struct Summary {
  std::string suite;
  int episodes = 0;  ///< finished
  int episodes_requested = 0;
  double success_rate = 0;                ///< share of finished episodes with `success`
  std::optional<double> contact_error_m;  ///< mean over episodes that recorded one
  /// the same with UniHSI's joint-centre pelvis point (EpisodeResult)
  std::optional<double> contact_error_joint_centre_m;
  /// share of the episodes that recorded it with `success` and success_unihsi_points
  /// (EpisodeResult); nullopt when none did (journals before session 31)
  std::optional<double> success_rate_unihsi_points;
  double success_steps = 0;  ///< mean steps completed
  double steps_total = 0;    ///< mean steps of the plans
  double fall_rate = 0;
  double extra_pass_rate = 0;  ///< share passing the suite's extra check (1 without one)
  double wall_per_sim = 0;     ///< total wall time / total simulated time
  double sim_time_s = 0;       ///< total
  double wall_time_s = 0;      ///< total
  /// The episodes' motion metrics (MeanMotionMetrics); nullopt when no record has them.
  std::optional<MotionMetrics> motion;
};

/// Aggregates `records` (finished episodes) of `suite`.
Summary Summarize(std::string_view suite, const std::vector<EpisodeRecord>& records,
                  int episodes_requested);

/// One line of episodes.jsonl: episode, seed, variant, success, plan_success, the
/// EpisodeResultJson() fields, the extra metric (when the suite has one), scene and plan.
nlohmann::ordered_json EpisodeRecordJson(const EpisodeRecord& record);

/// The inverse of EpisodeRecordJson for everything but `scene`, `plan` and the per-step lists
/// of `result` (left empty): what Summarize and a results table need. InvalidArgument naming
/// the key when one is missing or of the wrong type.
core::StatusOr<EpisodeRecord> EpisodeRecordFromJson(const nlohmann::json& j);

/// What to run.
struct EvalOptions {
  std::string suite = "sit";  ///< a plan suite's registry name (eval/suites.h)
  int episodes = 10;
  uint64_t seed = 1;
  std::string out_dir;
  control::MpcConfig config;
  /// Every K-th episode (0, K, 2K, ...) is recorded and its contact sheet rendered to
  /// DIR/ep<i>.png; 0 renders none.
  int video_every = 0;
  /// Walking policy file: when set, get-close steps that start standing are walked with it
  /// (control::WalkThenContactController) and the MPC does the rest.
  std::string walk_policy;
  /// Continue the run in out_dir: keep its finished episodes and run only the missing ones
  /// (eval/eval_job.h).
  bool resume = false;
  /// Every human of every episode gets this length scale (a child 0.6, a tall adult 1.2);
  /// furniture keeps its size. Only suites in ScalableSuites().
  double human_scale = 1.0;
};

/// The plan suites whose episodes stay valid for any body size (sit, sit-far, lie, lie-far):
/// the others place targets (markers, hand contacts) for an adult's reach.
const std::vector<std::string>& ScalableSuites();

/// summary.json: suite, episodes, episodes_requested, success_rate, contact_error_m (null when
/// none), success_steps, fall_rate, wall_per_sim, seed, preset, config, git_revision,
/// mujoco_version, and the extra fields of Summary.
nlohmann::ordered_json SummaryJson(const Summary& summary, const EvalOptions& options);

/// Runs episode `index` of `options` (no files written except its contact sheet).
/// Errors: Internal when the generated episode cannot be set up (a suite bug or a world/
/// change), naming the suite, episode and seed.
core::StatusOr<EpisodeRecord> RunSuiteEpisode(const EvalOptions& options, int index);

}  // namespace simhuman::eval
