#pragma once
/// `simhuman plan`: turns a text command into a Chain of Contacts for a scene and prints it.

#include <ostream>
#include <string>

#include "simhuman/app/llm_flags.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/language/planner.h"
#include "simhuman/world/scene.h"

namespace simhuman::app {

/// The flags of `simhuman plan`.
struct PlanFlags {
  std::string scene;                ///< built-in scene name or scene JSON file
  std::string command;              ///< the text command
  std::string planner = "offline";  ///< one of PlannerNames()
  LlmFlags llm;                     ///< --llm-* flags (with --planner llm)
  bool explain = false;             ///< also print one line per step
  std::string out;                  ///< also write the plan JSON here (empty: do not)
};

/// The planner's view of a scene's humans (start pose and posture of each).
language::PlanContext PlanContextFor(const world::SceneSpec& spec,
                                     const core::SceneCatalog& catalog);

/// Plans `command` for the scene with the named planner. Errors: unknown planner
/// (InvalidArgument), and the planner's own (see language/planner.h).
core::StatusOr<language::PlanResult> PlanCommandText(const std::string& planner,
                                                     const LlmFlags& llm,
                                                     const std::string& command,
                                                     const world::SceneSpec& spec,
                                                     const core::SceneCatalog& catalog);

/// Runs the command: prints the plan JSON to `out` (with --explain, then one line per step
/// "step i: <words>"), writes --out if given. On failure one line on `err` and a non-zero exit
/// code: kExitBadInput for unknown or impossible commands, scenes and planners; kExitAmbiguous
/// when the planner asks a clarifying question.
int PlanCommand(const PlanFlags& flags, std::ostream& out, std::ostream& err);

/// Exit code of `simhuman plan` when the command is ambiguous (the question is on stderr).
inline constexpr int kExitAmbiguous = 4;

}  // namespace simhuman::app
