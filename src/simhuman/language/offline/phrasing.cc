// Rewording of the offline planner on the raw words, before the lexicon: how people script a
// character ("NPC walks to the armchair, sits, rests its hands on both armrests, then gets
// up"), gerund continuations ("and then getting back up"), chat spellings ("ur", "goto"),
// participle poses ("knees bent up", "head raised off the pillow"), a pose said by what it
// avoids ("without touching the backrest") and trailing purpose clauses ("so the foot stays
// flat"), which say nothing the pose does not.

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/rewrite.h"

namespace simhuman::language::offline {
namespace {

// a character named as the subject of a scripted line, dropped at the start of a clause
const std::set<std::string>& Subjects() {
  static const auto* words = new std::set<std::string>{
      "npc", "character", "agent", "avatar", "human", "person", "player", "he", "she", "they"};
  return *words;
}

// third-person and -ing forms of the verbs the lexicon reads, and chat spellings
const std::map<std::string, std::string>& VerbForms() {
  static const auto* words = new std::map<std::string, std::string>{
      {"walks", "walk"},     {"walking", "walk"},  {"gets", "get"},       {"getting", "get"},
      {"stands", "stand"},   {"crosses", "cross"}, {"rests", "rest"},     {"puts", "put"},
      {"putting", "put"},    {"leans", "lean"},    {"goes", "go"},        {"going", "go"},
      {"moves", "move"},     {"moving", "move"},   {"places", "place"},   {"placing", "place"},
      {"picks", "pick"},     {"picking", "pick"},  {"lifts", "lift"},     {"lifting", "lift"},
      {"raises", "raise"},   {"raising", "raise"}, {"turns", "turn"},     {"turning", "turn"},
      {"types", "type"},     {"carries", "carry"}, {"carrying", "carry"}, {"bends", "bend"},
      {"bending", "bend"},   {"grabs", "grab"},    {"grabbing", "grab"},  {"takes", "take"},
      {"taking", "take"},    {"brings", "bring"},  {"bringing", "bring"}, {"stacks", "stack"},
      {"stacking", "stack"}, {"sets", "set"},      {"lays", "lay"},       {"approaches", "go"},
      {"approaching", "go"}, {"presses", "touch"}, {"press", "touch"},    {"pressing", "touch"},
      {"chill", "rest"},     {"chills", "rest"},   {"chilling", "rest"},  {"ur", "your"},
      {"yr", "your"}};
  return *words;
}

// a limb of the character, after an optional side ("hands", "left knee"; not "left arm", an
// armrest)
bool IsLimbAt(const Tokens& raw, size_t k) {
  static const std::set<std::string> kLimbs = {"hand", "hands", "elbow", "elbows", "knee", "knees",
                                               "foot", "feet",  "leg",   "legs",   "head"};
  if (k < raw.size() && (raw[k] == "left" || raw[k] == "right" || raw[k] == "both")) ++k;
  return k < raw.size() && kLimbs.count(raw[k]) > 0;
}

// "high_stool003" split at its '_': the type "high_stool" and the rest of the id
bool IsSplitId(const std::string& w, const std::string& next) {
  const size_t digits = next.find_first_of("0123456789");
  if (digits == 0 || digits == std::string::npos) return false;
  if (next.find_first_not_of("0123456789", digits) != std::string::npos) return false;
  return TypeWords().count(w + "_" + next.substr(0, digits)) > 0;
}

bool IsSeparator(const std::string& w) { return w == "then" || w == "and"; }

}  // namespace

Tokens Reword(const Tokens& raw) {
  Tokens out;
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  for (size_t i = 0; i < raw.size(); ++i) {
    const std::string& w = raw[i];
    const bool start = out.empty() || IsSeparator(out.back());
    // "NPC sits ...", "the character walks to ...", "then he gets up"
    if (start && (Subjects().count(w) || (w == "the" && Subjects().count(at(i + 1))))) {
      if (w == "the") ++i;
      continue;
    }
    // "its hands", "his left knee": the character's own body is "your"
    if ((w == "its" || w == "his" || w == "her" || w == "their") && IsLimbAt(raw, i + 1)) {
      out.push_back("your");
      continue;
    }
    if (IsSplitId(w, at(i + 1))) {
      out.push_back(w + "_" + raw[++i]);
      continue;
    }
    // "press a key on the laptop": the laptop's keyboard
    if ((w == "key" || w == "keys") && (at(i + 1) == "on" || at(i + 1) == "of")) {
      const size_t k = at(i + 2) == "the" ? i + 3 : i + 2;
      if (at(k).rfind("laptop", 0) == 0 || at(k) == "computer" || at(k) == "notebook") {
        out.insert(out.end(), {raw[k], "keyboard"});
        i = k;
        continue;
      }
    }
    if (w == "goto") {
      out.insert(out.end(), {"go", "to"});
      continue;
    }
    // "without touching the backrest", "without leaning back": leaning forward
    if (w == "without") {
      size_t k = i + 1;
      while (k < raw.size() && k <= i + 4 && raw[k] != "backrest" && raw[k] != "back") ++k;
      if (k < raw.size() && k <= i + 4) {
        if (at(k + 1) == "rest") ++k;
        out.insert(out.end(), {"leaning", "forward"});
        i = k;
        continue;
      }
    }
    // "knees bent up", "head raised off the pillow": the limb is up
    if ((w == "bent" || w == "raised" || w == "lifted") && !out.empty() &&
        IsLimbAt(out, out.size() - 1)) {
      out.push_back("up");
      if (at(i + 1) == "up") ++i;
      if (at(i + 1) == "off") {
        size_t k = i + 2;
        if (at(k) == "the") ++k;
        if (at(k) == "pillow" || at(k) == "mattress" || at(k) == "bed") i = k;
      }
      continue;
    }
    // "..., so the foot stays flat": a purpose clause says nothing the pose does not
    if (w == "so" && !start && out.back() != "ok" && out.back() != "okay") {
      static const std::set<std::string> kClause = {"that", "the",  "your", "it",
                                                    "its",  "they", "my"};
      if (kClause.count(at(i + 1))) {
        while (i + 1 < raw.size() && raw[i + 1] != "then") ++i;
        continue;
      }
    }
    if (w == "chill" && at(i + 1) == "out") ++i;
    // "and then standing back up" (a bare "standing" is a filler)
    if (w == "standing" && (at(i + 1) == "up" || (at(i + 1) == "back" && at(i + 2) == "up"))) {
      out.push_back("stand");
      continue;
    }
    auto form = VerbForms().find(w);
    out.push_back(form != VerbForms().end() ? form->second : w);
  }
  return out;
}

}  // namespace simhuman::language::offline
