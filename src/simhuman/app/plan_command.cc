#include "simhuman/app/plan_command.h"

#include <fstream>

#include "simhuman/app/common.h"
#include "simhuman/app/planner_factory.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::app {
namespace {

const char kCommand[] = "plan";

}  // namespace

language::PlanContext PlanContextFor(const world::SceneSpec& spec,
                                     const core::SceneCatalog& catalog) {
  language::PlanContext context;
  context.scene = &catalog;
  for (const world::HumanSpec& h : spec.humans) {
    context.agents.push_back({h.pos_xy.x(), h.pos_xy.y(), h.yaw_rad, h.posture});
  }
  return context;
}

core::StatusOr<language::PlanResult> PlanCommandText(const std::string& planner,
                                                     const LlmFlags& llm,
                                                     const std::string& command,
                                                     const world::SceneSpec& spec,
                                                     const core::SceneCatalog& catalog) {
  SH_ASSIGN_OR_RETURN(std::unique_ptr<language::Planner> p, MakePlanner(planner, llm));
  return p->Plan(command, PlanContextFor(spec, catalog));
}

int PlanCommand(const PlanFlags& flags, std::ostream& out, std::ostream& err) {
  core::StatusOr<std::unique_ptr<language::Planner>> planner =
      MakePlanner(flags.planner, flags.llm);
  if (!planner.ok()) return ReportError(err, kCommand, planner.status());
  core::StatusOr<world::SceneSpec> scene = world::LoadScene(flags.scene);
  if (!scene.ok()) return ReportError(err, kCommand, scene.status());
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(*scene);
  if (!catalog.ok()) return ReportError(err, kCommand, catalog.status());
  core::StatusOr<language::PlanResult> result =
      (*planner)->Plan(flags.command, PlanContextFor(*scene, *catalog));
  if (!result.ok()) {
    if (absl::IsFailedPrecondition(result.status())) {
      err << "simhuman plan: " << result.status().message() << std::endl;
      return kExitAmbiguous;
    }
    return ReportError(err, kCommand, result.status());
  }
  const nlohmann::json j = plan::ContactChainToJson(result->chain);
  out << j.dump(2) << std::endl;
  if (flags.explain) {
    for (size_t i = 0; i < result->explanation.size(); ++i) {
      out << "step " << i + 1 << ": " << result->explanation[i] << std::endl;
    }
  }
  if (!flags.out.empty()) {
    std::ofstream file(flags.out);
    file << j.dump(2) << std::endl;
    if (!file) {
      return ReportError(err, kCommand,
                         absl::PermissionDeniedError("--out: cannot write '" + flags.out + "'"));
    }
  }
  return kExitOk;
}

}  // namespace simhuman::app
