#include "simhuman/language/offline/lexicon.h"

#include <algorithm>

namespace simhuman::language::offline {

namespace {

// idioms, politeness and filler, objects and parts: the second half of Phrases()
const std::vector<std::pair<Tokens, Tokens>>& IdiomPhrases() {
  static const auto* phrases = new std::vector<std::pair<Tokens, Tokens>>{
      // idioms for sitting, lying, standing up and typing
      {{"grab", "a", "seat"}, {"sit"}},
      {{"grab", "a", "chair"}, {"sit"}},
      {{"take", "a", "load", "off"}, {"sit"}},
      {{"plop", "down"}, {"sit"}},
      {{"plonk", "down"}, {"sit"}},
      {{"sit", "back"}, {"recline"}},
      {{"leaning"}, {"with", "lean"}},
      {{"reclining"}, {"recline"}},  // a participle states a pose ("sit, leaning back")
      {{"hop", "into"}, {"rest", "in"}},
      {{"hop", "in"}, {"rest", "in"}},
      {{"hop", "up", "on"}, {"rest", "on"}},
      {{"hop", "up", "onto"}, {"rest", "on"}},
      {{"hop", "on"}, {"rest", "on"}},
      {{"hop", "onto"}, {"rest", "on"}},
      {{"get", "into", "bed"}, {"lie", "on", "bed"}},
      {{"go", "to", "bed"}, {"lie", "on", "bed"}},
      {{"go", "to", "sleep"}, {"lie"}},
      {{"hit", "the", "hay"}, {"lie"}},
      {{"hit", "the", "sack"}, {"lie"}},
      {{"get", "some", "sleep"}, {"lie"}},
      {{"get", "some", "rest"}, {"rest"}},
      {{"pull", "up", "a", "chair"}, {"sit", "on", "chair", "near", "table"}},
      {{"stand", "back", "up"}, {"stand", "up"}},
      {{"get", "back", "up"}, {"stand", "up"}},
      {{"get", "out", "of", "bed"}, {"stand", "up"}},
      {{"get", "out", "of", "the", "bed"}, {"stand", "up"}},
      {{"get", "off", "the", "bed"}, {"stand", "up"}},
      {{"come", "back"}, {}},
      {{"go", "back"}, {}},
      {{"come", "back", "to"}, {"go"}},
      {{"go", "back", "to"}, {"go"}},
      {{"start", "typing"}, {"type"}},
      {{"begin", "typing"}, {"type"}},
      {{"do", "some", "typing"}, {"type"}},
      {{"use", "the", "computer"}, {"type", "on", "laptop"}},
      {{"use", "the", "laptop"}, {"type", "on", "laptop"}},
      {{"work", "on", "the", "computer"}, {"type", "on", "laptop"}},
      {{"work", "on", "the", "laptop"}, {"type", "on", "laptop"}},
      {{"desk", "chair"}, {"chair"}},
      {{"office", "chair"}, {"chair"}},
      {{"computer", "chair"}, {"chair"}},
      {{"one", "leg", "crossed", "over", "the", "other"}, {"legs", "cross"}},
      {{"one", "leg", "over", "the", "other"}, {"legs", "cross"}},
      {{"behind", "you"}, {}},
      {{"in", "front", "of", "you"}, {}},
      // politeness, filler phrases that carry no action, and the default lying pose
      {{"ok", "so"}, {}},
      {{"okay", "so"}, {}},
      {{"go", "ahead", "and"}, {}},
      {{"go", "ahead"}, {}},
      {{"real", "quick"}, {}},
      {{"for", "me"}, {}},
      {{"for", "a", "bit"}, {}},
      {{"for", "a", "sec"}, {}},
      {{"for", "a", "second"}, {}},
      {{"for", "a", "while"}, {}},
      {{"for", "a", "moment"}, {}},
      {{"for", "a", "minute"}, {}},
      {{"for", "a", "little", "while"}, {}},
      {{"once", "youre", "done"}, {"then"}},
      {{"once", "you", "are", "done"}, {"then"}},
      {{"when", "youre", "done"}, {"then"}},
      {{"when", "you", "are", "done"}, {"then"}},
      {{"id", "like", "you", "to"}, {}},
      {{"i", "d", "like", "you", "to"}, {}},
      {{"would", "you", "mind"}, {}},
      {{"do", "you", "mind"}, {}},
      {{"can", "u"}, {}},
      {{"could", "u"}, {}},
      {{"i", "want", "you", "to"}, {}},
      {{"i", "would", "like", "you", "to"}, {}},
      {{"i", "need", "you", "to"}, {}},
      {{"can", "you"}, {}},
      {{"could", "you"}, {}},
      {{"would", "you"}, {}},
      {{"on", "your", "back"}, {}},
      {{"face", "up"}, {}},
      {{"facing", "up"}, {}},
      // objects and parts
      {{"high", "stool"}, {"high_stool"}},
      {{"long", "box"}, {"long_box"}},
      {{"long", "boxes"}, {"long_box"}},
      {{"bar", "stool"}, {"high_stool"}},
      {{"arm", "chair"}, {"armchair"}},
      {{"easy", "chair"}, {"armchair"}},
      {{"arm", "rest"}, {"armrest"}},
      {{"arm", "rests"}, {"armrests"}},
      {{"back", "rest"}, {"backrest"}},
      {{"table", "top"}, {"tabletop"}},
      {{"the", "other", "knee"}, {"other_knee"}},
      {{"other", "knee"}, {"other_knee"}},
      {{"the", "other", "leg"}, {"other_knee"}},
      {{"other", "leg"}, {"other_knee"}},
  };
  return *phrases;
}

}  // namespace

// phrases rewritten to one canonical token before anything else (longest match first)
const std::vector<std::pair<Tokens, Tokens>>& Phrases() {
  static const auto* phrases = new std::vector<std::pair<Tokens, Tokens>>{
      // clause separators
      {{"and", "then"}, {"then"}},
      {{"after", "that"}, {"then"}},
      {{"after", "this"}, {"then"}},
      {{"afterwards"}, {"then"}},
      {{"afterward"}, {"then"}},
      {{"finally"}, {"then"}},
      {{"and", "finally"}, {"then"}},
      {{"once", "done"}, {"then"}},
      {{"next", "to"}, {"near"}},
      {{"next"}, {"then"}},
      {{"left", "and", "right"}, {"both"}},
      // relations
      {{"on", "top", "of"}, {"onto"}},
      {{"on", "to"}, {"onto"}},
      {{"in", "front", "of"}, {"front_of"}},
      {{"to", "the", "left", "of"}, {"left_of"}},
      {{"to", "the", "right", "of"}, {"right_of"}},
      {{"on", "the", "left", "of"}, {"left_of"}},
      {{"on", "the", "right", "of"}, {"right_of"}},
      {{"left", "of"}, {"left_of"}},
      {{"right", "of"}, {"right_of"}},
      {{"in", "back", "of"}, {"behind"}},
      {{"close", "to"}, {"near"}},
      {{"closest", "to"}, {"nearest"}},
      {{"nearest", "to"}, {"nearest"}},
      {{"farthest", "from"}, {"farthest"}},
      {{"furthest", "from"}, {"farthest"}},
      {{"beside"}, {"near"}},
      {{"besides"}, {"near"}},
      {{"by"}, {"near"}},
      {{"alongside"}, {"near"}},
      {{"closest"}, {"nearest"}},
      {{"furthest"}, {"farthest"}},
      // verbs
      {{"take", "a", "seat"}, {"sit"}},
      {{"have", "a", "seat"}, {"sit"}},
      {{"be", "seated"}, {"sit"}},
      {{"seat", "yourself"}, {"sit"}},
      {{"have", "a", "rest"}, {"rest"}},
      {{"take", "a", "rest"}, {"rest"}},
      {{"take", "a", "nap"}, {"lie"}},
      {{"have", "a", "nap"}, {"lie"}},
      {{"lay", "down"}, {"lie"}},
      {{"get", "up"}, {"stand", "up"}},
      {{"rise"}, {"stand", "up"}},
      {{"get", "closer", "to"}, {"go"}},
      {{"get", "close", "to"}, {"go"}},
      {{"get", "near"}, {"go"}},
      {{"make", "your", "way", "to"}, {"go"}},
      {{"go", "over", "to"}, {"go"}},
      {{"walk", "over", "to"}, {"go"}},
      {{"pick", "up"}, {"grab"}},
      {{"pick", "it", "up"}, {"grab", "it"}},
      {{"pick", "them", "up"}, {"grab", "them"}},
      // carrying teams ("you" alone is a filler)
      {{"you", "two"}, {"team2"}},
      {{"you", "three"}, {"team3"}},
      {{"you", "four"}, {"team4"}},
      {{"the", "two", "of", "you"}, {"team2"}},
      {{"the", "three", "of", "you"}, {"team3"}},
      {{"the", "four", "of", "you"}, {"team4"}},
      {{"both", "of", "you"}, {"team2"}},
      {{"you", "both"}, {"team2"}},
      {{"all", "of", "you"}, {"teamall"}},
      {{"you", "all"}, {"teamall"}},
      {{"everyone"}, {"teamall"}},
      {{"everybody"}, {"teamall"}},
      {{"together"}, {"teamany"}},
      {{"get", "on"}, {"geton"}},
      {{"get", "onto"}, {"geton"}},
      {{"climb", "on"}, {"geton"}},
      {{"climb", "onto"}, {"geton"}},
      {{"head", "over", "to"}, {"go"}},
      {{"head", "to"}, {"go"}},
      {{"head", "towards"}, {"go"}},
      {{"nip", "over", "to"}, {"go"}},
      {{"nip", "to"}, {"go"}},
      {{"wander", "over", "to"}, {"go"}},
      {{"wander", "to"}, {"go"}},
      {{"crash", "on"}, {"lie", "on"}},
      {{"crash", "in"}, {"lie", "in"}},
      {{"have", "a", "lie"}, {"lie"}},  // "have a lie-down"
      {{"have", "a", "sit"}, {"sit"}},  // "have a sit down"
      {{"take", "hold", "of"}, {"grab"}},
      {{"settle", "into"}, {"sit", "in"}},
      {{"settle", "in"}, {"sit", "in"}},
      {{"pop", "yourself"}, {"sit"}},  // "pop yourself down on the settee"
      {{"rises"}, {"stand", "up"}},
      {{"crosses", "to"}, {"go"}},  // a stage direction: "[crosses to the armchair]"
      {{"cross", "to"}, {"go"}},
      // a director's and a tester's framing: "from the top: ...", "Step 1: ..."
      {{"from", "the", "top"}, {}},
      {{"on", "action"}, {}},
      {{"step", "1"}, {}},
      {{"step", "2"}, {}},
      {{"step", "3"}, {}},
      {{"step", "4"}, {}},
      {{"step", "5"}, {}},
      // a nurse's encouragement: "let's get you sitting down ...", "that's it"
      {{"lets", "get", "you"}, {}},
      {{"thats", "it"}, {}},
      {{"nice", "and", "slow"}, {}},
      {{"nice", "and", "easy"}, {}},
  };
  static const auto* all = [] {
    auto* v = new std::vector<std::pair<Tokens, Tokens>>(*phrases);
    v->insert(v->end(), IdiomPhrases().begin(), IdiomPhrases().end());
    v->insert(v->end(), EverydayPhrases().begin(), EverydayPhrases().end());
    return v;
  }();
  return *all;
}

namespace {

// single-word synonyms (everyday ones are in everyday.cc)
const std::map<std::string, std::string>& BasicSynonyms() {
  static const auto* words = new std::map<std::string, std::string>{
      {"couch", "sofa"},      {"settee", "sofa"},      {"desk", "table"},
      {"computer", "laptop"}, {"notebook", "laptop"},  {"crate", "box"},
      {"cube", "box"},        {"block", "box"},        {"ball", "sphere"},
      {"tube", "cylinder"},   {"gray", "grey"},        {"walk", "go"},
      {"move", "move"},       {"head", "head"},        {"approach", "go"},
      {"come", "go"},         {"run", "go"},           {"step", "go"},
      {"proceed", "go"},      {"sleep", "lie"},        {"nap", "lie"},
      {"lay", "lie"},         {"lying", "lie"},        {"recline", "recline"},
      {"sitting", "sit"},     {"seated", "sit"},       {"sits", "sit"},
      {"lies", "lie"},        {"relax", "rest"},       {"touch", "touch"},
      {"tap", "touch"},       {"touches", "touch"},    {"reaches", "reach"},
      {"reaching", "reach"},  {"grasp", "grab"},       {"hold", "grab"},
      {"take", "grab"},       {"place", "put"},        {"set", "put"},
      {"rest", "rest"},       {"leaned", "lean"},      {"onto", "onto"},
      {"upon", "on"},         {"atop", "onto"},        {"palm", "hand"},
      {"palms", "hands"},     {"belly", "stomach"},    {"tummy", "stomach"},
      {"abdomen", "stomach"}, {"tummy", "stomach"},    {"backwards", "back"},
      {"backward", "back"},   {"forwards", "forward"}, {"armrests", "armrests"},
      {"largest", "big"},     {"large", "big"},        {"bigger", "big"},
      {"biggest", "big"},     {"larger", "big"},       {"little", "small"},
      {"smaller", "small"},   {"smallest", "small"},   {"tiny", "small"},
      {"leftmost", "left"},   {"rightmost", "right"},  {"raise", "raise"},
      {"lift", "raise"},      {"bend", "raise"},       {"pull", "raise"},
      {"roll", "turn"},       {"towards", "to"},       {"toward", "to"},
      {"into", "in"},         {"dont", "dont"},        {"lap", "knees"},
      {"thats", "that"},      {"crossed", "cross"},    {"crossing", "cross"},
      {"bring", "carry"},     {"haul", "carry"},       {"lug", "carry"},
      {"drop", "put"},        {"perch", "sit"},        {"plop", "sit"},
      {"plonk", "sit"},       {"resting", "with"},     {"typing", "type"},
      {"pls", "please"},      {"plz", "please"},       {"but", "and"},
      {"flattest", "flat"},   {"pick", "grab"},        {"fwd", "forward"},
      {"pop", "put"},
  };
  return *words;
}

}  // namespace

// single-word synonyms
const std::map<std::string, std::string>& Synonyms() {
  static const auto* words = [] {
    auto* w = new std::map<std::string, std::string>(BasicSynonyms());
    w->insert(EverydaySynonyms().begin(), EverydaySynonyms().end());
    return w;
  }();
  return *words;
}

// words dropped everywhere: fillers and determiners (relations and "your" are kept)
const std::set<std::string>& Fillers() {
  static const auto* words = new std::set<std::string>{
      "the", "a", "an", "please", "now", "just", "first", "slowly", "gently", "carefully",
      "quickly", "also", "again", "down", "over", "kindly", "could", "you", "can", "should", "i",
      "want", "would", "like", "to_", "for", "this", "my", "both_", "along", "there_",
      "comfortably", "straight", "located", "placed", "standing", "sitting_", "lying_", "one_",
      "ok", "okay", "so", "u", "thanks", "thank", "thx", "some", "yeah", "alright",
      // spoken fillers and slang ("um can you like sit down", "yo go sit on the couch fr")
      "um", "uh", "erm", "hmm", "hey", "yo", "fr", "rn", "bro", "cheers", "briefly", "bit", "round",
      "lets", "instead"};
  static const auto* all = [] {
    auto* w = new std::set<std::string>(*words);
    w->insert(EverydayFillers().begin(), EverydayFillers().end());
    return w;
  }();
  return *all;
}

const std::set<std::string>& Colors() {
  static const auto* words = new std::set<std::string>{
      "red", "green", "blue", "yellow", "white", "black", "brown", "grey", "orange", "purple"};
  return *words;
}

// object type words (singular and plural) -> canonical type
const std::map<std::string, std::string>& TypeWords() {
  static const auto* words = new std::map<std::string, std::string>{{"chair", "chair"},
                                                                    {"chairs", "chair"},
                                                                    {"armchair", "armchair"},
                                                                    {"armchairs", "armchair"},
                                                                    {"sofa", "sofa"},
                                                                    {"sofas", "sofa"},
                                                                    {"stool", "stool"},
                                                                    {"stools", "stool"},
                                                                    {"high_stool", "high_stool"},
                                                                    {"bed", "bed"},
                                                                    {"beds", "bed"},
                                                                    {"table", "table"},
                                                                    {"tables", "table"},
                                                                    {"laptop", "laptop"},
                                                                    {"laptops", "laptop"},
                                                                    {"box", "box"},
                                                                    {"long_box", "long_box"},
                                                                    {"boxes", "box"},
                                                                    {"cylinder", "cylinder"},
                                                                    {"cylinders", "cylinder"},
                                                                    {"sphere", "sphere"},
                                                                    {"spheres", "sphere"},
                                                                    {"cone", "cone"},
                                                                    {"cones", "cone"},
                                                                    {"hourglass", "hourglass"},
                                                                    {"hourglasses", "hourglass"},
                                                                    {"mesh", "mesh"},
                                                                    {"meshes", "mesh"},
                                                                    {"marker", "marker"},
                                                                    {"markers", "marker"},
                                                                    {"target", "marker"},
                                                                    {"object", ""},
                                                                    {"thing", ""},
                                                                    {"one", ""}};
  return *words;
}

// part words -> the name looked up among a part's name and aliases
const std::map<std::string, std::string>& PartWords() {
  static const auto* words = new std::map<std::string, std::string>{
      {"seat", "seat"},         {"cushion", "seat"},      {"backrest", "back surface"},
      {"back", "back surface"}, {"arm", "arm"},           {"arms", "arm"},
      {"armrest", "arm"},       {"armrests", "arm"},      {"pillow", "pillow"},
      {"pillows", "pillow"},    {"mattress", "mattress"}, {"top", "top"},
      {"tabletop", "top"},      {"surface", "surface"},   {"board", "board"},
      {"keyboard", "keyboard"}, {"keys", "keyboard"},     {"key", "keyboard"},
      {"screen", "screen"},     {"display", "screen"},    {"monitor", "screen"},
      {"lid", "lid"},           {"edge", "edge"},         {"body", "body"},
      {"point", "point"}};
  return *words;
}

const std::set<std::string>& Relations() {
  static const auto* words = new std::set<std::string>{
      "near", "nearest", "farthest", "left_of", "right_of", "front_of", "behind", "onto", "on"};
  return *words;
}

const std::set<std::string>& OtherWords() {
  static const auto* words = new std::set<std::string>{
      "then",    "and",     "sit",      "lie",      "rest",       "stand",   "up",     "go",
      "move",    "touch",   "reach",    "grab",     "put",        "stack",   "cross",  "lean",
      "raise",   "turn",    "keep",     "with",     "while",      "your",    "hand",   "hands",
      "elbow",   "elbows",  "knee",     "knees",    "other_knee", "foot",    "feet",   "leg",
      "legs",    "stomach", "head",     "shoulder", "side",       "left",    "right",  "both",
      "forward", "front",   "in",       "at",       "to",         "of",      "it",     "them",
      "that",    "which",   "is",       "are",      "its",        "away",    "from",   "off",
      "big",     "small",   "tall",     "short",    "far",        "nearby",  "middle", "centre",
      "center",  "there",   "yours",    "own",      "one",        "edge",    "each",   "against",
      "dont",    "lean",    "place",    "using",    "either",     "s",       "geton",  "carry",
      "here",    "team2",   "team3",    "team4",    "teamall",    "teamany", "door",   "doors",
      "doorway", "exit",    "entrance", "recline",  "type",       "flat",    "notice", "use",
      "before",  "after"};
  return *words;
}

bool Known(const std::string& w) {
  return Colors().count(w) || TypeWords().count(w) || PartWords().count(w) ||
         Relations().count(w) || OtherWords().count(w);
}

bool IsBodyWord(const std::string& w) {
  static const std::set<std::string> kWords = {"hand",  "hands",      "elbow",    "elbows", "knee",
                                               "knees", "other_knee", "foot",     "feet",   "leg",
                                               "legs",  "stomach",    "shoulder", "your"};
  return kWords.count(w) > 0;
}

// phrase rewriting, synonyms, fillers
Tokens Normalize(const Tokens& in) {
  Tokens out;
  for (size_t i = 0; i < in.size();) {
    const Tokens* best_to = nullptr;
    size_t best_len = 0;
    for (const auto& [from, to] : Phrases()) {
      if (from.size() <= best_len || i + from.size() > in.size()) continue;
      if (std::equal(from.begin(), from.end(), in.begin() + static_cast<long>(i))) {
        best_to = &to;
        best_len = from.size();
      }
    }
    if (best_to != nullptr) {
      for (const std::string& t : *best_to) out.push_back(t);
      i += best_len;
      continue;
    }
    std::string w = in[i++];
    // a reason says why, not what: "sit down because you're tired" (up to the clause's end);
    // a clause that starts with "not" corrects the one before: "sit on the stool, not the chair"
    // as does "don't go/sit/lie ..." before what to do instead
    const bool clause_start = out.empty() || out.back() == "then";
    const bool dont_move = w == "dont" && clause_start && i < in.size() &&
                           (in[i] == "go" || in[i] == "walk" || in[i] == "sit" || in[i] == "lie");
    if (w == "because" || w == "since" || w == "cause" || w == "cuz" ||
        (w == "not" && clause_start) || dont_move) {
      while (i < in.size() && in[i] != "then") ++i;
      continue;
    }
    auto syn = Synonyms().find(w);
    if (syn != Synonyms().end()) w = syn->second;
    if (Fillers().count(w)) continue;
    // a manner adverb the lexicon does not list ("softly", "calmly") says how, not what
    if (w.size() >= 5 && w.compare(w.size() - 2, 2, "ly") == 0 && !Known(w)) continue;
    out.push_back(w);
  }
  return out;
}

}  // namespace simhuman::language::offline
