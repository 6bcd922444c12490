#pragma once
/// The offline planner's general fallback (internal to language/). When the rules refuse a
/// command with kInvalidArgument (a word they cannot place, a clause without an action), the
/// fallback reads the command again by slots instead of by grammar:
/// - words: every word the lexicon does not know is looked up by stem ("slaps" -> touch,
///   "perching" -> sit, "stood" -> stand up), as a plural or a slip of an object word, as a
///   word that names the human ("the avatar", "your butt") or a time ("at dawn"); what is left
///   is dropped, unless it heads an object phrase ("the fridge"): an unknown object;
/// - slots: the actions (sit, lie, rest, stand up, go, touch, put, carry, type, poses), the
///   scene's objects (id, type, colour, part) and the body parts, in the order they occur;
/// - plan: each action with the words that follow it becomes one canonical clause, an object
///   named without an action becomes the one that "it" and an object-less action refer to,
///   and the clauses are planned by the rules' own Session (the same plan builders).
/// It refuses (kInvalidArgument) a command with a negation, an unknown action applied to an
/// object ("kick the box"), an unknown object as the target of an action, or no action at
/// all; ambiguity still asks (kFailedPrecondition). docs/FORMATS.md, "Language commands".

#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/language/offline/clauses.h"
#include "simhuman/language/offline/common.h"
#include "simhuman/language/planner.h"

namespace simhuman::language::offline {

/// How the fallback reads one word the lexicon does not know (fallback_words.cc).
struct WordReading {
  enum Kind {
    kUnknown,  // nothing: dropped, or an unknown object when it heads an object phrase
    kAction,   // an action verb by its stem: `word` is the canonical verb
    kObject,   // an object or part word by plural or spelling: `word` is the known word
    kDrop,     // a word that names the human, its body as a whole, or a time
  } kind = kUnknown;
  std::string word;
};

/// Reads a word that is not Known() (nor a synonym, filler or phrase word): see WordReading.
WordReading ReadWord(const std::string& w);
/// Whether the fallback leaves `w` to the lexicon (it is a known, synonym, filler or phrase
/// word).
bool LexiconWord(const std::string& w);
/// Whether `w` (raw) denies what follows ("not", "don't", "never", "without", ...).
bool IsNegation(const std::string& w);
/// Whether `w` (raw) opens an object phrase: a determiner, a possessive or a preposition
/// ("the", "your", "on", "into"; not "to", which also opens an infinitive).
bool OpensObject(const std::string& w);

/// The fallback's reading of `command` as canonical clauses (what the Session then plans).
/// kInvalidArgument when it finds no clear meaning (see the file comment).
core::StatusOr<std::vector<ClauseWords>> FallbackClauses(std::string_view command,
                                                         const core::SceneCatalog& scene);

/// How many of the object types, object ids and limbs (hand, elbow, foot, knee) that `words`
/// (normalised) name `plan` uses none of (coverage.cc); 0 for a plan with a carry step. The
/// planner asks the fallback again when the rules' plan leaves something out.
int Uncovered(const Tokens& words, const PlanResult& plan, const core::SceneCatalog& scene);

/// Plans FallbackClauses() with the rules' Session; errors as FallbackClauses() and Session.
core::StatusOr<PlanResult> FallbackPlan(std::string_view command, const PlanContext& context);

}  // namespace simhuman::language::offline
