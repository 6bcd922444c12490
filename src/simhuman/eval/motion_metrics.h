#pragma once
/// Human-norm motion metrics of one human's recorded motion: gait (speed, cadence, step length,
/// knee flexion, trunk and head pitch, arm swing and its phase, foot skating and clearance,
/// double support, jerk), computed from kinematics alone, so every recorded run (eval episodes,
/// `simhuman run`, a replayed trajectory) gets them. Each is compared with published adult norms
/// (MotionNorms(); sources in docs/BENCHMARKS.md, "Human-norm motion metrics").
///
/// Input: one MotionSample per recorded frame (SampleMotion reads it from MuJoCo kinematics;
/// the computation itself is MuJoCo-free and testable with synthetic frames).
///
/// Walking is judged on **steady stretches**: runs of frames, at least kMinStretchS long, where
/// the pelvis moves faster than kWalkingSpeed x sqrt(scale) (speed from a 0.5 s centred
/// difference). Gait metrics use those frames only, as gait norms are for steady walking; a
/// motion with no such stretch has no gait metrics (`walking_s` 0, the others NaN).
/// A foot is **on the ground** when the lowest corner of its box is within kContactHeight x
/// scale of the floor (z = 0): a foot on a bed or a step is not. Foot skating uses that; the
/// stance phase (steps, swings, double support) starts there and ends only when the foot rises
/// above kLiftHeight x scale, so a heel or toe rocking in stance is not counted as a step.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

inline constexpr double kWalkingSpeed = 0.3;     ///< m/s at scale 1 (times sqrt(scale))
inline constexpr double kMinStretchS = 2.0;      ///< s
inline constexpr double kContactHeight = 0.015;  ///< m at scale 1 (times scale)
inline constexpr double kLiftHeight = 0.03;      ///< m at scale 1: a stance phase ends above this
inline constexpr double kSeatedPelvis = 0.70;    ///< m at scale 1: pelvis below this is seated
inline constexpr double kStandingPelvis = 0.88;  ///< m at scale 1: above this is standing

/// One frame of one human (world frame, metres, radians).
struct MotionSample {
  double time_s = 0;
  Eigen::Vector3d pelvis = Eigen::Vector3d::Zero();
  double yaw_rad = 0;          ///< pelvis heading
  double trunk_pitch_rad = 0;  ///< torso forward lean from vertical (+ forward)
  double head_pitch_rad = 0;   ///< head forward tilt from vertical (+ down)
  Eigen::Vector3d foot[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  ///< left, right
  double foot_low_z[2] = {0, 0};  ///< lowest corner of each foot box
  Eigen::Vector3d hand[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  ///< left, right
  double knee_rad[2] = {0, 0};           ///< flexion, left, right
  double shoulder_flex_rad[2] = {0, 0};  ///< sagittal flexion (+ forward), left, right
};

/// The metrics (NaN where undefined: no steady walking, no swing, ...).
struct MotionMetrics {
  double scale = 1.0;
  double duration_s = 0;
  double walking_s = 0;              ///< time in steady stretches
  double speed_mps = NAN;            ///< distance / time over the stretches
  double cadence_spm = NAN;          ///< foot strikes per minute
  double step_length_m = NAN;        ///< distance / foot strikes
  double stance_knee_deg = NAN;      ///< mean knee flexion of feet on the ground
  double swing_knee_peak_deg = NAN;  ///< mean over swings of the peak knee flexion
  double trunk_pitch_deg = NAN;      ///< mean forward lean of the torso while walking
  double head_pitch_deg = NAN;       ///< mean forward tilt of the head while walking
  double arm_swing_deg = NAN;        ///< shoulder flexion range (5th-95th percentile), mean of arms
  double arm_swing_m = NAN;          ///< fore-aft hand excursion relative to the pelvis (same)
  /// correlation of each hand's fore-aft position with the same side's foot (relative to the
  /// pelvis, heading frame): -1 is perfect counter-phase (the human way), +1 in phase
  double arm_leg_phase_corr = NAN;
  double double_support = NAN;         ///< share of walking time with both feet on the ground
  double foot_skate_mps = NAN;         ///< mean horizontal speed of feet on the ground (all frames)
  double swing_clearance_min_m = NAN;  ///< mean over swings of the mid-swing minimum height
  double swing_clearance_peak_m = NAN;  ///< mean over swings of the peak height
  double pelvis_jerk_rms = NAN;  ///< RMS of the pelvis's third derivative while walking, m/s^3
  int foot_strikes = 0;
  int swings = 0;
  // getting up (sit-to-stand): a rise is the pelvis going from seated height (below
  // kSeatedPelvis x scale) to standing height (above kStandingPelvis x scale); it starts at
  // seat-off, the last frame before that within 2 cm x scale of the seated minimum (an attempt
  // that sinks back to seated height is sitting again: only the rise after it counts)
  int rises = 0;
  double rise_s = NAN;  ///< mean seat-off to standing time
  /// Mean time from the start of the trunk's forward lean before seat-off (the last frame within
  /// kLeanOnsetRad of the least lean in the kLeanLookBackS before seat-off) to standing: the
  /// whole stand-up, as sit-to-stand durations are timed
  double sit_to_stand_s = NAN;
  double rise_extra_steps = NAN;  ///< mean foot strikes during a rise
  int rises_staggered = 0;        ///< rises where the pelvis sank back 5 cm x scale on the way
  int rises_clean = 0;            ///< rises with no step and no sinking back
};

/// Computes the metrics of `frames` (time-ordered, at a fixed rate of at least 20 Hz) of a
/// human of length scale `scale`.
MotionMetrics ComputeMotionMetrics(const std::vector<MotionSample>& frames, double scale);

/// One published norm: the metric's key, the range a healthy adult walking at comfortable
/// speed shows, and where it comes from (short citation; full ones in docs/BENCHMARKS.md).
struct MotionNorm {
  std::string key;   ///< MotionMetrics field name as in MotionMetricsJson
  std::string what;  ///< human words
  double lo = -INFINITY, hi = INFINITY;
  std::string source;
};
const std::vector<MotionNorm>& MotionNorms();

/// How far a value is outside its norm: 0 inside, else the distance to the nearer end (NaN:
/// the metric is undefined).
double NormGap(const MotionNorm& n, double value);
/// The value of `key` in `m` (NaN for an unknown key).
double MetricValue(const MotionMetrics& m, const std::string& key);

/// {"walking_s": ..., "speed_mps": ..., ...}: every field (null for NaN), then "norms": per
/// norm {value, lo, hi, gap, ok}.
nlohmann::ordered_json MotionMetricsJson(const MotionMetrics& m);
/// The inverse of MotionMetricsJson (the "norms" part is ignored). Errors name the key.
core::StatusOr<MotionMetrics> MotionMetricsFromJson(const nlohmann::json& j);

/// Mean of several episodes' metrics, each weighted by its walking time (the frame-count
/// metrics by their counts); episodes without walking count only for foot skating.
MotionMetrics MeanMotionMetrics(const std::vector<MotionMetrics>& all);

/// Lines "  speed_mps  0.72  norm 1.0-1.6  (0.28 below)" for a printout.
std::string MotionNormsReport(const MotionMetrics& m);

/// Reads agent `agent`'s sample from `d` (kinematics must be current: mj_kinematics or a step).
MotionSample SampleMotion(const mjModel* m, const mjData* d, const world::SimWorld& world,
                          int agent);

/// The metrics of agent `agent` over a recorded trajectory (`qpos` frames of `world`'s model):
/// runs kinematics on a scratch mjData for each frame.
MotionMetrics TrajectoryMotionMetrics(const world::SimWorld& world, int agent,
                                      const std::vector<double>& time_s,
                                      const std::vector<std::vector<double>>& qpos);

}  // namespace simhuman::eval
