#pragma once
/// Rewrites of the offline planner before clauses are planned: a few typing slips corrected
/// against the known vocabulary ("armchiar", "teh"), and clauses that only make sense with their
/// neighbour ("grab the ball with your left hand, then put it on the box" is one pick and place;
/// "sit down, then type" sits at the laptop).

#include <string>
#include <vector>

#include "simhuman/language/offline/clauses.h"
#include "simhuman/language/offline/common.h"

namespace simhuman::language::offline {

/// Optimal string alignment distance (insertions, deletions, substitutions and transpositions
/// of neighbours each cost 1).
int EditDistance(const std::string& a, const std::string& b);

/// Replaces each unknown word of `raw` (tokenized, not normalised) by the one object, part,
/// colour or function word it is a slip of: a swap of two neighbouring letters (3+ letters),
/// one other edit (5+ letters) or two edits (8+ letters). A word with several such corrections,
/// or with a digit (an object id), is kept.
Tokens CorrectTypos(const Tokens& raw);

/// Joins "grab/pick up A [with your H hand]" and a following "put it REL B" into one "put A REL
/// B with your H hand"; a bare "sit" before "type" becomes "sit at the keyboard" (the seat at
/// the laptop).
void JoinClauses(std::vector<ClauseWords>& clauses);

}  // namespace simhuman::language::offline
