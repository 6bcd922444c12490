#include "simhuman/learn/ppo_config.h"

#include <algorithm>
#include <string>

#include "simhuman/core/field_table.h"
#include "simhuman/learn/tasks.h"

namespace simhuman::learn {
namespace {

using core::NumberRange;
using F = core::Field<PpoConfig>;

// one table drives reading, validation and JSON output; cross-field checks are in Validate()
const core::FieldTable<PpoConfig>& Table() {
  const NumberRange kPositive = NumberRange::Above(0);
  const NumberRange kAtLeast0 = NumberRange::AtLeast(0);
  const NumberRange kAtLeast1 = NumberRange::AtLeast(1);
  const NumberRange kThreads = NumberRange::Closed(1, 64);
  static const core::FieldTable<PpoConfig> kTable(
      "training config",
      {F("task", &PpoConfig::task, "training task").OneOf(TaskNames()),
       F("total_steps", &PpoConfig::total_steps, "env steps of the run").In(kAtLeast1),
       F("num_envs", &PpoConfig::num_envs, "parallel envs").In(NumberRange::Closed(1, 4096)),
       F("threads", &PpoConfig::threads, "env worker threads").In(kThreads),
       F("torch_threads", &PpoConfig::torch_threads, "LibTorch threads while collecting")
           .In(kThreads),
       F("update_torch_threads", &PpoConfig::update_torch_threads,
         "LibTorch threads during the update")
           .In(kThreads),
       F("rollout_chunks", &PpoConfig::rollout_chunks,
         "env chunks inferred and stepped per worker (0: whole batch); at most num_envs")
           .In(kAtLeast0),
       F("physics_solver", &PpoConfig::physics_solver, "MuJoCo solver of the training physics")
           .OneOf({"auto", "newton", "pgs"}),
       F("body_scales", &PpoConfig::body_scales, "humans' length scales spread over the envs")
           .MinItems(1)
           .In(NumberRange::Closed(0.5, 1.5)),
       F("walk_gait", &PpoConfig::walk_gait,
         "walk and carry tasks' reference gait (\"\" the original, or human)"),
       F("carry_grip", &PpoConfig::carry_grip,
         "carry task: the hands grip the box while holding it (agent kind humanoid_grip)"),
       F("carry_held_start_frac", &PpoConfig::carry_held_start_frac,
         "carry task: share of training episodes that start holding the box")
           .In(NumberRange::Closed(0, 1)),
       F("carry_put_down_start_frac", &PpoConfig::carry_put_down_start_frac,
         "carry task: share of training episodes that start part-way into the put-down")
           .In(NumberRange::Closed(0, 1)),
       F("walk_gait_weight", &PpoConfig::walk_gait_weight,
         "walk task: weight of the reward for the legs following the reference gait")
           .In(kAtLeast0),
       F("walk_gait_width", &PpoConfig::walk_gait_width,
         "walk task: that term is exp(-summed squared leg error / this), rad^2")
           .In(kPositive),
       F("walk_foot_slip_weight", &PpoConfig::walk_foot_slip_weight,
         "walk task: weight of the penalty on feet sliding while on the ground")
           .In(kAtLeast0),
       F("walk_route_share", &PpoConfig::walk_route_share,
         "walk task: share of new targets at the end of a random route, steered as in scenes")
           .In(NumberRange::Closed(0, 1)),
       F("seed", &PpoConfig::seed, "run seed"),
       F("rollout_steps", &PpoConfig::rollout_steps, "steps per env per iteration").In(kAtLeast1),
       F("epochs", &PpoConfig::epochs, "PPO epochs per iteration").In(kAtLeast1),
       F("minibatches", &PpoConfig::minibatches, "minibatches per epoch").In(kAtLeast1),
       F("lr", &PpoConfig::lr, "Adam learning rate").In(kPositive),
       F("lr_final_frac", &PpoConfig::lr_final_frac, "final lr as a fraction of lr")
           .In(NumberRange::Closed(0, 1)),
       F("gamma", &PpoConfig::gamma, "discount").In(NumberRange::AboveUpTo(0, 1)),
       F("lambda", &PpoConfig::lambda, "GAE lambda").In(NumberRange::Closed(0, 1)),
       F("clip", &PpoConfig::clip, "PPO ratio clip").In(kPositive),
       F("value_clip", &PpoConfig::value_clip, "value clip around the old prediction")
           .In(kPositive),
       F("value_coef", &PpoConfig::value_coef, "value loss weight"),
       F("entropy_coef", &PpoConfig::entropy_coef, "entropy bonus weight"),
       F("max_grad_norm", &PpoConfig::max_grad_norm, "gradient norm clip").In(kPositive),
       F("target_kl", &PpoConfig::target_kl,
         "epochs stop once a minibatch's approximate KL exceeds 1.5x this (0: off)")
           .In(kAtLeast0),
       F("init_std", &PpoConfig::init_std, "initial action std dev").In(kPositive),
       F("hidden", &PpoConfig::hidden, "actor layer widths").MinItems(1).In(kAtLeast1),
       F("critic_hidden", &PpoConfig::critic_hidden,
         "value network layer widths (empty: as hidden)")
           .In(kAtLeast1),
       F("checkpoint_every_s", &PpoConfig::checkpoint_every_s, "wall seconds between checkpoints"),
       F("max_bad_updates", &PpoConfig::max_bad_updates,
         "non-finite updates in a row before aborting")
           .In(kAtLeast1),
       F("curriculum_max_steps", &PpoConfig::curriculum_max_steps,
         "env steps at one curriculum level before it rises (0: only on success)"),
       F("init_from", &PpoConfig::init_from, "policy file to start from (empty: random)"),
       F("critic_warmup_iters", &PpoConfig::critic_warmup_iters,
         "value-only iterations after init_from")
           .In(kAtLeast0),
       F("amp_clips", &PpoConfig::amp_clips, "AMP clip files (.clip.json or .bvh)").NonEmpty(),
       F("amp_task_weight", &PpoConfig::amp_task_weight, "AMP task reward weight").In(kAtLeast0),
       F("amp_style_weight", &PpoConfig::amp_style_weight, "AMP style reward weight").In(kAtLeast0),
       F("amp_grad_penalty", &PpoConfig::amp_grad_penalty, "discriminator gradient penalty")
           .In(kAtLeast0),
       F("amp_disc_hidden", &PpoConfig::amp_disc_hidden, "discriminator layer widths")
           .MinItems(1)
           .In(kAtLeast1),
       F("amp_disc_lr", &PpoConfig::amp_disc_lr, "discriminator learning rate").In(kPositive),
       F("amp_disc_batch", &PpoConfig::amp_disc_batch, "pairs per discriminator minibatch")
           .In(kAtLeast1),
       F("amp_disc_updates", &PpoConfig::amp_disc_updates,
         "discriminator minibatches per iteration")
           .In(kAtLeast1),
       F("amp_replay_size", &PpoConfig::amp_replay_size,
         "agent pairs kept for the discriminator; at least amp_disc_batch")});
  return kTable;
}

}  // namespace

absl::Status PpoConfig::Validate() const {
  SH_RETURN_IF_ERROR(Table().Validate(*this));
  if (physics_solver == "pgs" && !TaskHasSolverChoice(task)) {
    return absl::InvalidArgumentError("training config: physics_solver '" + physics_solver +
                                      "' applies to the walk task only; task is '" + task + "'");
  }
  if (!TaskHasBodyScales(task) &&
      std::any_of(body_scales.begin(), body_scales.end(), [](double s) { return s != 1.0; })) {
    return absl::InvalidArgumentError(
        "training config: body_scales other than [1] apply to the walk task only; task is '" +
        task + "'");
  }
  // AMP compares the agent's motion with the clips in metres and seconds; a scaled body's
  // transitions are not Froude-normalised to the clips' adult, so the discriminator would
  // judge size instead of style
  if (!amp_clips.empty() &&
      std::any_of(body_scales.begin(), body_scales.end(), [](double s) { return s != 1.0; })) {
    return absl::InvalidArgumentError(
        "training config: body_scales other than [1] cannot be combined with amp_clips (AMP's "
        "clips are one adult's motion, not scaled to the bodies); drop one of the two");
  }
  if (absl::Status s = CheckWalkGaitTask(task, walk_gait); !s.ok()) {
    return core::Annotate(s, "training config");
  }
  if (carry_grip && !TaskIsCarry(task)) {
    return absl::InvalidArgumentError(
        "training config: carry_grip applies to the carry tasks only; task is '" + task + "'");
  }
  const PpoConfig defaults;
  if (task != "carry" && carry_held_start_frac != defaults.carry_held_start_frac) {
    return absl::InvalidArgumentError(
        "training config: carry_held_start_frac applies to the carry task only; task is '" + task +
        "'");
  }
  if (task != "carry" && carry_put_down_start_frac != defaults.carry_put_down_start_frac) {
    return absl::InvalidArgumentError(
        "training config: carry_put_down_start_frac applies to the carry task only; task is '" +
        task + "'");
  }
  if (!TaskHasBodyScales(task) && (walk_gait_weight != defaults.walk_gait_weight ||
                                   walk_gait_width != defaults.walk_gait_width ||
                                   walk_foot_slip_weight != defaults.walk_foot_slip_weight ||
                                   walk_route_share != defaults.walk_route_share)) {
    return absl::InvalidArgumentError(
        "training config: walk_gait_weight, walk_gait_width, walk_foot_slip_weight and "
        "walk_route_share apply to the walk task only; task is '" +
        task + "'");
  }
  if (static_cast<int>(body_scales.size()) > num_envs) {
    return absl::InvalidArgumentError(
        "training config 'body_scales' has " + std::to_string(body_scales.size()) +
        " entries; it may have at most num_envs (" + std::to_string(num_envs) + ")");
  }
  if (rollout_chunks > num_envs) {
    return absl::InvalidArgumentError(
        "training config 'rollout_chunks' = " + std::to_string(rollout_chunks) +
        " is invalid; it must not exceed num_envs (" + std::to_string(num_envs) + ")");
  }
  if (static_cast<int64_t>(num_envs) * rollout_steps < minibatches) {
    return absl::InvalidArgumentError(
        "training config: num_envs x rollout_steps (" + std::to_string(num_envs) + " x " +
        std::to_string(rollout_steps) + ") must be at least minibatches (" +
        std::to_string(minibatches) + ")");
  }
  if (amp_replay_size < amp_disc_batch) {
    return absl::InvalidArgumentError(
        "training config 'amp_replay_size' = " + std::to_string(amp_replay_size) +
        " is invalid; it must be at least amp_disc_batch (" + std::to_string(amp_disc_batch) + ")");
  }
  return absl::OkStatus();
}

nlohmann::json PpoConfig::ToJson() const { return Table().ToJson(*this); }

core::StatusOr<PpoConfig> PpoConfig::FromCheckpointJson(const nlohmann::json& j) {
  SH_ASSIGN_OR_RETURN(PpoConfig c, FromJson(j));
  if (!j.contains("critic_hidden")) c.critic_hidden.clear();
  return c;
}

const std::vector<std::string>& PpoConfig::ResumableKeys() {
  static const std::vector<std::string> keys = {
      "curriculum_max_steps",  "lr",
      "lr_final_frac",         "target_kl",
      "entropy_coef",          "checkpoint_every_s",
      "carry_held_start_frac", "carry_put_down_start_frac",
      "max_bad_updates",       "walk_route_share"};
  return keys;
}

core::StatusOr<PpoConfig> PpoConfig::WithResumeChanges(const nlohmann::json& stored,
                                                       const nlohmann::json& changes) {
  if (!changes.is_object()) {
    return absl::InvalidArgumentError(
        "training config changes for a resumed run: not a JSON object of config keys");
  }
  const std::vector<std::string>& ok = ResumableKeys();
  nlohmann::json j = stored;
  for (const auto& [key, value] : changes.items()) {
    if (std::find(ok.begin(), ok.end(), key) == ok.end()) {
      std::string valid;
      for (const std::string& k : ok) valid += (valid.empty() ? "" : ", ") + k;
      return absl::InvalidArgumentError("training config '" + key +
                                        "' cannot change in a resumed run; valid: " + valid);
    }
    j[key] = value;
  }
  return FromCheckpointJson(j);
}

core::StatusOr<PpoConfig> PpoConfig::FromJson(const nlohmann::json& j) {
  PpoConfig c;
  SH_RETURN_IF_ERROR(Table().Read(j, "/", &c));
  SH_RETURN_IF_ERROR(c.Validate());
  return c;
}

}  // namespace simhuman::learn
