#pragma once
/// The planners `simhuman plan` and `simhuman run --command` can use, by name.

#include <memory>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/language/planner.h"

namespace simhuman::app {

/// Names accepted by --planner, in the order listed in help and errors ("offline", ...).
std::vector<std::string> PlannerNames();

/// A new planner called `name`. InvalidArgument naming --planner and listing PlannerNames()
/// for an unknown name.
core::StatusOr<std::unique_ptr<language::Planner>> MakePlanner(const std::string& name);

}  // namespace simhuman::app
