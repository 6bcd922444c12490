#pragma once
/// The LLM planner: turns a command into a Chain of Contacts by asking a language model behind an
/// OpenAI-compatible chat-completions endpoint (llama.cpp's server, Ollama, vLLM, hosted APIs),
/// with the prompt of UniHSI's Table 4 built from the scene (prompt.h). The reply is only ever
/// treated as a plan: it is extracted (reply_extract.h), parsed strictly, and grounded against
/// the scene; a rejected reply is sent back with the errors for at most `max_repair_rounds`
/// rounds. The result is grounded or an error, never an ungrounded plan. No MuJoCo here.

#include <memory>
#include <string>
#include <string_view>

#include "simhuman/core/status.h"
#include "simhuman/language/http_chat_client.h"
#include "simhuman/language/planner.h"
#include "simhuman/language/prompt.h"

namespace simhuman::language {

/// Settings of LlmPlanner. Validate() names the field at fault and its valid range.
struct LlmPlannerOptions {
  /// The chat client's settings: URL ("/chat/completions" is appended), model (required),
  /// per-attempt timeout, retries and backoff, reply size cap, temperature (0 for repeatable
  /// plans) and token budget. `chat.api_key` must stay empty: the key comes from the variable
  /// named by `api_key_env`, so it is never kept in (or written out with) the options.
  ChatClientOptions chat;
  /// Name of the environment variable holding the API key (read at each Plan() call; unset or
  /// empty: no Authorization header). The key is never logged or put in a status message.
  std::string api_key_env = "SIMHUMAN_LLM_API_KEY";
  int max_repair_rounds = 2;        ///< rejected replies sent back with their errors; 0..5
  size_t max_command_bytes = 2000;  ///< a longer command is InvalidArgument
  /// Folder with system.txt, user.txt and repair.txt.
  std::string template_dir = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/prompts";
  /// Planner used when the LLM fails (backend error, or no valid plan after the repair rounds);
  /// not owned, must outlive the LlmPlanner; nullptr: no fallback. Input errors of our own
  /// (an over-long command, a missing scene) never fall back.
  Planner* fallback = nullptr;

  /// OK, or InvalidArgument starting with the field name: "chat.<field>: ..." for the chat
  /// client's settings (ChatClientOptions::Validate()), else e.g. "max_repair_rounds: ...".
  core::Status Validate() const;
};

/// When LlmPlanner used its fallback planner, the first explanation line starts with this text,
/// then the LLM's failure reason in parentheses, then the fallback's own first line.
inline constexpr std::string_view kFallbackNote = "[LLM planner failed; fallback planner used]";

/// A Planner backed by a chat-completions server. Thread-compatible: one Plan() at a time.
class LlmPlanner : public Planner {
 public:
  /// Validates `options` and loads the prompt templates; errors name the field or the file.
  static core::StatusOr<std::unique_ptr<LlmPlanner>> Create(LlmPlannerOptions options);

  /// Asks the model for a plan of `command` in `context.scene` and grounds it.
  /// Errors (all prefixed "llm planner: "):
  /// - InvalidArgument: a command longer than max_command_bytes, a missing scene, or no valid
  ///   plan after max_repair_rounds repair rounds (the last parse or grounding error, naming the
  ///   JSON pointer and listing the scene's valid names);
  /// - Unavailable / DeadlineExceeded: the server failed (see HttpChatClient::Complete()).
  /// With a fallback planner, LLM failures return the fallback's result instead (its error, if
  /// it fails too); its first explanation line is prefixed with kFallbackNote and the LLM's
  /// reason, so the explanation stays one line per step. last_fallback_reason() tells too.
  core::StatusOr<PlanResult> Plan(std::string_view command, const PlanContext& context) override;

  std::string name() const override { return "llm"; }

  /// The chat messages of the first request for `command` (for tests and --explain). Does not
  /// contact the server.
  core::StatusOr<std::vector<ChatMessage>> BuildMessages(std::string_view command,
                                                         const PlanContext& context) const;

  /// Why the last Plan() used the fallback planner; empty when it did not.
  const std::string& last_fallback_reason() const { return last_fallback_reason_; }
  /// Number of chat requests the last Plan() sent (1 + repair rounds used).
  int last_requests() const { return last_requests_; }

 private:
  LlmPlanner(LlmPlannerOptions options, PromptTemplates templates);
  core::StatusOr<PlanResult> PlanWithLlm(std::string_view command, const PlanContext& context);

  LlmPlannerOptions options_;
  PromptTemplates templates_;
  std::string last_fallback_reason_;
  int last_requests_ = 0;
};

/// One line in words for a grounded step: its label when it has one, else generated from the
/// pairs ("pelvis contact seat surface of chair000 (up)"; "get close to chair000 (front)").
std::string ExplainStep(const plan::ContactStep& step);

}  // namespace simhuman::language
