#pragma once
/// The registry of multi-agent training tasks by name (MappoConfig::task). A new team task
/// adds one entry in multi_agent_tasks.cc.

#include <memory>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/learn/multi_agent_env.h"

namespace simhuman::learn {

/// The registered task names, e.g. "team_carry".
std::vector<std::string> MultiAgentTaskNames();

/// Builds task `name` with `num_envs` envs of `num_agents` agents. InvalidArgument naming the
/// task and listing the valid names (or the valid team sizes).
core::StatusOr<std::unique_ptr<MultiAgentVecTask>> MakeMultiAgentTask(const std::string& name,
                                                                      int num_envs, int num_agents);

}  // namespace simhuman::learn
