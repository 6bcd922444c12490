#pragma once
/// Shared vocabulary of the offline planner's files (internal to language/): the token list the
/// parsers work on, helpers over spans of it, and the two ways a command is refused (Planner's
/// status codes). Nothing here keeps state.

#include <set>
#include <string>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::language::offline {

using core::BodyJoint;
using core::CatalogObject;
using plan::ContactPair;
using plan::ContactStep;
using plan::ContactType;
using plan::Direction;

/// A command as lower-case words, after tokenizing and (usually) lexicon normalisation.
using Tokens = std::vector<std::string>;

/// kInvalidArgument: not understood, impossible, or names something the scene lacks.
inline absl::Status Invalid(const std::string& message) {
  return absl::InvalidArgumentError(message);
}
/// kFailedPrecondition: the command is ambiguous; `message` is a question ending in '?'.
inline absl::Status Question(const std::string& message) {
  return absl::FailedPreconditionError(message);
}

/// The words tokens[b, e) joined by single spaces (clamped to the list), for messages.
std::string Join(const Tokens& tokens, size_t b, size_t e);
/// All words joined by single spaces.
std::string Join(const Tokens& tokens);

/// Whether `w` occurs in t[b, e) (clamped to the list).
bool Has(const Tokens& t, size_t b, size_t e, const std::string& w);
/// Index of the first of `words` in t[b, e), or e.
size_t Find(const Tokens& t, size_t b, size_t e, const std::set<std::string>& words);
/// The side word ("left", "right", "both") right before t[i] (skipping "your"), not looking
/// before b; "" when there is none.
std::string SideBefore(const Tokens& t, size_t b, size_t i);

}  // namespace simhuman::language::offline
