#pragma once
/// The `carry` suite: the single-carrier carrying policy on CooHOI's single-box protocol
/// (Table 1): a cube of side 0.25-0.75 m (0.5 m scaled 0.5-1.5) and 2-13 kg, the destination
/// 1-20 m from the box in any direction, the human starting 1-5 m from the box at any heading
/// (CooHOI's release starts straight ahead; we do not). Episodes run the carry task's phases,
/// observations and terminations (learn/carry_env.h) with the policy's mean action.
///
/// Success is per episode, as our issue asks (CooHOI's release reports the best fraction of
/// environments within 0.2 m at any moment, which is looser): after the put-down the box rests
/// on the floor within 0.2 m of the destination for 1 s, and nobody fell. Precision is the mean
/// final distance of the box to its destination over the successful episodes.

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::learn {

struct CarryEvalOptions {
  std::string policy;  ///< a carry policy file (simhuman train --task carry)
  /// A walking policy file (simhuman train --task walk, the same reference gait) that drives
  /// the approach phase instead of the carry policy (which takes over at the lift); empty: the
  /// carry policy walks up too. The carry observation begins with the walking one.
  std::string approach_policy;
  /// A walking policy file (same gait) that walks every walking phase: the approach, the carry
  /// (shown its own arm swing: control::CarryBlindArms) and the retreat; its arm outputs are
  /// unused (the arms follow the task's reference and grip). Empty: the policies above walk.
  std::string walker;
  /// A lift policy file (simhuman train --task carry-lift, same gait and grip) that drives the
  /// lift; empty: the carry policy lifts.
  std::string lift_policy;
  /// A delivery policy file (simhuman train --task carry-deliver, same gait and grip) that drives
  /// the carry and the put-down; empty: the walker (or the carry policy) carries and the carry
  /// policy puts down.
  std::string deliver_policy;
  /// The lift and the put-down by the model-based controller instead of a policy: the keyframe
  /// reference with quasi-static support (control/policy/carry_support.h) and no residual
  /// action. Excludes lift_policy and deliver_policy.
  bool model_squats = false;
  int episodes = 100;
  uint64_t seed = 1;
  double min_dist_m = 1.0, max_dist_m = 20.0;  ///< box to destination
  double min_mass_kg = 2.0, max_mass_kg = 13.0;
  double min_scale = 0.5, max_scale = 1.5;  ///< of a 0.5 m cube
  /// Episode time: this much plus 2.5 s per metre of the destination distance (a walk at
  /// 0.4 m/s), so a 20 m carry gets 80 s.
  double base_time_s = 30.0;
};

struct CarryEpisode {
  int index = 0;
  double mass_kg = 0, side_m = 0, dist_m = 0;
  bool success = false;
  bool fell = false;
  std::string end_reason;  ///< "success", a CarryFailureName(), or "timeout"
  std::string last_phase;  ///< the carry phase the episode ended in
  double time_s = 0;
  double final_dist_m = 0;  ///< box centre to the destination (horizontal) at the end
};

struct CarryEvalSummary {
  int episodes = 0;
  double success_rate = 0, fall_rate = 0;
  double precision_m = -1;  ///< mean final distance over successes; -1 without any
  /// Success rate per mass bin [2,5), [5,8), [8,11), [11,13] kg (episodes, successes).
  std::vector<int> mass_bin_episodes, mass_bin_successes;
  std::vector<std::string> mass_bin_labels;
};

/// Runs the suite; `on_episode` (optional) sees each finished episode. Errors: the policy
/// file (missing, or not a carry policy), bad ranges.
core::StatusOr<CarryEvalSummary> RunCarryEval(
    const CarryEvalOptions& options, std::vector<CarryEpisode>* episodes,
    const std::function<void(const CarryEpisode&)>& on_episode = nullptr);

/// One line of the suite's episodes.jsonl.
nlohmann::ordered_json CarryEpisodeJson(const CarryEpisode& e);
/// The suite's summary.json: rates, precision, per-mass success, options.
nlohmann::ordered_json CarrySummaryJson(const CarryEvalSummary& s, const CarryEvalOptions& o);

}  // namespace simhuman::learn
