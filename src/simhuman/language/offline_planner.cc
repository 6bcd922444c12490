#include "simhuman/language/offline_planner.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "simhuman/plan/metrics.h"
#include "simhuman/plan/validate.h"

namespace simhuman::language {
namespace {

using core::BodyJoint;
using core::CatalogObject;
using plan::ContactPair;
using plan::ContactStep;
using plan::ContactType;
using plan::Direction;
using Tokens = std::vector<std::string>;

// two candidates closer than this (m) to a reference, or this close in a left/right ordering,
// are not told apart
constexpr double kTieM = 0.05;
// a reference deeper than this in nested relations is refused (keeps parsing linear)
constexpr int kMaxNesting = 3;

absl::Status Invalid(const std::string& message) { return absl::InvalidArgumentError(message); }
absl::Status Question(const std::string& message) { return absl::FailedPreconditionError(message); }

std::string Join(const Tokens& tokens, size_t b, size_t e) {
  std::string out;
  for (size_t i = b; i < e && i < tokens.size(); ++i) {
    if (!out.empty()) out += ' ';
    out += tokens[i];
  }
  return out;
}
std::string Join(const Tokens& tokens) { return Join(tokens, 0, tokens.size()); }

// ---------------------------------------------------------------- lexicon

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
      {{"get", "on"}, {"geton"}},
      {{"get", "onto"}, {"geton"}},
      {{"climb", "on"}, {"geton"}},
      {{"climb", "onto"}, {"geton"}},
      {{"head", "over", "to"}, {"go"}},
      {{"head", "to"}, {"go"}},
      {{"head", "towards"}, {"go"}},
      // politeness and the default lying pose
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

// single-word synonyms
const std::map<std::string, std::string>& Synonyms() {
  static const auto* words = new std::map<std::string, std::string>{
      {"couch", "sofa"},      {"settee", "sofa"},      {"desk", "table"},
      {"computer", "laptop"}, {"notebook", "laptop"},  {"crate", "box"},
      {"cube", "box"},        {"block", "box"},        {"ball", "sphere"},
      {"tube", "cylinder"},   {"gray", "grey"},        {"walk", "go"},
      {"move", "move"},       {"head", "head"},        {"approach", "go"},
      {"come", "go"},         {"run", "go"},           {"step", "go"},
      {"proceed", "go"},      {"sleep", "lie"},        {"nap", "lie"},
      {"lay", "lie"},         {"lying", "lie"},        {"recline", "lie"},
      {"sitting", "sit"},     {"seated", "sit"},       {"sits", "sit"},
      {"lies", "lie"},        {"relax", "rest"},       {"touch", "touch"},
      {"tap", "touch"},       {"touches", "touch"},    {"reaches", "reach"},
      {"reaching", "reach"},  {"grasp", "grab"},       {"hold", "grab"},
      {"take", "grab"},       {"place", "put"},        {"set", "put"},
      {"rest", "rest"},       {"leaning", "lean"},     {"onto", "onto"},
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
      {"into", "in"},         {"yourself", "your"},    {"dont", "dont"},
      {"lap", "knees"},       {"thats", "that"},       {"crossed", "cross"},
      {"crossing", "cross"},
  };
  return *words;
}

// words dropped everywhere: fillers and determiners (relations and "your" are kept)
const std::set<std::string>& Fillers() {
  static const auto* words = new std::set<std::string>{
      "the",      "a",         "an",      "please",   "now",      "just",   "first",  "slowly",
      "gently",   "carefully", "quickly", "also",     "again",    "down",   "over",   "kindly",
      "could",    "you",       "can",     "should",   "i",        "want",   "would",  "like",
      "to_",      "for",       "this",    "my",       "both_",    "along",  "there_", "comfortably",
      "straight", "located",   "placed",  "standing", "sitting_", "lying_", "one_"};
  return *words;
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
                                                                    {"boxes", "box"},
                                                                    {"cylinder", "cylinder"},
                                                                    {"cylinders", "cylinder"},
                                                                    {"sphere", "sphere"},
                                                                    {"spheres", "sphere"},
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
      {"keyboard", "keyboard"}, {"keys", "keyboard"},     {"screen", "screen"},
      {"display", "screen"},    {"monitor", "screen"},    {"lid", "lid"},
      {"edge", "edge"},         {"body", "body"},         {"point", "point"}};
  return *words;
}

const std::set<std::string>& Relations() {
  static const auto* words = new std::set<std::string>{
      "near", "nearest", "farthest", "left_of", "right_of", "front_of", "behind", "onto", "on"};
  return *words;
}

const std::set<std::string>& OtherWords() {
  static const auto* words = new std::set<std::string>{
      "then",   "and",        "sit",   "lie",   "rest",    "stand", "up",      "go",     "move",
      "touch",  "reach",      "grab",  "put",   "stack",   "cross", "lean",    "raise",  "turn",
      "keep",   "with",       "while", "your",  "hand",    "hands", "elbow",   "elbows", "knee",
      "knees",  "other_knee", "foot",  "feet",  "leg",     "legs",  "stomach", "head",   "shoulder",
      "side",   "left",       "right", "both",  "forward", "front", "in",      "at",     "to",
      "of",     "it",         "them",  "that",  "which",   "is",    "are",     "its",    "away",
      "from",   "off",        "big",   "small", "tall",    "short", "far",     "nearby", "middle",
      "centre", "center",     "there", "yours", "own",     "one",   "edge",    "each",   "against",
      "dont",   "lean",       "place", "using", "either",  "s",     "geton"};
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

// ---------------------------------------------------------------- tokenizer

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
    } else if (c == ',' || c == '.' || c == ';' || c == '!' || c == '?' || c == ':') {
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
    auto syn = Synonyms().find(w);
    if (syn != Synonyms().end()) w = syn->second;
    if (Fillers().count(w)) continue;
    out.push_back(w);
  }
  return out;
}

// ---------------------------------------------------------------- scene helpers

struct Point2 {
  double x = 0, y = 0;
};

// horizontal distance from `p` to the object's footprint (its local bounds turned by its yaw)
double FootprintDistance(const CatalogObject& o, Point2 p) {
  if (o.shapes.empty()) return std::hypot(p.x - o.pose.pos.x(), p.y - o.pose.pos.y());
  const auto [lo, hi] = o.LocalBounds();
  const double yaw = plan::ObjectYaw(o.pose);
  const double dx = p.x - o.pose.pos.x(), dy = p.y - o.pose.pos.y();
  const double lx = std::cos(yaw) * dx + std::sin(yaw) * dy;
  const double ly = -std::sin(yaw) * dx + std::cos(yaw) * dy;
  const double ex = std::max({lo.x() - lx, 0.0, lx - hi.x()});
  const double ey = std::max({lo.y() - ly, 0.0, ly - hi.y()});
  return std::hypot(ex, ey);
}

double CentreDistance(const CatalogObject& a, const CatalogObject& b) {
  return std::hypot(a.pose.pos.x() - b.pose.pos.x(), a.pose.pos.y() - b.pose.pos.y());
}

double Volume(const CatalogObject& o) {
  if (o.shapes.empty()) return 0.0;
  const auto [lo, hi] = o.LocalBounds();
  const Eigen::Vector3d d = hi - lo;
  return d.x() * d.y() * d.z();
}

// the viewer's frame: where the human starts and which way it faces
struct Viewer {
  double x = 0, y = 0, yaw = 0;
  // (forward, left) coordinates of a world offset
  std::pair<double, double> Local(double dx, double dy) const {
    return {std::cos(yaw) * dx + std::sin(yaw) * dy, -std::sin(yaw) * dx + std::cos(yaw) * dy};
  }
};

enum class Rel { kNear, kNearest, kFarthest, kLeftOf, kRightOf, kFrontOf, kBehind, kOn };

std::optional<Rel> RelFromWord(const std::string& w) {
  if (w == "near" || w == "at") return Rel::kNear;
  if (w == "nearest") return Rel::kNearest;
  if (w == "farthest") return Rel::kFarthest;
  if (w == "left_of") return Rel::kLeftOf;
  if (w == "right_of") return Rel::kRightOf;
  if (w == "front_of") return Rel::kFrontOf;
  if (w == "behind") return Rel::kBehind;
  if (w == "on" || w == "onto") return Rel::kOn;
  return std::nullopt;
}

std::string RelText(Rel r) {
  switch (r) {
    case Rel::kNear:
      return "next to";
    case Rel::kNearest:
      return "nearest to";
    case Rel::kFarthest:
      return "farthest from";
    case Rel::kLeftOf:
      return "left of";
    case Rel::kRightOf:
      return "right of";
    case Rel::kFrontOf:
      return "in front of";
    case Rel::kBehind:
      return "behind";
    case Rel::kOn:
      return "on";
  }
  return "";
}

// the side relation of `a` seen from `ref` in the viewer's frame (the dominant axis)
Rel SideRelation(const CatalogObject& a, const CatalogObject& ref, const Viewer& v) {
  auto [f, l] = v.Local(a.pose.pos.x() - ref.pose.pos.x(), a.pose.pos.y() - ref.pose.pos.y());
  if (std::abs(l) >= std::abs(f)) return l > 0 ? Rel::kLeftOf : Rel::kRightOf;
  return f > 0 ? Rel::kBehind : Rel::kFrontOf;
}

bool HoldsSide(Rel r, const CatalogObject& a, const CatalogObject& ref, const Viewer& v) {
  auto [f, l] = v.Local(a.pose.pos.x() - ref.pose.pos.x(), a.pose.pos.y() - ref.pose.pos.y());
  switch (r) {
    case Rel::kLeftOf:
      return l > kTieM && l >= std::abs(f) - kTieM;
    case Rel::kRightOf:
      return -l > kTieM && -l >= std::abs(f) - kTieM;
    case Rel::kBehind:
      return f > kTieM && f >= std::abs(l) - kTieM;
    case Rel::kFrontOf:
      return -f > kTieM && -f >= std::abs(l) - kTieM;
    default:
      return false;
  }
}

// `a` rests on `ref`: its origin lies over ref's footprint and above the floor
bool RestsOn(const CatalogObject& a, const CatalogObject& ref) {
  if (a.id == ref.id) return false;
  return a.pose.pos.z() > 0.05 && FootprintDistance(ref, {a.pose.pos.x(), a.pose.pos.y()}) < 1e-6;
}

std::string Describe(const CatalogObject& o) {
  std::string colour = o.color.empty() ? "" : o.color + " ";
  std::string type = o.type == "high_stool" ? "high stool" : o.type;
  return o.id + " (" + colour + type + ")";
}

std::string TypeText(const std::string& type) { return type == "high_stool" ? "high stool" : type; }

bool HasPart(const CatalogObject& o, const std::string& name) {
  for (const core::CatalogPart& p : o.parts) {
    if (p.name == name) return true;
  }
  return false;
}

// parts of `o` whose name or an alias equals `word` (normalized)
std::vector<const core::CatalogPart*> PartsNamed(const CatalogObject& o, const std::string& word) {
  std::vector<const core::CatalogPart*> out;
  const std::string want = core::NormalizeName(word);
  for (const core::CatalogPart& p : o.parts) {
    bool hit = core::NormalizeName(p.name) == want;
    for (const std::string& a : p.aliases) hit = hit || core::NormalizeName(a) == want;
    if (hit) out.push_back(&p);
  }
  return out;
}

std::string PartsText(const CatalogObject& o) {
  std::vector<std::string> names = o.PartNames();
  return names.empty() ? std::string("(no parts)") : core::JoinNames(names);
}

std::string ObjectsWith(const core::SceneCatalog& scene, const std::string& part) {
  std::vector<std::string> ids;
  for (const CatalogObject& o : scene.objects) {
    if (HasPart(o, part)) ids.push_back(Describe(o));
  }
  return ids.empty() ? std::string("none in this scene") : core::JoinNames(ids);
}

// ---------------------------------------------------------------- noun phrases

enum class Select { kNone, kLeft, kRight, kBig, kSmall, kNear, kFar };

struct NounPhrase {
  bool pronoun = false;
  std::string id;  // an object id written out, e.g. "chair000"
  std::string color;
  std::string type;       // canonical type, or "" (any)
  bool has_type = false;  // a type word (or "object"/"one") was given
  std::string part;       // lookup name of a part, e.g. "seat", "arm"; "" for none
  std::string part_side;  // "left"/"right" for a part, or ""
  Select select = Select::kNone;
  struct Relation {
    Rel rel;
    std::unique_ptr<NounPhrase> ref;
  };
  std::vector<Relation> relations;
  std::string text;  // the words, for messages

  bool Empty() const {
    return !pronoun && id.empty() && color.empty() && !has_type && part.empty() &&
           relations.empty() && select == Select::kNone;
  }
};

bool IsRelativizer(const std::string& w) {
  return w == "that" || w == "which" || w == "is" || w == "are";
}

core::StatusOr<NounPhrase> ParseNounPhrase(const Tokens& t, size_t b, size_t e, int depth,
                                           const std::string& clause);

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

// ---------------------------------------------------------------- planner state

enum class Posture { kStand, kSit, kLie };

enum class VariantKind {
  kHandsOnArms,
  kHandsOffArms,
  kElbowsOnArms,
  kHandsOnKnees,
  kHandsOnStomach,
  kFootOnKnee,
  kLeanForward,
  kLeanBack,
  kKneesUp,
  kHandsOnPillow,
  kOnSide,
  kHeadUp,
};

struct Variant {
  VariantKind kind;
  std::string side;       // "left", "right" or "both" (the limb; for kOnSide the side lain on)
  std::string knee_side;  // kFootOnKnee: the knee's side
};

struct StepDraft {
  ContactStep step;
  std::string text;
  enum Kind { kMove, kSit, kLie, kOther } kind = kOther;
  const CatalogObject* object = nullptr;
  size_t base_pairs = 0;
  std::vector<std::string> variant_texts;
};

class Session {
 public:
  Session(const core::SceneCatalog& scene, const PlanContext& context) : scene_(scene) {
    AgentStart start;
    if (!context.agents.empty()) start = context.agents[0];
    pos_ = {start.x_m, start.y_m};
    viewer_ = {start.x_m, start.y_m, start.yaw_rad};
    if (start.posture == "sit" || start.posture == "lie") {
      // the seat (or bed) the human starts on: the nearest object it can sit (lie) on
      const std::string part = start.posture == "sit" ? "seat surface" : "mattress";
      double best = 1.5;
      for (const CatalogObject& o : scene.objects) {
        if (!HasPart(o, part) && !HasPart(o, "mattress")) continue;
        double d = FootprintDistance(o, pos_);
        if (d < best) {
          best = d;
          on_ = &o;
        }
      }
      if (on_ != nullptr) posture_ = start.posture == "sit" ? Posture::kSit : Posture::kLie;
    }
  }

  absl::Status Clause(const Tokens& t);

  core::StatusOr<PlanResult> Finish();

 private:
  // ---- references
  core::StatusOr<const CatalogObject*> Resolve(const NounPhrase& np, const std::string& clause,
                                               const std::string& need_part = "");
  core::StatusOr<std::vector<const CatalogObject*>> Candidates(const NounPhrase& np,
                                                               const std::string& clause);
  std::string Ambiguity(const NounPhrase& np, const std::vector<const CatalogObject*>& c) const;
  std::string Landmark(const CatalogObject& c,
                       const std::vector<const CatalogObject*>& exclude) const;

  // ---- steps
  void EnsureFree(const CatalogObject* target);
  void EnsureNear(const CatalogObject& target);
  void AddGetClose(const CatalogObject& o, Direction side, const std::string& text);
  absl::Status AddSit(const CatalogObject& o);
  absl::Status AddLie(const CatalogObject& o);
  absl::Status AddVariant(const Variant& v, const std::string& clause);
  void Push(StepDraft d) { steps_.push_back(std::move(d)); }

  // ---- clause kinds
  absl::Status SitOrLie(const Tokens& t, size_t b, bool lie, bool rest, const std::string& c);
  absl::Status Go(const Tokens& t, size_t b, const std::string& c);
  absl::Status StandUp(const std::string& c);
  absl::Status Reach(const Tokens& t, const std::string& c);
  absl::Status Tabletop(const Tokens& t, size_t b, const std::string& c);
  core::StatusOr<std::optional<Variant>> ParseVariant(const Tokens& t, size_t b, size_t e,
                                                      const std::string& c) const;

  const core::SceneCatalog& scene_;
  Viewer viewer_;
  Point2 pos_;
  Posture posture_ = Posture::kStand;
  const CatalogObject* on_ = nullptr;     // what the human sits or lies on
  const CatalogObject* focus_ = nullptr;  // the object last referred to ("it")
  std::vector<StepDraft> steps_;
};

ContactPair Pair(const CatalogObject& o, const std::string& part, BodyJoint joint, ContactType type,
                 Direction dir) {
  ContactPair p;
  p.object = o.id;
  p.part = part;
  p.joint = joint;
  p.type = type;
  p.direction = dir;
  return p;
}

std::string NounOf(const NounPhrase& np) {
  std::string s = np.color.empty() ? "" : np.color + " ";
  if (!np.type.empty()) return s + TypeText(np.type);
  if (!np.part.empty()) return s + "object with a " + np.part;
  return s + "object";
}

core::StatusOr<std::vector<const CatalogObject*>> Session::Candidates(const NounPhrase& np,
                                                                      const std::string& clause) {
  std::vector<const CatalogObject*> c;
  if (np.pronoun) {
    if (focus_ == nullptr) {
      return Invalid("'" + np.text + "' in \"" + clause +
                     "\" refers to nothing mentioned before; name the object. The scene has: " +
                     DescribeSceneObjects(scene_));
    }
    c.push_back(focus_);
  } else if (!np.id.empty()) {
    const CatalogObject* o = scene_.Find(np.id);
    if (o == nullptr) {
      return Invalid("there is no object '" + np.id + "' in this scene (\"" + clause +
                     "\"); the scene has: " + DescribeSceneObjects(scene_));
    }
    c.push_back(o);
  } else {
    for (const CatalogObject& o : scene_.objects) {
      // a high stool is a stool too
      if (!np.type.empty() && o.type != np.type &&
          !(np.type == "stool" && o.type == "high_stool")) {
        continue;
      }
      if (!np.color.empty() && o.color != np.color) continue;
      if (np.type.empty() && !np.part.empty() && PartsNamed(o, np.part).empty()) continue;
      c.push_back(&o);
    }
    if (c.empty()) {
      return Invalid("there is no " + NounOf(np) + " in this scene (\"" + clause +
                     "\"); the scene has: " + DescribeSceneObjects(scene_));
    }
  }
  for (const NounPhrase::Relation& r : np.relations) {
    SH_ASSIGN_OR_RETURN(const CatalogObject* ref, Resolve(*r.ref, clause));
    std::vector<const CatalogObject*> kept;
    for (const CatalogObject* o : c) {
      if (o == ref) continue;
      bool ok = true;
      if (r.rel == Rel::kOn) ok = RestsOn(*o, *ref);
      if (r.rel == Rel::kLeftOf || r.rel == Rel::kRightOf || r.rel == Rel::kFrontOf ||
          r.rel == Rel::kBehind) {
        ok = HoldsSide(r.rel, *o, *ref, viewer_);
      }
      if (ok) kept.push_back(o);
    }
    if ((r.rel == Rel::kNear || r.rel == Rel::kNearest || r.rel == Rel::kFarthest) &&
        !kept.empty()) {
      // the nearest (farthest) ones; ties stay ambiguous
      const double sign = r.rel == Rel::kFarthest ? -1.0 : 1.0;
      double best = 1e300;
      for (const CatalogObject* o : kept) best = std::min(best, sign * CentreDistance(*o, *ref));
      std::vector<const CatalogObject*> top;
      for (const CatalogObject* o : kept) {
        if (sign * CentreDistance(*o, *ref) <= best + kTieM) top.push_back(o);
      }
      kept = top;
    }
    if (kept.empty()) {
      std::vector<std::string> ids;
      for (const CatalogObject* o : c) ids.push_back(Describe(*o));
      return Invalid("no " + NounOf(np) + " is " + RelText(r.rel) + " " + Describe(*ref) + " (\"" +
                     clause + "\"); candidates: " + core::JoinNames(ids));
    }
    c = kept;
  }
  if (np.select != Select::kNone && c.size() > 1) {
    auto key = [&](const CatalogObject* o) {
      switch (np.select) {
        case Select::kLeft:
          return -viewer_.Local(o->pose.pos.x() - viewer_.x, o->pose.pos.y() - viewer_.y).second;
        case Select::kRight:
          return viewer_.Local(o->pose.pos.x() - viewer_.x, o->pose.pos.y() - viewer_.y).second;
        case Select::kBig:
          return -Volume(*o);
        case Select::kSmall:
          return Volume(*o);
        case Select::kNear:
          return FootprintDistance(*o, pos_);
        case Select::kFar:
          return -FootprintDistance(*o, pos_);
        case Select::kNone:
          break;
      }
      return 0.0;
    };
    const bool volume = np.select == Select::kBig || np.select == Select::kSmall;
    double best = 1e300;
    for (const CatalogObject* o : c) best = std::min(best, key(o));
    std::vector<const CatalogObject*> top;
    for (const CatalogObject* o : c) {
      const double tie = volume ? 0.05 * std::abs(best) + 1e-9 : kTieM;
      if (key(o) <= best + tie) top.push_back(o);
    }
    c = top;
  }
  return c;
}

// "left of the green sphere": a relation to the nearest object that colour and type name
// uniquely and that is not one of the candidates
std::string Session::Landmark(const CatalogObject& c,
                              const std::vector<const CatalogObject*>& exclude) const {
  const CatalogObject* best = nullptr;
  double best_d = 1e300;
  for (const CatalogObject& o : scene_.objects) {
    if (std::find(exclude.begin(), exclude.end(), &o) != exclude.end()) continue;
    int same = 0;
    for (const CatalogObject& p : scene_.objects) same += p.type == o.type && p.color == o.color;
    if (same != 1) continue;
    double d = CentreDistance(c, o);
    if (d < best_d) {
      best_d = d;
      best = &o;
    }
  }
  if (best == nullptr) return "";
  Rel rel = RestsOn(c, *best) ? Rel::kOn : SideRelation(c, *best, viewer_);
  return RelText(rel) + " the " + best->color + " " + TypeText(best->type);
}

std::string Session::Ambiguity(const NounPhrase& np,
                               const std::vector<const CatalogObject*>& c) const {
  std::vector<std::string> options;
  std::set<std::string> seen;
  for (const CatalogObject* o : c) {
    std::string where = Landmark(*o, c);
    if (where.empty() || seen.count(where)) {
      char buf[64];
      std::snprintf(buf, sizeof(buf), "at (%.2f, %.2f)", o->pose.pos.x(), o->pose.pos.y());
      where = buf;
    }
    seen.insert(where);
    options.push_back("the one " + where + " (" + o->id + ")");
  }
  std::string list;
  for (size_t i = 0; i < options.size(); ++i) {
    if (i > 0) list += i + 1 == options.size() ? " or " : ", ";
    list += options[i];
  }
  return "Which " + NounOf(np) + ": " + list + "?";
}

core::StatusOr<const CatalogObject*> Session::Resolve(const NounPhrase& np,
                                                      const std::string& clause,
                                                      const std::string& need_part) {
  SH_ASSIGN_OR_RETURN(std::vector<const CatalogObject*> c, Candidates(np, clause));
  if (c.size() > 1 && !need_part.empty()) {
    // a type-less description ("sit on the red one") keeps the objects that fit the request
    std::vector<const CatalogObject*> fit;
    for (const CatalogObject* o : c) {
      if (HasPart(*o, need_part)) fit.push_back(o);
    }
    if (!fit.empty() && np.type.empty()) c = fit;
  }
  if (c.size() > 1) return Question(Ambiguity(np, c));
  return c[0];
}

// ---------------------------------------------------------------- steps

void Session::AddGetClose(const CatalogObject& o, Direction side, const std::string& text) {
  StepDraft d;
  ContactPair p;
  p.object = o.id;
  p.part = std::string(plan::kNoneName);
  p.type = ContactType::kNotCare;
  p.direction = side;
  d.step.pairs.push_back(p);
  d.kind = StepDraft::kMove;
  d.object = &o;
  d.text = text;
  Push(std::move(d));
  if (!o.shapes.empty()) {
    const Eigen::Vector3d sp = plan::StandPoint(o, side, plan::PairParams().stand_off_m);
    pos_ = {sp.x(), sp.y()};
  }
  posture_ = Posture::kStand;
  on_ = nullptr;
}

// standing up is implied before going to another object
void Session::EnsureFree(const CatalogObject* target) {
  if (posture_ == Posture::kStand || on_ == nullptr || on_ == target) return;
  const CatalogObject& from = *on_;
  AddGetClose(from, Direction::kFront, "stand up in front of " + Describe(from));
}

// getting close is implied before touching something out of reach
void Session::EnsureNear(const CatalogObject& target) {
  if (posture_ != Posture::kStand) return;
  if (FootprintDistance(target, pos_) <= kNearEnoughM) return;
  AddGetClose(target, Direction::kFront, "get close to " + Describe(target) + " (front)");
}

absl::Status Session::AddSit(const CatalogObject& o) {
  StepDraft d;
  d.kind = StepDraft::kSit;
  d.object = &o;
  if (HasPart(o, "seat surface")) {
    d.step.pairs.push_back(
        Pair(o, "seat surface", BodyJoint::kPelvis, ContactType::kContact, Direction::kUp));
    d.text = "sit on " + Describe(o);
  } else if (HasPart(o, "mattress")) {
    d.step.pairs.push_back(
        Pair(o, "mattress", BodyJoint::kPelvis, ContactType::kContact, Direction::kUp));
    if (HasPart(o, "pillow")) {
      d.step.pairs.push_back(
          Pair(o, "pillow", BodyJoint::kHead, ContactType::kNotContact, Direction::kUp));
    }
    d.text = "sit on the edge of " + Describe(o);
  } else {
    std::vector<std::string> seats;
    for (const CatalogObject& x : scene_.objects) {
      if (HasPart(x, "seat surface") || HasPart(x, "mattress")) seats.push_back(Describe(x));
    }
    return Invalid("cannot sit on " + Describe(o) + ": it has no seat (its parts: " + PartsText(o) +
                   "); objects to sit on: " +
                   (seats.empty() ? std::string("none in this scene") : core::JoinNames(seats)));
  }
  d.base_pairs = d.step.pairs.size();
  Push(std::move(d));
  posture_ = Posture::kSit;
  on_ = &o;
  pos_ = {o.pose.pos.x(), o.pose.pos.y()};
  return absl::OkStatus();
}

absl::Status Session::AddLie(const CatalogObject& o) {
  if (!HasPart(o, "mattress") || !HasPart(o, "pillow")) {
    return Invalid("cannot lie on " + Describe(o) +
                   ": lying needs a mattress and a pillow (its parts: " + PartsText(o) +
                   "); objects to lie on: " + ObjectsWith(scene_, "mattress"));
  }
  StepDraft d;
  d.kind = StepDraft::kLie;
  d.object = &o;
  d.step.pairs.push_back(
      Pair(o, "mattress", BodyJoint::kPelvis, ContactType::kContact, Direction::kUp));
  d.step.pairs.push_back(
      Pair(o, "pillow", BodyJoint::kHead, ContactType::kContact, Direction::kUp));
  d.base_pairs = 2;
  d.text = "lie on " + Describe(o);
  Push(std::move(d));
  posture_ = Posture::kLie;
  on_ = &o;
  pos_ = {o.pose.pos.x(), o.pose.pos.y()};
  return absl::OkStatus();
}

BodyJoint SideJoint(const std::string& side, BodyJoint left, BodyJoint right) {
  return side == "left" ? left : right;
}

std::vector<std::string> Sides(const std::string& side) {
  if (side == "both") return {"left", "right"};
  return {side};
}

std::string VariantText(const Variant& v) {
  const std::string limb = v.side == "both" ? "both" : v.side;
  switch (v.kind) {
    case VariantKind::kHandsOnArms:
      return limb + (v.side == "both" ? " hands on the arms" : " hand on the " + v.side + " arm");
    case VariantKind::kHandsOffArms:
      return limb + (v.side == "both" ? " hands" : " hand") + " away from the arms";
    case VariantKind::kElbowsOnArms:
      return limb + (v.side == "both" ? " elbows on the arms" : " elbow on the " + v.side + " arm");
    case VariantKind::kHandsOnKnees:
      return limb + (v.side == "both" ? " hands on the knees" : " hand on the " + v.side + " knee");
    case VariantKind::kHandsOnStomach:
      return limb + (v.side == "both" ? " hands" : " hand") + " on the stomach";
    case VariantKind::kFootOnKnee:
      return v.side + " foot on the " + v.knee_side + " knee";
    case VariantKind::kLeanForward:
      return "leaning forward";
    case VariantKind::kLeanBack:
      return "leaning back";
    case VariantKind::kKneesUp:
      return v.side == "both" ? "knees up" : v.side + " knee up";
    case VariantKind::kHandsOnPillow:
      return limb + (v.side == "both" ? " hands" : " hand") + " on the pillow";
    case VariantKind::kOnSide:
      return "on the " + v.side + " side";
    case VariantKind::kHeadUp:
      return "head up";
  }
  return "";
}

absl::Status Session::AddVariant(const Variant& v, const std::string& clause) {
  const bool lie_only = v.kind == VariantKind::kKneesUp || v.kind == VariantKind::kHandsOnPillow ||
                        v.kind == VariantKind::kOnSide || v.kind == VariantKind::kHeadUp;
  const bool sit_only = v.kind == VariantKind::kHandsOnArms ||
                        v.kind == VariantKind::kHandsOffArms ||
                        v.kind == VariantKind::kElbowsOnArms ||
                        v.kind == VariantKind::kLeanForward || v.kind == VariantKind::kLeanBack;
  const std::string what = VariantText(v);
  if (posture_ == Posture::kStand || on_ == nullptr) {
    return Invalid("\"" + clause + "\" (" + what + ") is a pose while " +
                   (lie_only ? "lying" : "sitting") + "; say first what to " +
                   (lie_only ? "lie" : "sit") + " on (e.g. \"" + (lie_only ? "lie" : "sit") +
                   " on the " + (lie_only ? "bed" : "chair") + ", then " + clause + "\")");
  }
  if (lie_only && posture_ != Posture::kLie) {
    return Invalid("\"" + clause + "\" (" + what + ") is a lying pose, but the human sits on " +
                   Describe(*on_) + "; lie on a bed first");
  }
  if (sit_only && posture_ != Posture::kSit) {
    return Invalid("\"" + clause + "\" (" + what + ") is a sitting pose, but the human lies on " +
                   Describe(*on_) + "; sit up first (\"sit on it\")");
  }
  const CatalogObject& o = *on_;
  std::vector<ContactPair> pairs;
  auto need = [&](const std::string& part) -> absl::Status {
    if (HasPart(o, part)) return absl::OkStatus();
    return Invalid("\"" + clause + "\": " + Describe(o) + " has no " + part + " (its parts: " +
                   PartsText(o) + "); objects with a " + part + ": " + ObjectsWith(scene_, part));
  };
  const bool lying = posture_ == Posture::kLie;
  switch (v.kind) {
    case VariantKind::kHandsOnArms:
    case VariantKind::kHandsOffArms:
    case VariantKind::kElbowsOnArms:
      for (const std::string& s : Sides(v.side)) {
        SH_RETURN_IF_ERROR(need(s + " arm"));
        const bool elbow = v.kind == VariantKind::kElbowsOnArms;
        BodyJoint j = elbow ? SideJoint(s, BodyJoint::kLeftElbow, BodyJoint::kRightElbow)
                            : SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand);
        if (v.kind == VariantKind::kHandsOffArms) {
          pairs.push_back(Pair(o, s + " arm", j, ContactType::kNotContact, Direction::kNone));
        } else {
          pairs.push_back(Pair(o, s + " arm", j, ContactType::kContact, Direction::kUp));
        }
      }
      break;
    case VariantKind::kHandsOnKnees:
      for (const std::string& s : Sides(v.side)) {
        pairs.push_back(Pair(o, s + " knee",
                             SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand),
                             ContactType::kContact, Direction::kUp));
      }
      break;
    case VariantKind::kHandsOnStomach:
      for (const std::string& s : Sides(v.side)) {
        pairs.push_back(Pair(o, "pelvis", SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand),
                             ContactType::kContact, Direction::kNone));
      }
      break;
    case VariantKind::kFootOnKnee:
      pairs.push_back(Pair(o, v.knee_side + " knee",
                           SideJoint(v.side, BodyJoint::kLeftFoot, BodyJoint::kRightFoot),
                           ContactType::kContact, lying ? Direction::kUp : Direction::kNone));
      break;
    case VariantKind::kLeanForward:
    case VariantKind::kLeanBack:
      SH_RETURN_IF_ERROR(need("back surface"));
      pairs.push_back(
          Pair(o, "back surface", BodyJoint::kTorso,
               v.kind == VariantKind::kLeanBack ? ContactType::kContact : ContactType::kNotContact,
               Direction::kNone));
      break;
    case VariantKind::kKneesUp:
      for (const std::string& s : Sides(v.side)) {
        pairs.push_back(Pair(o, "mattress",
                             SideJoint(s, BodyJoint::kLeftKnee, BodyJoint::kRightKnee),
                             ContactType::kNotContact, Direction::kNone));
      }
      break;
    case VariantKind::kHandsOnPillow:
      for (const std::string& s : Sides(v.side)) {
        pairs.push_back(Pair(o, "pillow", SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand),
                             ContactType::kContact, Direction::kNone));
      }
      break;
    case VariantKind::kOnSide:
      // lying on the left side lifts the right shoulder off the mattress
      pairs.push_back(Pair(o, "mattress",
                           SideJoint(v.side, BodyJoint::kRightShoulder, BodyJoint::kLeftShoulder),
                           ContactType::kNotContact, Direction::kNone));
      break;
    case VariantKind::kHeadUp:
      pairs.push_back(
          Pair(o, "pillow", BodyJoint::kHead, ContactType::kNotContact, Direction::kNone));
      break;
  }
  // merge into the current sit/lie step unless it already poses one of these joints
  StepDraft* last = steps_.empty() ? nullptr : &steps_.back();
  const StepDraft::Kind kind = lying ? StepDraft::kLie : StepDraft::kSit;
  bool merge = last != nullptr && last->kind == kind && last->object == &o;
  if (merge) {
    for (size_t k = last->base_pairs; k < last->step.pairs.size(); ++k) {
      for (const ContactPair& p : pairs) {
        if (last->step.pairs[k].joint == p.joint) merge = false;
      }
    }
  }
  if (!merge) {
    StepDraft d;
    d.kind = kind;
    d.object = &o;
    if (lying) {
      d.step.pairs.push_back(
          Pair(o, "mattress", BodyJoint::kPelvis, ContactType::kContact, Direction::kUp));
      d.step.pairs.push_back(
          Pair(o, "pillow", BodyJoint::kHead, ContactType::kContact, Direction::kUp));
      d.text = "lie on " + Describe(o);
    } else if (HasPart(o, "seat surface")) {
      d.step.pairs.push_back(
          Pair(o, "seat surface", BodyJoint::kPelvis, ContactType::kContact, Direction::kUp));
      d.text = "sit on " + Describe(o);
    } else {
      d.step.pairs.push_back(
          Pair(o, "mattress", BodyJoint::kPelvis, ContactType::kContact, Direction::kUp));
      d.step.pairs.push_back(
          Pair(o, "pillow", BodyJoint::kHead, ContactType::kNotContact, Direction::kUp));
      d.text = "sit on the edge of " + Describe(o);
    }
    d.base_pairs = d.step.pairs.size();
    Push(std::move(d));
    last = &steps_.back();
  }
  for (const ContactPair& p : pairs) {
    // head up replaces the head-on-pillow pair of lying
    auto same = std::find_if(last->step.pairs.begin(), last->step.pairs.end(),
                             [&](const ContactPair& q) { return q.joint == p.joint; });
    if (same != last->step.pairs.end()) {
      *same = p;
    } else {
      last->step.pairs.push_back(p);
    }
  }
  last->variant_texts.push_back(what);
  return absl::OkStatus();
}

// ---------------------------------------------------------------- clause parsing

bool Has(const Tokens& t, size_t b, size_t e, const std::string& w) {
  return std::find(t.begin() + static_cast<long>(std::min(b, t.size())),
                   t.begin() + static_cast<long>(std::min(e, t.size())),
                   w) != t.begin() + static_cast<long>(std::min(e, t.size()));
}

// index of the first of `words` in [b, e), or e
size_t Find(const Tokens& t, size_t b, size_t e, const std::set<std::string>& words) {
  for (size_t i = b; i < e; ++i) {
    if (words.count(t[i])) return i;
  }
  return e;
}

// the side word right before t[i] (skipping "your"), or ""
std::string SideBefore(const Tokens& t, size_t b, size_t i) {
  while (i > b) {
    --i;
    if (t[i] == "your") continue;
    if (t[i] == "left" || t[i] == "right" || t[i] == "both") return t[i];
    return "";
  }
  return "";
}

core::StatusOr<std::optional<Variant>> Session::ParseVariant(const Tokens& t, size_t b, size_t e,
                                                             const std::string& c) const {
  static const std::set<std::string> kHand = {"hand", "hands"};
  static const std::set<std::string> kElbow = {"elbow", "elbows"};
  static const std::set<std::string> kFoot = {"foot", "feet", "leg", "legs"};
  static const std::set<std::string> kKnee = {"knee", "knees", "other_knee"};
  static const std::set<std::string> kArm = {"arm", "arms", "armrest", "armrests"};
  auto limb_side = [&](size_t i) {
    std::string s = SideBefore(t, b, i);
    if (!s.empty()) return s;
    const std::string& w = t[i];
    return (w.back() == 's' || w == "feet") ? std::string("both") : std::string("right");
  };
  const bool away = Has(t, b, e, "away") || Has(t, b, e, "off") || Has(t, b, e, "dont");
  size_t hand = Find(t, b, e, kHand);
  size_t elbow = Find(t, b, e, kElbow);
  size_t foot = Find(t, b, e, kFoot);
  size_t knee = Find(t, b, e, kKnee);
  size_t arm = Find(t, b, e, kArm);
  Variant v{VariantKind::kLeanBack, "both", ""};
  if (Has(t, b, e, "lean")) {
    v.kind = (Has(t, b, e, "forward") || Has(t, b, e, "front_of")) ? VariantKind::kLeanForward
                                                                   : VariantKind::kLeanBack;
    if (v.kind == VariantKind::kLeanBack && !Has(t, b, e, "back") && !Has(t, b, e, "against") &&
        !Has(t, b, e, "backrest")) {
      return Invalid("\"" + c + "\": lean which way? say \"lean forward\" or \"lean back\"");
    }
    return std::optional<Variant>(v);
  }
  if (foot < e && knee < e) {
    v.kind = VariantKind::kFootOnKnee;
    std::string fs = SideBefore(t, b, foot), ks = SideBefore(t, b, knee);
    if (t[knee] == "other_knee") ks = "";
    if (fs.empty() && !ks.empty()) fs = ks == "left" ? "right" : "left";
    if (fs.empty() || fs == "both") fs = "right";
    if (ks.empty() || ks == "both") ks = fs == "left" ? "right" : "left";
    if (ks == fs) {
      return Invalid("\"" + c +
                     "\": a foot cannot rest on its own knee; say e.g. \"right foot "
                     "on the left knee\"");
    }
    v.side = fs;
    v.knee_side = ks;
    return std::optional<Variant>(v);
  }
  if (Has(t, b, e, "cross") && (Has(t, b, e, "legs") || foot < e)) {
    v.kind = VariantKind::kFootOnKnee;
    v.side = "right";
    v.knee_side = "left";
    return std::optional<Variant>(v);
  }
  if (elbow < e && arm < e) {
    v.kind = VariantKind::kElbowsOnArms;
    v.side = limb_side(elbow);
    return std::optional<Variant>(v);
  }
  if (hand < e) {
    v.side = limb_side(hand);
    if (arm < e && (posture_ == Posture::kSit || away)) {
      v.kind = away ? VariantKind::kHandsOffArms : VariantKind::kHandsOnArms;
      std::string arm_side = SideBefore(t, b, arm);
      if (v.side != "both" && !arm_side.empty() && arm_side != "both" && arm_side != v.side) {
        return Invalid("\"" + c + "\": the " + v.side + " hand goes on the " + v.side +
                       " arm; a hand on the opposite arm is not in the vocabulary");
      }
      return std::optional<Variant>(v);
    }
    if (knee < e) {
      v.kind = VariantKind::kHandsOnKnees;
      return std::optional<Variant>(v);
    }
    if (Has(t, b, e, "stomach")) {
      v.kind = VariantKind::kHandsOnStomach;
      return std::optional<Variant>(v);
    }
    if (Has(t, b, e, "pillow") && posture_ == Posture::kLie) {
      v.kind = VariantKind::kHandsOnPillow;
      return std::optional<Variant>(v);
    }
    return std::optional<Variant>();  // a reach
  }
  if (knee < e && (Has(t, b, e, "up") || Has(t, b, e, "raise"))) {
    v.kind = VariantKind::kKneesUp;
    v.side = limb_side(knee);
    if (t[knee] == "knees") v.side = "both";
    return std::optional<Variant>(v);
  }
  if (Has(t, b, e, "side") && foot == e && hand == e) {
    std::string s = SideBefore(t, b, Find(t, b, e, {"side"}));
    if (s != "left" && s != "right") {
      return Invalid("\"" + c +
                     "\": on which side? say \"on your left side\" or \"on your "
                     "right side\"");
    }
    v.kind = VariantKind::kOnSide;
    v.side = s;
    return std::optional<Variant>(v);
  }
  if (Has(t, b, e, "head") && (Has(t, b, e, "up") || Has(t, b, e, "raise"))) {
    v.kind = VariantKind::kHeadUp;
    return std::optional<Variant>(v);
  }
  return std::optional<Variant>();
}

// part to touch and direction, for a reach without a named part
std::pair<std::string, Direction> ReachPart(const CatalogObject& o) {
  for (const char* p : {"board", "keyboard", "top", "seat surface", "mattress", "point", "body"}) {
    if (HasPart(o, p)) {
      const std::string name = p;
      return {name, name == "point" || name == "body" ? Direction::kNone : Direction::kUp};
    }
  }
  return {o.parts.empty() ? std::string() : o.parts[0].name, Direction::kNone};
}

Direction PartDirection(const std::string& part) {
  if (part == "screen" || part == "back surface" || part == "front side") return Direction::kFront;
  if (part == "left side") return Direction::kLeft;
  if (part == "right side") return Direction::kRight;
  if (part == "back side") return Direction::kBack;
  if (part == "body" || part == "point") return Direction::kNone;
  return Direction::kUp;
}

// the single part of `o` that `np` names; `side` picks an arm when the words do not
core::StatusOr<std::string> ResolvePart(const CatalogObject& o, const NounPhrase& np,
                                        const std::string& side, const std::string& clause) {
  std::string word = np.part;
  if (word == "arm" && !np.part_side.empty()) word = np.part_side + " arm";
  if (word == "seat") word = "seat surface";
  std::vector<const core::CatalogPart*> parts = PartsNamed(o, word);
  if (parts.size() > 1 && (side == "left" || side == "right")) {
    std::vector<const core::CatalogPart*> sided;
    for (const core::CatalogPart* p : parts) {
      if (p->name.rfind(side, 0) == 0) sided.push_back(p);
    }
    if (!sided.empty()) parts = sided;
  }
  if (parts.empty()) {
    return Invalid(Describe(o) + " has no part '" + np.part + "' (\"" + clause +
                   "\"); its parts: " + PartsText(o));
  }
  if (parts.size() > 1) {
    std::vector<std::string> names;
    for (const core::CatalogPart* p : parts) names.push_back("the " + p->name);
    return Question("Which " + np.part + " of " + Describe(o) + ": " +
                    (names.size() == 2 ? names[0] + " or " + names[1] : core::JoinNames(names)) +
                    "?");
  }
  return parts[0]->name;
}

absl::Status Session::SitOrLie(const Tokens& t, size_t b, bool lie, bool rest,
                               const std::string& c) {
  // [on|in|at|onto] NP [with|while|your ...variant]
  size_t i = b;
  while (i < t.size() && (t[i] == "on" || t[i] == "onto" || t[i] == "in" || t[i] == "at" ||
                          t[i] == "to" || t[i] == "up")) {
    ++i;
  }
  static const std::set<std::string> kStop = {
      "with",  "while", "your", "lean", "hand", "hands", "knees", "knee",  "head", "elbows",
      "elbow", "foot",  "feet", "legs", "leg",  "cross", "keep",  "raise", "and",  "facing"};
  size_t j = Find(t, i, t.size(), kStop);
  // "lie on the bed on your left side": a trailing "on" before "your" belongs to the pose
  size_t np_end = j;
  while (np_end > i && (t[np_end - 1] == "on" || t[np_end - 1] == "in")) --np_end;
  const std::string part = lie ? "mattress" : "seat surface";
  const CatalogObject* o = nullptr;
  if (np_end > i) {
    SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, i, np_end, 0, c));
    SH_ASSIGN_OR_RETURN(o, Resolve(np, c, part));
  } else if (on_ != nullptr && (HasPart(*on_, part) || (!lie && HasPart(*on_, "mattress")))) {
    o = on_;
  } else if (focus_ != nullptr &&
             (HasPart(*focus_, part) || (!lie && HasPart(*focus_, "mattress")))) {
    o = focus_;
  } else {
    std::vector<const CatalogObject*> fit;
    for (const CatalogObject& x : scene_.objects) {
      if (HasPart(x, part)) fit.push_back(&x);
    }
    if (fit.empty()) {
      return Invalid("\"" + c + "\": nothing in this scene to " + (lie ? "lie" : "sit") +
                     " on; the scene has: " + DescribeSceneObjects(scene_));
    }
    if (fit.size() > 1) {
      std::vector<std::string> names;
      for (const CatalogObject* x : fit) names.push_back(Describe(*x));
      return Question(std::string(lie ? "Lie" : "Sit") + " on which: " + core::JoinNames(names) +
                      "?");
    }
    o = fit[0];
  }
  if (!lie && !HasPart(*o, "seat surface") && !HasPart(*o, "mattress") && i > b &&
      t[i - 1] == "at") {
    // "sit at the table": the seat nearest to it
    const CatalogObject* best = nullptr;
    double best_d = 1e300;
    bool tie = false;
    for (const CatalogObject& x : scene_.objects) {
      if (!HasPart(x, "seat surface")) continue;
      const double d = CentreDistance(x, *o);
      if (d < best_d - kTieM) {
        tie = false;
        best = &x;
        best_d = d;
      } else if (d <= best_d + kTieM) {
        tie = true;
      }
    }
    if (best == nullptr) {
      return Invalid("\"" + c + "\": there is no seat to sit at " + Describe(*o) +
                     "; the scene has: " + DescribeSceneObjects(scene_));
    }
    if (tie) return Question("Which seat at " + Describe(*o) + " should I sit on?");
    o = best;
  }
  if (rest) lie = !HasPart(*o, "seat surface") && HasPart(*o, "mattress");
  focus_ = o;
  if (!(on_ == o && posture_ != Posture::kStand)) {
    EnsureFree(o);
    EnsureNear(*o);
  }
  if (lie) {
    SH_RETURN_IF_ERROR(AddLie(*o));
  } else if (!(on_ == o && posture_ == Posture::kSit && !steps_.empty() &&
               steps_.back().kind == StepDraft::kSit && steps_.back().object == o)) {
    SH_RETURN_IF_ERROR(AddSit(*o));
  }
  if (j < t.size()) {
    size_t vb = j;
    while (vb < t.size() && (t[vb] == "with" || t[vb] == "while" || t[vb] == "and")) ++vb;
    SH_ASSIGN_OR_RETURN(std::optional<Variant> v, ParseVariant(t, vb, t.size(), c));
    if (!v) {
      return Invalid("did not understand '" + Join(t, j, t.size()) + "' in \"" + c +
                     "\"; poses I know: hands/elbows on the arms, hands on the knees or stomach, "
                     "foot on the other knee, lean forward/back, knees up, hands on the pillow, "
                     "on the left/right side, head up");
    }
    SH_RETURN_IF_ERROR(AddVariant(*v, c));
  }
  return absl::OkStatus();
}

absl::Status Session::Go(const Tokens& t, size_t b, const std::string& c) {
  size_t i = b;
  Direction side = Direction::kFront;
  while (i < t.size() && (t[i] == "to" || t[i] == "near" || t[i] == "at" || t[i] == "up" ||
                          t[i] == "in" || t[i] == "on")) {
    ++i;
  }
  if (i < t.size() && t[i] == "front_of") {
    ++i;
  } else if (i < t.size() && t[i] == "behind") {
    side = Direction::kBack;
    ++i;
  } else if (i + 2 < t.size() &&
             (t[i] == "left" || t[i] == "right" || t[i] == "front" || t[i] == "back") &&
             (t[i + 1] == "side" || (t[i] == "front" && t[i + 1] == "of")) && t[i + 2] == "of") {
    side = t[i] == "left"    ? Direction::kLeft
           : t[i] == "right" ? Direction::kRight
           : t[i] == "back"  ? Direction::kBack
                             : Direction::kFront;
    i += 3;
  } else if (i + 1 < t.size() && (t[i] == "front" || t[i] == "back") && t[i + 1] == "of") {
    side = t[i] == "back" ? Direction::kBack : Direction::kFront;
    i += 2;
  } else if (i < t.size() && t[i] == "left_of") {
    side = Direction::kLeft;
    ++i;
  } else if (i < t.size() && t[i] == "right_of") {
    side = Direction::kRight;
    ++i;
  }
  if (i >= t.size()) {
    return Invalid("\"" + c +
                   "\": go where? name an object; the scene has: " + DescribeSceneObjects(scene_));
  }
  SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, i, t.size(), 0, c));
  SH_ASSIGN_OR_RETURN(const CatalogObject* o, Resolve(np, c));
  focus_ = o;
  EnsureFree(nullptr);
  std::string text = "get close to " + Describe(*o);
  if (side != Direction::kFront)
    text += " (" + std::string(plan::DirectionName(side)) + " side)";
  else
    text += " (front)";
  AddGetClose(*o, side, text);
  return absl::OkStatus();
}

absl::Status Session::StandUp(const std::string& c) {
  if (posture_ == Posture::kStand || on_ == nullptr) {
    return Invalid("\"" + c + "\": the human is already standing; say first what to sit or lie on");
  }
  EnsureFree(nullptr);
  return absl::OkStatus();
}

absl::Status Session::Reach(const Tokens& t, const std::string& c) {
  // find the hand words and the verb; the object follows the verb's preposition
  static const std::set<std::string> kHand = {"hand", "hands"};
  size_t hand = Find(t, 0, t.size(), kHand);
  std::string side = "right";
  if (hand < t.size()) {
    side = SideBefore(t, 0, hand);
    if (side.empty()) side = t[hand] == "hands" ? "both" : "right";
  }
  // object words: everything after the last verb/preposition that is not the hand phrase
  static const std::set<std::string> kLead = {"touch", "reach", "grab",  "put",    "rest",  "on",
                                              "onto",  "to",    "at",    "for",    "with",  "your",
                                              "left",  "right", "both",  "hand",   "hands", "lie",
                                              "in",    "keep",  "using", "either", "each"};
  // the object is the span that follows the first preposition after the verb, up to "with"
  size_t b = 0;
  while (b < t.size() && kLead.count(t[b])) {
    // "left"/"right" belong to the object when no hand word follows them
    if ((t[b] == "left" || t[b] == "right" || t[b] == "both") &&
        !(b + 1 < t.size() && (kHand.count(t[b + 1])))) {
      break;
    }
    ++b;
  }
  size_t e = t.size();
  size_t with = Find(t, b, t.size(), {"with", "using"});
  if (with < e) e = with;
  if (b >= e) {
    return Invalid("\"" + c + "\": touch what? name an object; the scene has: " +
                   DescribeSceneObjects(scene_));
  }
  SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, b, e, 0, c));
  if (!np.part.empty() && np.part_side.empty() && np.part == "arm" && side != "both") {
    np.part_side = side;
  }
  SH_ASSIGN_OR_RETURN(const CatalogObject* o, Resolve(np, c));
  if (side == "both" && np.part == "arm" && np.part_side.empty() && HasPart(*o, "left arm") &&
      HasPart(*o, "right arm")) {
    // both hands on the armrests: each hand on its own side
    focus_ = o;
    if (posture_ != Posture::kStand && on_ != o && FootprintDistance(*o, pos_) > kNearEnoughM) {
      EnsureFree(nullptr);
    }
    EnsureNear(*o);
    StepDraft d;
    for (const std::string& s : Sides(side)) {
      d.step.pairs.push_back(Pair(*o, s + " arm",
                                  SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand),
                                  ContactType::kContact, Direction::kUp));
    }
    d.text = "both hands touch the arms of " + Describe(*o);
    Push(std::move(d));
    return absl::OkStatus();
  }
  std::string part;
  Direction dir = Direction::kNone;
  if (np.part.empty()) {
    std::tie(part, dir) = ReachPart(*o);
  } else {
    SH_ASSIGN_OR_RETURN(part, ResolvePart(*o, np, side, c));
    dir = PartDirection(part);
  }
  focus_ = o;
  // sitting, a reach within arm's length keeps the seat; anything else stands up first
  if (posture_ != Posture::kStand && on_ != o && FootprintDistance(*o, pos_) > kNearEnoughM) {
    EnsureFree(nullptr);
  }
  EnsureNear(*o);
  StepDraft d;
  std::vector<std::string> sides = Sides(side);
  for (const std::string& s : sides) {
    d.step.pairs.push_back(Pair(*o, part, SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand),
                                ContactType::kContact, dir));
  }
  d.text = (side == "both" ? std::string("both hands touch the ") : side + " hand touches the ") +
           part + " of " + Describe(*o);
  Push(std::move(d));
  return absl::OkStatus();
}

// the part an object is put on (top-like) and the part it is put next to
std::string TopPart(const CatalogObject& o) {
  for (const char* p : {"top", "board", "keyboard", "seat surface", "mattress", "body", "point"}) {
    if (HasPart(o, p)) return p;
  }
  return o.parts.empty() ? std::string() : o.parts[0].name;
}
std::string BodyPart(const CatalogObject& o) {
  if (HasPart(o, "body")) return "body";
  return TopPart(o);
}

// the reference object's side (its own frame) closest to a viewer-frame direction
Direction ObjectSide(const CatalogObject& ref, double wx, double wy) {
  Direction best = Direction::kFront;
  double best_dot = -2;
  for (Direction d : {Direction::kFront, Direction::kBack, Direction::kLeft, Direction::kRight}) {
    Eigen::Vector3d v = plan::DirectionVector(d, ref.pose);
    double dot = v.x() * wx + v.y() * wy;
    if (dot > best_dot) {
      best_dot = dot;
      best = d;
    }
  }
  return best;
}

absl::Status Session::Tabletop(const Tokens& t, size_t b, const std::string& c) {
  // put NP1 [that is REL NP] DEST_REL NP2 [REL NP]
  std::string hand = "right";
  size_t e = t.size();
  size_t with = Find(t, b, e, {"with", "using"});
  if (with < e) {
    size_t h = Find(t, with, e, {"hand"});
    if (h < e) {
      std::string s = SideBefore(t, with, h);
      if (s == "left" || s == "right") hand = s;
    } else {
      return Invalid("did not understand '" + Join(t, with, e) + "' in \"" + c + "\"");
    }
    e = with;
  }
  size_t dest = e;
  bool relative = false;
  for (size_t i = b; i < e; ++i) {
    if (IsRelativizer(t[i])) {
      relative = true;
      continue;
    }
    if (RelFromWord(t[i]) && t[i] != "nearest" && t[i] != "farthest") {
      if (relative) {
        relative = false;
        continue;
      }
      dest = i;
      break;
    }
  }
  if (dest == e || dest == b) {
    return Invalid("\"" + c +
                   "\": put what where? say e.g. \"put the red box on the blue "
                   "cylinder\" (relations: on, on top of, next to, left of, right of, in front "
                   "of, behind)");
  }
  if (dest + 1 >= e) {
    return Invalid("\"" + c + "\": '" + RelText(*RelFromWord(t[dest])) +
                   "' needs an object after it");
  }
  SH_ASSIGN_OR_RETURN(NounPhrase what, ParseNounPhrase(t, b, dest, 0, c));
  SH_ASSIGN_OR_RETURN(NounPhrase where, ParseNounPhrase(t, dest + 1, e, 0, c));
  SH_ASSIGN_OR_RETURN(const CatalogObject* a, Resolve(what, c));
  SH_ASSIGN_OR_RETURN(const CatalogObject* ref, Resolve(where, c));
  if (!a->movable) {
    std::vector<std::string> movable;
    for (const CatalogObject& o : scene_.objects) {
      if (o.movable) movable.push_back(Describe(o));
    }
    return Invalid(
        "\"" + c + "\": " + Describe(*a) + " cannot be moved; movable objects: " +
        (movable.empty() ? std::string("none in this scene") : core::JoinNames(movable)));
  }
  if (a == ref) {
    return Invalid("\"" + c + "\": cannot put " + Describe(*a) + " " +
                   RelText(*RelFromWord(t[dest])) + " itself");
  }
  const Rel rel = *RelFromWord(t[dest]);
  Direction dir = Direction::kNone;
  std::string part = BodyPart(*ref);
  const double c_yaw = std::cos(viewer_.yaw), s_yaw = std::sin(viewer_.yaw);
  switch (rel) {
    case Rel::kOn:
      dir = Direction::kUp;
      part = TopPart(*ref);
      break;
    case Rel::kLeftOf:
      dir = ObjectSide(*ref, -s_yaw, c_yaw);
      break;
    case Rel::kRightOf:
      dir = ObjectSide(*ref, s_yaw, -c_yaw);
      break;
    case Rel::kFrontOf:
      dir = ObjectSide(*ref, -c_yaw, -s_yaw);
      break;
    case Rel::kBehind:
      dir = ObjectSide(*ref, c_yaw, s_yaw);
      break;
    default:
      break;
  }
  const std::string subject_part = BodyPart(*a);
  focus_ = a;
  EnsureFree(nullptr);
  EnsureNear(*a);
  const BodyJoint hand_joint = SideJoint(hand, BodyJoint::kLeftHand, BodyJoint::kRightHand);
  ContactPair grasp = Pair(*a, subject_part, hand_joint, ContactType::kContact, Direction::kNone);
  StepDraft g;
  g.step.pairs.push_back(grasp);
  g.text = "grasp " + Describe(*a) + " with the " + hand + " hand";
  Push(std::move(g));
  EnsureNear(*ref);
  StepDraft goal;
  goal.step.pairs.push_back(grasp);
  ContactPair on;
  on.subject_object = a->id;
  on.subject_part = subject_part;
  on.object = ref->id;
  on.part = part;
  on.type = ContactType::kContact;
  on.direction = dir;
  goal.step.pairs.push_back(on);
  goal.text = "put " + Describe(*a) + " " + (rel == Rel::kOn ? "on top of" : RelText(rel)) + " " +
              Describe(*ref);
  Push(std::move(goal));
  return absl::OkStatus();
}

absl::Status Session::Clause(const Tokens& t) {
  const std::string c = Join(t);
  for (const std::string& w : t) {
    if (!Known(w) && scene_.Find(w) == nullptr) {
      return Invalid("did not understand the word '" + w + "' in \"" + c +
                     "\"; I understand: sit, lie, rest, stand up, go to / walk to / approach, "
                     "touch / reach, put your hand(s) on, put the <colour> <shape> on <object>, "
                     "with object types chair, armchair, sofa, stool, high stool, bed, table, "
                     "laptop, box, cylinder, sphere. The scene has: " +
                     DescribeSceneObjects(scene_));
    }
  }
  size_t i = 0;
  while (i < t.size() && (t[i] == "your" || t[i] == "then" || t[i] == "and")) ++i;
  if (i >= t.size()) return absl::OkStatus();
  const std::string& v = t[i];
  auto next = [&](size_t k) { return k < t.size() ? t[k] : std::string(); };
  if (v == "rest" && (IsBodyWord(next(i + 1)) || next(i + 1) == "left" || next(i + 1) == "right" ||
                      next(i + 1) == "both")) {
    SH_ASSIGN_OR_RETURN(std::optional<Variant> var, ParseVariant(t, i, t.size(), c));
    if (var) return AddVariant(*var, c);
    return Reach(t, c);
  }
  // "go lie on the bed", "go and sit down": the going is implied by the interaction
  if (v == "go" && (next(i + 1) == "sit" || next(i + 1) == "lie" || next(i + 1) == "rest" ||
                    next(i + 1) == "touch" || next(i + 1) == "put")) {
    return Clause(Tokens(t.begin() + static_cast<long>(i) + 1, t.end()));
  }
  if (v == "go" && i + 1 == t.size()) return absl::OkStatus();
  if (v == "sit" || v == "lie" || v == "rest") {
    return SitOrLie(t, i + 1, v == "lie", v == "rest", c);
  }
  if (v == "stand" && next(i + 1) == "up") {
    if (i + 2 < t.size() && t[i + 2] != "then") {
      return Invalid("did not understand '" + Join(t, i + 2, t.size()) +
                     "' after 'stand up' in \"" + c + "\"");
    }
    return StandUp(c);
  }
  if (v == "stand" || v == "go" ||
      (v == "move" && (next(i + 1) == "to" || next(i + 1) == "near"))) {
    return Go(t, i + 1, c);
  }
  if (v == "put" || v == "stack" || v == "move" || v == "rest" || v == "keep" || v == "place") {
    if (IsBodyWord(next(i + 1)) || next(i + 1) == "left" || next(i + 1) == "right" ||
        next(i + 1) == "both") {
      SH_ASSIGN_OR_RETURN(std::optional<Variant> var, ParseVariant(t, i, t.size(), c));
      if (var) return AddVariant(*var, c);
      return Reach(t, c);
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
  if (var) return AddVariant(*var, c);
  if (Has(t, i, t.size(), "touch") || Has(t, i, t.size(), "reach")) return Reach(t, c);
  return Invalid("did not understand \"" + c +
                 "\"; commands start with sit, lie, rest, stand up, go to, walk to, approach, "
                 "touch, reach, put, place, stack, lean, cross, raise");
}

core::StatusOr<PlanResult> Session::Finish() {
  if (steps_.empty()) {
    return Invalid(
        "the command asks for nothing to do; say e.g. \"sit on the chair\". The scene "
        "has: " +
        DescribeSceneObjects(scene_));
  }
  PlanResult out;
  for (StepDraft& d : steps_) {
    std::string text = d.text;
    if (!d.variant_texts.empty()) {
      text += ", ";
      for (size_t k = 0; k < d.variant_texts.size(); ++k) {
        text += (k ? " and " : "") + d.variant_texts[k];
      }
    }
    d.step.label = text;
    out.chain.steps.push_back(std::move(d.step));
    out.explanation.push_back(text);
  }
  absl::Status st = plan::ValidateAndGround(out.chain, scene_);
  if (!st.ok()) {
    return absl::InternalError("the offline planner built an invalid plan: " +
                               std::string(st.message()));
  }
  return out;
}

}  // namespace

std::string DescribeSceneObjects(const core::SceneCatalog& scene) {
  if (scene.objects.empty()) return "no objects";
  std::string out;
  for (const CatalogObject& o : scene.objects) {
    if (!out.empty()) out += "; ";
    out += Describe(o) + ": " + PartsText(o);
  }
  return out;
}

core::StatusOr<PlanResult> OfflinePlanner::Plan(std::string_view command,
                                                const PlanContext& context) {
  if (context.scene == nullptr) return Invalid("no scene given to the planner");
  SH_ASSIGN_OR_RETURN(Tokens raw, Tokenize(command));
  Tokens tokens = Normalize(raw);
  // clauses: split on "then" and "and"
  std::vector<Tokens> clauses(1);
  for (const std::string& w : tokens) {
    if (w == "then" || w == "and") {
      if (!clauses.back().empty()) clauses.emplace_back();
      if (static_cast<int>(clauses.size()) > kMaxClauses) {
        return Invalid("the command has more than " + std::to_string(kMaxClauses) +
                       " clauses; split it into several commands");
      }
      continue;
    }
    clauses.back().push_back(w);
  }
  if (clauses.back().empty()) clauses.pop_back();
  Session session(*context.scene, context);
  for (const Tokens& clause : clauses) SH_RETURN_IF_ERROR(session.Clause(clause));
  return session.Finish();
}

}  // namespace simhuman::language
