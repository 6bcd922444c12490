// Verb handlers for the body: sit, lie and rest on an object (with an optional pose), go to an
// object (and which side of it), stand up, and touch or reach an object or one of its parts with
// one or both hands.

#include <set>
#include <tuple>
#include <utility>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {
namespace {

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

// the direction of a touch on a named part: its outward side, up for top-like parts
Direction PartDirection(const std::string& part) {
  if (part == "screen" || part == "back surface" || part == "front side") return Direction::kFront;
  if (part == "left side") return Direction::kLeft;
  if (part == "right side") return Direction::kRight;
  if (part == "back side") return Direction::kBack;
  if (part == "body" || part == "point") return Direction::kNone;
  return Direction::kUp;
}

}  // namespace

absl::Status Session::SitOrLie(const Tokens& t, size_t b, SitMode mode, const std::string& c) {
  // [on|in|at|onto] NP [with|while|your ...variant]
  size_t i = b;
  // "sit next to / in front of the desk": at it, as "sit at the desk"
  bool at = false;
  while (i < t.size() &&
         (t[i] == "on" || t[i] == "onto" || t[i] == "in" || t[i] == "at" || t[i] == "to" ||
          t[i] == "up" || t[i] == "near" || t[i] == "front_of" || t[i] == "flat")) {
    at = at || t[i] == "at" || t[i] == "near" || t[i] == "front_of";
    ++i;
  }
  static const std::set<std::string> kStop = {
      "with",  "while", "your", "lean", "hand", "hands", "knees", "knee",  "head", "elbows",
      "elbow", "foot",  "feet", "legs", "leg",  "cross", "keep",  "raise", "and",  "facing"};
  size_t j = Find(t, i, t.size(), kStop);
  // "lie in bed on the left side": the side is a pose
  for (size_t k = i; k + 2 < j; ++k) {
    if ((t[k] == "on" || t[k] == "onto") && (t[k + 1] == "left" || t[k + 1] == "right") &&
        t[k + 2] == "side") {
      j = k;
    }
  }
  // "sit with your legs crossed on the sofa": the object named after the pose
  if (j == i && j < t.size()) {
    for (size_t k = t.size(); k-- > j + 1;) {
      if (t[k] != "on" && t[k] != "in" && t[k] != "at" && t[k] != "onto") continue;
      bool body = false;
      for (size_t m = k + 1; m < t.size(); ++m) body = body || IsBodyWord(t[m]) || t[m] == "side";
      if (body || k + 1 >= t.size() || !(TypeWords().count(t[k + 1]) || Colors().count(t[k + 1]))) {
        break;
      }
      Tokens moved(t.begin(), t.begin() + static_cast<long>(i));
      moved.insert(moved.end(), t.begin() + static_cast<long>(k), t.end());
      moved.insert(moved.end(), t.begin() + static_cast<long>(j), t.begin() + static_cast<long>(k));
      return SitOrLie(moved, b, mode, c);
    }
  }
  // "lie on the bed on your left side": a trailing "on" before "your" belongs to the pose
  size_t np_end = j;
  while (np_end > i && (t[np_end - 1] == "on" || t[np_end - 1] == "in")) --np_end;
  bool lie = mode == SitMode::kLie;
  const std::string part = lie ? "mattress" : "seat surface";
  const CatalogObject* o = nullptr;
  if (np_end > i) {
    SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, i, np_end, 0, c));
    const CatalogObject* here = on_ != nullptr ? on_ : focus_;
    if (np.part == "edge" && !np.has_type && np.id.empty() && !np.pronoun && here != nullptr) {
      o = here;  // "sit up on the edge": of what the human is on
    } else {
      SH_ASSIGN_OR_RETURN(o, Resolve(np, c, part));
    }
  } else if (mode == SitMode::kRecline && on_ != nullptr &&
             (HasPart(*on_, "mattress") || HasPart(*on_, "back surface"))) {
    o = on_;  // "sit on the edge of the bed, then lie back"
  } else if (mode == SitMode::kRecline) {
    SH_ASSIGN_OR_RETURN(o, OnlyObjectWith({"seat surface", "back surface"}, "recline", c));
  } else if (focus_ != nullptr && focus_ != on_ && on_ != nullptr &&
             (HasPart(*focus_, part) || (!lie && HasPart(*focus_, "mattress")))) {
    o = focus_;  // "sit on the bed's edge. Then the stool, go sit": the seat named since
  } else if (on_ != nullptr && (HasPart(*on_, part) || (!lie && HasPart(*on_, "mattress")))) {
    o = on_;
  } else if (const CatalogObject* seat = lie ? nullptr : SeatBy(focus_)) {
    o = seat;  // "walk to the desk and sit down": the seat at it
  } else {
    SH_ASSIGN_OR_RETURN(o, OnlyObjectWith({part}, lie ? "lie" : "sit", c));
  }
  if (!lie && !HasPart(*o, "seat surface") && !HasPart(*o, "mattress") && at) {
    SH_ASSIGN_OR_RETURN(o, SeatAt(*o, c));  // "sit at the table": the seat nearest to it
  }
  if (mode == SitMode::kRest || mode == SitMode::kRecline) {
    lie = !HasPart(*o, "seat surface") && HasPart(*o, "mattress");
  }
  focus_ = o;
  if (!(on_ == o && posture_ != Posture::kStand)) {
    EnsureFree(o);
    EnsureNear(*o);
  }
  // already sitting or lying there ("get into bed and lie on your left side"): a pose joins
  const bool there = on_ == o && !steps_.empty() && steps_.back().object == o &&
                     ((lie && posture_ == Posture::kLie && steps_.back().kind == StepDraft::kLie) ||
                      (!lie && posture_ == Posture::kSit && steps_.back().kind == StepDraft::kSit));
  if (lie && !there) {
    SH_RETURN_IF_ERROR(AddLie(*o));
  } else if (!there) {
    SH_RETURN_IF_ERROR(AddSit(*o));
  }
  if (mode == SitMode::kRecline && !lie) {
    SH_RETURN_IF_ERROR(AddVariant({VariantKind::kLeanBack, "both", ""}, c));
  }
  if (j < t.size()) return SitPose(t, j, c);
  return absl::OkStatus();
}

// the pose said with a sit or lie, t[j, ...): "with your hands on your knees", "leaning back",
// "with both hands on the laptop keyboard" (a seated reach joining the sit step)
absl::Status Session::SitPose(const Tokens& t, size_t j, const std::string& c) {
  size_t vb = j;
  while (vb < t.size() && (t[vb] == "with" || t[vb] == "while" || t[vb] == "and")) ++vb;
  // "on your left side on the bed with your left hand on the pillow": two poses, both kept
  const size_t with = Find(t, vb, t.size(), {"with"});
  if (with < t.size()) {
    SH_ASSIGN_OR_RETURN(std::optional<Variant> first, ParseVariant(t, vb, with, c));
    SH_ASSIGN_OR_RETURN(std::optional<Variant> second, ParseVariant(t, with + 1, t.size(), c));
    if (first && second) {
      SH_RETURN_IF_ERROR(AddVariant(*first, c));
      return AddVariant(*second, c);
    }
  }
  SH_ASSIGN_OR_RETURN(std::optional<Variant> v, ParseVariant(t, vb, t.size(), c));
  if (v) return AddVariant(*v, c);
  if (posture_ == Posture::kSit && Find(t, vb, t.size(), {"hand", "hands"}) < t.size()) {
    return Reach(Tokens(t.begin() + static_cast<long>(vb), t.end()), c, true);
  }
  return Invalid("did not understand '" + Join(t, j, t.size()) + "' in \"" + c +
                 "\"; poses I know: hands/elbows on the arms, hands on the knees or stomach, "
                 "foot on the other knee, lean forward/back, knees up, hands on the pillow, "
                 "on the left/right side, head up");
}

absl::Status Session::Go(const Tokens& t, size_t b, const std::string& c) {
  size_t i = b;
  // "go from the sofa to the armchair": to the first (unless there already), then the second
  if (i < t.size() && t[i] == "from") {
    const size_t to = Find(t, i + 1, t.size(), {"to"});
    if (to + 1 < t.size()) {
      SH_ASSIGN_OR_RETURN(NounPhrase from, ParseNounPhrase(t, i + 1, to, 0, c));
      SH_ASSIGN_OR_RETURN(const CatalogObject* o, Resolve(from, c));
      const bool there = on_ == o || (!steps_.empty() && steps_.back().kind == StepDraft::kMove &&
                                      steps_.back().object == o);
      if (!there)
        SH_RETURN_IF_ERROR(Go(
            Tokens(t.begin() + static_cast<long>(i) + 1, t.begin() + static_cast<long>(to)), 0, c));
      i = to + 1;
    }
  }
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

absl::Status Session::NoticeOrUse(const Tokens& t, size_t i, const std::string& c) {
  if (i + 1 >= t.size()) {
    return Invalid("\"" + c + "\": " + t[i] +
                   " what? name an object; the scene has: " + DescribeSceneObjects(scene_));
  }
  SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, i + 1, t.size(), 0, c));
  SH_ASSIGN_OR_RETURN(const CatalogObject* o, Resolve(np, c));
  focus_ = o;
  if (t[i] == "notice") return absl::OkStatus();
  if (HasPart(*o, "keyboard") || np.part == "keyboard") return Type(t, i + 1, c);
  return SitOrLie(t, i + 1, SitMode::kRest, c);
}

std::optional<absl::Status> Session::Mention(const Tokens& t, size_t i, const std::string& c) {
  if (!sequenced_ && clause_ > 1) return std::nullopt;
  core::StatusOr<NounPhrase> np = ParseNounPhrase(t, i, t.size(), 0, c);
  if (!np.ok() || (!np->has_type && np->id.empty() && np->color.empty() && !np->pronoun) ||
      !np->part.empty()) {
    return std::nullopt;
  }
  core::StatusOr<const CatalogObject*> o = Resolve(*np, c);
  if (!o.ok()) return o.status();
  focus_ = *o;
  return absl::OkStatus();
}

absl::Status Session::StandUp(const std::string& c) {
  if (posture_ == Posture::kStand || on_ == nullptr) {
    return Invalid("\"" + c + "\": the human is already standing; say first what to sit or lie on");
  }
  EnsureFree(nullptr);
  return absl::OkStatus();
}

absl::Status Session::Reach(const Tokens& t, const std::string& c, bool in_pose) {
  // find the hand words and the verb; the object follows the verb's preposition
  static const std::set<std::string> kHand = {"hand", "hands"};
  size_t hand = Find(t, 0, t.size(), kHand);
  std::string side = "right";
  if (hand < t.size()) {
    side = SideBefore(t, 0, hand);
    if (side.empty()) side = t[hand] == "hands" ? "both" : "right";
  }
  // object words: everything after the last verb/preposition that is not the hand phrase
  static const std::set<std::string> kLead = {"touch", "reach", "grab",  "put",   "rest",   "on",
                                              "flat",  "onto",  "to",    "at",    "for",    "with",
                                              "your",  "left",  "right", "both",  "hand",   "hands",
                                              "lie",   "in",    "keep",  "using", "either", "each"};
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
  if (b >= e && focus_ != nullptr && !in_pose) {
    // "the box, touch with left hand": the object just named
    Tokens with_it = t;
    with_it.insert(with_it.begin() + static_cast<long>(e), "it");
    return Reach(with_it, c, in_pose);
  }
  if (b >= e) {
    return Invalid("\"" + c + "\": touch what? name an object; the scene has: " +
                   DescribeSceneObjects(scene_));
  }
  SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, b, e, 0, c));
  if (!np.part.empty() && np.part_side.empty() && np.part == "arm" && side != "both") {
    np.part_side = side;
  }
  // seated, "the armrests" / "the backrest" are those of the seat
  const CatalogObject* o = nullptr;
  if (on_ != nullptr && posture_ != Posture::kStand && !np.part.empty() && !np.has_type &&
      np.id.empty() && np.color.empty() && !np.pronoun && np.relations.empty() &&
      !PartsNamed(*on_, np.part).empty()) {
    o = on_;
  } else {
    SH_ASSIGN_OR_RETURN(o, Resolve(np, c));
  }
  // "grip the armrests" while sitting: the hands-on-armrests pose
  if (o == on_ && posture_ == Posture::kSit && np.part == "arm") {
    std::string s = np.part_side.empty() ? side : np.part_side;
    if (hand == t.size() && (Has(t, 0, t.size(), "armrests") || Has(t, 0, t.size(), "arms"))) {
      s = "both";
    }
    return AddVariant({VariantKind::kHandsOnArms, s, ""}, c);
  }
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
  if (np.part.empty() && o->movable && HasPart(*o, "body") && Find(t, 0, b, {"grab"}) < b) {
    part = "body";  // "pick up the red box": a grasp, as in the grasp step of a put (TAB)
  } else if (np.part.empty()) {
    std::tie(part, dir) = ReachPart(*o);
  } else {
    SH_ASSIGN_OR_RETURN(part, ResolvePart(*o, np, side, c));
    dir = PartDirection(part);
  }
  focus_ = o;
  // sitting, a reach within arm's length keeps the seat; anything else stands up first
  if (posture_ != Posture::kStand && on_ != o && FootprintDistance(*o, pos_) > kNearEnoughM) {
    if (in_pose) {
      return Invalid("\"" + c + "\": " + Describe(*o) + " is out of reach from " + Describe(*on_) +
                     "; sit closer to it first");
    }
    EnsureFree(nullptr);
  }
  if (posture_ != Posture::kStand && on_ != nullptr) {
    AddSeatedReach(*o, part, Sides(side), in_pose);
    return absl::OkStatus();
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

}  // namespace simhuman::language::offline
