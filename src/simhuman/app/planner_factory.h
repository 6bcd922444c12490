#pragma once
/// The planners `simhuman plan` and `simhuman run --command` can use, by name.

#include <memory>
#include <string>
#include <vector>

#include "simhuman/app/llm_flags.h"
#include "simhuman/core/status.h"
#include "simhuman/language/planner.h"

namespace simhuman::app {

/// Names accepted by --planner, in the order listed in help and errors ("offline", ...).
std::vector<std::string> PlannerNames();

/// A new planner called `name`; `llm` holds the --llm-* flags (used by "llm" only; with
/// --llm-fallback the offline planner takes over when the LLM fails). InvalidArgument naming
/// --planner and listing PlannerNames() for an unknown name, or naming the --llm-* flag at fault.
core::StatusOr<std::unique_ptr<language::Planner>> MakePlanner(const std::string& name,
                                                               const LlmFlags& llm = {});

}  // namespace simhuman::app
