#include "simhuman/learn/multi_agent_tasks.h"

#include <functional>

#include "simhuman/learn/team_carry_env.h"

namespace simhuman::learn {
namespace {

struct Entry {
  const char* name;
  int min_agents, max_agents;
  std::function<std::unique_ptr<MultiAgentVecTask>(int envs, int agents)> make;
};

const std::vector<Entry>& Registry() {
  static const std::vector<Entry> r = {
      {"team_carry", 2, 8,
       [](int envs, int agents) { return std::make_unique<TeamCarryTask>(envs, agents); }},
  };
  return r;
}

}  // namespace

std::vector<std::string> MultiAgentTaskNames() {
  std::vector<std::string> names;
  for (const Entry& e : Registry()) names.push_back(e.name);
  return names;
}

core::StatusOr<std::unique_ptr<MultiAgentVecTask>> MakeMultiAgentTask(const std::string& name,
                                                                      int num_envs,
                                                                      int num_agents) {
  for (const Entry& e : Registry()) {
    if (name != e.name) continue;
    if (num_agents < e.min_agents || num_agents > e.max_agents) {
      return absl::InvalidArgumentError(
          "task '" + name + "' takes " + std::to_string(e.min_agents) + " to " +
          std::to_string(e.max_agents) + " agents, not " + std::to_string(num_agents));
    }
    return e.make(num_envs, num_agents);
  }
  std::string valid;
  for (const std::string& n : MultiAgentTaskNames()) valid += (valid.empty() ? "" : ", ") + n;
  return absl::InvalidArgumentError("unknown multi-agent task '" + name + "'; valid: " + valid);
}

}  // namespace simhuman::learn
