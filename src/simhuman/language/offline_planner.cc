#include "simhuman/language/offline_planner.h"

#include <string>
#include <utility>
#include <vector>

#include "simhuman/language/offline/clauses.h"
#include "simhuman/language/offline/fallback.h"
#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/rewrite.h"
#include "simhuman/language/offline/session.h"

namespace simhuman::language {

std::string DescribeSceneObjects(const core::SceneCatalog& scene) {
  if (scene.objects.empty()) return "no objects";
  std::string out;
  for (const core::CatalogObject& o : scene.objects) {
    if (!out.empty()) out += "; ";
    out += offline::Describe(o) + ": " + offline::PartsText(o);
  }
  return out;
}

namespace {

// the rules: normalised words, clauses, one verb handler per clause
core::StatusOr<PlanResult> PlanByRules(std::string_view command, const PlanContext& context,
                                       offline::Tokens& read) {
  SH_ASSIGN_OR_RETURN(offline::Tokens raw, offline::Tokenize(offline::CodeToWords(command)));
  raw = offline::ReadSpokenForms(offline::ApplyCorrections(raw));
  offline::Tokens tokens = offline::Normalize(offline::CorrectTypos(offline::Reword(raw)));
  read = tokens;
  SH_ASSIGN_OR_RETURN(std::vector<offline::ClauseWords> clauses,
                      offline::SplitMarkedClauses(tokens));
  // chatter (vocatives, labels, "good job", scene descriptions) is dropped unless it is all
  // the command says or follows a bare "and" as a verb would ("sit down and sing")
  std::vector<offline::ClauseWords> kept;
  for (size_t k = 0; k < clauses.size(); ++k) {
    const bool coordinated = k > 0 && !clauses[k].sequenced;
    if (!coordinated && offline::IsChatter(clauses[k].words, *context.scene)) continue;
    kept.push_back(clauses[k]);
  }
  if (!kept.empty()) clauses = std::move(kept);
  offline::JoinClauses(clauses);
  offline::JoinParticipleBase(raw, clauses);
  offline::Session session(*context.scene, context);
  for (const offline::ClauseWords& clause : clauses) {
    session.NextClause(clause.sequenced);
    SH_RETURN_IF_ERROR(session.Clause(clause.words));
  }
  return session.Finish();
}

}  // namespace

core::StatusOr<PlanResult> OfflinePlanner::Plan(std::string_view command,
                                                const PlanContext& context) {
  if (context.scene == nullptr) return offline::Invalid("no scene given to the planner");
  offline::Tokens read;
  core::StatusOr<PlanResult> rules = PlanByRules(command, context, read);
  if (rules.ok()) {
    // a plan that leaves out an object or limb the command names may have misread a clause:
    // the fallback's plan is taken when it leaves out fewer (ambiguity or refusal keeps the rules')
    const int missing = offline::Uncovered(read, *rules, *context.scene);
    if (missing == 0) return rules;
    core::StatusOr<PlanResult> slots = offline::FallbackPlan(command, context);
    if (slots.ok() && offline::Uncovered(read, *slots, *context.scene) < missing) return slots;
    return rules;
  }
  if (rules.status().code() != absl::StatusCode::kInvalidArgument) return rules;
  // what the rules refuse is read again by slots (offline/fallback.h); when that finds no
  // clear meaning either, the rules' answer (what is not understood, what is) stands
  core::StatusOr<PlanResult> slots = offline::FallbackPlan(command, context);
  if (slots.ok() || slots.status().code() == absl::StatusCode::kFailedPrecondition) return slots;
  return rules;
}

}  // namespace simhuman::language
