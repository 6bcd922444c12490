// Step builders: the get-close step, the implied stand-up and get-close steps, the sit and lie
// steps, and the assembly of the drafts into a grounded chain.

#include "simhuman/language/offline/objects.h"
#include "simhuman/language/offline/session.h"
#include "simhuman/language/offline_planner.h"
#include "simhuman/plan/metrics.h"
#include "simhuman/plan/validate.h"

namespace simhuman::language::offline {

Session::Session(const core::SceneCatalog& scene, const PlanContext& context) : scene_(scene) {
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

BodyJoint SideJoint(const std::string& side, BodyJoint left, BodyJoint right) {
  return side == "left" ? left : right;
}

std::vector<std::string> Sides(const std::string& side) {
  if (side == "both") return {"left", "right"};
  return {side};
}

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
  left_seat_ = true;
}

// getting close is implied before touching something out of reach
void Session::EnsureNear(const CatalogObject& target) {
  if (posture_ != Posture::kStand) return;
  // moving from one object to another always walks to the next one (even a near one)
  if (!left_seat_ && FootprintDistance(target, pos_) <= kNearEnoughM &&
      !PartBlocksTheWay(target, "seat surface", pos_)) {
    return;
  }
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

namespace {

bool SamePairs(const ContactStep& a, const ContactStep& b) {
  if (a.pairs.size() != b.pairs.size()) return false;
  for (size_t k = 0; k < a.pairs.size(); ++k) {
    const ContactPair &p = a.pairs[k], &q = b.pairs[k];
    if (p.object != q.object || p.part != q.part || p.joint != q.joint || p.type != q.type ||
        p.direction != q.direction || p.agent != q.agent) {
      return false;
    }
  }
  return true;
}

}  // namespace

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
    // a step said twice in a row ("touch it. the BOX.", "put your hands on the keyboard; type")
    // is held, not repeated
    if (!out.chain.steps.empty() && !d.step.carry && !out.chain.steps.back().carry &&
        out.explanation.back() == text && SamePairs(out.chain.steps.back(), d.step)) {
      continue;
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

}  // namespace simhuman::language::offline
