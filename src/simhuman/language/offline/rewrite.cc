#include "simhuman/language/offline/rewrite.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <utility>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/spatial.h"

namespace simhuman::language::offline {
namespace {

// every word the lexicon reads (not corrected)
const std::set<std::string>& Vocabulary() {
  static const auto* words = [] {
    auto* w = new std::set<std::string>();
    for (const auto& [from, to] : Phrases()) w->insert(from.begin(), from.end());
    for (const auto& [from, to] : Synonyms()) w->insert(from);
    w->insert(Fillers().begin(), Fillers().end());
    return w;
  }();
  return *words;
}

// the words a slip is corrected to: objects, parts, colours, body words, function words
const std::set<std::string>& Targets() {
  static const auto* words = [] {
    auto* w = new std::set<std::string>{
        "the",     "your",    "with",     "then",     "and",      "hand",    "hands",
        "elbow",   "elbows",  "knee",     "knees",    "foot",     "feet",    "legs",
        "stomach", "please",  "down",     "front",    "behind",   "left",    "right",
        "side",    "onto",    "back",     "top",      "sit",      "lie",     "stand",
        "walk",    "touch",   "reach",    "lean",     "cross",    "type",    "rest",
        "put",     "place",   "grab",     "carry",    "sitting",  "lying",   "standing",
        "walking", "leaning", "touching", "armrests", "backrest", "recline", "approach"};
    for (const auto& [from, to] : TypeWords()) {
      if (!to.empty()) w->insert(from);
    }
    for (const auto& [from, to] : PartWords()) w->insert(from);
    for (const auto& [from, to] : Synonyms()) {
      if (TypeWords().count(to) && !TypeWords().at(to).empty()) w->insert(from);
    }
    w->insert(Colors().begin(), Colors().end());
    return w;
  }();
  return *words;
}

bool IsTransposition(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  size_t i = 0;
  while (i < a.size() && a[i] == b[i]) ++i;
  return i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] &&
         a.compare(i + 2, std::string::npos, b, i + 2, std::string::npos) == 0;
}

}  // namespace

int EditDistance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

namespace {

bool Readable(const std::string& w) { return Known(w) || Vocabulary().count(w) > 0; }

// a word with a letter held down ("sitt", "bedd", "pleeease"), a plural or possessive of a
// known word ("boxs", "couches", "desks"): that word; "" when there is none
std::string KnownForm(const std::string& w) {
  std::string once;  // every run of a letter once
  for (char c : w) {
    if (once.empty() || once.back() != c) once += c;
  }
  if (once != w && Readable(once)) return once;
  std::string twice;  // runs of three or more letters twice ("coool")
  for (size_t i = 0; i < w.size(); ++i) {
    if (i >= 2 && w[i] == w[i - 1] && w[i] == w[i - 2]) continue;
    twice += w[i];
  }
  if (twice != w && Readable(twice)) return twice;
  for (size_t cut : {1, 2}) {
    if (w.size() > cut + 2 && w.back() == 's' && Readable(w.substr(0, w.size() - cut))) {
      return w.substr(0, w.size() - cut);
    }
  }
  return "";
}

}  // namespace

namespace {

// after a colour or size word a noun is due: a word one edit from exactly one object type is
// that type ("the yellow boy", "the high stoop")
std::string ObjectSlip(const std::string& before, const std::string& w) {
  static const std::set<std::string> kSizes = {"big", "small", "tall", "high", "short", "little"};
  if (!Colors().count(before) && !kSizes.count(before)) return "";
  if (Known(w) || Synonyms().count(w) || Fillers().count(w)) return "";
  std::string best;
  int count = 0;
  for (const auto& [word, type] : TypeWords()) {
    if (type.empty() || word.find('_') != std::string::npos) continue;
    if (EditDistance(w, word) == 1 && word != best) {
      best = word;
      ++count;
    }
  }
  return count == 1 ? best : "";
}

}  // namespace

Tokens CorrectTypos(const Tokens& raw) {
  Tokens out = raw;
  for (size_t k = 1; k < out.size(); ++k) {
    if (std::string s = ObjectSlip(out[k - 1], out[k]); !s.empty()) out[k] = s;
  }
  for (std::string& w : out) {
    if (w.size() < 3 || Readable(w)) continue;
    if (std::any_of(w.begin(), w.end(), [](char c) { return std::isdigit(c) != 0; })) continue;
    if (std::string k = KnownForm(w); !k.empty()) {
      w = k;
      continue;
    }
    const int allowed = w.size() >= 8 ? 2 : w.size() >= 5 ? 1 : 0;
    std::string best;
    int best_d = 3, count = 0;
    for (const std::string& t : Targets()) {
      const int d = IsTransposition(w, t) ? 1 : EditDistance(w, t);
      if (d > allowed && !(d == 1 && IsTransposition(w, t))) continue;
      if (d < best_d) {
        best = t;
        best_d = d;
        count = 1;
      } else if (d == best_d) {
        ++count;
      }
    }
    if (count == 1) w = best;
  }
  return out;
}

namespace {

// a self-correction at raw[i]: "no ," (a dash before it is a space), "actually (no)", "sorry
// ,", "I mean", "or rather", "wait no"; returns its length (0: none)
size_t CorrectionAt(const Tokens& raw, size_t i) {
  auto at = [&](size_t k) { return k < raw.size() ? raw[k] : std::string(); };
  size_t n = 0;
  if (raw[i] == "wait" && at(i + 1) == "no") n = 2;
  if (raw[i] == "actually" && at(i + 1) == "no") n = 2;
  if (raw[i] == "actually" && at(i + 1) == "then" && at(i + 2) == "no") n = 3;
  if (n == 0 && (raw[i] == "no" || raw[i] == "sorry" || raw[i] == "actually") &&
      at(i + 1) == "then") {
    n = 1;
  }
  if ((raw[i] == "i" && at(i + 1) == "mean") || (raw[i] == "or" && at(i + 1) == "rather")) n = 2;
  if (n == 0) return 0;
  while (at(i + n) == "then") ++n;
  return n;
}

// a side or colour word stands for its kind when a correction is aligned with what it corrects
std::string Shape(const std::string& w) {
  if (w == "left" || w == "right" || w == "both") return "<side>";
  if (Colors().count(w)) return "<colour>";
  return w;
}

}  // namespace

Tokens ApplyCorrections(const Tokens& raw) {
  Tokens out;
  for (size_t i = 0; i < raw.size(); ++i) {
    const size_t n = CorrectionAt(raw, i);
    if (n == 0) {
      out.push_back(raw[i]);
      continue;
    }
    // the correction Y runs to the next clause break; it replaces the part of the clause before
    // it that starts like Y (two words alike, else one; side and colour words alike by kind)
    while (!out.empty() && out.back() == "then") out.pop_back();  // the comma before the marker
    size_t b = out.size();
    while (b > 0 && out[b - 1] != "then" && out[b - 1] != "and") --b;
    size_t e = i + n;
    while (e < raw.size() && raw[e] != "then") ++e;
    const Tokens y(raw.begin() + static_cast<long>(i + n), raw.begin() + static_cast<long>(e));
    size_t from = out.size();
    for (int words = 2; words >= 1 && from == out.size() && !y.empty(); --words) {
      for (size_t p = b; p < out.size() && (words == 1 || from == out.size()); ++p) {
        bool same = Shape(out[p]) == Shape(y[0]);
        if (words == 2) {
          same = same && y.size() > 1 && p + 1 < out.size() && Shape(out[p + 1]) == Shape(y[1]);
        }
        if (same && (words == 1 || from == out.size())) from = p;  // two: the first; one: the last
      }
    }
    if (from < out.size()) out.resize(from);
    i += n - 1;  // Y follows as it is
  }
  return out;
}

namespace {

bool Contains(const Tokens& t, const std::string& w) {
  return std::find(t.begin(), t.end(), w) != t.end();
}

// "with your left hand" / "using both hands" and nothing else
bool IsInstrument(const Tokens& a) {
  if (a.empty() || (a[0] != "with" && a[0] != "using")) return false;
  for (size_t k = 1; k < a.size(); ++k) {
    if (a[k] != "your" && a[k] != "left" && a[k] != "right" && a[k] != "both" && a[k] != "hand" &&
        a[k] != "hands") {
      return false;
    }
  }
  return a.back() == "hand" || a.back() == "hands";
}

// an object named first ("red box on ...", "box002 on ..."): a clause without its verb
bool StartsWithObject(const Tokens& b) {
  if (b.empty()) return false;
  const std::string& w = b[0];
  auto type = TypeWords().find(w);
  return Colors().count(w) > 0 || (type != TypeWords().end() && !type->second.empty()) ||
         std::any_of(w.begin(), w.end(), [](char c) { return std::isdigit(c) != 0; });
}

// "lift them off" after "... your hands on the armrests": "raise your hands off armrests"
bool TakeThemOff(const std::vector<ClauseWords>& clauses, size_t k, Tokens& b) {
  if (b.size() != 3 || b[1] != "them" || b[2] != "off" ||
      (b[0] != "raise" && b[0] != "grab" && b[0] != "move")) {
    return false;
  }
  for (size_t p = k + 1; p-- > 0;) {
    const Tokens& a = clauses[p].words;
    for (size_t h = 0; h < a.size(); ++h) {
      if (a[h] != "hands" && a[h] != "hand") continue;
      const size_t on = static_cast<size_t>(
          std::find(a.begin() + static_cast<long>(h), a.end(), "on") - a.begin());
      if (on >= a.size()) continue;
      size_t from = h;
      while (from > 0 && (a[from - 1] == "your" || a[from - 1] == "left" ||
                          a[from - 1] == "right" || a[from - 1] == "both")) {
        --from;
      }
      Tokens joined = {"raise"};
      joined.insert(joined.end(), a.begin() + static_cast<long>(from),
                    a.begin() + static_cast<long>(on));
      joined.push_back("off");
      joined.insert(joined.end(), a.begin() + static_cast<long>(on) + 1, a.end());
      b = std::move(joined);
      return true;
    }
  }
  return false;
}

// verbs a clause may consist of alone ("sit", "go to") before its object comes as a clause
// of its own ("sit(chair)", "sofa. sit.") or is left out ("sit on the sofa, then the armchair")
bool IsBareVerb(const Tokens& a) {
  static const std::set<std::string> kVerbs = {"sit",   "lie",  "rest", "recline", "go",
                                               "touch", "grab", "type", "reach",   "notice"};
  if (a.empty() || a.size() > 2 || !kVerbs.count(a[0])) return false;
  return a.size() == 1 || a[1] == "to" || a[1] == "on" || a[1] == "in" || a[1] == "at";
}

// a clause that starts with a verb and names no object ("touch with left hand", "pick up")
bool WantsObject(const Tokens& c) {
  static const std::set<std::string> kVerbs = {"sit", "lie",  "rest",  "touch", "grab",
                                               "put", "type", "reach", "stack", "go"};
  if (c.empty() || !kVerbs.count(c[0])) return false;
  for (const std::string& w : c) {
    auto t = TypeWords().find(w);
    if ((t != TypeWords().end() && !t->second.empty()) || Colors().count(w) || w == "it" ||
        w == "them" || w == "there" ||
        std::any_of(w.begin(), w.end(), [](char ch) { return std::isdigit(ch) != 0; })) {
      return false;
    }
  }
  return true;
}

// an object alone, after an optional preposition ("the armchair", "on the stool", "it")
bool IsObjectOnly(const Tokens& b) {
  size_t i = 0;
  if (!b.empty() &&
      (b[0] == "on" || b[0] == "onto" || b[0] == "in" || b[0] == "at" || b[0] == "to")) {
    ++i;
  }
  if (i >= b.size()) return false;
  if (!StartsWithObject(Tokens(b.begin() + static_cast<long>(i), b.end())) && b[i] != "it" &&
      b[i] != "them" && !PartWords().count(b[i])) {
    return false;
  }
  for (size_t k = i; k < b.size(); ++k) {
    const std::string& w = b[k];
    const bool object_word =
        Colors().count(w) || TypeWords().count(w) || PartWords().count(w) || w == "it" ||
        w == "them" || w == "big" || w == "small" || w == "flat" || w == "left" || w == "right" ||
        w == "nearest" || w == "farthest" ||
        std::any_of(w.begin(), w.end(), [](char c) { return std::isdigit(c) != 0; });
    if (!object_word) return false;
  }
  return true;
}

bool HasRelation(const Tokens& b) {
  return std::any_of(b.begin() + 1, b.end(), [](const std::string& w) { return RelFromWord(w); });
}

// "before X, Y" and "Y after X": X first; "after X, Y" is in order already
void OrderBeforeAfter(std::vector<ClauseWords>& clauses) {
  for (size_t k = 0; k < clauses.size(); ++k) {
    Tokens& a = clauses[k].words;
    const size_t p = static_cast<size_t>(
        std::find_if(a.begin(), a.end(),
                     [](const std::string& w) { return w == "before" || w == "after"; }) -
        a.begin());
    if (p >= a.size()) continue;
    const bool before = a[p] == "before";
    Tokens head(a.begin(), a.begin() + static_cast<long>(p));
    Tokens tail(a.begin() + static_cast<long>(p) + 1, a.end());
    if (p == 0 && before && k + 1 < clauses.size() && !tail.empty()) {
      a = std::move(tail);  // "before you lie down, sit on the bed"
      std::swap(clauses[k], clauses[k + 1]);
      clauses[k].sequenced = clauses[k + 1].sequenced = true;
      ++k;
      continue;
    }
    if (head.empty() || tail.empty()) {
      a = head.empty() ? tail : head;
      continue;
    }
    a = before ? head : tail;
    ClauseWords second{before ? tail : head, true};
    clauses.insert(clauses.begin() + static_cast<long>(k) + 1, second);
    ++k;
  }
  clauses.erase(std::remove_if(clauses.begin(), clauses.end(),
                               [](const ClauseWords& c) { return c.words.empty(); }),
                clauses.end());
}

// clauses that are pieces of one: a verb and its object said apart, an object that takes the
// verb before it, a verbless placement ("red box on blue box"), a trailing instrument, and a
// grasp said twice ("grab the ball and hold it")
void JoinFragments(std::vector<ClauseWords>& clauses) {
  OrderBeforeAfter(clauses);
  // "climb onto the bar stool" with nothing after it: rest on it
  if (!clauses.empty() && !clauses.back().words.empty() && clauses.back().words[0] == "geton") {
    Tokens& last = clauses.back().words;
    last[0] = "on";
    last.insert(last.begin(), "rest");
  }
  for (size_t k = 0; k < clauses.size(); ++k) {
    Tokens& b = clauses[k].words;
    // "lean forward, then back (again)": the lean before
    if (k > 0 && !b.empty() && (b[0] == "back" || b[0] == "forward") && b.size() <= 2 &&
        Contains(clauses[k - 1].words, "lean")) {
      b.insert(b.begin(), "lean");
    }
    if (StartsWithObject(b) && HasRelation(b) && !IsObjectOnly(b) &&
        (k == 0 || clauses[k - 1].words.empty() ||
         (clauses[k - 1].words[0] != "put" && clauses[k - 1].words[0] != "stack" &&
          clauses[k - 1].words[0] != "move"))) {
      b.insert(b.begin(), "put");  // "red box on blue box"
    }
    if (k == 0) continue;
    Tokens& a = clauses[k - 1].words;
    // "go and sit. Then the box, touch with left hand": the box is the next clause's topic
    const bool topic = k + 1 < clauses.size() && WantsObject(clauses[k + 1].words);
    const bool join_verb = IsBareVerb(a) && IsObjectOnly(b) && !topic;
    const bool verb_after = IsObjectOnly(a) && IsBareVerb(b) && !IsBareVerb(a);
    const bool instrument = IsInstrument(b) && k + 1 == clauses.size();
    const bool regrasp = !a.empty() && a[0] == "grab" && b.size() == 2 && b[0] == "grab" &&
                         (b[1] == "it" || b[1] == "them");
    if (join_verb || instrument) {
      a.insert(a.end(), b.begin(), b.end());
    } else if (verb_after) {
      a.insert(a.begin(), b.begin(), b.end());
    } else if (!regrasp) {
      // "sit on the sofa, then (on) the armchair": the verb before
      static const std::set<std::string> kRepeat = {"sit", "lie", "rest", "recline", "touch", "go"};
      if (!topic && !a.empty() && kRepeat.count(a[0]) && IsObjectOnly(b) && b[0] != "it" &&
          b[0] != "them") {
        b.insert(b.begin(), a[0]);
      }
      continue;
    }
    clauses.erase(clauses.begin() + static_cast<long>(k));
    --k;
  }
}

}  // namespace

void JoinClauses(std::vector<ClauseWords>& clauses) {
  JoinFragments(clauses);
  for (size_t k = 0; k < clauses.size(); ++k) {
    Tokens& a = clauses[k].words;
    // "with your left hand put the box on ...": the instrument goes after what it does
    for (size_t h = 1; h + 1 < a.size() && IsInstrument(a) == false; ++h) {
      if ((a[h] != "hand" && a[h] != "hands") ||
          !IsInstrument(Tokens(a.begin(), a.begin() + h + 1))) {
        continue;
      }
      std::rotate(a.begin(), a.begin() + static_cast<long>(h) + 1, a.end());
      break;
    }
    // "sit with your hands on the keyboard": the seat at the laptop
    if (a.size() > 2 && a[0] == "sit" && a[1] == "with" &&
        (Contains(a, "keyboard") || Contains(a, "laptop"))) {
      a.insert(a.begin() + 1, {"at", "keyboard"});
    }
    if (k + 1 < clauses.size()) TakeThemOff(clauses, k, clauses[k + 1].words);
  }
  for (size_t k = 0; k + 1 < clauses.size(); ++k) {
    Tokens& a = clauses[k].words;
    Tokens& b = clauses[k + 1].words;
    if (a.size() == 1 && a[0] == "sit" && !b.empty() && b[0] == "type") {
      a = {"sit", "at", "keyboard"};
      continue;
    }
    // "with your left hand, put the red box on the cylinder": the hand ends the next clause
    if (IsInstrument(a)) {
      b.insert(b.end(), a.begin(), a.end());
      clauses[k + 1].sequenced = clauses[k].sequenced;
      clauses.erase(clauses.begin() + static_cast<long>(k));
      --k;
      continue;
    }
    // "put the ball on the cylinder, then the red box on the yellow one": the verb is kept
    const bool placing = !a.empty() && (a[0] == "put" || a[0] == "stack" || a[0] == "move");
    if (placing && StartsWithObject(b) &&
        std::any_of(b.begin(), b.end(), [](const std::string& w) { return RelFromWord(w); })) {
      b.insert(b.begin(), a[0]);
    }
    // "grab A [with your H hand]" + "put it REL B" (or "place REL B") -> "put A REL B [...]"
    const bool put = b.size() >= 2 && (b[0] == "put" || b[0] == "move" || b[0] == "stack") &&
                     ((b.size() >= 3 && b[1] == "it" && RelFromWord(b[2]).has_value()) ||
                      RelFromWord(b[1]).has_value());
    if (a.size() < 2 || a[0] != "grab" || !put) continue;
    const size_t skip = b[1] == "it" ? 2 : 1;
    const size_t with =
        static_cast<size_t>(std::find(a.begin(), a.end(), std::string("with")) - a.begin());
    Tokens joined = {"put"};
    joined.insert(joined.end(), a.begin() + 1, a.begin() + static_cast<long>(with));
    joined.insert(joined.end(), b.begin() + static_cast<long>(skip), b.end());
    joined.insert(joined.end(), a.begin() + static_cast<long>(with), a.end());
    clauses[k].words = std::move(joined);
    clauses.erase(clauses.begin() + static_cast<long>(k) + 1);
  }
}

void JoinParticipleBase(const Tokens& raw, std::vector<ClauseWords>& clauses) {
  if (raw.empty() || clauses.size() < 2) return;
  size_t k = 0;  // after a label ("Shot 10: lying on the bed, ...")
  if (raw.size() > 3 && raw[2] == "then" &&
      raw[1].find_first_not_of("0123456789") == std::string::npos) {
    k = 3;
  }
  if (raw[k] != "seated" && raw[k] != "sitting" && raw[k] != "lying") return;
  const Tokens& base = clauses[0].words;
  if (base.empty() || (base[0] != "sit" && base[0] != "lie")) return;
  clauses[1].sequenced = false;
}

}  // namespace simhuman::language::offline
