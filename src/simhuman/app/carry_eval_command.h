#pragma once
/// `simhuman eval --suite carry`: the carrying policy on CooHOI's single-box protocol
/// (learn/carry_eval.h).

#include <ostream>

#include "simhuman/app/eval_command.h"

namespace simhuman::app {

/// Runs the suite with --policy (default assets/policies/carry.pt when it exists): a row per
/// episode, a summary, DIR/episodes.jsonl and DIR/summary.json. kExitBadInput for a missing
/// or wrong policy and bad flags.
int CarryEvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
