// What a command leaves implicit: the seat of "sit at the table", the seat or bed a pose
// implies ("lean back in the armchair", "cross your legs" with one seat in the scene), the seat
// pairs kept while a seated human touches something (UniHSI Table 7), and typing on a laptop
// (both hands on its keyboard, seated).

#include <set>
#include <utility>

#include "simhuman/language/offline/lexicon.h"
#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"

namespace simhuman::language::offline {
namespace {

// the parts a pose needs on the object it implies; empty: the pose implies nothing
std::vector<std::string> ImpliedParts(VariantKind k) {
  switch (k) {
    case VariantKind::kLeanForward:
    case VariantKind::kLeanBack:
      return {"seat surface", "back surface"};
    case VariantKind::kFootOnKnee:
      return {"seat surface"};
    case VariantKind::kElbowsOnArms:
      return {"seat surface", "left arm"};
    case VariantKind::kKneesUp:
    case VariantKind::kOnSide:
    case VariantKind::kHeadUp:
    case VariantKind::kHeadOnPillow:
      return {"mattress", "pillow"};
    default:
      return {};
  }
}

bool HasAll(const CatalogObject& o, const std::vector<std::string>& parts) {
  for (const std::string& p : parts) {
    if (!HasPart(o, p)) return false;
  }
  return true;
}

}  // namespace

StepDraft Session::PostureDraft() const {
  StepDraft d;
  const CatalogObject& o = *on_;
  d.object = &o;
  if (posture_ == Posture::kLie) {
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
  return d;
}

void Session::AddSeatedReach(const CatalogObject& o, const std::string& part,
                             const std::vector<std::string>& sides, bool in_pose) {
  std::vector<ContactPair> hands;
  for (const std::string& s : sides) {
    hands.push_back(Pair(o, part, SideJoint(s, BodyJoint::kLeftHand, BodyJoint::kRightHand),
                         ContactType::kContact, Direction::kNone));
  }
  const std::string what =
      (sides.size() == 2 ? std::string("both hands on the ") : sides[0] + " hand on the ") + part +
      " of " + Describe(o);
  StepDraft* last = steps_.empty() ? nullptr : &steps_.back();
  if (in_pose && last != nullptr && last->object == on_ &&
      (last->clause == clause_ || attributive_) &&
      (last->kind == StepDraft::kSit || last->kind == StepDraft::kLie)) {
    for (const ContactPair& p : hands) last->step.pairs.push_back(p);
    last->variant_texts.push_back(what);
    return;
  }
  StepDraft d = PostureDraft();
  for (const ContactPair& p : hands) d.step.pairs.push_back(p);
  d.variant_texts.push_back(what);
  d.kind = StepDraft::kOther;
  Push(std::move(d));
}

core::StatusOr<const CatalogObject*> Session::OnlyObjectWith(const std::vector<std::string>& parts,
                                                             const std::string& verb,
                                                             const std::string& c) const {
  if (on_ != nullptr && HasAll(*on_, parts)) return on_;
  if (focus_ != nullptr && HasAll(*focus_, parts)) return focus_;
  std::vector<const CatalogObject*> fit;
  for (const CatalogObject& x : scene_.objects) {
    if (HasAll(x, parts)) fit.push_back(&x);
  }
  if (fit.empty()) {
    return Invalid("\"" + c + "\": nothing in this scene to " + verb + " on (it needs " +
                   core::JoinNames(parts) + "); the scene has: " + DescribeSceneObjects(scene_));
  }
  if (fit.size() > 1) {
    std::vector<std::string> names;
    for (const CatalogObject* x : fit) names.push_back(Describe(*x));
    std::string v = verb;
    v[0] = static_cast<char>(v[0] - 'a' + 'A');
    return Question(v + " on which: " + core::JoinNames(names) + "?");
  }
  return fit[0];
}

core::StatusOr<const CatalogObject*> Session::SeatAt(const CatalogObject& o,
                                                     const std::string& c) const {
  const CatalogObject* best = nullptr;
  double best_d = 1e300;
  bool tie = false;
  for (const CatalogObject& x : scene_.objects) {
    if (!HasPart(x, "seat surface")) continue;
    const double d = CentreDistance(x, o);
    if (d < best_d - kTieM) {
      tie = false;
      best = &x;
      best_d = d;
    } else if (d <= best_d + kTieM) {
      tie = true;
    }
  }
  if (best == nullptr) {
    return Invalid("\"" + c + "\": there is no seat to sit at " + Describe(o) +
                   "; the scene has: " + DescribeSceneObjects(scene_));
  }
  if (tie) return Question("Which seat at " + Describe(o) + " should I sit on?");
  return best;
}

const CatalogObject* Session::SeatBy(const CatalogObject* o) const {
  if (o == nullptr || HasPart(*o, "seat surface") || HasPart(*o, "mattress")) return nullptr;
  constexpr double kSeatByM = 1.0;  // a seat pulled up to a table is well within this
  const CatalogObject* found = nullptr;
  for (const CatalogObject& x : scene_.objects) {
    if (!HasPart(x, "seat surface")) continue;
    if (FootprintDistance(*o, {x.pose.pos.x(), x.pose.pos.y()}) > kSeatByM) continue;
    if (found != nullptr) return nullptr;  // several: the question lists them
    found = &x;
  }
  return found;
}

absl::Status Session::ImpliedBase(const Variant& v, const Tokens& t, size_t b, size_t e,
                                  const std::string& c) {
  const std::vector<std::string> parts = ImpliedParts(v.kind);
  if (parts.empty()) return absl::OkStatus();
  // the object named after the last "in"/"on"/"at" ("lean back in the armchair")
  const CatalogObject* o = nullptr;
  for (size_t k = e; k-- > b + 1;) {
    if (t[k] != "in" && t[k] != "on" && t[k] != "at" && t[k] != "onto") continue;
    bool body = false;
    for (size_t m = k + 1; m < e; ++m) body = body || IsBodyWord(t[m]) || t[m] == "side";
    if (body || k + 1 >= e) break;
    SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, k + 1, e, 0, c));
    if (!np.has_type && np.id.empty()) break;
    SH_ASSIGN_OR_RETURN(o, Resolve(np, c, parts[0]));
    break;
  }
  if (o == nullptr) {
    if (posture_ != Posture::kStand && on_ != nullptr) return absl::OkStatus();
    SH_ASSIGN_OR_RETURN(o, OnlyObjectWith(parts, parts[0] == "mattress" ? "lie" : "sit", c));
  }
  if (on_ == o && posture_ != Posture::kStand) return absl::OkStatus();
  focus_ = o;
  EnsureFree(o);
  EnsureNear(*o);
  if (parts[0] == "mattress") return AddLie(*o);
  return AddSit(*o);
}

absl::Status Session::Type(const Tokens& t, size_t b, const std::string& c) {
  size_t i = b;
  while (i < t.size() &&
         (t[i] == "on" || t[i] == "at" || t[i] == "in" || t[i] == "using" || t[i] == "away")) {
    ++i;
  }
  const size_t e = Find(t, i, t.size(), {"with", "using"});  // "... with both hands"
  const CatalogObject* o = nullptr;
  if (i < e) {
    SH_ASSIGN_OR_RETURN(NounPhrase np, ParseNounPhrase(t, i, e, 0, c));
    SH_ASSIGN_OR_RETURN(o, Resolve(np, c, "keyboard"));
    // "type at the desk": the laptop on it
    const CatalogObject* on = nullptr;
    for (const CatalogObject& x : scene_.objects) {
      if (HasPart(*o, "keyboard") || !HasPart(x, "keyboard") || !RestsOn(x, *o)) continue;
      on = on == nullptr ? &x : o;  // several: keep `o` (the error names the laptops)
    }
    if (on != nullptr) o = on;
  } else {
    std::vector<const CatalogObject*> fit;
    for (const CatalogObject& x : scene_.objects) {
      if (HasPart(x, "keyboard")) fit.push_back(&x);
    }
    if (fit.empty()) {
      return Invalid("\"" + c + "\": there is nothing to type on in this scene; the scene has: " +
                     DescribeSceneObjects(scene_));
    }
    if (fit.size() > 1) {
      std::vector<std::string> names;
      for (const CatalogObject* x : fit) names.push_back(Describe(*x));
      return Question("Type on which: " + core::JoinNames(names) + "?");
    }
    o = fit[0];
  }
  if (!HasPart(*o, "keyboard")) {
    return Invalid("\"" + c + "\": " + Describe(*o) +
                   " has no keyboard; objects with one: " + ObjectsWith(scene_, "keyboard"));
  }
  focus_ = o;
  if (posture_ != Posture::kSit || on_ == nullptr || FootprintDistance(*o, pos_) > kNearEnoughM) {
    // typing is done seated: the seat at the laptop first
    SH_ASSIGN_OR_RETURN(const CatalogObject* seat, SeatAt(*o, c));
    if (!(on_ == seat && posture_ == Posture::kSit)) {
      EnsureFree(seat);
      EnsureNear(*seat);
      SH_RETURN_IF_ERROR(AddSit(*seat));
    }
  }
  // "type ... with your right hand": that hand only
  std::vector<std::string> sides = {"left", "right"};
  if (const size_t hand = Find(t, e, t.size(), {"hand"}); hand < t.size()) {
    const std::string side = SideBefore(t, e, hand);
    if (side == "left" || side == "right") sides = {side};
  }
  AddSeatedReach(*o, "keyboard", sides, false);
  return absl::OkStatus();
}

}  // namespace simhuman::language::offline
