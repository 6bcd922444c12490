#include "simhuman/language/offline/clauses.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {

namespace {

// typographic punctuation and emoji (UTF-8) at s[i]: a curly apostrophe is dropped like "'"
// (`kind` 0: the word goes on), curly quotes, dashes and emoji separate words (1), an
// ellipsis, a bullet or an arrow separates clauses (2). Returns the bytes used (0: none of
// these). Letters outside ASCII stay refused.
size_t Utf8Punctuation(std::string_view s, size_t i, int& kind) {
  auto byte = [&](size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0; };
  const unsigned char c = byte(i), d = byte(i + 1), e = byte(i + 2);
  kind = 1;
  if (c == 0xe2 && d == 0x80) {
    if (e == 0x98 || e == 0x99) kind = 0;  // curly apostrophes
    if (e == 0xa6 || e == 0xa2) kind = 2;  // ellipsis, bullet
    if (kind != 1 || e == 0x9c || e == 0x9d || e == 0x93 || e == 0x94) return 3;  // quotes, dashes
  }
  if (c == 0xe2 && d == 0x86 && e >= 0x90 && e <= 0x9f) {  // arrows
    kind = 2;
    return 3;
  }
  // pictographs and emoji: U+2600-U+27BF, U+1F300-U+1FAFF, and the emoji variation selector
  if (c == 0xe2 && d >= 0x98 && d <= 0x9e && e >= 0x80 && e <= 0xbf) return 3;
  if (c == 0xf0 && d == 0x9f && e >= 0x8c && e <= 0xab && byte(i + 3) >= 0x80 &&
      byte(i + 3) <= 0xbf) {
    return 4;
  }
  if (c == 0xef && d == 0xb8 && e == 0x8f) return 3;
  return 0;
}

}  // namespace

core::StatusOr<Tokens> Tokenize(std::string_view command) {
  if (command.size() > kMaxCommandBytes) {
    return Invalid("the command is " + std::to_string(command.size()) + " bytes long; at most " +
                   std::to_string(kMaxCommandBytes) +
                   " are accepted (split it into several commands)");
  }
  Tokens out;
  std::string word;
  auto flush = [&] {
    if (!word.empty()) out.push_back(std::move(word));
    word.clear();
  };
  int kind = 0;
  for (size_t i = 0; i < command.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(command[i]);
    if (std::isalnum(c)) {
      // "SitOnSofa": a capital after a small letter starts a word
      if (std::isupper(c) && i > 0 && std::islower(static_cast<unsigned char>(command[i - 1]))) {
        flush();
      }
      word += static_cast<char>(std::tolower(c));
    } else if (c == '\'') {
      continue;  // "chair's" -> "chairs", "don't" -> "dont"
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '-' || c == '_' || c == '/' || c == '"' ||
               c == '`' || c == '*' || c == '~' || c == '#') {
      flush();  // quotes, markdown emphasis and bullets ("* sit", "#1") say nothing
    } else if (c == ',' || c == '.' || c == ';' || c == '!' || c == '?' || c == ':' ||
               c == '>' ||  // "sit chair002 -> type on laptop001": an arrow sequences
               c == '(' || c == ')' || c == '[' || c == ']' ||  // "[sits in the chair]"
               c == '\n' || c == '|' || c == '=') {             // one step a line
      flush();
      out.push_back("then");
    } else if (c == '&' || c == '+') {
      flush();
      out.push_back("and");
    } else if (size_t n = Utf8Punctuation(command, i, kind)) {
      if (kind > 0) flush();
      if (kind == 2) out.push_back("then");
      i += n - 1;
    } else {
      char buf[96];
      if (c >= 0x20 && c < 0x7f) {
        std::snprintf(buf, sizeof(buf), "character '%c' at offset %zu", c, i);
      } else {
        std::snprintf(buf, sizeof(buf), "byte 0x%02x at offset %zu", c, i);
      }
      return Invalid(std::string("cannot read the command: unexpected ") + buf +
                     "; commands are plain English words with , . ; separating clauses");
    }
  }
  flush();
  return out;
}

namespace {

// a run-on without "and" ("go to the armchair sit down"): a verb right after an object, a body
// part or a finished verb starts a new clause
bool StartsRunOn(const Tokens& t, size_t k) {
  static const std::set<std::string> kVerbs = {
      "sit", "lie",   "stand", "touch", "type",  "recline", "lean",  "rest",  "go",
      "put", "place", "grab",  "cross", "raise", "reach",   "carry", "stack", "turn"};
  if (k == 0 || !kVerbs.count(t[k])) return false;
  const std::string& p = t[k - 1];
  if (p == "sit" || p == "lie" || p == "recline" || p == "up" || p == "it" || p == "them" ||
      p == "there" || p == "here") {
    return true;
  }
  if ((p == "legs" || p == "leg") && t[k] == "cross") return false;  // "legs cross"
  auto type = TypeWords().find(p);
  return (type != TypeWords().end() && p != "one") || PartWords().count(p) > 0 ||
         (IsBodyWord(p) && p != "your" && p != "hand" && p != "hands") ||
         (std::any_of(p.begin(), p.end(), [](char ch) { return std::isdigit(ch) != 0; }) &&
          std::any_of(p.begin(), p.end(), [](char ch) { return std::isalpha(ch) != 0; }));
}

bool IsIdLike(const std::string& w) {
  return std::any_of(w.begin(), w.end(), [](char ch) { return std::isdigit(ch) != 0; }) &&
         std::any_of(w.begin(), w.end(), [](char ch) { return std::isalpha(ch) != 0; });
}

}  // namespace

bool IsChatter(const Tokens& words, const core::SceneCatalog& scene) {
  // "there is/are ...": a description of the scene, not an instruction
  if (!words.empty() && (words[0] == "theres" || (words[0] == "there" && words.size() > 1 &&
                                                  (words[1] == "is" || words[1] == "are")))) {
    return true;
  }
  for (const std::string& w : words) {
    if (Known(w) || scene.Find(w) != nullptr || IsIdLike(w)) return false;
  }
  return true;
}

absl::Status Session::SkipUnknownWords(Tokens& t, const std::string& c) const {
  static const std::set<std::string> kBefore = {"on",  "onto", "to",   "in",   "at",   "near",
                                                "off", "of",   "from", "your", "with", "against"};
  size_t verb = 0;
  while (verb < t.size() && (t[verb] == "your" || t[verb] == "then" || t[verb] == "and")) ++verb;
  Tokens kept;
  for (size_t k = 0; k < t.size(); ++k) {
    const std::string& w = t[k];
    // "laptop002's keyboard": the id's possessive
    if (IsIdLike(w) && w.back() == 's' && scene_.Find(w.substr(0, w.size() - 1)) != nullptr) {
      kept.push_back(w.substr(0, w.size() - 1));
      continue;
    }
    if (Known(w) || scene_.Find(w) != nullptr) {
      kept.push_back(w);
      continue;
    }
    // an unknown word is skipped inside a clause (a modifier, a name, a slip); it is an error as
    // the action (the verb position), as an object (after a relation, a colour or a size, or
    // ending the clause) and when it looks like an object id
    const std::string& p = k > 0 ? t[k - 1] : std::string();
    const bool object = kBefore.count(p) || Colors().count(p) || p == "big" || p == "small" ||
                        p == "tall" || p == "short" || k + 1 == t.size() || IsIdLike(w);
    if (k == verb) {
      return Invalid(
          "did not understand the action '" + w + "' in \"" + c +
          "\"; I understand: sit, lie, rest, stand up, go to / walk to / approach, "
          "touch / reach, put your hand(s) on, put the <colour> <shape> on <object>, "
          "carry / bring / pick up / put down <object> (to <object>), "
          "with object types chair, armchair, sofa, stool, high stool, bed, table, "
          "laptop, box, long box, cylinder, sphere, cone, hourglass, mesh. The scene has: " +
          DescribeSceneObjects(scene_));
    }
    if (object) {
      return Invalid(
          "did not understand the word '" + w + "' in \"" + c +
          "\"; I understand object types chair, armchair, sofa, stool, high stool, "
          "bed, table, laptop, box, long box, cylinder, sphere, cone, hourglass, mesh and "
          "body parts hands, "
          "elbows, knees, feet, stomach, head. The scene has: " +
          DescribeSceneObjects(scene_));
    }
  }
  t = std::move(kept);
  return absl::OkStatus();
}

core::StatusOr<std::vector<ClauseWords>> SplitMarkedClauses(const Tokens& tokens) {
  std::vector<ClauseWords> clauses(1);
  bool then = false;  // a "then" since the last clause's words
  for (size_t k = 0; k < tokens.size(); ++k) {
    const std::string& w = tokens[k];
    if (!clauses.back().words.empty() && StartsRunOn(tokens, k)) {
      clauses.emplace_back();
      clauses.back().sequenced = false;
    }
    if (w == "then" || w == "and") {
      then = then || w == "then";
      if (!clauses.back().words.empty()) clauses.emplace_back();
      clauses.back().sequenced = then;
      if (static_cast<int>(clauses.size()) > kMaxClauses) {
        return Invalid("the command has more than " + std::to_string(kMaxClauses) +
                       " clauses; split it into several commands");
      }
      continue;
    }
    if (clauses.back().words.empty()) clauses.back().sequenced = then;
    then = false;
    clauses.back().words.push_back(w);
  }
  if (clauses.back().words.empty()) clauses.pop_back();
  return clauses;
}

core::StatusOr<std::vector<Tokens>> SplitClauses(const Tokens& tokens) {
  SH_ASSIGN_OR_RETURN(std::vector<ClauseWords> marked, SplitMarkedClauses(tokens));
  std::vector<Tokens> out;
  for (ClauseWords& c : marked) out.push_back(std::move(c.words));
  return out;
}

absl::Status Session::Clause(const Tokens& words) {
  const std::string c = Join(words);
  // team words ("you two", "both of you", "together") say who carries
  Tokens t;
  team_ = 0;
  for (const std::string& w : words) {
    if (w == "team2" || w == "team3" || w == "team4") {
      team_ = w.back() - '0';
    } else if (w == "teamall") {
      team_ = scene_.num_agents();
    } else if (w == "teamany") {
      if (team_ == 0) team_ = -1;
    } else {
      t.push_back(w);
    }
  }
  if (team_ > scene_.num_agents()) {
    return Invalid(
        ""
        " + c + "
        " asks for " +
        std::to_string(team_) +
        " carriers but the scene "
        "has " +
        std::to_string(scene_.num_agents()) +
        " human(s): valid agents are "
        "0.." +
        std::to_string(scene_.num_agents() - 1));
  }
  SH_RETURN_IF_ERROR(SkipUnknownWords(t, c));
  size_t i = 0;
  while (i < t.size() && (t[i] == "your" || t[i] == "then" || t[i] == "and")) ++i;
  if (i >= t.size()) return absl::OkStatus();
  const std::string& v = t[i];
  // "hands on your knees", "with your left elbow on the armrest": a pose stated, not ordered
  static const std::set<std::string> kPoseVerbs = {
      "put", "place", "rest", "lean",    "cross", "raise", "turn", "keep", "move",
      "sit", "lie",   "type", "recline", "touch", "reach", "grab", "stack"};
  attributive_ = kPoseVerbs.count(v) == 0;
  auto next = [&](size_t k) { return k < t.size() ? t[k] : std::string(); };
  // "put your hands", "put left hand", "rest both elbows": a body part follows the verb
  auto body_next = [&] {
    const std::string& w = next(i + 1);
    return IsBodyWord(w) ||
           ((w == "left" || w == "right" || w == "both") && IsBodyWord(next(i + 2)));
  };
  if (v == "rest" && body_next()) {
    SH_ASSIGN_OR_RETURN(std::optional<Variant> var, ParseVariant(t, i, t.size(), c));
    if (!var) return Reach(t, c);
    SH_RETURN_IF_ERROR(ImpliedBase(*var, t, i, t.size(), c));
    return AddVariant(*var, c);
  }
  // "go lie on the bed", "go and sit down": the going is implied by the interaction
  if (v == "go" && (next(i + 1) == "sit" || next(i + 1) == "lie" || next(i + 1) == "rest" ||
                    next(i + 1) == "touch" || next(i + 1) == "put" || next(i + 1) == "stand" ||
                    next(i + 1) == "recline" || next(i + 1) == "type")) {
    return Clause(Tokens(t.begin() + static_cast<long>(i) + 1, t.end()));
  }
  if (v == "go" && i + 1 == t.size()) return absl::OkStatus();
  if (v == "sit" || v == "lie" || v == "rest" || v == "recline") {
    const SitMode mode = v == "sit"    ? SitMode::kSit
                         : v == "lie"  ? SitMode::kLie
                         : v == "rest" ? SitMode::kRest
                                       : SitMode::kRecline;
    return SitOrLie(t, i + 1, mode, c);
  }
  if (v == "type") return Type(t, i + 1, c);
  if (v == "notice" || v == "use") return NoticeOrUse(t, i, c);
  // "then stand", "stand up from the chair", "get off the bed" (stand up from)
  if (v == "stand" && i + 1 == t.size()) return StandUp(c);
  if (v == "stand" && next(i + 1) == "up") {
    if (i + 2 < t.size() && (t[i + 2] == "from" || t[i + 2] == "off" || t[i + 2] == "of" ||
                             t[i + 2] == "in" || t[i + 2] == "on")) {
      return StandUp(c);
    }
    if (i + 2 < t.size() && t[i + 2] != "then") {
      return Invalid("did not understand '" + Join(t, i + 2, t.size()) +
                     "' after 'stand up' in \"" + c + "\"");
    }
    return StandUp(c);
  }
  // carrying: carry/bring (anything carryable), pick up/take/hold/lift (when the object is
  // carryable; otherwise a reach, as before)
  if (v == "carry") return Carry(t, i + 1, CarryDefault::kHold, c);
  if ((v == "grab" || v == "raise") && !IsBodyWord(next(i + 1)) &&
      IsCarryClause(t, i + 1, true, c)) {
    return Carry(t, i + 1, CarryDefault::kHold, c);
  }
  if ((v == "put" || v == "place" || v == "move" || v == "stack") && !IsBodyWord(next(i + 1)) &&
      IsCarryClause(t, i + 1, false, c)) {
    return Carry(t, i + 1, CarryDefault::kPutDown, c);
  }
  if (v == "stand" || v == "go" ||
      (v == "move" && (next(i + 1) == "to" || next(i + 1) == "near"))) {
    return Go(t, i + 1, c);
  }
  if (v == "put" || v == "stack" || v == "move" || v == "rest" || v == "keep" || v == "place") {
    if (body_next()) {
      SH_ASSIGN_OR_RETURN(std::optional<Variant> var, ParseVariant(t, i, t.size(), c));
      if (!var) return Reach(t, c);
      SH_RETURN_IF_ERROR(ImpliedBase(*var, t, i, t.size(), c));
      return AddVariant(*var, c);
    }
    if (v == "keep") {
      return Invalid("did not understand \"" + c + "\"");
    }
    return Tabletop(t, i + 1, c);
  }
  if (v == "touch" || v == "reach" || v == "grab") return Reach(t, c);
  if (v == "geton") {
    // "get on the bed (and lie down)": go to it if it is far; the next clause says what to do
    if (i + 1 >= t.size()) {
      return Invalid("\"" + c + "\": get on what? name an object; the scene has: " +
                     DescribeSceneObjects(scene_));
    }
    SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, i + 1, t.size(), 0, c));
    SH_ASSIGN_OR_RETURN(const CatalogObject* o, Resolve(np, c));
    focus_ = o;
    EnsureFree(o);
    EnsureNear(*o);
    return absl::OkStatus();
  }
  // a pose: "cross your right foot over your left knee", "lean back", "knees up", "with ..."
  SH_ASSIGN_OR_RETURN(std::optional<Variant> var, ParseVariant(t, i, t.size(), c));
  if (var) {
    SH_RETURN_IF_ERROR(ImpliedBase(*var, t, i, t.size(), c));
    return AddVariant(*var, c);
  }
  if (Has(t, i, t.size(), "touch") || Has(t, i, t.size(), "reach")) return Reach(t, c);
  // ", both hands on the desk": a touch stated without a verb joins the sit it follows
  if (attributive_ && posture_ == Posture::kSit &&
      Find(t, i, t.size(), {"hand", "hands"}) < t.size()) {
    return Reach(t, c, true);
  }
  if (std::optional<absl::Status> mention = Mention(t, i, c)) return *mention;
  return Invalid("did not understand \"" + c +
                 "\"; commands start with sit, lie, rest, stand up, go to, walk to, approach, "
                 "touch, reach, put, place, stack, carry, bring, pick up, lean, cross, raise");
}

}  // namespace simhuman::language::offline
