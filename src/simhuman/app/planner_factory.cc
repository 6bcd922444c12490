#include "simhuman/app/planner_factory.h"

#include <functional>
#include <utility>

#include "simhuman/language/llm_planner.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::app {
namespace {

using Factory = std::function<core::StatusOr<std::unique_ptr<language::Planner>>(const LlmFlags&)>;

// the LLM planner together with the offline planner it may fall back to (owned here, so the
// fallback pointer stays valid for the LLM planner's life)
class LlmWithFallback : public language::Planner {
 public:
  static core::StatusOr<std::unique_ptr<language::Planner>> Create(const LlmFlags& flags) {
    auto p = std::unique_ptr<LlmWithFallback>(new LlmWithFallback());
    p->offline_ = std::make_unique<language::OfflinePlanner>();
    SH_ASSIGN_OR_RETURN(language::LlmPlannerOptions options,
                        LlmOptionsFromFlags(flags, p->offline_.get()));
    SH_ASSIGN_OR_RETURN(p->llm_, language::LlmPlanner::Create(std::move(options)));
    return std::unique_ptr<language::Planner>(std::move(p));
  }
  core::StatusOr<language::PlanResult> Plan(std::string_view command,
                                            const language::PlanContext& context) override {
    return llm_->Plan(command, context);
  }
  std::string name() const override { return llm_->name(); }

 private:
  LlmWithFallback() = default;
  std::unique_ptr<language::OfflinePlanner> offline_;
  std::unique_ptr<language::LlmPlanner> llm_;
};

// one line per planner
const std::vector<std::pair<std::string, Factory>>& Planners() {
  static const auto* planners = new std::vector<std::pair<std::string, Factory>>{
      {"offline",
       [](const LlmFlags&) -> core::StatusOr<std::unique_ptr<language::Planner>> {
         return std::make_unique<language::OfflinePlanner>();
       }},
      {"llm", &LlmWithFallback::Create},
  };
  return *planners;
}

}  // namespace

std::vector<std::string> PlannerNames() {
  std::vector<std::string> out;
  for (const auto& [name, make] : Planners()) out.push_back(name);
  return out;
}

core::StatusOr<std::unique_ptr<language::Planner>> MakePlanner(const std::string& name,
                                                               const LlmFlags& llm) {
  for (const auto& [n, make] : Planners()) {
    if (n == name) return make(llm);
  }
  return absl::InvalidArgumentError("--planner: unknown planner '" + name +
                                    "'; valid planners are: " + core::JoinNames(PlannerNames()));
}

}  // namespace simhuman::app
