// The fallback's word readings: action verbs by stem, object words by plural and spelling, and
// the words that name the human or a time (fallback.h).

#include <map>
#include <set>
#include <string>

#include "simhuman/language/offline/fallback.h"
#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/rewrite.h"

namespace simhuman::language::offline {
namespace {

// verb stems -> the canonical verb the rules read (base forms and irregular forms): sitting,
// lying, resting, standing up
const std::map<std::string, std::string>& ActionStems() {
  static const auto* words = new std::map<std::string, std::string>{
      // sitting
      {"sit", "sit"},
      {"sat", "sit"},
      {"seat", "sit"},
      {"perch", "sit"},
      {"plop", "sit"},
      {"plonk", "sit"},
      {"plunk", "sit"},
      {"settle", "sit"},
      {"squat", "sit"},
      {"park", "sit"},
      {"sink", "sit"},
      {"sank", "sit"},
      {"sunk", "sit"},
      {"slump", "sit"},
      {"slouch", "sit"},
      {"straddle", "sit"},
      {"ensconce", "sit"},
      // lying
      {"lie", "lie"},
      {"lay", "lie"},
      {"lain", "lie"},
      {"stretch", "lie"},
      {"sprawl", "lie"},
      {"sleep", "lie"},
      {"slept", "lie"},
      {"nap", "lie"},
      {"snooze", "lie"},
      {"doze", "lie"},
      {"slumber", "lie"},
      {"kip", "lie"},
      {"supine", "lie"},
      {"prone", "lie"},
      {"recumbent", "lie"},
      {"recline", "recline"},
      // resting (sit on a seat, lie on a bed)
      {"rest", "rest"},
      {"relax", "rest"},
      {"lounge", "rest"},
      {"unwind", "rest"},
      {"repose", "rest"},
      {"loll", "rest"},
      {"nestle", "rest"},
      {"snuggle", "rest"},
      {"flop", "rest"},
      {"collapse", "rest"},
      // standing up
      {"stand", "stand"},
      {"stood", "stand"},
      {"rise", "stand"},
      {"rose", "stand"},
      {"risen", "stand"},
      {"arise", "stand"},
      {"arose", "stand"},
  };
  return *words;
}

// verb stems of going, touching, holding, putting and carrying (see ActionStems())
const std::map<std::string, std::string>& MovingStems() {
  static const auto* words = new std::map<std::string, std::string>{
      // going
      {"go", "go"},
      {"went", "go"},
      {"gone", "go"},
      {"walk", "go"},
      {"stroll", "go"},
      {"amble", "go"},
      {"wander", "go"},
      {"approach", "go"},
      {"advance", "go"},
      {"proceed", "go"},
      {"march", "go"},
      {"stride", "go"},
      {"strode", "go"},
      {"saunter", "go"},
      {"mosey", "go"},
      {"trot", "go"},
      {"jog", "go"},
      {"run", "go"},
      {"ran", "go"},
      {"sprint", "go"},
      {"dash", "go"},
      {"hurry", "go"},
      {"rush", "go"},
      {"hasten", "go"},
      {"hike", "go"},
      {"trek", "go"},
      {"pace", "go"},
      {"come", "go"},
      {"came", "go"},
      {"travel", "go"},
      {"sidle", "go"},
      {"shuffle", "go"},
      {"hobble", "go"},
      {"limp", "go"},
      {"toddle", "go"},
      {"waddle", "go"},
      {"stagger", "go"},
      {"creep", "go"},
      {"crept", "go"},
      {"sneak", "go"},
      {"snuck", "go"},
      {"tiptoe", "go"},
      {"glide", "go"},
      {"meander", "go"},
      {"roam", "go"},
      {"return", "go"},
      {"visit", "go"},
      {"navigate", "go"},
      {"scurry", "go"},
      {"scamper", "go"},
      {"head", "go"},
      {"step", "go"},
      {"move", "move"},
      // touching and holding
      {"touch", "touch"},
      {"reach", "reach"},
      {"tap", "touch"},
      {"pat", "touch"},
      {"slap", "touch"},
      {"smack", "touch"},
      {"poke", "touch"},
      {"prod", "touch"},
      {"press", "touch"},
      {"feel", "touch"},
      {"felt", "touch"},
      {"rub", "touch"},
      {"stroke", "touch"},
      {"brush", "touch"},
      {"caress", "touch"},
      {"pet", "touch"},
      {"graze", "touch"},
      {"knock", "touch"},
      {"thump", "touch"},
      {"contact", "touch"},
      {"grab", "grab"},
      {"grasp", "grab"},
      {"grip", "grab"},
      {"clutch", "grab"},
      {"clasp", "grab"},
      {"seize", "grab"},
      {"hold", "grab"},
      {"held", "grab"},
      // putting and carrying
      {"put", "put"},
      {"place", "put"},
      {"set", "put"},
      {"position", "put"},
      {"deposit", "put"},
      {"stack", "stack"},
      {"pile", "stack"},
      {"carry", "carry"},
      {"bring", "carry"},
      {"brought", "carry"},
      {"haul", "carry"},
      {"lug", "carry"},
      {"tote", "carry"},
      {"ferry", "carry"},
      {"transport", "carry"},
      {"fetch", "carry"},
      {"deliver", "carry"},
      // poses and typing
      {"lean", "lean"},
      {"leant", "lean"},
      {"tilt", "lean"},
      {"type", "type"},
  };
  return *words;
}

// words that name the human or its body as a whole, and times: they say nothing to plan
const std::set<std::string>& DroppedWords() {
  static const auto* words = new std::set<std::string>{
      "butt",     "bum",      "bottom",    "rear",  "backside",  "booty",   "tush",
      "bottoms",  "buttocks", "posterior", "rump",  "self",      "weight",  "dawn",
      "dusk",     "morning",  "evening",   "night", "tonight",   "today",   "noon",
      "midnight", "sunrise",  "sunset",    "day",   "afternoon", "instant", "twice",
      "times",    "me",       "us",        "him",   "yourselves"};
  return *words;
}

bool IsObjectWord(const std::string& w) {
  auto type = TypeWords().find(w);
  if (type != TypeWords().end()) return !type->second.empty();
  if (PartWords().count(w)) return true;
  auto syn = Synonyms().find(w);
  return syn != Synonyms().end() && syn->second != w && IsObjectWord(syn->second);
}

// a verb form's stem candidates: "slaps" -> slap, "perching" -> perch, "plopped" -> plop
std::string ActionByStem(const std::string& w) {
  auto look = [](const std::string& s) -> std::string {
    auto a = ActionStems().find(s);
    if (a != ActionStems().end()) return a->second;
    a = MovingStems().find(s);
    return a == MovingStems().end() ? std::string() : a->second;
  };
  if (std::string a = look(w); !a.empty()) return a;
  auto ends = [&](const char* suffix) {
    const std::string s = suffix;
    return w.size() > s.size() + 1 && w.compare(w.size() - s.size(), s.size(), s) == 0;
  };
  std::string stem;
  for (const char* suffix : {"ing", "ed", "es", "s", "d"}) {
    if (!ends(suffix)) continue;
    stem = w.substr(0, w.size() - std::string(suffix).size());
    if (std::string a = look(stem); !a.empty()) return a;
    if (std::string a = look(stem + "e"); !a.empty()) return a;  // "settling", "dozed"
    // "plopped", "sitting": a doubled last consonant
    if (stem.size() > 2 && stem.back() == stem[stem.size() - 2]) {
      if (std::string a = look(stem.substr(0, stem.size() - 1)); !a.empty()) return a;
    }
    if (stem.size() > 1 && stem.back() == 'i') {  // "hurried", "carries"
      if (std::string a = look(stem.substr(0, stem.size() - 1) + "y"); !a.empty()) return a;
    }
  }
  return "";
}

// an object or part word the lexicon knows, from a plural ("couches", "armrests") or a slip of
// one edit in a word of four letters or more ("sofs")
std::string ObjectByForm(const std::string& w) {
  for (const char* suffix : {"es", "s"}) {
    const std::string s = suffix;
    if (w.size() > s.size() + 2 && w.compare(w.size() - s.size(), s.size(), s) == 0) {
      const std::string stem = w.substr(0, w.size() - s.size());
      if (IsObjectWord(stem)) return stem;
    }
  }
  if (w.size() < 4) return "";
  std::string best;
  int count = 0;
  for (const auto& [word, type] : TypeWords()) {
    if (type.empty() || word.size() < 4 || EditDistance(w, word) != 1) continue;
    if (best.empty() || TypeWords().at(best) != type) ++count;
    best = word;
  }
  return count == 1 ? best : "";
}

}  // namespace

bool LexiconWord(const std::string& w) {
  static const auto* phrase_words = [] {
    auto* s = new std::set<std::string>();
    for (const auto& [from, to] : Phrases()) s->insert(from.begin(), from.end());
    return s;
  }();
  return Known(w) || Synonyms().count(w) || Fillers().count(w) || phrase_words->count(w) ||
         Subjects().count(w);
}

WordReading ReadWord(const std::string& w) {
  if (DroppedWords().count(w)) return {WordReading::kDrop, ""};
  if (std::string a = ActionByStem(w); !a.empty()) return {WordReading::kAction, a};
  if (std::string o = ObjectByForm(w); !o.empty()) return {WordReading::kObject, o};
  return {WordReading::kUnknown, ""};
}

bool IsNegation(const std::string& w) {
  static const std::set<std::string> kWords = {
      "not",   "dont",    "doesnt",   "didnt",  "never", "no",      "cannot",
      "cant",  "wont",    "shouldnt", "mustnt", "nor",   "neither", "without",
      "avoid", "refrain", "nobody",   "isnt",   "arent", "wasnt",   "werent"};
  return kWords.count(w) > 0;
}

bool OpensObject(const std::string& w) {
  static const std::set<std::string> kWords = {
      "the",    "a",     "an",     "this",  "that", "these",   "those", "my",      "your",
      "his",    "her",   "its",    "their", "our",  "some",    "any",   "another", "each",
      "on",     "onto",  "upon",   "in",    "into", "inside",  "at",    "near",    "by",
      "beside", "under", "over",   "from",  "with", "against", "of",    "towards", "toward",
      "behind", "atop",  "across", "thy",   "ur",   "yr"};
  // "the top shelf", "the seat belt": a part word before a noun is its modifier
  return kWords.count(w) > 0 || (PartWords().count(w) > 0 && w != "back");
}

}  // namespace simhuman::language::offline
