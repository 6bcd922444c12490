// Rewording of the offline planner on the raw words, before the lexicon: how people script a
// character ("NPC walks to the armchair, sits, rests its hands on both armrests, then gets
// up", "the robot is going to sit", "make him sit down"), gerund and past forms ("and then
// getting back up", "he walked over and sat down"), chat spellings ("ur", "goto"), numbered
// and framed steps ("1. sit", "Task: ..."), participle poses ("knees bent up", "with bent
// knees", "head raised off the pillow"), a pose said by what it avoids ("without touching the
// backrest", "don't touch the armrests"), the back as a body part ("rest your back against
// the backrest"), objects set down with a posture verb ("lay the ball on the box") and
// trailing purpose clauses ("so the foot stays flat"), which say nothing the pose does not.

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/rewrite.h"

namespace simhuman::language::offline {

// a character named as the subject of a scripted line, dropped at the start of a clause
const std::set<std::string>& Subjects() {
  static const auto* words = new std::set<std::string>{
      "npc",     "character", "agent",    "avatar",  "human",    "person",      "player",
      "he",      "she",       "they",     "hes",     "shes",     "theyre",      "man",
      "woman",   "guy",       "girl",     "boy",     "lady",     "gentleman",   "figure",
      "actor",   "actress",   "model",    "robot",   "bot",      "dummy",       "mannequin",
      "sim",     "puppet",    "patient",  "subject", "user",     "protagonist", "hero",
      "kid",     "child",     "humanoid", "char",    "chara",    "operator",    "client",
      "recruit", "cadet",     "trainee",  "guest",   "resident", "visitor"};
  return *words;
}

namespace {

// third-person, -ing and past forms of the verbs the lexicon reads, and chat spellings
const std::map<std::string, std::string>& VerbForms() {
  static const auto* words = new std::map<std::string, std::string>{
      {"walks", "walk"},       {"makes", "make"},       {"reaches", "reach"},
      {"lies", "lie"},         {"walking", "walk"},     {"gets", "get"},
      {"getting", "get"},      {"stands", "stand"},     {"crosses", "cross"},
      {"rests", "rest"},       {"puts", "put"},         {"putting", "put"},
      {"leans", "lean"},       {"goes", "go"},          {"going", "go"},
      {"moves", "move"},       {"moving", "move"},      {"places", "place"},
      {"placing", "place"},    {"picks", "pick"},       {"picking", "pick"},
      {"lifts", "lift"},       {"lifting", "lift"},     {"raises", "raise"},
      {"raising", "raise"},    {"turns", "turn"},       {"turning", "turn"},
      {"types", "type"},       {"carries", "carry"},    {"carrying", "carry"},
      {"bends", "bend"},       {"bending", "bend"},     {"grabs", "grab"},
      {"grabbing", "grab"},    {"takes", "take"},       {"taking", "take"},
      {"brings", "bring"},     {"bringing", "bring"},   {"stacks", "stack"},
      {"stacking", "stack"},   {"sets", "set"},         {"lays", "lay"},
      {"approaches", "go"},    {"approaching", "go"},   {"presses", "touch"},
      {"press", "touch"},      {"pressing", "touch"},   {"chill", "rest"},
      {"chills", "rest"},      {"chilling", "rest"},    {"ur", "your"},
      {"yr", "your"},          {"laying", "lie"},       {"layin", "lie"},
      {"lyin", "lie"},         {"sittin", "sit"},       {"touching", "touch"},
      {"tapping", "tap"},      {"taps", "tap"},         {"holding", "hold"},
      {"holds", "hold"},       {"heading", "head"},     {"heads", "head"},
      {"coming", "come"},      {"comes", "come"},       {"running", "run"},
      {"runs", "run"},         {"stepping", "step"},    {"steps", "step"},
      {"relaxing", "relax"},   {"relaxes", "relax"},    {"napping", "nap"},
      {"naps", "nap"},         {"sleeping", "sleep"},   {"sleeps", "sleep"},
      {"lounging", "lounge"},  {"lounges", "lounge"},   {"perching", "perch"},
      {"perches", "perch"},    {"settling", "settle"},  {"settles", "settle"},
      {"climbing", "climb"},   {"climbs", "climb"},     {"hopping", "hop"},
      {"hops", "hop"},         {"rising", "rise"},      {"strolls", "stroll"},
      {"strolling", "stroll"}, {"wanders", "wander"},   {"wandering", "wander"},
      {"uses", "use"},         {"using_", "use"},       {"works", "work"},
      {"working", "work"},     {"reclines", "recline"}, {"reclining_", "recline"},
      {"walked", "walk"},      {"went", "go"},          {"sat", "sit"},
      {"stood", "stand"},      {"laid", "lay"},         {"leaned", "lean"},
      {"leant", "lean"},       {"touched", "touch"},    {"reached", "reach"},
      {"rested", "rest"},      {"placed_", "place"},    {"moved", "move"},
      {"picked", "pick"},      {"grabbed", "grab"},     {"typed", "type"},
      {"raised_", "raise"},    {"turned", "turn"},      {"rolled", "roll"},
      {"approached", "go"},    {"headed", "head"},      {"stepped", "step"},
      {"came", "come"},        {"ran", "run"},          {"got", "get"},
      {"took", "take"},        {"stacked", "stack"},    {"carried", "carry"},
      {"brought", "bring"},    {"dropped", "drop"},     {"relaxed_", "relax"},
      {"napped", "nap"},       {"slept", "sleep"},      {"perched", "perch"},
      {"plopped", "plop"},     {"settled", "settle"},   {"climbed", "climb"},
      {"hopped", "hop"},       {"rose", "rise"},        {"tapped", "tap"},
      {"pressed", "touch"},    {"crossed_", "cross"},   {"lifted_", "lift"}};
  return *words;
}

// verbs a clause starts with (after "going to", "gonna")
bool IsVerbWord(const std::string& w) {
  static const std::set<std::string> kVerbs = {
      "sit",   "lie",   "lay",  "stand", "walk",  "go",    "touch",    "reach", "lean",
      "put",   "place", "type", "rest",  "get",   "take",  "grab",     "pick",  "move",
      "cross", "raise", "turn", "carry", "relax", "head",  "approach", "come",  "use",
      "have",  "try",   "set",  "stack", "lift",  "bring", "hop",      "crash", "chill"};
  return kVerbs.count(w) > 0;
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

// an object type or a synonym of one ("bed", "ball", "couch")
bool IsThing(const std::string& w) {
  auto syn = Synonyms().find(w);
  const std::string& type = syn != Synonyms().end() ? syn->second : w;
  auto t = TypeWords().find(type);
  return t != TypeWords().end() && !t->second.empty();
}

// "3", "2nd": a list number or ordinal (object ids have letters first)
bool IsNumber(const std::string& w) {
  if (w.empty() || !std::isdigit(static_cast<unsigned char>(w[0]))) return false;
  const size_t letters = w.find_first_not_of("0123456789");
  if (letters == std::string::npos) return true;
  const std::string suffix = w.substr(letters);
  return suffix == "st" || suffix == "nd" || suffix == "rd" || suffix == "th";
}

bool IsNumberWord(const std::string& w) {
  static const std::set<std::string> kWords = {"one", "two",   "three", "four", "five",
                                               "six", "seven", "eight", "nine", "ten"};
  return kWords.count(w) > 0 || IsNumber(w);
}

// "Task: ...", "Step 3: ...", "1. ...": framing before the words that say what to do; returns
// the words to skip at raw[i] (0: none)
size_t FramingAt(const Tokens& raw, size_t i, bool start) {
  static const std::set<std::string> kFrames = {
      "task",    "tasks",    "goal",     "instruction", "instructions", "command", "commands",
      "action",  "actions",  "todo",     "objective",   "directions",   "note",    "request",
      "mission", "sequence", "scenario", "prompt",      "order",        "orders",  "steps"};
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  if (IsNumber(raw[i])) return 1;
  // "SHOT 7 - ...", "Beat 3: ...", "Scene 2, ...": a label and its number open a clause
  if (start && IsNumber(at(i + 1)) && !IsVerbWord(raw[i]) && !Known(raw[i]) &&
      !Synonyms().count(raw[i])) {
    return 2;
  }
  if ((raw[i] == "step" || raw[i] == "steps") && IsNumberWord(at(i + 1))) return 2;
  if (start && kFrames.count(raw[i]) && (at(i + 1).empty() || at(i + 1) == "then")) return 1;
  return 0;
}

// a subject at raw[k] ("he", "the robot", "our guy"); returns its length (0: none)
size_t SubjectAt(const Tokens& raw, size_t k) {
  static const std::set<std::string> kDeterminers = {"the", "our", "my", "your", "this", "that"};
  if (k < raw.size() && Subjects().count(raw[k])) return 1;
  if (k + 1 < raw.size() && kDeterminers.count(raw[k]) && Subjects().count(raw[k + 1])) return 2;
  return 0;
}

// what follows a dropped subject: "is going to", "will", "needs to", "should" (length)
size_t AuxiliaryAt(const Tokens& raw, size_t k) {
  static const std::set<std::string> kAux = {
      "is",    "are",   "will", "should", "must", "can",   "could", "would", "shall", "may",
      "might", "needs", "has",  "wants",  "ll",   "gonna", "going", "about", "to",    "then"};
  size_t n = 0;
  while (k + n < raw.size() && kAux.count(raw[k + n]) && raw[k + n] != "then") ++n;
  return n;
}

// a subject at raw[k] followed (after auxiliaries) by a verb: "he walks", "he's leaning"
bool VerbAfterSubject(const Tokens& raw, size_t k) {
  k += SubjectAt(raw, k);
  k += AuxiliaryAt(raw, k);
  if (k >= raw.size()) return false;
  std::string w = raw[k];
  if (auto f = VerbForms().find(w); f != VerbForms().end()) w = f->second;
  if (w.size() > 3 && w.back() == 's' && IsVerbWord(w.substr(0, w.size() - 1))) return true;
  if (w.size() > 5 && w.compare(w.size() - 3, 3, "ing") == 0) {
    const std::string stem = w.substr(0, w.size() - 3);
    if (IsVerbWord(stem) || IsVerbWord(stem.substr(0, stem.size() - 1))) return true;
  }
  return IsVerbWord(w);
}

// "sits", "crosses", "picks": a third-person form of a verb the lexicon reads
bool IsThirdPerson(const std::string& w) {
  if (w.size() < 4 || w.back() != 's') return false;
  auto f = VerbForms().find(w);
  if (f != VerbForms().end()) return IsVerbWord(f->second) || Known(f->second);
  const std::string stem = w.substr(0, w.size() - 1);
  return IsVerbWord(stem) || (w.size() > 4 && w.compare(w.size() - 2, 2, "es") == 0 &&
                              IsVerbWord(w.substr(0, w.size() - 2)));
}

// a name at a clause start ("MARA turns", "Leo crosses to ..."): a word the lexicon does not
// know, nor an object word, right before a third-person verb
bool IsNamedSubject(const Tokens& raw, size_t i) {
  const std::string& w = raw[i];
  if (i + 1 >= raw.size() || !IsThirdPerson(raw[i + 1])) return false;
  if (Known(w) || IsVerbWord(w) || IsThing(w) || Fillers().count(w) || VerbForms().count(w)) {
    return false;
  }
  return std::none_of(w.begin(), w.end(), [](char c) { return std::isdigit(c); });
}

// "make him sit", "have the character walk", "I'd like the human to ...": the causer's verb
// (kept when it is part of a wrapper: "I want", "I'd like") and the subject are dropped
size_t CausativeAt(const Tokens& raw, size_t i, Tokens& out) {
  static const std::set<std::string> kCause = {"make", "have",  "let",  "get",  "tell",
                                               "ask",  "allow", "help", "want", "need",
                                               "like", "see",   "watch"};
  if (!kCause.count(raw[i])) return 0;
  size_t s = SubjectAt(raw, i + 1);
  if (s == 0 && i + 1 < raw.size() && (raw[i + 1] == "him" || raw[i + 1] == "her")) s = 1;
  if (s == 0) return 0;
  if (raw[i] == "want" || raw[i] == "need" || raw[i] == "like") out.push_back(raw[i]);
  size_t n = 1 + s;
  if (i + n < raw.size() && raw[i + n] == "to") ++n;
  return n;
}

// "don't touch the armrests", "without touching the backrest", "do not lean back": the pose
// they leave; returns the words used (0: none)
size_t AvoidedPose(const Tokens& raw, size_t i, Tokens& out) {
  size_t k = i + 1;
  if (raw[i] == "do" && (k >= raw.size() || raw[k] != "not")) return 0;
  if (raw[i] == "do") ++k;
  if (raw[i] != "without" && raw[i] != "dont" && raw[i] != "do" && raw[i] != "never") return 0;
  static const std::set<std::string> kGoing = {"go", "walk", "move", "head", "come", "run"};
  if (k < raw.size() && kGoing.count(raw[k])) return 0;  // "don't go to the back of the sofa"
  for (size_t e = std::min(raw.size(), k + 4); k < e && !IsSeparator(raw[k]); ++k) {
    const std::string& w = raw[k];
    if (w == "backrest" || w == "back" || w == "seatback") {
      if (k + 1 < raw.size() && raw[k + 1] == "rest") ++k;
      out.insert(out.end(), {"leaning", "forward"});
      return k + 1 - i;
    }
    if (w == "armrest" || w == "armrests" || w == "arms" ||
        (w == "arm" && k + 1 < raw.size() && raw[k + 1] == "rests")) {
      if (w == "arm") ++k;
      out.insert(out.end(), {"with", "hands", "off", "armrests"});
      return k + 1 - i;
    }
  }
  return 0;
}

// the words of one clause so far in `out` (after its last separator)
size_t ClauseStart(const Tokens& out) {
  size_t b = out.size();
  while (b > 0 && !IsSeparator(out[b - 1])) --b;
  return b;
}

// rules about the character's body: "its hands", "your arms", "your back against ...",
// "knees bent up", "with bent knees", "bring your knees up", "with your left"
bool RewordBody(const Tokens& raw, size_t& i, Tokens& out) {
  const std::string& w = raw[i];
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  const bool owner = w == "its" || w == "his" || w == "her" || w == "their";
  const bool yours = w == "your" || w == "ur" || w == "yr" || (owner && w != "its");
  // "its hands", "his left knee": the character's own body is "your"
  if (owner && (IsLimbAt(raw, i + 1) || IsBodyWord(at(i + 1)) || at(i + 1) == "side" ||
                ((at(i + 1) == "left" || at(i + 1) == "right") && at(i + 2) == "side"))) {
    out.push_back("your");
    return true;
  }
  // "your arms on the armrests": the hands; "your forearms": the elbows
  size_t a = i + 1;
  if (at(a) == "left" || at(a) == "right" || at(a) == "both") ++a;
  if (yours && (at(a) == "arm" || at(a) == "arms") && at(a + 1) != "rest" && at(a + 1) != "rests") {
    out.push_back("your");
    if (a > i + 1) out.push_back(raw[i + 1]);
    out.push_back(at(a) == "arm" ? "hand" : "hands");
    i = a;
    return true;
  }
  // "rest your back against the backrest", "with your back against it": leaning back
  if ((yours || w == "its") && at(i + 1) == "back" && (i == 0 || raw[i - 1] != "on")) {
    static const std::set<std::string> kAgainst = {"against", "on",   "into",    "to",
                                                   "onto",    "flat", "pressed", "firmly"};
    static const std::set<std::string> kVerbs = {"rest",  "put", "press", "keep", "push",
                                                 "place", "lay", "set",   "lean", "touch"};
    if (kAgainst.count(at(i + 2))) {
      if (!out.empty() && kVerbs.count(out.back())) out.pop_back();
      out.insert(out.end(), {"lean", "back"});
      ++i;
      return true;
    }
  }
  // "knees bent up", "head raised off the pillow": the limb is up
  if ((w == "bent" || w == "raised" || w == "lifted" || w == "flexed") && !out.empty() &&
      IsLimbAt(out, out.size() - 1)) {
    out.push_back("up");
    if (at(i + 1) == "up") ++i;
    if (at(i + 1) == "off") {
      size_t k = i + 2;
      if (at(k) == "the") ++k;
      if (at(k) == "pillow" || at(k) == "mattress" || at(k) == "bed") i = k;
    }
    return true;
  }
  // "elbow propped on the armrest", "hands resting on your knees": the limb is placed there
  static const std::set<std::string> kPlaced = {"resting",    "placed", "planted", "propped",
                                                "positioned", "folded", "clasped", "laid"};
  if (kPlaced.count(w) && !out.empty() && IsLimbAt(out, out.size() - 1)) {
    const std::string& limb = out.back();
    if (w == "propped" && (limb == "head" || limb == "knee" || limb == "knees")) {
      out.push_back("up");
    }
    return true;
  }
  // "arms on the armrests" said without "your": the hands
  if ((w == "arms" || w == "arm") && (at(i + 1) == "on" || at(i + 1) == "onto") &&
      (i == 0 || IsSeparator(raw[i - 1]) || raw[i - 1] == "with" || raw[i - 1] == "both")) {
    out.push_back(w == "arms" ? "hands" : "hand");
    return true;
  }
  // "with bent knees", "bring your knees up": raised
  if (((w == "bent" || w == "raised" || w == "lifted" || w == "flexed") && IsLimbAt(raw, i + 1)) ||
      (w == "bring" && (at(i + 1) == "your" || at(i + 1) == "ur") && IsLimbAt(raw, i + 2))) {
    out.push_back("raise");
    return true;
  }
  // "touch it with your left": the left hand; "lie on your right": the right side
  if ((w == "left" || w == "right") && i >= 2 && (at(i + 1).empty() || IsSeparator(at(i + 1)))) {
    if (raw[i - 2] == "with" || raw[i - 2] == "using") {
      out.insert(out.end(), {w, "hand"});
      return true;
    }
    if ((raw[i - 1] == "your" || raw[i - 1] == "ur") &&
        (raw[i - 2] == "on" || raw[i - 2] == "onto" || raw[i - 2] == "to")) {
      out.insert(out.end(), {w, "side"});
      return true;
    }
  }
  // "roll over to the left", "turn to your right": onto that side
  if (w == "roll" || w == "rolls" || w == "turn" || w == "turns") {
    for (size_t k = i + 1; k <= i + 4 && k < raw.size() && !IsSeparator(raw[k]); ++k) {
      if ((raw[k] == "left" || raw[k] == "right") &&
          (at(k + 1).empty() || IsSeparator(at(k + 1)))) {
        out.insert(out.end(), {"turn", "onto", "your", raw[k], "side"});
        i = k;
        return true;
      }
      if (raw[k] == "left" || raw[k] == "right") break;
    }
  }
  // "use your left hand to put ...": with the left hand
  if ((w == "use" || w == "using") &&
      (at(i + 1) == "your" || at(i + 1) == "ur" || at(i + 1) == "the")) {
    size_t k = i + 2;
    if (at(k) == "left" || at(k) == "right" || at(k) == "both") ++k;
    if (at(k) == "hand" || at(k) == "hands") {
      out.push_back("with");
      for (size_t m = i + 1; m <= k; ++m) out.push_back(raw[m]);
      i = at(k + 1) == "to" ? k + 1 : k;
      return true;
    }
  }
  return false;
}

// rules about objects: "lay/sit/rest the ball on the box" (put), "pick the box up", "lift the
// ball" (a grasp), "the blue can" (a cylinder), "the bed's left side", ids split at '_', "press
// a key on the laptop"
bool RewordObjects(const Tokens& raw, size_t& i, Tokens& out) {
  const std::string& w = raw[i];
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  static const std::set<std::string> kDeterminers = {"the",  "a",    "an",    "it",   "them",
                                                     "this", "that", "these", "those"};
  static const std::set<std::string> kPosture = {"lay",    "lays",  "laid",  "sit",
                                                 "sits",   "rest",  "rests", "stand",
                                                 "stands", "plonk", "plop",  "perch"};
  if (kPosture.count(w) && kDeterminers.count(at(i + 1))) {
    out.push_back("put");
    return true;
  }
  if ((w == "lay" || w == "lays" || w == "laid") &&
      (at(i + 1) == "your" || at(i + 1) == "ur" || at(i + 1) == "a" || at(i + 1) == "both" ||
       at(i + 1) == "one" || IsLimbAt(raw, i + 1))) {
    out.push_back("put");  // "lay your head on the pillow", "lay a hand on the table"
    return true;
  }
  // "crown the box with it": put it on the box; "keep the ball on the box": put it there
  if (w == "crown" && kDeterminers.count(at(i + 1))) {
    size_t e = i + 1;
    while (e < raw.size() && raw[e] != "with" && raw[e] != "then") ++e;
    if (at(e) == "with" && (at(e + 1) == "it" || at(e + 1) == "them")) {
      out.insert(out.end(), {"put", raw[e + 1], "on"});
      out.insert(out.end(), raw.begin() + static_cast<long>(i) + 1,
                 raw.begin() + static_cast<long>(e));
      i = e + 1;
      return true;
    }
  }
  if (w == "keep" && (at(i + 1) == "the" || at(i + 1) == "a") && !IsLimbAt(raw, i + 2)) {
    out.push_back("put");
    return true;
  }
  const size_t b = ClauseStart(out);
  static const std::set<std::string> kGrasp = {"pick", "lift", "grab", "take", "scoop"};
  if (w == "up" && out.size() > b + 1 && kGrasp.count(out[b]) &&
      (at(i + 1).empty() || IsSeparator(at(i + 1)) || at(i + 1) == "with" ||
       at(i + 1) == "using")) {
    return true;  // "pick the box up"
  }
  if ((w == "lift" || w == "lifts") && !IsLimbAt(raw, i + 1) &&
      !(at(i + 1) == "up" && (IsLimbAt(raw, i + 2) || at(i + 2) == "your")) &&
      at(i + 1) != "your" && at(i + 1) != "ur" && at(i + 1) != "them" && !IsSeparator(at(i + 1)) &&
      !at(i + 1).empty()) {
    out.push_back("grab");  // "lift the ball": a grasp (a carry when it is heavy)
    if (at(i + 1) == "up") ++i;
    return true;
  }
  if ((w == "can" || w == "cans") && i > 0 &&
      (kDeterminers.count(raw[i - 1]) || Colors().count(raw[i - 1]))) {
    out.push_back("cylinder");
    return true;
  }
  // "the bed's left side": the left side of the bed
  if (w.size() > 2 && w.back() == 's' && IsThing(w.substr(0, w.size() - 1)) &&
      (at(i + 1) == "left" || at(i + 1) == "right" || at(i + 1) == "front" ||
       at(i + 1) == "back") &&
      at(i + 2) == "side") {
    out.insert(out.end(), {raw[i + 1], "side", "of", w.substr(0, w.size() - 1)});
    i += 2;
    return true;
  }
  // "put the ball on the red box's left": left of the red box
  if (w.size() > 2 && w.back() == 's' && IsThing(w.substr(0, w.size() - 1)) &&
      (at(i + 1) == "left" || at(i + 1) == "right") &&
      (at(i + 2).empty() || IsSeparator(at(i + 2)))) {
    size_t p = out.size();
    while (p > 0 && (out[p - 1] == "the" || out[p - 1] == "a" || Colors().count(out[p - 1]))) --p;
    Tokens np(out.begin() + static_cast<long>(p), out.end());
    if (p > 0 && (out[p - 1] == "on" || out[p - 1] == "to" || out[p - 1] == "at")) --p;
    out.resize(p);
    out.insert(out.end(), {raw[i + 1], "of"});
    out.insert(out.end(), np.begin(), np.end());
    out.push_back(w.substr(0, w.size() - 1));
    ++i;
    return true;
  }
  if (IsSplitId(w, at(i + 1))) {
    out.push_back(w + "_" + raw[++i]);
    return true;
  }
  // "press a key on the laptop": the laptop's keyboard
  if ((w == "key" || w == "keys") && (at(i + 1) == "on" || at(i + 1) == "of")) {
    const size_t k = at(i + 2) == "the" ? i + 3 : i + 2;
    if (at(k).rfind("laptop", 0) == 0 || at(k) == "computer" || at(k) == "notebook") {
      out.insert(out.end(), {raw[k], "keyboard"});
      i = k;
      return true;
    }
  }
  return false;
}

bool IsGoing(const std::string& w) {
  static const std::set<std::string> kGoing = {"go",   "walk", "come",  "head", "run",   "move",
                                               "goes", "went", "back",  "want", "like",  "need",
                                               "have", "has",  "ought", "used", "going", "wants"};
  return kGoing.count(w) > 0;
}

// a verb of a purpose clause: one the lexicon reads, or an unknown word that is no object
bool IsPurposeVerb(const std::string& w) {
  if (w.empty() || IsSeparator(w) || IsThing(w) || IsNumber(w)) return false;
  static const std::set<std::string> kNot = {"the",   "a",    "your", "its",  "his",   "her",
                                             "my",    "it",   "them", "this", "that",  "left",
                                             "right", "both", "one",  "face", "stand", "sitting"};
  if (kNot.count(w) || Colors().count(w)) return false;
  return IsVerbWord(w) || !Known(w);
}

// homophones of speech-to-text: "than" between clauses (then), "the bad" (bed), "read"/"blew"
// before an object type (red/blue), "write hand" (right); returns the words used (0: none)
size_t Homophone(const Tokens& raw, size_t i, Tokens& out) {
  const std::string& w = raw[i];
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  const std::string prev = out.empty() ? std::string() : out.back();
  if (w == "than" && !out.empty() && IsVerbWord(at(i + 1))) {
    out.push_back("then");
    return 1;
  }
  if (w == "bad" && (prev == "the" || prev == "on" || prev == "onto" || prev == "in" ||
                     prev == "to" || prev == "off")) {
    out.push_back("bed");
    return 1;
  }
  if ((w == "read" || w == "blew") && IsThing(at(i + 1))) {
    out.push_back(w == "read" ? "red" : "blue");
    return 1;
  }
  if (w == "write" && IsLimbAt(raw, i + 1)) {
    out.push_back("right");
    return 1;
  }
  if (w == "thy" || w == "thine") {
    out.push_back("your");
    return 1;
  }
  // "stack it right on the box": an intensifier, not a side
  if (w == "right" && (at(i + 1) == "on" || at(i + 1) == "onto" || at(i + 1) == "into") &&
      (prev == "it" || prev == "them" || IsThing(prev))) {
    return 1;
  }
  return 0;
}

// chat spellings and clause-level rules: "goto", "chill out", "standing back up", a trailing
// purpose clause
bool RewordClause(const Tokens& raw, size_t& i, Tokens& out) {
  const std::string& w = raw[i];
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  if (w == "goto") {
    out.insert(out.end(), {"go", "to"});
    return true;
  }
  // "for him to sit": "for you to" (the wrappers know it)
  if (w == "for" && at(i + 2) == "to" &&
      (at(i + 1) == "him" || at(i + 1) == "her" || at(i + 1) == "them" || SubjectAt(raw, i + 1))) {
    out.insert(out.end(), {"for", "you", "to"});
    i += 2;
    return true;
  }
  // "let your hands rest": the hands rest
  if (w == "let" &&
      (at(i + 1) == "your" || at(i + 1) == "its" || at(i + 1) == "his" || at(i + 1) == "her")) {
    return true;
  }
  // "L hand", "R knee", "L armrest": the side spelled by its letter
  if ((w == "l" || w == "r") && (IsLimbAt(raw, i + 1) || at(i + 1).rfind("arm", 0) == 0)) {
    out.push_back(w == "l" ? "left" : "right");
    return true;
  }
  // "come to sit", "go to lie": the purpose is the action
  if ((w == "come" || w == "go" || w == "head") && at(i + 1) == "to" && IsVerbWord(at(i + 2)) &&
      at(i + 2) != "have") {
    out.push_back("go");
    ++i;
    return true;
  }
  const bool start = out.empty() || IsSeparator(out.back());
  // "please to sit", "make sit on the chair": the verb that follows
  const bool polite = !out.empty() && (out.back() == "please" || out.back() == "pls" ||
                                       out.back() == "kindly" || out.back() == "just");
  if (((w == "to" && (start || polite)) || w == "make" || w == "do") && IsVerbWord(at(i + 1))) {
    return true;
  }
  // "a) walk ... b) sit": a list letter
  if (w.size() == 1 && w != "a" && w != "i" && std::isalpha(static_cast<unsigned char>(w[0])) &&
      at(i + 1) == "then") {
    return true;
  }
  // "..., so the foot stays flat": a purpose clause says nothing the pose does not
  if (w == "so" && !start && out.back() != "ok" && out.back() != "okay") {
    static const std::set<std::string> kClause = {"that", "the", "your", "it", "its", "they", "my"};
    if (kClause.count(at(i + 1))) {
      while (i + 1 < raw.size() && raw[i + 1] != "then") ++i;
      return true;
    }
  }
  if (size_t n = Homophone(raw, i, out)) {
    i += n - 1;
    return true;
  }
  // "lean back to admire the view", "lie on the bed to rest": a purpose after a finished
  // clause (not "go to sit", not "next to", not an object after "to") says nothing more
  static const std::set<std::string> kFinished = {"back", "forward", "down", "there", "here"};
  if (w == "to" && !start && i >= 2 && IsPurposeVerb(at(i + 1)) && !IsGoing(raw[i - 2]) &&
      (IsThing(out.back()) || kFinished.count(out.back()))) {
    while (i + 1 < raw.size() && raw[i + 1] != "then") ++i;
    return true;
  }
  // "hold 10 s", "hold for 5 seconds": how long, not a grasp
  if (w == "hold" && (IsNumberWord(at(i + 1)) || (at(i + 1) == "for" && IsNumberWord(at(i + 2))) ||
                      at(i + 1) == "it" || at(i + 1).empty() || IsSeparator(at(i + 1)))) {
    while (i + 1 < raw.size() && raw[i + 1] != "then") ++i;
    return true;
  }
  // "the box in the corner", "the chair by the wall": a room feature says nothing
  static const std::set<std::string> kFeatures = {"corner", "wall", "window", "door", "doorway"};
  if ((w == "in" || w == "by" || w == "against" || w == "near") && at(i + 1) == "the" &&
      kFeatures.count(at(i + 2)) && !out.empty() && IsThing(out.back())) {
    i += 2;
    return true;
  }
  // "Exhausted from the dungeon, ...": a scene-setting participle opening the command
  if (out.empty() && !Known(w) && w.size() > 4 && w.compare(w.size() - 2, 2, "ed") == 0 &&
      !VerbForms().count(w) &&
      (at(i + 1) == "from" || at(i + 1) == "after" || at(i + 1) == "by" || at(i + 1) == "with")) {
    while (i + 1 < raw.size() && raw[i + 1] != "then") ++i;
    return true;
  }
  if (w == "chill" && at(i + 1) == "out") {
    out.push_back("rest");
    ++i;
    return true;
  }
  // "and then standing back up" (a bare "standing" is a filler)
  if (w == "standing" && (at(i + 1) == "up" || (at(i + 1) == "back" && at(i + 2) == "up"))) {
    out.push_back("stand");
    return true;
  }
  return false;
}

}  // namespace

Tokens Reword(const Tokens& raw) {
  Tokens out;
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  for (size_t i = 0; i < raw.size(); ++i) {
    const std::string& w = raw[i];
    bool start = true;  // only sequencing words and fillers so far in this clause
    for (size_t k = ClauseStart(out); k < out.size(); ++k) start = start && Fillers().count(out[k]);
    // "okay so in this one he walks ...": a subject before a verb starts the clause
    if (!start && SubjectAt(raw, i) > 0 && VerbAfterSubject(raw, i)) {
      out.resize(ClauseStart(out));
      start = true;
    }
    if (size_t n = FramingAt(raw, i, start)) {
      i += n - 1;
      continue;
    }
    if (start && IsNamedSubject(raw, i)) continue;
    // "NPC sits ...", "the character walks to ...", "then he gets up", "the robot will sit"
    if ((start || (!out.empty() && out.back() == "that")) && SubjectAt(raw, i) > 0) {
      i += SubjectAt(raw, i);
      i += AuxiliaryAt(raw, i);
      // "he's been working all day": what went before, not what to do
      if (at(i) == "been" || at(i) == "had") {
        while (i + 1 < raw.size() && raw[i + 1] != "then") ++i;
        continue;
      }
      // "he's leaning back": the progressive is the verb
      const std::string& v = at(i);
      if (v.size() > 5 && v.compare(v.size() - 3, 3, "ing") == 0) {
        std::string stem = v.substr(0, v.size() - 3);
        if (!IsVerbWord(stem)) stem.pop_back();  // "sitting"
        if (IsVerbWord(stem)) {
          out.push_back(stem);
          continue;
        }
      }
      --i;
      continue;
    }
    // "like he is listening": a simile says how, not what (to the clause's end)
    if (w == "like" && SubjectAt(raw, i + 1) > 0) {
      while (i + 1 < raw.size() && raw[i + 1] != "then") ++i;
      continue;
    }
    if (size_t n = CausativeAt(raw, i, out)) {
      i += n - 1;
      continue;
    }
    // "going to sit", "gonna lie down": the verb that follows
    if ((w == "going" || w == "about") && at(i + 1) == "to" && IsVerbWord(at(i + 2))) {
      ++i;
      continue;
    }
    if (size_t n = AvoidedPose(raw, i, out)) {
      i += n - 1;
      continue;
    }
    if (RewordBody(raw, i, out) || RewordObjects(raw, i, out) || RewordClause(raw, i, out)) {
      continue;
    }
    auto form = VerbForms().find(w);
    out.push_back(form != VerbForms().end() ? form->second : w);
  }
  return out;
}

}  // namespace simhuman::language::offline
