#pragma once
/// The `walk` suite: the walking policy alone in an empty room. Each episode places the human
/// at the origin with a random heading and a target stand point 1-10 m away in a random
/// direction with a random final heading; success is standing within 0.2 m and 15 degrees of
/// it, stopped (< 0.2 m/s) for 0.5 s, within 30 s, without a fall. Foot skating is the mean
/// horizontal speed of feet in contact with the floor (m/s) over the episode.

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::eval {

struct WalkEvalOptions {
  std::string policy;  ///< policy file
  int episodes = 100;
  uint64_t seed = 1;
  double min_dist_m = 1.0, max_dist_m = 10.0;
  double time_limit_s = 30.0;
  std::string sheet_dir;  ///< where contact sheets go (ep<i>.png)
  int video_every = 0;    ///< render every K-th episode's contact sheet; 0: none
  bool video = false;     ///< also write ep<i>.mp4 for rendered episodes
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
  std::string sheet_path;     ///< contact sheet, when rendered
  std::string render_error;
};

struct WalkEvalSummary {
  int episodes = 0;
  double success_rate = 0, fall_rate = 0;
  double mean_time_s = 0;  ///< over successes
  double foot_skate_mps = 0;
  double final_dist_m = 0, final_yaw_err_deg = 0;  ///< means
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
