#include "simhuman/language/offline/clauses.h"

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
  for (size_t i = 0; i < command.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(command[i]);
    if (std::isalnum(c)) {
      word += static_cast<char>(std::tolower(c));
    } else if (c == '\'') {
      continue;  // "chair's" -> "chairs", "don't" -> "dont"
    } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '-' || c == '_' ||
               c == '/') {
      flush();
    } else if (c == ',' || c == '.' || c == ';' || c == '!' || c == '?' || c == ':' ||
               c == '>' ||  // "sit chair002 -> type on laptop001": an arrow sequences
               c == '(' || c == ')' || c == '[' || c == ']') {  // "[sits in the chair]"
      flush();
      out.push_back("then");
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

core::StatusOr<std::vector<ClauseWords>> SplitMarkedClauses(const Tokens& tokens) {
  std::vector<ClauseWords> clauses(1);
  bool then = false;  // a "then" since the last clause's words
  for (const std::string& w : tokens) {
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
  for (const std::string& w : t) {
    if (!Known(w) && scene_.Find(w) == nullptr) {
      return Invalid("did not understand the word '" + w + "' in \"" + c +
                     "\"; I understand: sit, lie, rest, stand up, go to / walk to / approach, "
                     "touch / reach, put your hand(s) on, put the <colour> <shape> on <object>, "
                     "carry / bring / pick up / put down <object> (to <object>), "
                     "with object types chair, armchair, sofa, stool, high stool, bed, table, "
                     "laptop, box, long box, cylinder, sphere. The scene has: " +
                     DescribeSceneObjects(scene_));
    }
  }
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
  if (v == "stand" && next(i + 1) == "up") {
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
  return Invalid("did not understand \"" + c +
                 "\"; commands start with sit, lie, rest, stand up, go to, walk to, approach, "
                 "touch, reach, put, place, stack, carry, bring, pick up, lean, cross, raise");
}

}  // namespace simhuman::language::offline
