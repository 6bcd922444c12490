#pragma once
/// The command-line flags of the LLM planner (`--planner llm`), shared by the commands that plan
/// from language (`simhuman plan`, later `run --command`): adding them to a CLI11 command and
/// turning them into language::LlmPlannerOptions with errors that name the flag.

#include <CLI/CLI.hpp>
#include <string>

#include "simhuman/core/status.h"
#include "simhuman/language/llm_planner.h"

namespace simhuman::app {

/// Values of the LLM flags; defaults are LlmPlannerOptions' defaults.
struct LlmFlags {
  std::string url = language::LlmPlannerOptions().chat.url;  ///< --llm-url
  std::string model;                                         ///< --llm-model (required with llm)
  double timeout_s = language::LlmPlannerOptions().chat.timeout_s;  ///< --llm-timeout, seconds
  std::string key_env = language::LlmPlannerOptions().api_key_env;  ///< --llm-key-env
  bool fallback = false;  ///< --llm-fallback: use the offline planner when the LLM fails
};

/// Adds --llm-url, --llm-model, --llm-timeout, --llm-key-env and --llm-fallback to `command`
/// in an option group "LLM planner". `flags` receives the values and must outlive parsing.
void AddLlmFlags(CLI::App& command, LlmFlags& flags);

/// The planner options for the parsed `flags`. `fallback_planner` (not owned) becomes
/// LlmPlannerOptions::fallback when --llm-fallback was given. Errors are InvalidArgument and
/// start with the flag at fault, e.g. "--llm-timeout: must be in (0, 3600] seconds, got -1";
/// --llm-fallback without a fallback planner is an error too. The API key itself is never read
/// here (LlmPlanner reads the variable named by --llm-key-env when it plans).
core::StatusOr<language::LlmPlannerOptions> LlmOptionsFromFlags(
    const LlmFlags& flags, language::Planner* fallback_planner);

}  // namespace simhuman::app
