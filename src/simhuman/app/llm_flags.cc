#include "simhuman/app/llm_flags.h"

#include <array>
#include <string_view>
#include <utility>

namespace simhuman::app {
namespace {

// LlmPlannerOptions field (its path in Validate() messages) -> the flag that sets it, to name the
// flag in errors
constexpr std::array<std::pair<std::string_view, std::string_view>, 4> kFieldFlags = {{
    {"chat.url", "--llm-url"},
    {"chat.model", "--llm-model"},
    {"chat.timeout_s", "--llm-timeout"},
    {"api_key_env", "--llm-key-env"},
}};

}  // namespace

void AddLlmFlags(CLI::App& command, LlmFlags& flags) {
  CLI::Option_group* group = command.add_option_group("LLM planner", "Settings of --planner llm");
  group
      ->add_option("--llm-url", flags.url,
                   "Base URL of an OpenAI-compatible API (llama.cpp server, Ollama, vLLM, ...); "
                   "/chat/completions is appended")
      ->capture_default_str();
  group->add_option("--llm-model", flags.model, "Model name sent to the server (required)");
  group->add_option("--llm-timeout", flags.timeout_s, "Seconds to wait for each reply")
      ->capture_default_str();
  group
      ->add_option("--llm-key-env", flags.key_env,
                   "Environment variable that holds the API key (unset: no key is sent)")
      ->capture_default_str();
  group->add_flag(
      "--llm-fallback", flags.fallback,
      "Use the offline planner when the LLM fails (unreachable, timeout, no valid plan)");
}

core::StatusOr<language::LlmPlannerOptions> LlmOptionsFromFlags(
    const LlmFlags& flags, language::Planner* fallback_planner) {
  language::LlmPlannerOptions options;
  options.chat.url = flags.url;
  options.chat.model = flags.model;
  options.chat.timeout_s = flags.timeout_s;
  options.api_key_env = flags.key_env;
  if (flags.fallback) {
    if (fallback_planner == nullptr) {
      return absl::InvalidArgumentError(
          "--llm-fallback: no fallback planner is available for this command");
    }
    options.fallback = fallback_planner;
  }
  core::Status status = options.Validate();
  if (status.ok()) return options;
  std::string message(status.message());
  for (const auto& [field, flag] : kFieldFlags) {
    std::string prefix = std::string(field) + ": ";
    if (message.compare(0, prefix.size(), prefix) == 0) {
      return core::Status(status.code(), std::string(flag) + ": " + message.substr(prefix.size()));
    }
  }
  return status;  // a field without a flag keeps its default, so this is not expected
}

}  // namespace simhuman::app
