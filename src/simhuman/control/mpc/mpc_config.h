#pragma once
/// Settings of the reference-guided predictive-sampling MPC, in one strict struct.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "simhuman/core/status.h"

namespace simhuman::control {

/// All tunables of MpcController. Times in seconds, angles in radians.
struct MpcConfig {
  std::string preset = "fast";
  int samples = 16;         ///< rollouts per replan (incl. the nominal and the reference)
  int knots = 4;            ///< spline knots over the horizon
  double horizon_s = 0.6;   ///< rollout length
  double plan_dt_s = 0.01;  ///< planning model time step
  double replan_s = 0.03;   ///< control period: one replan per period
  double noise_rad = 0.08;  ///< knot perturbation std dev (legs and spine; arms 1.5x)
  double small_noise_fraction = 0.25;  ///< share of samples drawn at 0.3x noise
  double ramp_speed_rad_s = 0.9;       ///< reference ramp speed (largest joint change)
  double min_ramp_s = 0.8;
  double max_ramp_s = 3.0;
  int threads = 2;
  /// Longest interval between replans while the caller is behind real time (the live
  /// server): replans are skipped, the current plan kept, up to this age. 0 (the default, or
  /// anything <= replan_s): never skipped. Skipping keeps `serve` at real time but lowers
  /// the quality of heavy steps (lying; docs/BENCHMARKS.md, issue 18).
  double max_replan_s = 0;
  // cost weights
  double w_track = 4.0;     ///< body points toward the reference pose trajectory
  double w_contact = 30.0;  ///< contact terms (x adaptive weights, Eq. 9)
  double w_balance = 12.0;  ///< capture point over the feet (while not seated)
  double w_upright = 3.0;   ///< torso upright (stand and sit postures)
  double w_effort = 0.05;   ///< normalised actuator force squared
  double w_ctrl = 0.3;      ///< servo targets away from the reference
  double w_velocity = 0.002;
  double w_com_velocity = 10.0;     ///< centre-of-mass speed squared (calm, human-paced motion)
  double w_fall = 30.0;             ///< head below its safe height
  double fall_head_height_m = 0.5;  ///< head below this (scaled) ends the episode as a fall
  /// Aim correction for hand contacts: once the reference has arrived, the reference's hand
  /// target moves past the contact point by this fraction of the remaining miss (position
  /// servos under gravity leave a reaching hand short). 0 (the default) disables it: the hand
  /// servo below holds hands better (reach 99 % vs 96 % with both, 100 episodes).
  double aim_gain = 0.0;
  /// Hand servo for hand contacts: once the reference has arrived and the hand is within
  /// 0.15 m (scaled) of its contact point, each replan adds this fraction of the damped
  /// least-squares arm joint change that would close the miss (shoulder and elbow of that
  /// hand) to an offset on those servo targets, an integral action against the sag of a
  /// position servo under gravity and against the trunk's sway. 0 disables it.
  double hand_servo_gain = 0.3;
  /// Largest offset (rad) the hand servo may add to one arm joint's servo target.
  double hand_servo_max_rad = 0.6;

  /// Every field finite and in range (one field table, mpc_config.cc, drives Validate, ToJson
  /// and FromJson); the message names the field, its value and the valid range.
  absl::Status Validate() const;
  /// Every key, "preset" included.
  nlohmann::json ToJson() const;
  /// Strict: an unknown key is an error naming it and listing the valid keys, a wrong type one
  /// naming its JSON pointer and the expected type, a bad value one naming the key, the value
  /// and the valid range. Missing keys keep the preset's value (the preset named by "preset",
  /// default "fast"). Errors start with `where` (a file name; empty: no prefix).
  static absl::StatusOr<MpcConfig> FromJson(const nlohmann::json& j, std::string_view where);
  /// "fast" (the default) or "quality" (more samples, finer planning).
  static absl::StatusOr<MpcConfig> Preset(std::string_view name);
};

}  // namespace simhuman::control
