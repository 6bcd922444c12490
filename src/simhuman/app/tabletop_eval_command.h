#pragma once
/// `simhuman eval --suite tabletop|place|stack`: DASH's benchmark through the pick-and-place
/// pipeline (eval/tabletop_eval.h).

#include <ostream>

#include "simhuman/app/eval_command.h"

namespace simhuman::app {

/// A row per episode, a summary with the per-stage failure table, DIR/episodes.jsonl and
/// DIR/summary.json. kExitBadInput for bad flags or an unloadable grasp policy.
int TabletopEvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
