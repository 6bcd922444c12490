// Spoken verb forms on raw words (before Reword): reflexive and causative verbs ("set yourself on
// the chair", "let your hands rest on ..."), intensifiers ("lean right back"), encouragement and
// pleasantries that carry no action ("go on,", "I do hope ..."), "there" after an object, a
// verbless "over to X", a passive walk ("the chair is walked to"), and a movable object as the
// subject of its own placing ("the ball goes on the box").

#include <set>
#include <string>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/rewrite.h"

namespace simhuman::language::offline {
namespace {

std::string At(const Tokens& t, size_t k) { return k < t.size() ? t[k] : std::string(); }

// a clause break in raw words (punctuation is "then"), or the end
bool Break(const Tokens& t, size_t k) { return k >= t.size() || t[k] == "then" || t[k] == "and"; }

std::string Canonical(const std::string& w) {
  auto s = Synonyms().find(w);
  return s == Synonyms().end() ? w : s->second;
}

bool Body(const std::string& w) { return IsBodyWord(w) || IsBodyWord(Canonical(w)); }

// an object type word, also through a synonym ("desk", "ball", "couch")
bool TypeWord(const std::string& w) {
  auto t = TypeWords().find(Canonical(w));
  return t != TypeWords().end() && !t->second.empty();
}

bool Movable(const std::string& w) {
  static const std::set<std::string> kMovable = {"box",       "cylinder", "sphere",  "cone",
                                                 "hourglass", "mesh",     "long_box"};
  auto t = TypeWords().find(Canonical(w));
  return t != TypeWords().end() && kMovable.count(t->second) > 0;
}

const std::set<std::string>& Places() {
  static const auto* w =
      new std::set<std::string>{"on", "onto", "in", "into", "at", "upon", "atop", "down"};
  return *w;
}

// "set yourself on", "put yourself seated", "lay yourself down", "put you on the left side" at
// raw[i]: the words it stands for and its length (0: none)
size_t Reflexive(const Tokens& raw, size_t i, Tokens& out) {
  static const std::set<std::string> kPlace = {"set", "put",    "place",   "plant", "park",
                                               "lay", "sit",    "lie",     "plonk", "plop",
                                               "pop", "settle", "position"};
  const std::string& v = raw[i];
  const std::string self = At(raw, i + 1);
  if (!kPlace.count(v) || !(self == "yourself" || (self == "you" && v == "put"))) return 0;
  const bool lie = v == "lay" || v == "lie";
  size_t n = 2;
  // "put yourself on the left side": a turn onto that side
  size_t s = i + n;
  if (Places().count(At(raw, s)) && At(raw, s) != "down") ++s;
  if (At(raw, s) == "your" || At(raw, s) == "the") ++s;
  if ((At(raw, s) == "left" || At(raw, s) == "right") && At(raw, s + 1) == "side") {
    out = {"turn", "onto", "your", At(raw, s), "side"};
    return s + 2 - i;
  }
  if (At(raw, i + n) == "seated" || At(raw, i + n) == "sitting") {
    out = {"sit"};
    return n + 1;
  }
  if (At(raw, i + n) == "lying") {
    out = {"lie"};
    return n + 1;
  }
  if (!Places().count(At(raw, i + n)) && !Break(raw, i + n)) return 0;
  out = {lie ? "lie" : "sit"};
  return n;
}

// "let/allow your back rest against ...", "let both hands rest on ...", "make both knees high",
// "allow yourself to sink onto ..." at raw[i]
size_t Causative(const Tokens& raw, size_t i, Tokens& out) {
  const std::string& v = raw[i];
  if ((v == "let" || v == "allow") && At(raw, i + 1) == "yourself") {
    out = {};
    return At(raw, i + 2) == "to" ? 3 : 2;
  }
  if (v != "let" && v != "allow" && v != "make") return 0;
  size_t k = i + 1;
  Tokens body;
  while (k < raw.size() && k < i + 5 &&
         (Body(raw[k]) || raw[k] == "both" || raw[k] == "the" || raw[k] == "left" ||
          raw[k] == "right" ||
          (raw[k] == "back" && (At(raw, k - 1) == "your" || At(raw, k - 1) == "the")))) {
    body.push_back(raw[k] == "the" ? "your" : raw[k]);
    ++k;
  }
  bool named = false;
  for (const std::string& w : body) named = named || (Body(w) && w != "your") || w == "back";
  if (!named) return 0;
  if (At(raw, k) == "to") ++k;
  static const std::set<std::string> kRest = {"rest",  "lie",  "sit",  "hang",   "sink", "fall",
                                              "relax", "stay", "drop", "settle", "go",   "be"};
  static const std::set<std::string> kHigh = {"high", "higher", "up", "rise"};
  if (v == "make" ? !kHigh.count(At(raw, k)) : !kRest.count(At(raw, k))) return 0;
  if (v == "make") {
    out = {"raise"};
    out.insert(out.end(), body.begin(), body.end());
  } else if (body.back() == "back") {
    out = {"lean", "back"};  // "let your back rest against the backrest"
  } else {
    out = {"rest"};
    out.insert(out.end(), body.begin(), body.end());
  }
  return k + 1 - i;
}

// a first-person pleasantry or aside that opens a sentence ("I do hope you are keeping well",
// "I'm afraid my eyesight isn't what it was", "My late husband always typed that way"): the
// sentence, when it names no object type; 0 otherwise
size_t Aside(const Tokens& raw, size_t i) {
  if (i > 0 && raw[i - 1] != "then") return 0;
  const std::string a = At(raw, i), b = At(raw, i + 1), c = At(raw, i + 2);
  const bool opens = (a == "i" && (b == "hope" || b == "trust" || b == "fear" ||
                                   (b == "do" && c == "hope") || (b == "am" && c == "afraid"))) ||
                     (a == "im" && (b == "afraid" || b == "sorry")) ||
                     (a == "my" && !b.empty() && !Body(b) && !TypeWord(b));
  if (!opens) return 0;
  size_t e = i;
  while (e < raw.size() && raw[e] != "then") {
    if (TypeWord(raw[e])) return 0;
    ++e;
  }
  return e - i;
}

// "the chair is walked to", "the bed is approached": "go to the chair"
size_t PassiveWalk(const Tokens& raw, size_t i, Tokens& out) {
  if (i > 0 && !Break(raw, i - 1) && raw[i - 1] != "which") return 0;
  size_t k = i;
  while (k < raw.size() && k < i + 4 && raw[k] != "is" && !Break(raw, k)) ++k;
  if (k == i || At(raw, k) != "is" || !TypeWord(raw[k - 1])) return 0;
  if (raw[i] != "the" && !TypeWord(raw[i]) && !Colors().count(raw[i])) return 0;
  size_t e = k + 1;
  if (At(raw, e) == "then") ++e;
  if (At(raw, e) == "walked" && (At(raw, e + 1) == "to" || At(raw, e + 1) == "over")) {
    e += At(raw, e + 1) == "over" && At(raw, e + 2) == "to" ? 3 : 2;
  } else if (At(raw, e) == "approached") {
    ++e;
  } else {
    return 0;
  }
  out = {"go", "to"};
  out.insert(out.end(), raw.begin() + static_cast<long>(i), raw.begin() + static_cast<long>(k));
  return e - i;
}

// "the ball goes on the box", "the red block wants to sit on the cylinder": "put the ball on
// the box" (any object for go/belong; a movable one for sit/rest); `start` opens a sentence
size_t ObjectSubject(const Tokens& raw, size_t i, Tokens& out) {
  if (raw[i] != "the" || (i > 0 && raw[i - 1] != "then" && !Fillers().count(raw[i - 1]))) return 0;
  size_t k = i + 1;
  while (k < raw.size() && k < i + 4 && !Break(raw, k)) {
    const std::string& w = raw[k];
    size_t e = k + 1;
    bool sit_like = false;
    if (At(raw, e) == "wants" || At(raw, e) == "needs" || At(raw, e) == "has") {
      if (At(raw, e + 1) != "to") return 0;
      e += 2;
    } else if (At(raw, e) == "should" || At(raw, e) == "must") {
      ++e;
    }
    static const std::set<std::string> kGo = {"goes", "go", "belongs", "belong"};
    static const std::set<std::string> kSit = {"sit", "sits", "rest", "rests"};
    sit_like = kSit.count(At(raw, e)) > 0;
    if ((kGo.count(At(raw, e)) || (sit_like && Movable(w))) && !Subjects().count(w) && !Body(w) &&
        (Places().count(At(raw, e + 1)) || At(raw, e + 1) == "next")) {
      out = {"put"};
      out.insert(out.end(), raw.begin() + static_cast<long>(i),
                 raw.begin() + static_cast<long>(k + 1));
      return e + 1 - i;
    }
    ++k;
  }
  return 0;
}

// the end of the sentence or clause from raw[k] (the next "then" or "and", or the end)
size_t ClauseEnd(const Tokens& raw, size_t k) {
  while (k < raw.size() && raw[k] != "then" && raw[k] != "and") ++k;
  return k;
}

// whether raw[b, e) names an object type, an object part or a limb
bool NamesSomething(const Tokens& raw, size_t b, size_t e) {
  for (size_t k = b; k < e; ++k) {
    const std::string w = Canonical(raw[k]);
    if (TypeWord(raw[k]) || PartWords().count(w) || (Body(raw[k]) && raw[k] != "your")) return true;
  }
  return false;
}

// a clause that carries no action, at its start raw[i]: "if it isn't too much bother", "please
// forgive the typing", "feel how it tilts", a recipe's "leave to rest for five minutes"; its
// length (0: none)
size_t EmptyClause(const Tokens& raw, size_t i) {
  static const std::set<std::string> kBefore = {"then", "and", "so", "please"};
  if (i > 0 && !kBefore.count(raw[i - 1])) return 0;
  const std::string& w = raw[i];
  const size_t e = ClauseEnd(raw, i + 1);
  static const std::set<std::string> kPolite = {"bother", "trouble", "mind", "possible"};
  bool polite = false;
  for (size_t k = i; k < e; ++k) polite = polite || kPolite.count(raw[k]) > 0;
  if (w == "if" && polite && !NamesSomething(raw, i, e)) return e - i;
  if ((w == "forgive" || w == "excuse" || w == "pardon") && !NamesSomething(raw, i, e))
    return e - i;
  if (w == "feel" && (At(raw, i + 1) == "how" || !NamesSomething(raw, i + 1, e))) return e - i;
  if (w == "leave" && At(raw, i + 1) == "to") return ClauseEnd(raw, i) == i ? 0 : e - i;
  return 0;
}

// "give the laptop a (bit of a | quick) type": type on it; "do a little typing": type
size_t TypeIdiom(const Tokens& raw, size_t i, Tokens& out) {
  if (raw[i] == "do" && (At(raw, i + 1) == "a" || At(raw, i + 1) == "some")) {
    size_t k = i + 2;
    while (k < i + 5 && (At(raw, k) == "little" || At(raw, k) == "bit" || At(raw, k) == "of" ||
                         At(raw, k) == "quick" || At(raw, k) == "spot")) {
      ++k;
    }
    if (At(raw, k) != "typing") return 0;
    out = {"type"};
    return k + 1 - i;
  }
  if (raw[i] != "give") return 0;
  size_t k = i + 1;
  while (k < raw.size() && k < i + 5 && raw[k] != "a") ++k;
  if (At(raw, k) != "a" || k == i + 1 || !TypeWord(raw[k - 1])) return 0;
  size_t e = k + 1;
  while (e < k + 5 && (At(raw, e) == "bit" || At(raw, e) == "of" || At(raw, e) == "a" ||
                       At(raw, e) == "quick" || At(raw, e) == "little")) {
    ++e;
  }
  if (At(raw, e) != "type" && At(raw, e) != "tap") return 0;
  out = {"type", "on"};
  out.insert(out.end(), raw.begin() + static_cast<long>(i + 1), raw.begin() + static_cast<long>(k));
  return e + 1 - i;
}

// a limb before its verb at a clause start (topic first): "right hand put on right knee" ->
// "put right hand on right knee"
size_t LimbFirst(const Tokens& raw, size_t i, Tokens& out) {
  if (i > 0 && raw[i - 1] != "then" && raw[i - 1] != "and") return 0;
  size_t k = i;
  bool limb = false;
  while (k < raw.size() && k < i + 4 &&
         (Body(raw[k]) || raw[k] == "left" || raw[k] == "right" || raw[k] == "both")) {
    limb = limb || (Body(raw[k]) && raw[k] != "your");
    ++k;
  }
  static const std::set<std::string> kPut = {"put", "place", "rest", "lay", "set"};
  if (!limb || !kPut.count(At(raw, k)) || !Places().count(At(raw, k + 1))) return 0;
  out = {"put"};
  out.insert(out.end(), raw.begin() + static_cast<long>(i), raw.begin() + static_cast<long>(k));
  return k + 1 - i;
}

// one-word and short readings at raw[i]; the words they stand for in `out`, the length used
size_t Short(const Tokens& raw, size_t i, Tokens& out) {
  const std::string& w = raw[i];
  const std::string p = i > 0 ? raw[i - 1] : std::string("then");
  out = {};
  // "lean right back", "sink right down into it": "right" is an intensifier there
  static const std::set<std::string> kDirection = {"back", "down", "on",   "onto",   "in",
                                                   "into", "up",   "over", "across", "forward"};
  static const std::set<std::string> kNotAfter = {"your", "the",  "my",   "his",  "her",
                                                  "and",  "then", "both", "left", "their"};
  if (w == "right" && kDirection.count(At(raw, i + 1)) && !kNotAfter.count(p)) return 1;
  // "go on, sit down", "ah go on and sit": encouragement, not a walk
  if (w == "go" && At(raw, i + 1) == "on" && Break(raw, i + 2)) {
    return At(raw, i + 2) == "and" ? 3 : 2;
  }
  // "lie on the bed there", "the desk there": "there" points at the object just named
  const bool named = TypeWords().count(Canonical(p)) > 0 || p == "yoke";
  if (w == "there" && i > 0 &&
      ((named && Break(raw, i + 1)) ||
       (Places().count(At(raw, i + 1)) && At(raw, i + 1) != "down")))
    return 1;
  // "would you ever ...": a polite request; "have a go on the armchair": try it out
  if (w == "ever" && p == "you") return 1;
  if (w == "have" && At(raw, i + 1) == "a" && At(raw, i + 2) == "go" &&
      (At(raw, i + 3) == "on" || At(raw, i + 3) == "in")) {
    out = {"use"};
    return 4;
  }
  // "over to the stool for me, perch on it": a walk without its verb
  if (w == "over" && At(raw, i + 1) == "to" && p == "then") {
    out = {"go", "to"};
    return 2;
  }
  // "hold it.", "hold that": keep the pose just taken (no new step)
  if (w == "hold" && p == "then") {
    static const std::set<std::string> kPose = {"it", "that", "this", "still", "the"};
    size_t e = i + 1;
    if (kPose.count(At(raw, e))) ++e;
    if (At(raw, e) == "pose" || At(raw, e) == "position") ++e;
    if (e > i + 1 && Break(raw, e)) return e - i;
  }
  // "until done", "till you are done": when to stop, not a step
  if (w == "until" || w == "till") {
    size_t e = i + 1;
    if (At(raw, e) == "youre") ++e;
    if (At(raw, e) == "you" && At(raw, e + 1) == "are") e += 2;
    if (At(raw, e) == "done" || At(raw, e) == "finished") return e + 1 - i;
  }
  // "lay the hands on the knees", "the back against the backrest": a limb with "the" is yours
  // (not "the back of the chair", "the head of the bed")
  if ((w == "the" || w == "your") && At(raw, i + 1) == "back" && At(raw, i + 2) == "against") {
    // a verbless "(the) back against the backrest" is a pose of the sit it follows
    out = p == "then" ? Tokens{"with", "your"} : Tokens{"your"};
    return 1;
  }
  if (w == "the" && At(raw, i + 2) != "of" && Body(At(raw, i + 1)) && At(raw, i + 1) != "your") {
    out = {"your"};
    return 1;
  }
  // "As a tester(,) I want ...": a user story's role, not a subject
  if (w == "as" && (At(raw, i + 1) == "a" || At(raw, i + 1) == "an") &&
      (At(raw, i + 3) == "i" || (At(raw, i + 3) == "then" && At(raw, i + 4) == "i"))) {
    return 3;
  }
  // "your two hands": both
  if (w == "two" && Body(At(raw, i + 1))) {
    out = {"both"};
    return 1;
  }
  // "lay the hands on the knees": a body part after "lay" is put there
  if (w == "lay") {
    static const std::set<std::string> kDet = {"the", "both", "your", "his", "her", "my"};
    const std::string limb = kDet.count(At(raw, i + 1)) ? At(raw, i + 2) : At(raw, i + 1);
    if (Body(limb) && limb != "your" && Canonical(limb) != "head") {
      out = {"put"};
      return 1;
    }
  }
  // "is then seated on", "and is sat down on": the passive of sitting
  if (w == "is" && p == "and" &&
      (At(raw, i + 1) == "seated" || (At(raw, i + 1) == "then" && At(raw, i + 2) == "seated"))) {
    out = At(raw, i + 1) == "then" ? Tokens{"then", "sit"} : Tokens{"sit"};
    return At(raw, i + 1) == "then" ? 3 : 2;
  }
  // ", where it types": and types
  if (w == "where" &&
      (At(raw, i + 1) == "it" || At(raw, i + 1) == "he" || At(raw, i + 1) == "she")) {
    out = {"and"};
    return 2;
  }
  if (w == "after" && At(raw, i + 1) == "which") {
    out = {"then"};
    return 2;
  }
  // "pop down onto the chair": sit ("pop the ball on the box" stays a put)
  if (w == "pop" && At(raw, i + 1) == "down") {
    out = {"sit"};
    return 2;
  }
  // "try the sofa", "try out this desk chair": that seat is the one meant; "try to sit": sit
  if (w == "try" && At(raw, i + 1) == "to") return 2;
  if (w == "try" && (At(raw, i + 1) == "out" || At(raw, i + 1) == "the" ||
                     At(raw, i + 1) == "this" || TypeWord(At(raw, i + 1)))) {
    out = {"notice"};
    return At(raw, i + 1) == "out" ? 2 : 1;
  }
  // "that red yoke", "this desk chair": a determiner before a colour or type
  if ((w == "that" || w == "this") && (Colors().count(At(raw, i + 1)) || TypeWord(At(raw, i + 1))))
    return 1;
  // "sink (slowly) down onto the chair", "sink into it": sit
  if (w == "sink") {
    size_t k = i + 1;
    if (At(raw, k).size() > 3 && At(raw, k).compare(At(raw, k).size() - 2, 2, "ly") == 0) ++k;
    if (At(raw, k) == "right") ++k;
    if (Places().count(At(raw, k))) {
      out = {"sit"};
      return 1;
    }
  }
  // "do not lie down": "don't" (a negated clause after what to do is dropped as a correction)
  if (w == "do" && At(raw, i + 1) == "not") {
    out = {"dont"};
    return 2;
  }
  // "fold both hands over your stomach": on it
  if (w == "fold" && (Body(At(raw, i + 1)) || At(raw, i + 1) == "both")) {
    out = {"put"};
    return 1;
  }
  if (w == "over" && (p == "hands" || p == "hand") &&
      (At(raw, i + 1) == "your" || At(raw, i + 1) == "the")) {
    out = {"on"};
    return 1;
  }
  // "!stack red yellow": the first colour onto the second
  if (w == "stack" && Colors().count(At(raw, i + 1)) && Colors().count(At(raw, i + 2)) &&
      Break(raw, i + 3)) {
    out = {"stack", At(raw, i + 1), "onto", At(raw, i + 2)};
    return 3;
  }
  if (w == "writing" && TypeWord(At(raw, i + 1))) return 1;  // "the writing desk"
  if (w == "border" || w == "rim") {                         // "the border of the bed"
    out = {"edge"};
    return 1;
  }
  if (w == "yoke") {  // Irish English: a thing
    out = {"thing"};
    return 1;
  }
  return 0;
}

}  // namespace

Tokens ReadSpokenForms(const Tokens& raw) {
  Tokens out;
  for (size_t i = 0; i < raw.size();) {
    Tokens words;
    size_t n = Reflexive(raw, i, words);
    if (n == 0) n = Causative(raw, i, words);
    if (n == 0 && (n = Aside(raw, i)) > 0) words = {};
    if (n == 0) n = PassiveWalk(raw, i, words);
    if (n == 0 && (n = EmptyClause(raw, i)) > 0) words = {};
    if (n == 0) n = TypeIdiom(raw, i, words);
    if (n == 0) n = LimbFirst(raw, i, words);
    if (n == 0) n = ObjectSubject(raw, i, words);
    if (n == 0) n = Short(raw, i, words);
    if (n == 0) {
      out.push_back(raw[i++]);
      continue;
    }
    // ", where it types": the relative joins its clause like a bare "and"
    if (!words.empty() && words[0] == "and" && !out.empty() && out.back() == "then") out.pop_back();
    out.insert(out.end(), words.begin(), words.end());
    i += n;
  }
  return out;
}

}  // namespace simhuman::language::offline
