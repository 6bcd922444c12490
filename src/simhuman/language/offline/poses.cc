// Sitting and lying poses (UniHSI's interaction variants): reading a pose from a clause ("with
// your hands on your knees", "lean back", "cross your legs", "on your left side"), and adding
// its pairs to the current sit or lie step.

#include <algorithm>
#include <set>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/session.h"

namespace simhuman::language::offline {
namespace {

// the pose in words, appended to the text of its step
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
    case VariantKind::kHeadOnPillow:
      return "head on the pillow";
  }
  return "";
}

// a foot on a knee: "right foot on the left knee", "cross your legs", "cross your left leg over
// your right (one)", "with your right leg over your left"; nullopt when the words say neither
core::StatusOr<std::optional<Variant>> LegVariant(const Tokens& t, size_t b, size_t e, size_t foot,
                                                  size_t knee, const std::string& c) {
  std::string fs = SideBefore(t, b, foot), ks;
  if (knee < e) {
    ks = t[knee] == "other_knee" ? "" : SideBefore(t, b, knee);
  } else {
    for (size_t k = foot + 1; k < e && ks.empty(); ++k) {
      if ((t[k] == "left" || t[k] == "right") && !(k + 1 < e && IsBodyWord(t[k + 1]))) ks = t[k];
    }
    if (ks.empty() && !Has(t, b, e, "cross")) return std::optional<Variant>();
  }
  if (fs.empty() && !ks.empty() && ks != "both") fs = ks == "left" ? "right" : "left";
  if (fs.empty() || fs == "both") fs = "right";
  if (ks.empty() || ks == "both") ks = fs == "left" ? "right" : "left";
  if (ks == fs) {
    return Invalid("\"" + c +
                   "\": a foot cannot rest on its own knee; say e.g. \"right foot on the left "
                   "knee\"");
  }
  return std::optional<Variant>(Variant{VariantKind::kFootOnKnee, fs, ks});
}

}  // namespace

absl::Status Session::AddVariant(const Variant& v, const std::string& clause) {
  const bool lie_only = v.kind == VariantKind::kKneesUp || v.kind == VariantKind::kHandsOnPillow ||
                        v.kind == VariantKind::kOnSide || v.kind == VariantKind::kHeadUp ||
                        v.kind == VariantKind::kHeadOnPillow;
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
  SH_ASSIGN_OR_RETURN(std::vector<ContactPair> pairs, VariantPairs(v, clause));
  MergeIntoPoseStep(pairs, what);
  return absl::OkStatus();
}

// the pairs of pose `v` on the object the human sits or lies on; errors name a missing part
core::StatusOr<std::vector<ContactPair>> Session::VariantPairs(const Variant& v,
                                                               const std::string& clause) const {
  const CatalogObject& o = *on_;
  std::vector<ContactPair> pairs;
  auto need = [&](const std::string& part) -> absl::Status {
    if (HasPart(o, part)) return absl::OkStatus();
    return Invalid("\"" + clause + "\": " + Describe(o) + " has no " + part + " (its parts: " +
                   PartsText(o) + "); objects with a " + part + ": " + ObjectsWith(scene_, part));
  };
  const bool lying = posture_ == Posture::kLie;
  // UniHSI Table 8: one hand (elbow) on its armrest or knee points up, both hands none
  const Direction both = v.side == "both" ? Direction::kNone : Direction::kUp;
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
          pairs.push_back(Pair(o, s + " arm", j, ContactType::kContact, both));
        }
      }
      break;
    case VariantKind::kHandsOnKnees:
      for (const std::string& s : Sides(v.side)) {
        pairs.push_back(Pair(o, s + " knee",
                             SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand),
                             ContactType::kContact, both));
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
    case VariantKind::kHeadOnPillow:
      pairs.push_back(Pair(o, "pillow", BodyJoint::kHead, ContactType::kContact, Direction::kUp));
      break;
  }
  return pairs;
}

void Session::MergeIntoPoseStep(const std::vector<ContactPair>& pairs, const std::string& what) {
  const CatalogObject& o = *on_;
  const bool lying = posture_ == Posture::kLie;
  // merge into the current sit/lie step unless it already poses one of these joints
  StepDraft* last = steps_.empty() ? nullptr : &steps_.back();
  const StepDraft::Kind kind = lying ? StepDraft::kLie : StepDraft::kSit;
  // a pose ordered in a later clause ("sit down, then lean back") is a step of its own; one
  // said with the sit, after "and", or stated without a verb ("..., hands on your knees")
  // joins it
  bool merge = last != nullptr && last->kind == kind && last->object == &o &&
               (last->clause == clause_ || !sequenced_ || attributive_);
  if (merge) {
    for (size_t k = last->base_pairs; k < last->step.pairs.size(); ++k) {
      for (const ContactPair& p : pairs) {
        if (last->step.pairs[k].joint == p.joint) merge = false;
      }
    }
  }
  if (!merge) {
    Push(PostureDraft());
    steps_.back().kind = kind;
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
    // "lean on the left armrest (with your left elbow)": an elbow on the arm
    if (arm < e && !Has(t, b, e, "back") && !Has(t, b, e, "forward")) {
      v.kind = VariantKind::kElbowsOnArms;
      v.side = elbow < e ? limb_side(elbow) : SideBefore(t, b, arm);
      if (v.side.empty()) v.side = t[arm].back() == 's' ? "both" : "right";
      return std::optional<Variant>(v);
    }
    // forward: "lean forward / in / towards the screen"; back: "lean back / against the back"
    const bool back = Has(t, b, e, "back") || Has(t, b, e, "against") || Has(t, b, e, "backrest");
    const bool forward = Has(t, b, e, "forward") || Has(t, b, e, "front_of") ||
                         Has(t, b, e, "to") || Has(t, b, e, "near");
    v.kind = forward && !Has(t, b, e, "back") ? VariantKind::kLeanForward : VariantKind::kLeanBack;
    if (!back && !forward) {
      return Question("\"" + c + "\": lean which way, forward or back?");
    }
    return std::optional<Variant>(v);
  }
  if (foot < e) {
    SH_ASSIGN_OR_RETURN(std::optional<Variant> leg, LegVariant(t, b, e, foot, knee, c));
    if (leg) return leg;
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
    if (knee < e || (foot < e && t[foot] != "feet" && t[foot] != "foot")) {  // "on your legs"
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
      return Question("\"" + c + "\": on which side, your left side or your right side?");
    }
    v.kind = VariantKind::kOnSide;
    v.side = s;
    return std::optional<Variant>(v);
  }
  // "head up", "keep your head off the pillow"
  if (Has(t, b, e, "head") && (Has(t, b, e, "up") || Has(t, b, e, "raise") || away)) {
    v.kind = VariantKind::kHeadUp;
    return std::optional<Variant>(v);
  }
  if (Has(t, b, e, "head") && Has(t, b, e, "pillow")) {
    v.kind = VariantKind::kHeadOnPillow;
    return std::optional<Variant>(v);
  }
  return std::optional<Variant>();
}

}  // namespace simhuman::language::offline
