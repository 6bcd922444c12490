#include "simhuman/control/task.h"

#include <cmath>

#include "simhuman/world/humanoid.h"

namespace simhuman::control {

const char* PostureName(Posture p) {
  switch (p) {
    case Posture::kStand:
      return "stand";
    case Posture::kSit:
      return "sit";
    case Posture::kLieBack:
      return "lie on back";
    case Posture::kLieSide:
      return "lie on side";
    case Posture::kLean:
      return "lean";
  }
  return "stand";
}

double BodyPointClearance(core::BodyJoint j) {
  using core::BodyJoint;
  switch (j) {
    case BodyJoint::kPelvis:
      return 0.03;
    case BodyJoint::kTorso:
      return 0.06;
    case BodyJoint::kHead:
      return 0.10;
    case BodyJoint::kLeftHand:
    case BodyJoint::kRightHand:
      return 0.045;
    case BodyJoint::kLeftFoot:
    case BodyJoint::kRightFoot:
      return 0.03;
    case BodyJoint::kLeftHip:
    case BodyJoint::kRightHip:
      return 0.07;
    default:
      return 0.045;
  }
}

Eigen::Vector3d ContactTerm::Nearest(const Eigen::Vector3d& p,
                                     core::Span<const Eigen::Vector3d> pts) const {
  if (at_belly) return plan::BellyPoint(pts).pos;
  if (target_joint) return pts[static_cast<int>(*target_joint)];
  return core::NearestPointOnShapes(part->shapes, object->pose, p);
}

Eigen::Vector3d ContactTerm::Touch(const Eigen::Vector3d& p,
                                   core::Span<const Eigen::Vector3d> pts) const {
  Eigen::Vector3d np, d = dir;
  if (at_belly) {  // one belly solve for the point and its normal (the MPC's rollouts call this)
    const plan::BellyTouch belly = plan::BellyPoint(pts);
    np = belly.pos;
    if (d.squaredNorm() < 0.5) d = belly.normal;
  } else {
    np = Nearest(p, pts);
  }
  if (d.squaredNorm() < 0.5) {
    const Eigen::Vector3d away = p - np;
    d = away.norm() > 1e-6 ? Eigen::Vector3d(away.normalized()) : Eigen::Vector3d::UnitZ();
  }
  return np + d * clearance_m;
}

namespace {
bool IsSeatLike(const core::CatalogPart* part) {
  return part && (part->name == "seat surface" || part->name == "mattress");
}
}  // namespace

StepTask BuildStepTask(const plan::ContactStep& step, const core::SceneCatalog& scene, int agent,
                       double scale, const plan::PairParams& params) {
  StepTask task;
  task.label = step.label;
  if (step.carry) {
    for (int carrier : step.carry->Agents()) {
      if (carrier != agent) continue;
      task.carry_object = scene.Find(step.carry->object);
      task.carry_goal = step.carry->goal;
    }
  }
  bool pelvis_on_seat = false, head_down = false, side_lie = false, any_contact = false;
  for (const plan::ContactPair& pair : step.pairs) {
    if (pair.agent != agent) continue;
    const core::CatalogObject* obj = scene.Find(pair.object);
    if (pair.IsGetClose()) {
      task.get_close = true;
      task.focus = obj;
      task.side = pair.direction;
      task.stand_point = plan::StandPoint(*obj, pair.direction, params.stand_off_m);
      task.stand_yaw_rad = plan::StandFacingYaw(*obj, pair.direction);
      task.walk_point = task.stand_point;
      task.walk_yaw_rad = task.stand_yaw_rad;
      continue;
    }
    if (pair.type == plan::ContactType::kNotCare) continue;
    // object-object goals (tabletop) are evaluated, not driven: the controller has no
    // manipulation skill yet, so it only works on the hand pairs of such a step
    if (pair.IsObjectPair()) continue;
    ContactTerm t;
    t.joint = *pair.joint;
    t.type = pair.type;
    t.object = obj;
    t.target_joint = pair.part_joint;
    if (!pair.part_joint) t.part = obj->FindPart(pair.part);
    t.dir = plan::DirectionVector(pair.direction, obj->pose);
    t.clearance_m = scale * BodyPointClearance(t.joint);
    t.at_belly = plan::TouchesBelly(pair, params);
    // a body point has some flesh round it; the belly point is on the skin already
    if (t.target_joint && !t.at_belly) {
      t.clearance_m += scale * BodyPointClearance(*t.target_joint) * 0.5;
    }
    // a marker is a point to reach, not a surface to rest on
    if (!t.target_joint && obj && !obj->collides) t.clearance_m = 0.0;
    task.terms.push_back(t);
    if (pair.type != plan::ContactType::kContact) {
      if (t.part && t.part->name == "mattress" &&
          (t.joint == core::BodyJoint::kLeftShoulder ||
           t.joint == core::BodyJoint::kRightShoulder)) {
        side_lie = true;
      }
      continue;
    }
    any_contact = true;
    if (!task.focus && obj) task.focus = obj;
    if (t.joint == core::BodyJoint::kPelvis && IsSeatLike(t.part)) {
      pelvis_on_seat = true;
      task.focus = obj;
    }
    if (t.joint == core::BodyJoint::kHead && t.part &&
        (t.part->name == "pillow" || t.part->name == "mattress")) {
      head_down = true;
    }
  }
  if (pelvis_on_seat && head_down) {
    task.posture = side_lie ? Posture::kLieSide : Posture::kLieBack;
    // lying, the pelvis and head rest on their backs: touching distance is the body radius,
    // less what a soft pillow gives
    for (ContactTerm& t : task.terms) {
      if (t.joint == core::BodyJoint::kPelvis) t.clearance_m = 0.07 * scale;
      if (t.joint == core::BodyJoint::kHead) t.clearance_m = 0.06 * scale;
    }
  } else if (pelvis_on_seat) {
    task.posture = Posture::kSit;
  } else {
    task.posture = Posture::kStand;
  }
  (void)any_contact;
  return task;
}

void RefineLeaving(const StepTask& prev, StepTask* gc) {
  if (!gc->get_close || gc->focus == nullptr || prev.focus != gc->focus ||
      prev.posture == Posture::kStand || gc->side != plan::Direction::kFront) {
    return;
  }
  gc->walk_yaw_rad = std::remainder(gc->stand_yaw_rad + M_PI, 2.0 * M_PI);
}

void RefineLeavingFromStart(const Eigen::Vector3d& pelvis, double scale, StepTask* gc) {
  if (!gc->focus || !world::PelvisLowAsSeated(pelvis.z(), scale)) return;
  const Eigen::Vector3d local = gc->focus->pose.quat.conjugate() * (pelvis - gc->focus->pose.pos);
  const auto [lo, hi] = gc->focus->LocalBounds();
  if (local.x() < lo.x() || local.x() > hi.x() || local.y() < lo.y() || local.y() > hi.y()) return;
  StepTask seated;
  seated.focus = gc->focus;
  seated.posture = Posture::kSit;
  RefineLeaving(seated, gc);
}

void RefineApproach(const StepTask& next, double scale, StepTask* gc) {
  if (!gc->get_close || gc->focus == nullptr || next.focus != gc->focus) return;
  const core::CatalogObject& obj = *gc->focus;
  // one hand reaching a part of the object: stand so that the point is ahead of that shoulder
  if (next.posture == Posture::kStand && next.terms.size() == 1) {
    const ContactTerm& t = next.terms[0];
    const bool left = t.joint == core::BodyJoint::kLeftHand;
    const bool right = t.joint == core::BodyJoint::kRightHand;
    if ((left || right) && t.type == plan::ContactType::kContact && t.part != nullptr) {
      const Eigen::Vector3d probe = gc->stand_point + Eigen::Vector3d(0, 0, 1.0 * scale);
      const Eigen::Vector3d target = core::NearestPointOnShapes(t.part->shapes, obj.pose, probe);
      const Eigen::Vector2d fwd(std::cos(gc->stand_yaw_rad), std::sin(gc->stand_yaw_rad));
      const Eigen::Vector2d lft(-fwd.y(), fwd.x());
      const Eigen::Vector2d rel = (target - gc->stand_point).head<2>();
      const double ahead = rel.dot(fwd), across = rel.dot(lft);
      // only a point in front, within arm's length of the stand point
      if (ahead < 0.1 * scale || ahead > 0.9 * scale) return;
      Eigen::Vector2d shift = fwd * (ahead - kReachAheadM * scale) +
                              lft * (across - (left ? 1.0 : -1.0) * kReachAcrossM * scale);
      if (shift.norm() > kReachMaxShiftM) shift *= kReachMaxShiftM / shift.norm();
      gc->walk_point.head<2>() += shift;
    }
    return;
  }
  if (gc->side != plan::Direction::kFront) return;
  const auto [lo, hi] = obj.LocalBounds();
  Eigen::Vector3d local(hi.x() + scale * kSitStartM, 0.5 * (lo.y() + hi.y()), 0.0);
  const core::CatalogPart* pillow = obj.FindPart("pillow");
  const core::CatalogPart* mattress = obj.FindPart("mattress");
  const bool lie = next.posture == Posture::kLieBack || next.posture == Posture::kLieSide;
  if (pillow != nullptr && mattress != nullptr && (lie || next.posture == Posture::kSit)) {
    // a bed: sit down where lying back puts the head on the pillow
    auto [plo, phi] = core::ShapesBounds(pillow->shapes);
    auto [mlo, mhi] = core::ShapesBounds(mattress->shapes);
    double py = 0.5 * (plo.y() + phi.y()), my = 0.5 * (mlo.y() + mhi.y());
    local.y() = py + (py > my ? -1.0 : 1.0) * scale * kLieStartFromPillowM;
  } else if (next.posture == Posture::kSit) {
    // in front of the middle of the seat surface
    if (const core::CatalogPart* seat = obj.FindPart("seat surface")) {
      auto [slo, shi] = core::ShapesBounds(seat->shapes);
      local.y() = 0.5 * (slo.y() + shi.y());
    }
  } else {
    return;
  }
  Eigen::Vector3d world = obj.pose.Apply(local);
  world.z() = 0.0;
  gc->walk_point = world;
  gc->walk_yaw_rad = std::remainder(gc->stand_yaw_rad + M_PI, 2.0 * M_PI);
}

}  // namespace simhuman::control
