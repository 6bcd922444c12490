// The general fallback of the offline planner: a command the rules refuse is read by slots
// (actions, objects, body parts in the order they occur) and planned by the rules' Session
// (fallback.h).

#include "simhuman/language/offline/fallback.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/rewrite.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {
namespace {

// the canonical verbs a frame starts with
const std::set<std::string>& Actions() {
  static const auto* words = new std::set<std::string>{
      "sit",   "lie",  "rest", "recline", "stand", "go",    "move",  "touch",
      "reach", "grab", "put",  "stack",   "carry", "type",  "lean",  "cross",
      "raise", "turn", "keep", "geton",   "use",   "place", "notice"};
  return *words;
}

// verbs that ask for nothing when said alone ("MARA turns, sits in the chair")
bool NeedsMore(const std::string& v) {
  static const std::set<std::string> kVerbs = {"turn",  "raise", "cross", "put",   "grab",
                                               "touch", "reach", "carry", "move",  "stack",
                                               "keep",  "use",   "geton", "place", "notice"};
  return kVerbs.count(v) > 0;
}

bool IsId(const std::string& w) {
  return std::any_of(w.begin(), w.end(), [](char c) { return std::isdigit(c) != 0; }) &&
         std::any_of(w.begin(), w.end(), [](char c) { return std::isalpha(c) != 0; });
}

bool InScene(const std::string& w, const core::SceneCatalog& scene) {
  if (scene.Find(w) != nullptr) return true;
  return IsId(w) && w.back() == 's' && scene.Find(w.substr(0, w.size() - 1)) != nullptr;
}

// a word of a normalised clause that refers to an object (type, part, id, pronoun)
bool RefersToObject(const std::string& w, const core::SceneCatalog& scene) {
  static const std::set<std::string> kPronouns = {"it", "them", "there", "that", "its"};
  return TypeWords().count(w) || PartWords().count(w) || kPronouns.count(w) || InScene(w, scene);
}

bool IsPoseWord(const std::string& w) { return (IsBodyWord(w) && w != "your") || w == "head"; }

// a raw word for a limb ("palms", "hands")
bool IsLimb(const std::string& w) {
  auto syn = Synonyms().find(w);
  return IsPoseWord(syn == Synonyms().end() ? w : syn->second);
}

// the verb a raw word reads as (lexicon, synonym or stem), or ""
std::string VerbOf(const std::string& w) {
  if (Actions().count(w)) return w;
  auto syn = Synonyms().find(w);
  if (syn != Synonyms().end() && Actions().count(syn->second)) return syn->second;
  if (LexiconWord(w)) return "";
  WordReading r = ReadWord(w);
  return r.kind == WordReading::kAction ? r.word : "";
}

// a raw word that names an object the fallback can read (known or by form), or a scene id
bool NamesObject(const std::string& w, const core::SceneCatalog& scene) {
  if (InScene(w, scene)) return true;
  std::string k = w;
  auto syn = Synonyms().find(w);
  if (syn != Synonyms().end()) k = syn->second;
  if (TypeWords().count(k) || PartWords().count(k)) return true;
  return !LexiconWord(w) && ReadWord(w).kind == WordReading::kObject;
}

bool Unreadable(const std::string& w, const core::SceneCatalog& scene) {
  return !LexiconWord(w) && !InScene(w, scene) && ReadWord(w).kind == WordReading::kUnknown;
}

// the words of the raw clause at words[k] (to the next "then"/"and") name an object
bool ObjectFollows(const Tokens& words, size_t k, const core::SceneCatalog& scene) {
  for (size_t m = k + 1; m < words.size() && words[m] != "then" && words[m] != "and"; ++m) {
    if (NamesObject(words[m], scene) || words[m] == "it" || words[m] == "them") return true;
  }
  return false;
}

// "the green cube must be placed upon the yellow cube", "the chair is to be sat on": a passive
// about an object is said as the order ("put the green cube upon ...", "sit on the chair")
Tokens Passive(const Tokens& words, const core::SceneCatalog& scene) {
  static const std::set<std::string> kAux = {"is",   "are",   "be",  "was",  "were",
                                             "been", "being", "get", "gets", "got"};
  static const std::set<std::string> kModal = {"must",  "should", "shall", "will",  "can",  "could",
                                               "would", "may",    "might", "needs", "need", "has",
                                               "have",  "is",     "are",   "to",    "be",   "also"};
  Tokens out;
  size_t c = 0;      // start of the clause in `words` (or after the last passive read in it)
  size_t out_c = 0;  // the same place in `out`
  for (size_t k = 0; k < words.size(); ++k) {
    if (words[k] == "then" || words[k] == "and") {
      c = k + 1;
      out_c = out.size() + 1;
    }
    const std::string p = k + 1 < words.size() ? words[k + 1] : std::string();
    const WordReading r = ReadWord(p);
    // a participle, or after "be"/"get" any verb form ("to be sat on": Reword says "sit")
    const bool participle = (p.size() > 3 && p.compare(p.size() - 2, 2, "ed") == 0) || p == "sat" ||
                            p == "laid" || p == "lain" || p == "put" || p == "set" || p == "held" ||
                            p == "brought" || (words[k] != "is" && words[k] != "are");
    bool subject = false;
    for (size_t m = c; m < k; ++m) subject = subject || NamesObject(words[m], scene);
    if (!kAux.count(words[k]) || !participle || r.kind != WordReading::kAction || !subject) {
      out.push_back(words[k]);
      continue;
    }
    Tokens np;
    for (size_t m = c; m < k; ++m) {
      if (!kModal.count(words[m])) np.push_back(words[m]);
    }
    out.resize(out_c);
    out.push_back(r.word);
    size_t after = k + 2;
    const std::string q = after < words.size() ? words[after] : std::string();
    const std::string q2 = after + 1 < words.size() ? words[after + 1] : std::string();
    if (OpensObject(q) && (q2.empty() || q2 == "by" || q2 == "then" || q2 == "and")) {
      out.push_back(q);  // a stranded preposition: "sat on (by the human)"
      ++after;
    }
    out.insert(out.end(), np.begin(), np.end());
    k = after - 1;
    c = after;
    out_c = out.size();
  }
  return out;
}

// whether the raw clause around words[k] has an action verb other than words[k]
bool OtherVerbInClause(const Tokens& words, size_t k) {
  size_t b = k, e = k + 1;
  while (b > 0 && words[b - 1] != "then" && words[b - 1] != "and") --b;
  while (e < words.size() && words[e] != "then" && words[e] != "and") ++e;
  for (size_t m = b; m < e; ++m) {
    if (m != k && !VerbOf(words[m]).empty()) return true;
  }
  return false;
}

// Reads the words (before normalisation) the fallback way: a word the lexicon does not know
// becomes its action or object word, is dropped (a name of the human, a time, a modifier), or
// is marked: "?w" heads an object phrase the scene cannot match ("the fridge"), "!w" is an
// unknown action at a clause start applied to an object ("kick the box") or joined by "and".
Tokens ReadWords(const Tokens& words, const core::SceneCatalog& scene) {
  static const std::set<std::string> kCopula = {"be", "been", "being", "was", "were", "am"};
  static const std::set<std::string> kPossessive = {"your", "ur",    "yr",  "his", "her",
                                                    "my",   "their", "its", "thy"};
  Tokens out;
  bool slot = false;  // the word before opens an object phrase (or continues one)
  for (size_t k = 0; k < words.size(); ++k) {
    const std::string& w = words[k];
    const std::string prev = k > 0 ? words[k - 1] : std::string();
    const std::string next = k + 1 < words.size() ? words[k + 1] : std::string();
    const bool opened = OpensObject(prev) || Colors().count(prev) || !VerbOf(prev).empty();
    // the human named as a subject or an agent ("by the human"), a copula ("is to be"), and
    // "one of the seats" (the seats)
    if (Subjects().count(w) || kCopula.count(w) || (w == "one" && next == "of")) continue;
    if (w == "of" && prev == "one") continue;
    // "supine", "prone": lying, unless the clause says the verb
    if ((w == "supine" || w == "prone") && !OtherVerbInClause(words, k)) {
      out.push_back("lie");
      continue;
    }
    if (!Unreadable(w, scene)) {
      slot = false;
      const WordReading r = LexiconWord(w) || InScene(w, scene) ? WordReading{} : ReadWord(w);
      if (r.kind == WordReading::kDrop) {
        if (!out.empty() && kPossessive.count(out.back())) out.pop_back();  // "your butt"
        continue;
      }
      out.push_back(r.kind == WordReading::kAction || r.kind == WordReading::kObject ? r.word : w);
      continue;
    }
    slot = slot || opened;
    // a clause start: only fillers so far since "then" / "and"
    size_t c = out.size();
    while (c > 0 && out[c - 1] != "then" && out[c - 1] != "and") --c;
    bool start = true;
    for (size_t m = c; m < out.size(); ++m) start = start && Fillers().count(out[m]);
    const bool noun_next = NamesObject(next, scene) || (!next.empty() && Unreadable(next, scene));
    if (start && !opened) {
      // an unknown verb that moves a limb onto something: "add both hands to the keyboard"
      size_t b = k + 1;
      while (b < words.size() &&
             (kPossessive.count(words[b]) || words[b] == "the" || words[b] == "left" ||
              words[b] == "right" || words[b] == "both")) {
        ++b;
      }
      if (b < words.size() && IsLimb(words[b])) {
        out.push_back("put");
        continue;
      }
      const bool coordinated = c > 0 && out[c - 1] == "and";
      // "plug the lamp in": an unknown action on an object the scene lacks
      const bool unknown_object = (next == "the" || next == "a" || kPossessive.count(next)) &&
                                  k + 2 < words.size() && Unreadable(words[k + 2], scene);
      if (coordinated || unknown_object || ObjectFollows(words, k, scene)) out.push_back("!" + w);
      continue;
    }
    if (slot && !noun_next) out.push_back("?" + w);
  }
  return out;
}

// one clause of the fallback's reading, and whether it names an object
struct Frame {
  Tokens words;
  bool sequenced = true;
  bool object = false;
};

// Splits a normalised clause at its action words: the words before the first action, then one
// frame per action (a verb after "with", "while", "your" or a body word is a pose of the frame
// before: "with lean back", "legs cross").
std::pair<Tokens, std::vector<Tokens>> SplitFrames(const Tokens& t) {
  Tokens pre;
  std::vector<Tokens> frames;
  for (size_t k = 0; k < t.size(); ++k) {
    const std::string prev = k > 0 ? t[k - 1] : std::string();
    const bool pose_verb = prev == "with" || prev == "while" || prev == "your" ||
                           IsPoseWord(prev) || (prev == "go" && t[k] != "go");
    if (Actions().count(t[k]) && !(pose_verb && !frames.empty())) {
      frames.emplace_back();
    }
    (frames.empty() ? pre : frames.back()).push_back(t[k]);
  }
  return {pre, frames};
}

// Cleans one frame: an unknown object ("?w") is dropped when the frame names a known object
// too (a detail: "sit on the chair by the window"), else the frame is refused; a put or carry
// never drops one ("put the box on the fridge").
absl::Status CleanFrame(Frame& f, const core::SceneCatalog& scene, const std::string& c) {
  static const std::set<std::string> kLead = {
      "near", "on",      "onto",     "in",     "at",       "to",      "of",      "from",    "with",
      "off",  "left_of", "right_of", "behind", "front_of", "against", "nearest", "farthest"};
  static const std::set<std::string> kMoving = {"put", "stack", "carry", "move", "place"};
  std::string unknown;
  bool known = false;
  const std::string& verb = f.words[f.words[0].compare(0, 4, "team") == 0 ? 1 : 0];
  for (const std::string& w : f.words) {
    if (w[0] == '?') unknown = w.substr(1);
    if (w[0] != '?' && w[0] != '!' && RefersToObject(w, scene) && !PartWords().count(w)) {
      known = true;  // an object, not only a part ("the top shelf" names no known object)
    }
  }
  f.object = known;
  auto trim = [&] {  // "sit on (by the human)", "go to (reproduce)": a relation with no object
    while (f.words.size() > 1 && kLead.count(f.words.back())) f.words.pop_back();
  };
  if (unknown.empty()) {
    f.words.erase(std::remove_if(f.words.begin(), f.words.end(),
                                 [](const std::string& w) { return w[0] == '!'; }),
                  f.words.end());
    trim();
    return absl::OkStatus();
  }
  if (!known || kMoving.count(verb)) {
    return Invalid("did not understand the word '" + unknown + "' in \"" + c +
                   "\"; the scene has: " + DescribeSceneObjects(scene));
  }
  Tokens kept;
  for (const std::string& w : f.words) {
    if (w[0] == '!') continue;
    if (w[0] == '?') {
      while (!kept.empty() && kept.size() > 1 && kLead.count(kept.back())) kept.pop_back();
      continue;
    }
    kept.push_back(w);
  }
  f.words = std::move(kept);
  trim();
  return absl::OkStatus();
}

// "notice <object>": the first object a verbless clause names ("the couch?", "Stool!"), so
// that "it" and an object-less action refer to it; empty when it names none
Tokens Topic(const Tokens& t, const core::SceneCatalog& scene) {
  for (size_t k = 0; k < t.size(); ++k) {
    const std::string& w = t[k];
    const auto type = TypeWords().find(w);
    if (!InScene(w, scene) && (type == TypeWords().end() || type->second.empty())) continue;
    Tokens out = {"notice"};
    size_t b = k;
    while (b > 0 && (Colors().count(t[b - 1]) || t[b - 1] == "big" || t[b - 1] == "small" ||
                     t[b - 1] == "tall" || t[b - 1] == "short")) {
      --b;
    }
    out.insert(out.end(), t.begin() + static_cast<long>(b), t.begin() + static_cast<long>(k));
    out.push_back(InScene(w, scene) ? w : type->second);  // "sofas" (the sofa's) -> "sofa"
    return out;
  }
  return {};
}

bool IsBase(const Frame& f) {
  const std::string& v = f.words.empty() ? std::string() : f.words[0];
  return v == "sit" || v == "lie" || v == "rest" || v == "recline";
}

bool OnlyLimbs(const Tokens& t) {
  return !t.empty() && std::all_of(t.begin(), t.end(), [](const std::string& w) {
    return IsPoseWord(w) || w == "your" || w == "left" || w == "right" || w == "both";
  });
}

// "Hands: pillow" (a form's label and value) -> "hands on pillow"; "Up!" -> "stand up"
std::vector<ClauseWords> JoinLabels(std::vector<ClauseWords> segments) {
  std::vector<ClauseWords> out;
  for (size_t k = 0; k < segments.size(); ++k) {
    ClauseWords s = std::move(segments[k]);
    if (OnlyLimbs(s.words) && k + 1 < segments.size() && !segments[k + 1].words.empty() &&
        !Actions().count(segments[k + 1].words[0])) {
      s.words.push_back("on");
      s.words.insert(s.words.end(), segments[k + 1].words.begin(), segments[k + 1].words.end());
      ++k;
    }
    if (!s.words.empty() && s.words[0] == "up") s.words = {"stand", "up"};
    out.push_back(std::move(s));
  }
  return out;
}

// Composes the frames of the segments in order (see FallbackClauses()).
class Composer {
 public:
  explicit Composer(const core::SceneCatalog& scene) : scene_(scene) {}

  absl::Status Add(const ClauseWords& s) {
    const std::string c = Join(s.words);
    auto [pre, parts] = SplitFrames(s.words);
    for (const std::string& w : pre) {
      if (w[0] == '!' && parts.empty()) {
        return Invalid("did not understand the action '" + w.substr(1) + "' in \"" + c + "\"");
      }
    }
    // "switch the television on, then ...": a clause without an action that opens with a word
    // the fallback cannot read and names an object the scene lacks is an unknown action
    if (parts.empty() && !pre.empty() && pre[0][0] != '?' && pre[0][0] != '!' &&
        !OpensObject(pre[0]) && !Fillers().count(pre[0]) && !RefersToObject(pre[0], scene_) &&
        std::any_of(pre.begin(), pre.end(), [](const std::string& w) { return w[0] == '?'; })) {
      return Invalid("did not understand the action '" + pre[0] + "' in \"" + c + "\"");
    }
    pre.erase(std::remove_if(pre.begin(), pre.end(),
                             [](const std::string& w) { return w[0] == '!' || w[0] == '?'; }),
              pre.end());
    bool sequenced = s.sequenced;
    if (std::any_of(pre.begin(), pre.end(), IsPoseWord)) {
      // a pose said without a verb joins the sit or lie before it, else waits for the next one
      // ("hands on the keyboard, seated on the chair")
      if (!frames_.empty() && based_) {
        frames_.push_back({pre, sequenced, true});
        sequenced = false;
      } else {
        poses_.push_back(pre);
      }
    } else if (Tokens topic = Topic(pre, scene_); !topic.empty()) {
      // an object named after an action that named none ("lie down. the bed.") comes first
      size_t at = frames_.size();
      if (!frames_.empty() && !frames_.back().object && parts.empty()) at = frames_.size() - 1;
      frames_.insert(frames_.begin() + static_cast<long>(at), Frame{topic, true, true});
    }
    // "you two carry ...": who carries goes with the next action
    for (const std::string& w : pre) {
      if (w.compare(0, 4, "team") == 0) team_ = w;
    }
    if (!team_.empty() && !parts.empty()) {
      parts[0].insert(parts[0].begin(), team_);
      team_.clear();
    }
    for (Tokens& part : parts) {
      Frame f{std::move(part), sequenced, false};
      sequenced = false;
      SH_RETURN_IF_ERROR(CleanFrame(f, scene_, c));
      if (f.words.size() == 1 && NeedsMore(f.words[0])) continue;
      any_action_ = true;
      based_ = IsBase(f) || (based_ && f.words[0] == "lean");
      frames_.push_back(std::move(f));
      if (based_) {
        for (Tokens& p : poses_) frames_.push_back({std::move(p), false, true});
        poses_.clear();
      }
    }
    return absl::OkStatus();
  }

  core::StatusOr<std::vector<ClauseWords>> Finish(const std::string& read) {
    for (Tokens& p : poses_) frames_.push_back({std::move(p), true, true});
    if (!any_action_) return Invalid("found no action to plan in \"" + read + "\"");
    std::vector<ClauseWords> out;
    for (Frame& f : frames_) out.push_back({std::move(f.words), f.sequenced});
    JoinClauses(out);
    return out;
  }

 private:
  const core::SceneCatalog& scene_;
  std::vector<Frame> frames_;
  std::vector<Tokens> poses_;  // verbless poses waiting for the sit or lie they belong to
  std::string team_;           // a team word waiting for its action
  bool any_action_ = false;
  bool based_ = false;  // the last frame sits or lies (or poses while doing so)
};

}  // namespace

core::StatusOr<std::vector<ClauseWords>> FallbackClauses(std::string_view command,
                                                         const core::SceneCatalog& scene) {
  SH_ASSIGN_OR_RETURN(Tokens raw, Tokenize(CodeToWords(command)));
  for (const std::string& w : raw) {
    if (IsNegation(w)) return Invalid("the command says what not to do ('" + w + "')");
  }
  raw = ReadSpokenForms(ApplyCorrections(raw));
  // the human's own body named as a whole ("your butt") goes before spelling is corrected
  Tokens words;
  for (const std::string& w : Reword(raw)) {
    if (LexiconWord(w) || ReadWord(w).kind != WordReading::kDrop) {
      words.push_back(w);
    } else if (!words.empty() && OpensObject(words.back()) && words.back() != "the") {
      words.pop_back();
    }
  }
  const Tokens read = Normalize(ReadWords(Passive(CorrectTypos(words), scene), scene));
  SH_ASSIGN_OR_RETURN(std::vector<ClauseWords> segments, SplitMarkedClauses(read));
  Composer composer(scene);
  for (const ClauseWords& s : JoinLabels(std::move(segments))) SH_RETURN_IF_ERROR(composer.Add(s));
  return composer.Finish(Join(read));
}

core::StatusOr<PlanResult> FallbackPlan(std::string_view command, const PlanContext& context) {
  if (context.scene == nullptr) return Invalid("no scene given to the planner");
  SH_ASSIGN_OR_RETURN(std::vector<ClauseWords> clauses, FallbackClauses(command, *context.scene));
  Session session(*context.scene, context);
  for (const ClauseWords& clause : clauses) {
    session.NextClause(clause.sequenced);
    SH_RETURN_IF_ERROR(session.Clause(clause.words));
  }
  return session.Finish();
}

}  // namespace simhuman::language::offline
