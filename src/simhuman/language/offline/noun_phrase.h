#pragma once
/// Noun phrases of the offline planner: how a description of an object is parsed ("the big red
/// box left of the green sphere", "its keyboard", "the left armrest of the sofa", "it"). Parsing
/// only looks at words; references.cc resolves a parsed phrase against the scene.

#include <memory>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/language/offline/common.h"
#include "simhuman/language/offline/spatial.h"

namespace simhuman::language::offline {

/// A reference deeper than this in nested relations is refused (keeps parsing linear).
inline constexpr int kMaxNesting = 3;

/// A selection among several matching objects ("the left chair", "the big box", "the nearest
/// sofa", "the flat box": the lowest); kNone when the words give none.
enum class Select { kNone, kLeft, kRight, kBig, kSmall, kNear, kFar, kFlat };

/// A parsed description of one object (or one part of one object).
struct NounPhrase {
  bool pronoun = false;   // "it", "them", "there", "that", "its ...": the object last referred to
  std::string id;         // an object id written out, e.g. "chair000"
  std::string color;      // a colour word, or ""
  std::string type;       // canonical type, or "" (any)
  bool has_type = false;  // a type word (or "object"/"one") was given
  std::string part;       // lookup name of a part, e.g. "seat", "arm"; "" for none
  std::string part_side;  // "left"/"right" for a part, or ""
  Select select = Select::kNone;
  /// "left of <ref>": the object must stand in relation `rel` to the object `ref` describes.
  struct Relation {
    Rel rel;
    std::unique_ptr<NounPhrase> ref;
  };
  std::vector<Relation> relations;
  std::string text;  // the words, for messages

  /// True when the words said nothing about any object.
  bool Empty() const {
    return !pronoun && id.empty() && color.empty() && !has_type && part.empty() &&
           relations.empty() && select == Select::kNone;
  }
};

/// Whether `w` introduces a relative clause ("that", "which", "is", "are").
bool IsRelativizer(const std::string& w);

/// Parses t[b, e) as one noun phrase, `depth` levels deep in nested relations. Errors are
/// kInvalidArgument and quote `clause`: an empty description, a word that is not a relation
/// after the object, or nesting deeper than kMaxNesting.
core::StatusOr<NounPhrase> ParseNounPhrase(const Tokens& t, size_t b, size_t e, int depth,
                                           const std::string& clause);

/// The kind of object a phrase describes, in words ("red box", "object with a seat").
std::string NounOf(const NounPhrase& np);

}  // namespace simhuman::language::offline
