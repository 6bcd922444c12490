#include "simhuman/learn/tasks.h"

namespace simhuman::learn {

std::vector<std::string> TaskNames() {
  return {"walk",          "reach", "carry",          "carry-lift",
          "carry-deliver", "grasp", "grasp-residual", "place"};
}

bool TaskHasSolverChoice(std::string_view name) { return name == "walk"; }

bool TaskHasBodyScales(std::string_view name) { return name == "walk"; }

bool TaskIsCarry(std::string_view name) {
  return name == "carry" || name == "carry-lift" || name == "carry-deliver";
}

bool TaskHasWalkGait(std::string_view name) { return name == "walk" || TaskIsCarry(name); }

absl::Status CheckWalkGaitTask(std::string_view task, std::string_view gait) {
  if (gait.empty() || TaskHasWalkGait(task)) return absl::OkStatus();
  return absl::InvalidArgumentError("walk_gait '" + std::string(gait) +
                                    "' applies to the walk and carry tasks only; task is '" +
                                    std::string(task) + "'");
}

}  // namespace simhuman::learn
