#pragma once
/// Language to Chain of Contacts: the interface every planner (offline parser, LLM client)
/// implements. No MuJoCo and no Torch here: planners see the scene only through
/// core::SceneCatalog and the humans' start poses.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::language {

/// Where a simulated human starts, as the planner needs it (to decide whether an object is far
/// and a get-close step must be inserted, or whether a stand-up step is implied).
struct AgentStart {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
  std::string posture = "stand";  // "stand", "sit" or "lie"
};

/// Everything a planner may look at besides the command. `scene` must outlive the call.
struct PlanContext {
  const core::SceneCatalog* scene = nullptr;
  std::vector<AgentStart> agents;  // one per human; empty means one standing human at (0, 0)
};

/// A plan for a command: the grounded chain (ValidateAndGround() passed) plus one line in words
/// per step (what `simhuman plan --explain` prints).
struct PlanResult {
  plan::ContactChain chain;
  std::vector<std::string> explanation;  // same length as chain.steps
};

/// Status codes every planner uses, so callers and the `language` eval suite can tell them
/// apart:
/// - kFailedPrecondition: the command is ambiguous in this scene; the message is a clarifying
///   question that ends in '?' and lists the candidates.
/// - kInvalidArgument: not understood, impossible ("lie on the chair") or names something the
///   scene lacks; the message says what was not understood and what the scene offers.
/// - kUnavailable / kDeadlineExceeded: a backend (LLM server) failed.
class Planner {
 public:
  virtual ~Planner() = default;
  /// Turns one command into a grounded plan. Thread-compatible (one call at a time per
  /// instance). Never throws.
  virtual core::StatusOr<PlanResult> Plan(std::string_view command, const PlanContext& context) = 0;
  /// Short name for logs and result files, e.g. "offline", "llm".
  virtual std::string name() const = 0;
};

}  // namespace simhuman::language
