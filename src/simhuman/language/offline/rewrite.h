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

/// Rewords raw words (before CorrectTypos and Normalize, phrasing.cc): drops a scripted subject
/// at a clause start ("NPC sits", "then he gets up"), reads third-person and -ing verb forms and
/// chat spellings ("ur", "goto", "chill"), "its/his/her hands" as "your hands", "knees bent up"
/// and "head raised off the pillow" as "... up", "without touching the backrest" as "leaning
/// forward", and drops a trailing purpose clause ("so the foot stays flat").
Tokens Reword(const Tokens& raw);

/// Spoken verb forms on raw words, before Reword (spoken.cc): reflexive placement ("set/put/lay
/// yourself on X", "put yourself seated", "put you on the left side"), causatives ("let your
/// hands rest on", "allow yourself to sink onto", "make both knees high"), "lay the hands on",
/// the intensifier "right" ("lean right back"), encouragement ("go on,", "would you ever"),
/// first-person asides that name no object ("I do hope ...", "I'm afraid ...", "My late husband
/// ..."), "there" after a named object, a verbless "over to X", "hold it/that" (keep the pose),
/// "until done", a recipe's "leave to rest ...", passives ("is then seated on", "the chair is
/// walked to", "after which"), ", where it types", and an object as the subject of its own
/// placing ("the ball goes on the box", "the block wants to sit on the cylinder": put).
Tokens ReadSpokenForms(const Tokens& raw);

/// A command that opens with a participle base ("Seated in the chair, place your right hand on
/// your right knee"): the pose in the next clause joins the sit/lie step.
void JoinParticipleBase(const Tokens& raw, std::vector<ClauseWords>& clauses);

/// Self-corrections on raw words: "X -- no, Y", "X, actually no, Y", "X, sorry, Y", "X, I mean
/// Y" keep Y in X's place (Y replaces the part of its clause that starts like it: "go to the
/// chair, actually no, the stool" goes to the stool; "your left -- no, right -- hand" is the
/// right hand). A correction with nothing to align to only drops its marker.
Tokens ApplyCorrections(const Tokens& raw);

/// Optimal string alignment distance (insertions, deletions, substitutions and transpositions
/// of neighbours each cost 1).
int EditDistance(const std::string& a, const std::string& b);

/// Replaces each unknown word of `raw` (tokenized, not normalised) by the one object, part,
/// colour or function word it is a slip of: a swap of two neighbouring letters (3+ letters),
/// one other edit (5+ letters) or two edits (8+ letters). A word with several such corrections,
/// or with a digit (an object id), is kept.
Tokens CorrectTypos(const Tokens& raw);

/// Joins "grab/pick up A [with your H hand]" and a following "put it REL B" into one "put A REL
/// B with your H hand" (also with the object left out: "pick A, place right of B"); a bare "sit"
/// before "type", or a sit whose pose puts the hands on the keyboard, sits at the keyboard (the
/// seat at the laptop); a fronted instrument ("with your left hand, put ...") moves to the end of
/// the next clause; a clause that leaves out the verb ("put A on B, then C on D") takes the verb
/// of the clause before; "lift them off" after hands were put on a part takes those hands off it.
void JoinClauses(std::vector<ClauseWords>& clauses);

}  // namespace simhuman::language::offline
