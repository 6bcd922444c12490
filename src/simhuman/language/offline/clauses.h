#pragma once
/// Clause dispatch of the offline planner: a command's bytes become lower-case words, the words
/// are split into clauses, and Session::Clause() (clauses.cc) hands each clause to its verb
/// handler.

#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/language/offline/common.h"

namespace simhuman::language::offline {

/// Splits a command into lower-case words. Letters and digits form words; apostrophes are
/// dropped ("don't" -> "dont"); spaces, tabs, newlines, '-', '_' and '/' separate words; each
/// of , . ; ! ? : > (an arrow "->") becomes the clause separator "then". kInvalidArgument for a
/// command longer than kMaxCommandBytes or any other byte (the message names it and its offset).
core::StatusOr<Tokens> Tokenize(std::string_view command);

/// Commands written as code, as words (code_text.cc): "sit(chair000)" -> "sit chair000",
/// "armchair004.sit()" -> "sit armchair004", "touch(box004.top, hand='left')" -> "touch the top
/// of box004 with left hand", {"action": "sit", "hands": "stomach"} -> "sit, hands on stomach",
/// a loop over ['walk X', 'sit X'] -> "walk X, then sit X". Other text is returned unchanged.
std::string CodeToWords(std::string_view command);

/// One clause and how it was joined to the one before.
struct ClauseWords {
  Tokens words;
  bool sequenced = true;  // after "then", a comma or a full stop; false after a bare "and"
};

/// Splits normalised words into clauses at "then" and "and" (dropping empty clauses).
/// kInvalidArgument when there are more than kMaxClauses.
core::StatusOr<std::vector<ClauseWords>> SplitMarkedClauses(const Tokens& tokens);
/// Whether a clause is chatter to drop: no word of it is known or an object id (a vocative, a
/// label, "good job"), or it describes the scene ("there are boxes on the table").
bool IsChatter(const Tokens& words, const core::SceneCatalog& scene);

/// SplitMarkedClauses() without the joins.
core::StatusOr<std::vector<Tokens>> SplitClauses(const Tokens& tokens);

}  // namespace simhuman::language::offline
