#include "simhuman/eval/motion_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace simhuman::eval {
namespace {

// A synthetic walk along +x at `v` m/s: gait cycle `period` s, each foot on the ground for
// 60 % of it (so 20 % double support), planted feet still, hands swinging against the feet,
// trunk leaning `lean` rad, sampled at 30 Hz for `seconds`.
std::vector<MotionSample> SyntheticWalk(double v, double period, double seconds, double lean,
                                        bool hands_in_phase = false) {
  std::vector<MotionSample> frames;
  const double fps = 30;
  for (int i = 0; i <= static_cast<int>(seconds * fps); ++i) {
    MotionSample s;
    s.time_s = (i + 0.5) / fps;  // off the phase boundaries
    s.pelvis = Eigen::Vector3d(v * s.time_s, 0, 0.93);
    s.yaw_rad = 0;
    s.trunk_pitch_rad = lean;
    for (int side = 0; side < 2; ++side) {
      const double u = s.time_s / period + 0.5 * side;
      const double k = std::floor(u), ph = u - k;
      const bool stance = ph < 0.6;
      double x = v * period * k - 0.2;
      if (!stance) x += v * period * (ph - 0.6) / 0.4;
      s.foot[side] = Eigen::Vector3d(x, side == 0 ? 0.1 : -0.1, 0.05);
      s.foot_low_z[side] = stance ? 0.0 : 0.035 + 0.05 * std::sin(M_PI * (ph - 0.6) / 0.4);
      s.knee_rad[side] = stance ? 0.2 : 0.2 + 0.8 * std::sin(M_PI * (ph - 0.6) / 0.4);
      const double rel = x - s.pelvis.x();
      s.hand[side] = Eigen::Vector3d(s.pelvis.x() + (hands_in_phase ? 0.5 : -0.5) * rel, 0, 0.8);
      s.shoulder_flex_rad[side] = (hands_in_phase ? 0.5 : -0.5) * rel;
    }
    frames.push_back(s);
  }
  return frames;
}

TEST(MotionMetricsTest, ASyntheticWalkGivesItsSpeedCadenceStepsAndPhases) {
  const MotionMetrics m = ComputeMotionMetrics(SyntheticWalk(1.2, 1.0, 8.0, 0.1), 1.0);
  EXPECT_GT(m.walking_s, 7.0);
  EXPECT_NEAR(m.speed_mps, 1.2, 0.03);
  EXPECT_NEAR(m.cadence_spm, 120, 4);
  EXPECT_NEAR(m.step_length_m, 0.6, 0.03);
  EXPECT_NEAR(m.double_support, 0.2, 0.03);
  EXPECT_NEAR(m.trunk_pitch_deg, 0.1 * 180 / M_PI, 1e-6);
  EXPECT_NEAR(m.stance_knee_deg, 0.2 * 180 / M_PI, 1e-6);
  EXPECT_NEAR(m.swing_knee_peak_deg, 1.0 * 180 / M_PI, 3);
  EXPECT_LT(m.arm_leg_phase_corr, -0.99);
  EXPECT_NEAR(m.foot_skate_mps, 0.0, 1e-9);  // planted feet do not move
  EXPECT_NEAR(m.swing_clearance_min_m, 0.035 + 0.05 * std::sin(M_PI / 3), 0.006);
  EXPECT_NEAR(m.swing_clearance_peak_m, 0.085, 0.002);
  EXPECT_GT(m.swings, 10);
  // hands swinging with the legs are flagged in phase
  EXPECT_GT(ComputeMotionMetrics(SyntheticWalk(1.2, 1.0, 8.0, 0.1, true), 1.0).arm_leg_phase_corr,
            0.99);
}

TEST(MotionMetricsTest, StandingStillHasNoGaitAndSlidingFeetAreSkating) {
  std::vector<MotionSample> frames = SyntheticWalk(0.0, 1.0, 5.0, 0.0);
  for (auto& s : frames) {
    for (int side = 0; side < 2; ++side) {
      s.foot_low_z[side] = 0;
      s.foot[side] = Eigen::Vector3d(0.1 * s.time_s, 0, 0.05);  // sliding at 0.1 m/s
    }
  }
  const MotionMetrics m = ComputeMotionMetrics(frames, 1.0);
  EXPECT_EQ(m.walking_s, 0);
  EXPECT_TRUE(std::isnan(m.speed_mps));
  EXPECT_TRUE(std::isnan(m.cadence_spm));
  EXPECT_NEAR(m.foot_skate_mps, 0.1, 1e-6);
  // a walk shorter than a steady stretch is not judged as gait
  EXPECT_EQ(ComputeMotionMetrics(SyntheticWalk(1.2, 1.0, 1.5, 0.0), 1.0).walking_s, 0);
}

TEST(MotionMetricsTest, NormsJudgeAChildAfterFroudeScaling) {
  // a child of scale 0.64 walking like a scaled adult: speed x 0.8, cadence / 0.8
  const MotionMetrics adult = ComputeMotionMetrics(SyntheticWalk(1.2, 1.0, 8.0, 0.0), 1.0);
  std::vector<MotionSample> child = SyntheticWalk(1.2 * 0.8, 0.8, 8.0, 0.0);
  const MotionMetrics m = ComputeMotionMetrics(child, 0.64);
  EXPECT_NEAR(m.cadence_spm, 150, 5);
  const nlohmann::ordered_json j = MotionMetricsJson(m), ja = MotionMetricsJson(adult);
  EXPECT_NEAR(j["norms"]["speed_mps"]["value"].get<double>(),
              ja["norms"]["speed_mps"]["value"].get<double>(), 0.03);
  EXPECT_NEAR(j["norms"]["cadence_spm"]["value"].get<double>(),
              ja["norms"]["cadence_spm"]["value"].get<double>(), 5);
  EXPECT_TRUE(ja["norms"]["speed_mps"]["ok"].get<bool>());
  EXPECT_TRUE(ja["norms"]["cadence_spm"]["ok"].get<bool>());
  EXPECT_FALSE(ja["norms"]["swing_clearance_min_m"]["ok"].get<bool>());  // 6 cm: above 3 cm
  EXPECT_TRUE(j["norms_froude_scaled"].get<bool>());
  // a slow walk is below the speed norm by the difference
  const MotionMetrics slow = ComputeMotionMetrics(SyntheticWalk(0.7, 1.0, 8.0, 0.0), 1.0);
  EXPECT_NEAR(MotionMetricsJson(slow)["norms"]["speed_mps"]["gap"].get<double>(), 0.3, 0.03);
}

// seated (pelvis 0.55 m) for 1 s, then up to 0.93 m in `rise` s (sinking back about 10 cm near
// the top when `sink`, not down to seated height), then standing; feet planted; the trunk leans
// forward from 0.6 s (0.5 rad by 1.2 s) and straightens as the pelvis rises
std::vector<MotionSample> SitToStand(double rise, bool sink) {
  std::vector<MotionSample> frames;
  for (int i = 0; i < 150; ++i) {
    MotionSample s;
    s.time_s = (i + 0.5) / 30;
    const double u = std::clamp((s.time_s - 1.0) / rise, 0.0, 1.0);
    double z = 0.55 + 0.38 * u;
    if (sink && u > 0.75 && u < 0.95) z -= 0.14 * std::sin(M_PI * (u - 0.75) / 0.2);
    s.pelvis = Eigen::Vector3d(0, 0, z);
    s.trunk_pitch_rad = 0.5 * std::clamp((s.time_s - 0.6) / 0.6, 0.0, 1.0) * (1.0 - u);
    for (int side = 0; side < 2; ++side) s.foot[side] = Eigen::Vector3d(0.2, 0.1 - 0.2 * side, 0);
    frames.push_back(s);
  }
  return frames;
}

TEST(MotionMetricsTest, GettingUpIsTimedFromSeatOffAndSinkingBackIsCounted) {
  const MotionMetrics m = ComputeMotionMetrics(SitToStand(1.5, false), 1.0);
  EXPECT_EQ(m.rises, 1);
  // 0.88 m is reached 1.30 s after the rise starts; seat-off (2 cm up) 0.08 s after it
  EXPECT_NEAR(m.rise_s, 1.30 - 0.08, 0.05);
  // the whole stand-up from the lean's start (3 degrees past the seated lean, at 0.66 s) to
  // standing (2.30 s)
  EXPECT_NEAR(m.sit_to_stand_s, 2.30 - 0.66, 0.05);
  EXPECT_EQ(m.rise_extra_steps, 0);
  EXPECT_EQ(m.rises_clean, 1);
  const MotionMetrics s = ComputeMotionMetrics(SitToStand(2.0, true), 1.0);
  EXPECT_EQ(s.rises, 1);
  EXPECT_EQ(s.rises_staggered, 1);
  EXPECT_EQ(s.rises_clean, 0);
  EXPECT_TRUE(MotionMetricsJson(m)["norms"]["sit_to_stand_s"]["ok"].get<bool>());
  // a quick stand-up is below the norm
  EXPECT_FALSE(MotionMetricsJson(ComputeMotionMetrics(SitToStand(0.5, false),
                                                      1.0))["norms"]["sit_to_stand_s"]["ok"]
                   .get<bool>());
  // standing all along is no rise
  EXPECT_EQ(ComputeMotionMetrics(SyntheticWalk(0.0, 1.0, 5.0, 0.0), 1.0).rises, 0);
}

TEST(MotionMetricsTest, TheMeanWeighsEpisodesByWalkingTime) {
  MotionMetrics a = ComputeMotionMetrics(SyntheticWalk(1.2, 1.0, 8.0, 0.0), 1.0);
  MotionMetrics b = ComputeMotionMetrics(SyntheticWalk(0.8, 1.0, 4.0, 0.0), 1.0);
  MotionMetrics still;  // no walking: counts for nothing but duration
  still.duration_s = 3;
  still.foot_skate_mps = 0;
  const MotionMetrics mean = MeanMotionMetrics({a, b, still});
  const double expect =
      (a.speed_mps * a.walking_s + b.speed_mps * b.walking_s) / (a.walking_s + b.walking_s);
  EXPECT_NEAR(mean.speed_mps, expect, 1e-9);
  EXPECT_EQ(mean.foot_strikes, a.foot_strikes + b.foot_strikes);
}

}  // namespace
}  // namespace simhuman::eval
