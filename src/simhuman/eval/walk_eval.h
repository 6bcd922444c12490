#pragma once
/// The `walk` suite: the walking policy alone in an empty room. Each episode places the human
/// at the origin with a random heading and a target stand point 1-10 m away in a random
/// direction with a random final heading; success is standing within 0.2 m and 15 degrees of
/// it, stopped (< 0.2 m/s) for 0.5 s, within 30 s, without a fall. Foot skating is the mean
/// horizontal speed of feet in contact with the floor (m/s) over the episode.
///
/// The `walk-step` variant asks for short steps without turning: the stand point is 0.5-1.5 m
/// away, behind or beside the human (bearing 60-300 degrees from its heading), and the final
/// heading is the start heading. Each episode reports the largest heading change on the way
/// (max_turn_deg): a human that steps back or sideways keeps it small, one that turns round,
/// walks forward and turns back makes it large.

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/eval/motion_metrics.h"

namespace simhuman::eval {

struct WalkEvalOptions {
  std::string policy;  ///< policy file
  int episodes = 100;
  uint64_t seed = 1;
  double min_dist_m = 1.0, max_dist_m = 10.0;
  double time_limit_s = 30.0;
  std::string sheet_dir;    ///< where contact sheets go (ep<i>.png)
  int video_every = 0;      ///< render every K-th episode's contact sheet; 0: none
  bool video = false;       ///< also write ep<i>.mp4 for rendered episodes
  bool step_suite = false;  ///< the walk-step variant (min/max_dist_m are then ignored)
  std::string physics_solver = "newton";  ///< world::ModelOptions::solver
  double scale = 1.0;  ///< the human's length scale (targets and the success rule stay in metres)
};

struct WalkEpisode {
  int index = 0;
  double dist_m = 0;  ///< initial distance to the target
  bool success = false;
  bool fell = false;
  double time_s = 0;  ///< time to success (or the episode's length)
  double final_dist_m = 0, final_yaw_err_deg = 0;
  double foot_skate_mps = 0;
  double mean_speed_mps = 0;  ///< path length / time while walking
  double bearing_deg = 0;     ///< direction of the target from the start heading (left +)
  double max_turn_deg = 0;    ///< largest |heading - start heading| during the episode
  /// mean over the episode (policy steps) of the higher arm's angle from hanging straight
  /// down, shoulder to hand: a relaxed walking arm stays within about 20 degrees, an arm held
  /// out in front at shoulder height is at 90
  double arm_raise_deg = 0;
  MotionMetrics motion;    ///< human-norm gait metrics of the episode (eval/motion_metrics.h)
  std::string sheet_path;  ///< contact sheet, when rendered
  std::string render_error;
};

struct WalkEvalSummary {
  int episodes = 0;
  double success_rate = 0, fall_rate = 0;
  double mean_time_s = 0;  ///< over successes
  double foot_skate_mps = 0;
  double final_dist_m = 0, final_yaw_err_deg = 0;  ///< means
  double max_turn_deg = 0;                         ///< mean of the episodes' max_turn_deg
  double arm_raise_deg = 0;                        ///< mean of the episodes' arm_raise_deg
  /// share of successful episodes whose heading never left the start heading by 45 degrees
  /// or more (walk-step: stepped back or sideways instead of turning round)
  double no_turn_rate = 0;
  MotionMetrics motion;  ///< the episodes' metrics, weighted by walking time
};

/// Runs the suite; `on_episode` (optional) sees each finished episode. Errors: the policy file.
core::StatusOr<WalkEvalSummary> RunWalkEval(
    const WalkEvalOptions& options, std::vector<WalkEpisode>* episodes,
    const std::function<void(const WalkEpisode&)>& on_episode = nullptr);

/// One line of the suite's episodes.jsonl (docs/EVAL_PROTOCOLS.md, "walk").
nlohmann::ordered_json WalkEpisodeJson(const WalkEpisode& e);
/// The suite's summary.json: rates and means, the policy, the seed and provenance.
nlohmann::ordered_json WalkSummaryJson(const WalkEvalSummary& s, const WalkEvalOptions& options);

}  // namespace simhuman::eval
