#include "simhuman/app/planner_factory.h"

#include <functional>
#include <utility>

#include "simhuman/language/offline_planner.h"

namespace simhuman::app {
namespace {

using Factory = std::function<std::unique_ptr<language::Planner>()>;

// one line per planner
const std::vector<std::pair<std::string, Factory>>& Planners() {
  static const auto* planners = new std::vector<std::pair<std::string, Factory>>{
      {"offline", [] { return std::make_unique<language::OfflinePlanner>(); }},
  };
  return *planners;
}

}  // namespace

std::vector<std::string> PlannerNames() {
  std::vector<std::string> out;
  for (const auto& [name, make] : Planners()) out.push_back(name);
  return out;
}

core::StatusOr<std::unique_ptr<language::Planner>> MakePlanner(const std::string& name) {
  for (const auto& [n, make] : Planners()) {
    if (n == name) return make();
  }
  return absl::InvalidArgumentError("--planner: unknown planner '" + name +
                                    "'; valid planners are: " + core::JoinNames(PlannerNames()));
}

}  // namespace simhuman::app
