#include "simhuman/learn/tasks.h"

namespace simhuman::learn {

std::vector<std::string> TaskNames() {
  return {"walk", "reach", "carry", "grasp", "grasp-residual"};
}

bool TaskHasSolverChoice(std::string_view name) { return name == "walk"; }

bool TaskHasBodyScales(std::string_view name) { return name == "walk"; }

bool TaskHasWalkGait(std::string_view name) { return name == "walk" || name == "carry"; }

}  // namespace simhuman::learn
