#include "simhuman/language/llm_planner.h"

#include <cctype>
#include <cstdlib>
#include <map>
#include <utility>

#include "simhuman/language/reply_extract.h"
#include "simhuman/plan/validate.h"

namespace simhuman::language {
namespace {

constexpr std::string_view kReplySource = "llm reply";
constexpr int kMaxRepairRounds = 5;
constexpr size_t kMaxLabelChars = 200;
constexpr size_t kMaxExplainChars = 1000;
constexpr size_t kMaxEchoedReplyBytes = 8192;  // of a rejected reply, sent back for repair
constexpr size_t kMaxErrorChars = 2000;        // of the errors sent back for repair

core::Status Prefixed(const core::Status& s) { return core::Annotate(s, "llm planner"); }

// text from the model shown to a user: printable, one line, bounded
std::string Printable(std::string_view text, size_t max_chars) {
  std::string out;
  for (char c : text) {
    if (out.size() >= max_chars) break;
    unsigned char u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u == 0x7f) ? ' ' : c;
  }
  return out;
}

bool IsValidEnvName(const std::string& name) {
  if (name.empty()) return true;
  if (std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

// {"steps": []}: the model says it has no plan (rule 7 of the system prompt)
bool IsEmptyPlan(const nlohmann::json& j) {
  return j.is_object() && j.size() == 1 && j.contains("steps") && j["steps"].is_array() &&
         j["steps"].empty();
}

}  // namespace

core::Status LlmPlannerOptions::Validate() const {
  // the chat client names its own field ("timeout_s: ..."); the path from here adds "chat."
  if (core::Status s = chat.Validate(); !s.ok()) {
    return core::Status(s.code(), "chat." + std::string(s.message()));
  }
  if (!chat.api_key.empty()) {
    return absl::InvalidArgumentError(
        "chat.api_key: must be empty; put the key in the environment variable named by "
        "api_key_env (now '" +
        Preview(api_key_env) + "')");
  }
  if (!IsValidEnvName(api_key_env)) {
    return absl::InvalidArgumentError("api_key_env: '" + Preview(api_key_env) +
                                      "' is not an environment variable name (letters, digits "
                                      "and '_', not starting with a digit), e.g. "
                                      "SIMHUMAN_LLM_API_KEY");
  }
  if (max_repair_rounds < 0 || max_repair_rounds > kMaxRepairRounds) {
    return absl::InvalidArgumentError("max_repair_rounds: must be in [0, " +
                                      std::to_string(kMaxRepairRounds) + "], got " +
                                      std::to_string(max_repair_rounds));
  }
  if (max_command_bytes < 1 || max_command_bytes > 100000) {
    return absl::InvalidArgumentError("max_command_bytes: must be in [1, 100000], got " +
                                      std::to_string(max_command_bytes));
  }
  if (template_dir.empty()) {
    return absl::InvalidArgumentError(
        "template_dir: a folder with system.txt, user.txt and "
        "repair.txt is required, e.g. assets/prompts");
  }
  return absl::OkStatus();
}

LlmPlanner::LlmPlanner(LlmPlannerOptions options, PromptTemplates templates)
    : options_(std::move(options)), templates_(std::move(templates)) {}

core::StatusOr<std::unique_ptr<LlmPlanner>> LlmPlanner::Create(LlmPlannerOptions options) {
  SH_RETURN_IF_ERROR(Prefixed(options.Validate()));
  core::StatusOr<PromptTemplates> templates = LoadPromptTemplates(options.template_dir);
  if (!templates.ok()) return Prefixed(templates.status());
  return std::unique_ptr<LlmPlanner>(new LlmPlanner(std::move(options), *std::move(templates)));
}

core::StatusOr<std::vector<ChatMessage>> LlmPlanner::BuildMessages(
    std::string_view command, const PlanContext& context) const {
  if (context.scene == nullptr) {
    return absl::InvalidArgumentError("llm planner: no scene given (PlanContext::scene is null)");
  }
  if (command.size() > options_.max_command_bytes) {
    return absl::InvalidArgumentError(
        "llm planner: the command is " + std::to_string(command.size()) +
        " bytes long; the limit is " + std::to_string(options_.max_command_bytes) +
        " bytes (max_command_bytes); split it into shorter commands");
  }
  if (command.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return absl::InvalidArgumentError(
        "llm planner: the command is empty; say what the human "
        "should do, e.g. \"sit on the chair\"");
  }
  std::map<std::string, std::string> values = DescribeScene(*context.scene, context.agents);
  values["command"] = QuoteCommand(command);
  const std::string& dir = options_.template_dir;
  std::vector<ChatMessage> messages;
  core::StatusOr<std::string> system = FillTemplate(templates_.system, values, dir + "/system.txt");
  if (!system.ok()) return Prefixed(system.status());
  core::StatusOr<std::string> user = FillTemplate(templates_.user, values, dir + "/user.txt");
  if (!user.ok()) return Prefixed(user.status());
  messages.push_back({"system", *std::move(system)});
  messages.push_back({"user", *std::move(user)});
  return messages;
}

core::StatusOr<PlanResult> LlmPlanner::Plan(std::string_view command, const PlanContext& context) {
  last_fallback_reason_.clear();
  last_requests_ = 0;
  // our own input errors never fall back
  SH_RETURN_IF_ERROR(BuildMessages(command, context).status());
  core::StatusOr<PlanResult> result = PlanWithLlm(command, context);
  if (result.ok() || options_.fallback == nullptr) return result;

  last_fallback_reason_ = std::string(result.status().message());
  core::StatusOr<PlanResult> fallback = options_.fallback->Plan(command, context);
  if (!fallback.ok()) return fallback.status();
  std::string note = std::string(kFallbackNote) + " (" + last_fallback_reason_ + ")";
  if (fallback->explanation.empty()) {
    fallback->explanation.push_back(note);
  } else {
    fallback->explanation[0] = note + " " + fallback->explanation[0];
  }
  return fallback;
}

core::StatusOr<PlanResult> LlmPlanner::PlanWithLlm(std::string_view command,
                                                   const PlanContext& context) {
  SH_ASSIGN_OR_RETURN(std::vector<ChatMessage> messages, BuildMessages(command, context));
  ChatClientOptions copts = options_.chat;
  if (!options_.api_key_env.empty()) {
    if (const char* key = std::getenv(options_.api_key_env.c_str())) copts.api_key = key;
  }
  HttpChatClient client(std::move(copts));

  std::string last_error;
  for (int round = 0; round <= options_.max_repair_rounds; ++round) {
    ++last_requests_;
    core::StatusOr<std::string> reply = client.Complete(messages);
    if (!reply.ok()) return Prefixed(reply.status());

    // the reply is only ever read as a plan: extract, parse strictly, ground
    core::Status error;
    core::StatusOr<nlohmann::json> json = ExtractPlanJson(*reply);
    if (json.ok() && IsEmptyPlan(*json)) {
      return absl::InvalidArgumentError(
          "llm planner: the model found no plan for this command in this scene (it replied with "
          "an empty plan); the scene has objects: " +
          core::JoinNames(context.scene->ObjectIds()));
    }
    if (json.ok()) {
      core::StatusOr<plan::ContactChain> chain = plan::ParseContactChainJson(*json, kReplySource);
      if (chain.ok()) {
        error = plan::ValidateAndGround(*chain, *context.scene);
        if (error.ok()) {
          PlanResult result;
          result.chain = *std::move(chain);
          result.chain.source = "llm:" + options_.chat.model;
          for (const plan::ContactStep& step : result.chain.steps) {
            result.explanation.push_back(ExplainStep(step));
          }
          return result;
        }
      } else {
        error = chain.status();
      }
    } else {
      error = json.status();
    }
    last_error = std::string(error.message());
    if (round == options_.max_repair_rounds) break;

    // send the errors back for a repair round
    std::map<std::string, std::string> values = DescribeScene(*context.scene, context.agents);
    values["command"] = QuoteCommand(command);
    values["errors"] = last_error.substr(0, kMaxErrorChars);
    core::StatusOr<std::string> repair =
        FillTemplate(templates_.repair, values, options_.template_dir + "/repair.txt");
    if (!repair.ok()) return Prefixed(repair.status());
    messages.push_back({"assistant", reply->substr(0, kMaxEchoedReplyBytes)});
    messages.push_back({"user", *std::move(repair)});
  }
  return absl::InvalidArgumentError("llm planner: no valid plan from the model after " +
                                    std::to_string(options_.max_repair_rounds) + " repair round" +
                                    (options_.max_repair_rounds == 1 ? "" : "s") +
                                    "; last error: " + last_error);
}

std::string ExplainStep(const plan::ContactStep& step) {
  if (!step.label.empty()) return Printable(step.label, kMaxLabelChars);
  std::string out;
  for (const plan::ContactPair& p : step.pairs) {
    if (!out.empty()) out += "; ";
    if (p.agent != 0) out += "human " + std::to_string(p.agent) + ": ";
    if (p.IsGetClose()) {
      out += "get close to " + p.object + " (" + std::string(plan::DirectionName(p.direction)) +
             " side)";
      continue;
    }
    std::string target = p.part_joint ? p.part : p.part + " of " + p.object;
    out += std::string(core::BodyJointName(*p.joint)) + " " +
           std::string(plan::ContactTypeName(p.type)) + " " + target + " (" +
           std::string(plan::DirectionName(p.direction)) + ")";
  }
  return Printable(out, kMaxExplainChars);
}

}  // namespace simhuman::language
