#include "simhuman/language/offline/noun_phrase.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/objects.h"

namespace simhuman::language::offline {
namespace {

// parses relations starting at t[i]: [relativizer...] REL NP [REL NP ...]
absl::Status ParseRelations(const Tokens& t, size_t i, size_t e, int depth,
                            const std::string& clause, NounPhrase& np) {
  while (i < e) {
    while (i < e && IsRelativizer(t[i])) ++i;
    if (i >= e) break;
    std::optional<Rel> rel = RelFromWord(t[i]);
    if (!rel) {
      return Invalid("did not understand '" + Join(t, i, e) + "' in \"" + clause +
                     "\"; after an object I expect a relation such as next to, left of, right "
                     "of, in front of, behind, on, nearest");
    }
    ++i;
    // the reference runs to the next relation word that is not part of it
    size_t j = i;
    while (j < e && !RelFromWord(t[j]) && !IsRelativizer(t[j])) ++j;
    if (j == i) {
      return Invalid("'" + RelText(*rel) + "' needs an object after it in \"" + clause + "\"");
    }
    SH_ASSIGN_OR_RETURN(NounPhrase ref, ParseNounPhrase(t, i, j, depth + 1, clause));
    np.relations.push_back({*rel, std::make_unique<NounPhrase>(std::move(ref))});
    i = j;
  }
  return absl::OkStatus();
}

}  // namespace

bool IsRelativizer(const std::string& w) {
  return w == "that" || w == "which" || w == "is" || w == "are";
}

core::StatusOr<NounPhrase> ParseNounPhrase(const Tokens& t, size_t b, size_t e, int depth,
                                           const std::string& clause) {
  if (depth > kMaxNesting) {
    return Invalid("the object description in \"" + clause + "\" nests more than " +
                   std::to_string(kMaxNesting) + " relations; describe it more simply");
  }
  NounPhrase np;
  np.text = Join(t, b, e);
  size_t i = b;
  if (i < e && (t[i] == "it" || t[i] == "them" || t[i] == "there" || t[i] == "that")) {
    if (i + 1 == e || RelFromWord(t[i + 1])) {
      np.pronoun = true;
      ++i;
      SH_RETURN_IF_ERROR(ParseRelations(t, i, e, depth, clause, np));
      return np;
    }
    if (t[i] == "that") ++i;  // "that chair"
  }
  if (i < e && t[i] == "its") {
    // "its keyboard": a part of the object last referred to
    np.pronoun = true;
    ++i;
    if (i < e && (t[i] == "left" || t[i] == "right") && i + 1 < e && PartWords().count(t[i + 1])) {
      np.part_side = t[i++];
    }
    if (i < e && PartWords().count(t[i])) np.part = PartWords().at(t[i++]);
    SH_RETURN_IF_ERROR(ParseRelations(t, i, e, depth, clause, np));
    return np;
  }
  // adjectives
  for (; i < e; ++i) {
    const std::string& w = t[i];
    if (Colors().count(w)) {
      np.color = w;
    } else if (w == "big" || w == "tall") {
      np.select = Select::kBig;
    } else if (w == "small" || w == "short") {
      np.select = Select::kSmall;
    } else if (w == "flat" || w == "flattest" || w == "flatter") {
      np.select = Select::kFlat;
    } else if (w == "nearest" || w == "nearby") {
      if (i + 1 < e && !TypeWords().count(t[i + 1]) && !PartWords().count(t[i + 1]) &&
          !Colors().count(t[i + 1])) {
        break;  // "nearest the bed": a relation
      }
      np.select = Select::kNear;
    } else if (w == "far" || w == "farthest") {
      if (w == "farthest" && i + 1 < e && !TypeWords().count(t[i + 1]) &&
          !PartWords().count(t[i + 1])) {
        break;
      }
      np.select = Select::kFar;
    } else if (w == "left" || w == "right") {
      // "the left armrest": the side of a part; "the left chair": the leftmost chair
      if (i + 1 < e && (PartWords().count(t[i + 1]) || t[i + 1] == "side")) {
        np.part_side = w;
      } else {
        np.select = w == "left" ? Select::kLeft : Select::kRight;
      }
    } else if (w == "your" || w == "own") {
      continue;
    } else {
      break;
    }
  }
  // head noun: an id, a type or a part, possibly "part of <np>" or "<type>s part"
  if (i < e && std::any_of(t[i].begin(), t[i].end(),
                           [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); })) {
    np.id = t[i++];
    if (i < e && PartWords().count(t[i])) np.part = PartWords().at(t[i++]);
  } else if (i < e && TypeWords().count(t[i])) {
    np.type = TypeWords().at(t[i]);
    np.has_type = true;
    ++i;
    if (i < e && (t[i] == "left" || t[i] == "right") && i + 1 < e && PartWords().count(t[i + 1])) {
      np.part_side = t[i++];
    }
    if (i < e && PartWords().count(t[i])) np.part = PartWords().at(t[i++]);
  } else if (i < e && PartWords().count(t[i])) {
    np.part = PartWords().at(t[i++]);
    if (i < e && t[i] == "of") {
      ++i;
      // the owner: adjectives and a type
      size_t j = i;
      while (j < e && !RelFromWord(t[j]) && !IsRelativizer(t[j])) ++j;
      SH_ASSIGN_OR_RETURN(NounPhrase owner, ParseNounPhrase(t, i, j, depth + 1, clause));
      if (!owner.relations.empty() || owner.pronoun || !owner.part.empty()) {
        np.pronoun = owner.pronoun;
      }
      np.color = owner.color.empty() ? np.color : owner.color;
      np.type = owner.type;
      np.has_type = owner.has_type;
      if (owner.select != Select::kNone) np.select = owner.select;
      np.relations = std::move(owner.relations);
      i = j;
    }
  }
  // "the chair on the left" / "the box on the right": a selection, not a relation
  if (i + 2 == e && (t[i] == "on" || t[i] == "at" || t[i] == "to") &&
      (t[i + 1] == "left" || t[i + 1] == "right")) {
    np.select = t[i + 1] == "left" ? Select::kLeft : Select::kRight;
    i = e;
  }
  SH_RETURN_IF_ERROR(ParseRelations(t, i, e, depth, clause, np));
  if (np.Empty()) {
    return Invalid("expected an object in \"" + clause + "\", got '" + np.text + "'");
  }
  return np;
}

std::string NounOf(const NounPhrase& np) {
  std::string s = np.color.empty() ? "" : np.color + " ";
  if (!np.type.empty()) return s + TypeText(np.type);
  if (!np.part.empty()) return s + "object with a " + np.part;
  return s + "object";
}

}  // namespace simhuman::language::offline
