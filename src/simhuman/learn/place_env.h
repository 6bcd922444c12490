#pragma once
/// DASH's placing stage as a training task ("place"): a generated table scene
/// (control/manip/table_world.h, DASH's Appendix B, place or stack by the seed) is run through
/// the pipeline with the scripted grasp up to where placing begins, so placing starts from
/// exactly what reaching, grasping and transport leave (DASH collects 10,000 stable grasps to
/// start placing from); kEpisodesPerScene episodes start from that state. The policy is asked
/// before each descent segment (control/manip/place_task.h) and corrects the scripted placing's
/// aim, upright direction and descent speed; a scene whose pipeline ends before placing (a plan
/// failure, a grasp miss, a drop in transport) is skipped for the next one of the same seed.
///
/// Reward, at the episode's end only: 2 for DASH's success (plus ours: at rest 2 s after the
/// release), exp(-(d / 3 cm)^2) for the centre of mass's horizontal distance d from the target,
/// and the object's uprightness (1 upright, 0 at 30 degrees or more). Every episode ends by the
/// pipeline (no time limit: at most 4 segments).
///
/// The pipeline drives its own loop, so each env runs in a thread of its own that hands each
/// decision's observation to Step() and waits for the action (only the envs a VecEnv worker
/// steps run at once).

#include <memory>
#include <vector>

#include "simhuman/control/manip/place_task.h"
#include "simhuman/core/status.h"
#include "simhuman/learn/vec_env.h"

namespace simhuman::learn {

class PlaceTask : public VecTask {
 public:
  static core::StatusOr<std::unique_ptr<PlaceTask>> Create(int num_envs);
  ~PlaceTask() override;
  std::string name() const override { return "place"; }
  int num_envs() const override { return static_cast<int>(envs_.size()); }
  int obs_dim() const override { return control::manip::kPlaceObsDim; }
  int act_dim() const override { return control::manip::kPlaceActDim; }
  double action_limit() const override { return 1.0; }
  void Reset(int i, uint64_t seed, float* obs) override;
  void Step(int i, const float* action, float* obs, StepInfo* info) override;

  /// Scenes tried before one reaches placing (each a pipeline run up to transport's end); after
  /// that many the episode starts and ends at once with reward 0.
  static constexpr int kMaxScenesPerEpisode = 40;
  /// Episodes that start from one scene's state where placing begins (the reach, grasp and
  /// transport take about three quarters of a whole pipeline's time).
  static constexpr int kEpisodesPerScene = 6;
  /// Scenes run for env i so far (tests, logs).
  int scenes_run(int i) const;

  struct Env;  // one env's thread and hand-over state (place_env.cc)

 private:
  PlaceTask() = default;
  std::vector<std::unique_ptr<Env>> envs_;
};

/// The reward of a finished place episode (the header's rule): `success` by the pipeline,
/// `dxy_m` the centre of mass's horizontal distance from the target, `up_z` the z of the
/// object's up axis (1 upright).
float PlaceEpisodeReward(bool success, double dxy_m, double up_z);

}  // namespace simhuman::learn
