#include "simhuman/learn/ppo_config.h"

#include <string>

namespace simhuman::learn {

absl::Status PpoConfig::Validate() const {
  if (task != "walk" && task != "reach") {
    return absl::InvalidArgumentError("task '" + task + "' is unknown; valid: walk, reach");
  }
  if (total_steps <= 0) return absl::InvalidArgumentError("total_steps must be positive");
  if (num_envs <= 0 || num_envs > 4096)
    return absl::InvalidArgumentError("num_envs must be in [1, 4096]");
  if (threads <= 0 || threads > 64 || torch_threads <= 0 || torch_threads > 64 ||
      update_torch_threads <= 0 || update_torch_threads > 64) {
    return absl::InvalidArgumentError(
        "threads, torch_threads and update_torch_threads must be in [1, 64]");
  }
  if (physics_solver != "auto" && physics_solver != "newton" && physics_solver != "pgs") {
    return absl::InvalidArgumentError("physics_solver '" + physics_solver +
                                      "' is unknown; valid: auto, newton, pgs");
  }
  if (physics_solver == "pgs" && task != "walk") {
    return absl::InvalidArgumentError("physics_solver '" + physics_solver +
                                      "' applies to the walk task only; task is '" + task + "'");
  }
  if (rollout_chunks < 0 || rollout_chunks > num_envs) {
    return absl::InvalidArgumentError("rollout_chunks must be in [0, num_envs]");
  }
  if (critic_warmup_iters < 0) {
    return absl::InvalidArgumentError("critic_warmup_iters must not be negative");
  }
  if (rollout_steps <= 0 || epochs <= 0 || minibatches <= 0) {
    return absl::InvalidArgumentError("rollout_steps, epochs and minibatches must be positive");
  }
  if (static_cast<int64_t>(num_envs) * rollout_steps < minibatches) {
    return absl::InvalidArgumentError("num_envs x rollout_steps must be >= minibatches");
  }
  if (!(lr > 0) || !(lr_final_frac >= 0 && lr_final_frac <= 1)) {
    return absl::InvalidArgumentError("lr must be > 0 and lr_final_frac in [0, 1]");
  }
  if (!(gamma > 0 && gamma <= 1) || !(lambda >= 0 && lambda <= 1)) {
    return absl::InvalidArgumentError("gamma must be in (0, 1] and lambda in [0, 1]");
  }
  if (!(clip > 0) || !(value_clip > 0) || !(max_grad_norm > 0) || !(init_std > 0)) {
    return absl::InvalidArgumentError("clip, value_clip, max_grad_norm, init_std must be > 0");
  }
  if (hidden.empty() || *std::min_element(hidden.begin(), hidden.end()) <= 0) {
    return absl::InvalidArgumentError("hidden must list positive layer widths");
  }
  if (!critic_hidden.empty() &&
      *std::min_element(critic_hidden.begin(), critic_hidden.end()) <= 0) {
    return absl::InvalidArgumentError(
        "critic_hidden must list positive layer widths (or be empty: the same as hidden)");
  }
  if (max_bad_updates <= 0) return absl::InvalidArgumentError("max_bad_updates must be positive");
  if (!(amp_task_weight >= 0) || !(amp_style_weight >= 0) || !(amp_grad_penalty >= 0)) {
    return absl::InvalidArgumentError(
        "amp_task_weight, amp_style_weight and amp_grad_penalty must be >= 0");
  }
  if (amp_disc_hidden.empty() ||
      *std::min_element(amp_disc_hidden.begin(), amp_disc_hidden.end()) <= 0) {
    return absl::InvalidArgumentError("amp_disc_hidden must list positive layer widths");
  }
  if (!(amp_disc_lr > 0) || amp_disc_batch <= 0 || amp_disc_updates <= 0) {
    return absl::InvalidArgumentError(
        "amp_disc_lr, amp_disc_batch and amp_disc_updates must be positive");
  }
  if (amp_replay_size < amp_disc_batch) {
    return absl::InvalidArgumentError("amp_replay_size must be >= amp_disc_batch");
  }
  for (const std::string& c : amp_clips) {
    if (c.empty()) return absl::InvalidArgumentError("amp_clips holds an empty path");
  }
  return absl::OkStatus();
}

nlohmann::json PpoConfig::ToJson() const {
  return nlohmann::json{{"task", task},
                        {"total_steps", total_steps},
                        {"num_envs", num_envs},
                        {"threads", threads},
                        {"torch_threads", torch_threads},
                        {"update_torch_threads", update_torch_threads},
                        {"rollout_chunks", rollout_chunks},
                        {"physics_solver", physics_solver},
                        {"seed", seed},
                        {"rollout_steps", rollout_steps},
                        {"epochs", epochs},
                        {"minibatches", minibatches},
                        {"lr", lr},
                        {"lr_final_frac", lr_final_frac},
                        {"gamma", gamma},
                        {"lambda", lambda},
                        {"clip", clip},
                        {"value_clip", value_clip},
                        {"value_coef", value_coef},
                        {"entropy_coef", entropy_coef},
                        {"max_grad_norm", max_grad_norm},
                        {"init_std", init_std},
                        {"hidden", hidden},
                        {"critic_hidden", critic_hidden},
                        {"checkpoint_every_s", checkpoint_every_s},
                        {"max_bad_updates", max_bad_updates},
                        {"curriculum_max_steps", curriculum_max_steps},
                        {"init_from", init_from},
                        {"critic_warmup_iters", critic_warmup_iters},
                        {"amp_clips", amp_clips},
                        {"amp_task_weight", amp_task_weight},
                        {"amp_style_weight", amp_style_weight},
                        {"amp_grad_penalty", amp_grad_penalty},
                        {"amp_disc_hidden", amp_disc_hidden},
                        {"amp_disc_lr", amp_disc_lr},
                        {"amp_disc_batch", amp_disc_batch},
                        {"amp_disc_updates", amp_disc_updates},
                        {"amp_replay_size", amp_replay_size}};
}

core::StatusOr<PpoConfig> PpoConfig::FromCheckpointJson(const nlohmann::json& j) {
  SH_ASSIGN_OR_RETURN(PpoConfig c, FromJson(j));
  if (!j.contains("critic_hidden")) c.critic_hidden.clear();
  return c;
}

core::StatusOr<PpoConfig> PpoConfig::FromJson(const nlohmann::json& j) {
  if (!j.is_object()) return absl::InvalidArgumentError("training config must be a JSON object");
  PpoConfig c;
  nlohmann::json known = c.ToJson();
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!known.contains(it.key())) {
      return absl::InvalidArgumentError("/" + it.key() + ": unknown training config key");
    }
  }
  try {
    auto get = [&](const char* k, auto& v) {
      if (j.contains(k)) j.at(k).get_to(v);
    };
    get("task", c.task);
    get("total_steps", c.total_steps);
    get("num_envs", c.num_envs);
    get("threads", c.threads);
    get("torch_threads", c.torch_threads);
    get("update_torch_threads", c.update_torch_threads);
    get("rollout_chunks", c.rollout_chunks);
    get("physics_solver", c.physics_solver);
    get("seed", c.seed);
    get("rollout_steps", c.rollout_steps);
    get("epochs", c.epochs);
    get("minibatches", c.minibatches);
    get("lr", c.lr);
    get("lr_final_frac", c.lr_final_frac);
    get("gamma", c.gamma);
    get("lambda", c.lambda);
    get("clip", c.clip);
    get("value_clip", c.value_clip);
    get("value_coef", c.value_coef);
    get("entropy_coef", c.entropy_coef);
    get("max_grad_norm", c.max_grad_norm);
    get("init_std", c.init_std);
    get("hidden", c.hidden);
    get("critic_hidden", c.critic_hidden);
    get("checkpoint_every_s", c.checkpoint_every_s);
    get("max_bad_updates", c.max_bad_updates);
    get("curriculum_max_steps", c.curriculum_max_steps);
    get("init_from", c.init_from);
    get("critic_warmup_iters", c.critic_warmup_iters);
    get("amp_clips", c.amp_clips);
    get("amp_task_weight", c.amp_task_weight);
    get("amp_style_weight", c.amp_style_weight);
    get("amp_grad_penalty", c.amp_grad_penalty);
    get("amp_disc_hidden", c.amp_disc_hidden);
    get("amp_disc_lr", c.amp_disc_lr);
    get("amp_disc_batch", c.amp_disc_batch);
    get("amp_disc_updates", c.amp_disc_updates);
    get("amp_replay_size", c.amp_replay_size);
  } catch (const nlohmann::json::exception& e) {
    return absl::InvalidArgumentError(std::string("training config: ") + e.what());
  }
  SH_RETURN_IF_ERROR(c.Validate());
  return c;
}

}  // namespace simhuman::learn
