// The tabletop verb: put/place/stack/move an object on, next to, left of, right of, in front of
// or behind another, planned as a grasp step and an object-on-object goal step (DASH-style
// commands).

#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"
#include "simhuman/plan/metrics.h"

namespace simhuman::language::offline {
namespace {

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

}  // namespace

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
  if (rel == Rel::kOn) {
    dir = Direction::kUp;
    part = TopPart(*ref);
  } else if (rel == Rel::kLeftOf || rel == Rel::kRightOf || rel == Rel::kFrontOf ||
             rel == Rel::kBehind) {
    dir = ViewerSide(rel, *ref, viewer_);
  }
  const std::string subject_part = BodyPart(*a);
  focus_ = a;
  // seated at a table with both objects within a seated arm's reach (DASH's set-up): the hand
  // works from the seat; otherwise stand up and walk over first
  const bool seated_reach = posture_ == Posture::kSit &&
                            FootprintDistance(*a, pos_) <= kSeatedReachM &&
                            FootprintDistance(*ref, pos_) <= kSeatedReachM;
  if (!seated_reach) {
    EnsureFree(nullptr);
    EnsureNear(*a);
  }
  const BodyJoint hand_joint = SideJoint(hand, BodyJoint::kLeftHand, BodyJoint::kRightHand);
  ContactPair grasp = Pair(*a, subject_part, hand_joint, ContactType::kContact, Direction::kNone);
  StepDraft g;
  g.step.pairs.push_back(grasp);
  g.text = "grasp " + Describe(*a) + " with the " + hand + " hand";
  Push(std::move(g));
  if (!seated_reach) EnsureNear(*ref);
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

}  // namespace simhuman::language::offline
