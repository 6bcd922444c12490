#include "simhuman/learn/mappo_config.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "simhuman/core/json_io.h"
#include "simhuman/learn/multi_agent_tasks.h"

namespace simhuman::learn {
namespace {

// one table drives validation and JSON io of the numeric keys
struct Field {
  const char* name;
  int MappoConfig::*i;
  int64_t MappoConfig::*l;
  double MappoConfig::*d;
  double lo, hi;
};

const std::vector<Field>& Fields() {
  static const std::vector<Field> f = {
      {"num_agents", &MappoConfig::num_agents, nullptr, nullptr, 1, 64},
      {"total_steps", nullptr, &MappoConfig::total_steps, nullptr, 1, 1e12},
      {"num_envs", &MappoConfig::num_envs, nullptr, nullptr, 1, 4096},
      {"threads", &MappoConfig::threads, nullptr, nullptr, 1, 64},
      {"torch_threads", &MappoConfig::torch_threads, nullptr, nullptr, 1, 64},
      {"rollout_steps", &MappoConfig::rollout_steps, nullptr, nullptr, 1, 100000},
      {"epochs", &MappoConfig::epochs, nullptr, nullptr, 1, 1000},
      {"minibatches", &MappoConfig::minibatches, nullptr, nullptr, 1, 100000},
      {"lr", nullptr, nullptr, &MappoConfig::lr, 1e-9, 1},
      {"lr_final_frac", nullptr, nullptr, &MappoConfig::lr_final_frac, 0, 1},
      {"gamma", nullptr, nullptr, &MappoConfig::gamma, 1e-6, 1},
      {"lambda", nullptr, nullptr, &MappoConfig::lambda, 0, 1},
      {"clip", nullptr, nullptr, &MappoConfig::clip, 1e-6, 10},
      {"value_clip", nullptr, nullptr, &MappoConfig::value_clip, 1e-6, 1e6},
      {"value_coef", nullptr, nullptr, &MappoConfig::value_coef, 0, 1e6},
      {"entropy_coef", nullptr, nullptr, &MappoConfig::entropy_coef, 0, 1e6},
      {"max_grad_norm", nullptr, nullptr, &MappoConfig::max_grad_norm, 1e-9, 1e6},
      {"init_std", nullptr, nullptr, &MappoConfig::init_std, 1e-6, 100},
      {"checkpoint_every_s", nullptr, nullptr, &MappoConfig::checkpoint_every_s, 0, 1e12},
      {"max_bad_updates", &MappoConfig::max_bad_updates, nullptr, nullptr, 1, 1000},
  };
  return f;
}

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double Value(const MappoConfig& c, const Field& f) {
  if (f.i) return c.*(f.i);
  if (f.l) return static_cast<double>(c.*(f.l));
  return c.*(f.d);
}

absl::Status CheckWidths(const std::vector<int>& w, const char* key, bool may_be_empty) {
  bool ok = may_be_empty || !w.empty();
  for (int x : w) ok = ok && x > 0;
  if (ok) return absl::OkStatus();
  return absl::InvalidArgumentError(std::string("mappo config '") + key +
                                    "' must list positive layer widths" +
                                    (may_be_empty ? " (or be empty: the same as hidden)" : ""));
}

std::string Names(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

absl::Status MappoConfig::Validate() const {
  const std::vector<std::string> tasks = MultiAgentTaskNames();
  if (std::find(tasks.begin(), tasks.end(), task) == tasks.end()) {
    return absl::InvalidArgumentError("mappo config 'task' = '" + task +
                                      "' is unknown; valid: " + Names(tasks));
  }
  for (const Field& f : Fields()) {
    double v = Value(*this, f);
    if (!std::isfinite(v) || v < f.lo || v > f.hi) {
      return absl::InvalidArgumentError("mappo config '" + std::string(f.name) + "' = " + Num(v) +
                                        " is invalid; valid range is [" + Num(f.lo) + ", " +
                                        Num(f.hi) + "]");
    }
  }
  SH_RETURN_IF_ERROR(CheckWidths(hidden, "hidden", false));
  SH_RETURN_IF_ERROR(CheckWidths(critic_hidden, "critic_hidden", true));
  if (static_cast<int64_t>(num_envs) * num_agents * rollout_steps < minibatches) {
    return absl::InvalidArgumentError(
        "mappo config: num_envs x num_agents x rollout_steps must be >= minibatches");
  }
  return absl::OkStatus();
}

nlohmann::json MappoConfig::ToJson() const {
  nlohmann::json j{{"task", task},
                   {"seed", seed},
                   {"hidden", hidden},
                   {"critic_hidden", critic_hidden},
                   {"critic_agent_obs", critic_agent_obs}};
  for (const Field& f : Fields()) {
    if (f.i) {
      j[f.name] = this->*(f.i);
    } else if (f.l) {
      j[f.name] = this->*(f.l);
    } else {
      j[f.name] = this->*(f.d);
    }
  }
  return j;
}

core::StatusOr<MappoConfig> MappoConfig::FromJson(const nlohmann::json& j, std::string_view where) {
  const std::string at(where);
  MappoConfig c;
  const nlohmann::json defaults = c.ToJson();
  std::vector<std::string> keys;
  for (auto it = defaults.begin(); it != defaults.end(); ++it) keys.push_back(it.key());
  SH_RETURN_IF_ERROR(core::CheckKeys(j, keys, at.empty() ? "mappo config" : at));
  if (j.contains("task")) {
    SH_ASSIGN_OR_RETURN(c.task, core::GetString(j, "task", at));
  }
  for (const Field& f : Fields()) {
    if (!j.contains(f.name)) continue;
    SH_ASSIGN_OR_RETURN(double v, core::GetNumber(j, f.name, at));
    if (f.d) {
      c.*(f.d) = v;
      continue;
    }
    if (v != std::floor(v) || v < f.lo || v > f.hi) {
      return absl::InvalidArgumentError(at + "/" + f.name + ": " + Num(v) +
                                        " is not an integer in [" + Num(f.lo) + ", " + Num(f.hi) +
                                        "]");
    }
    if (f.i) c.*(f.i) = static_cast<int>(v);
    if (f.l) c.*(f.l) = static_cast<int64_t>(v);
  }
  try {
    if (j.contains("seed")) {
      if (!j.at("seed").is_number_unsigned()) {
        return absl::InvalidArgumentError(at + "/seed: expected a non-negative integer");
      }
      c.seed = j.at("seed").get<uint64_t>();
    }
    for (const char* k : {"hidden", "critic_hidden"}) {
      if (!j.contains(k)) continue;
      const nlohmann::json& w = j.at(k);
      bool ints = w.is_array();
      for (const auto& x : w) ints = ints && x.is_number_integer();
      if (!ints)
        return absl::InvalidArgumentError(at + "/" + k + ": expected an array of integers");
      (std::string(k) == "hidden" ? c.hidden : c.critic_hidden) = w.get<std::vector<int>>();
    }
    if (j.contains("critic_agent_obs")) {
      if (!j.at("critic_agent_obs").is_boolean()) {
        return absl::InvalidArgumentError(at + "/critic_agent_obs: expected true or false");
      }
      c.critic_agent_obs = j.at("critic_agent_obs").get<bool>();
    }
  } catch (const nlohmann::json::exception& e) {
    return absl::InvalidArgumentError(at + ": " + e.what());
  }
  SH_RETURN_IF_ERROR(c.Validate());
  return c;
}

}  // namespace simhuman::learn
