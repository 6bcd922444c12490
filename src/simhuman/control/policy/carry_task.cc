#include "simhuman/control/policy/carry_task.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "simhuman/control/arm_servo.h"
#include "simhuman/control/policy/carry_steer.h"
#include "simhuman/core/geometry.h"

namespace simhuman::control {
namespace {

// actuator (hinge) order of world::HumanoidJointNames() (as in walk_task.cc)
constexpr int kAbdY = 1, kRShX = 6, kRElbow = 9, kLShX = 10, kLElbow = 13;
constexpr int kRHipX = 14, kRHipY = 15, kRKnee = 17, kRAnkX = 18, kRAnkY = 19;
constexpr int kLHipX = 21, kLHipY = 22, kLKnee = 24, kLAnkX = 25, kLAnkY = 26;

// lift: squat and open until kSqueezeStart, squeeze until kRiseStart, then rise; put-down:
// lower until kLowerEnd, keep pressing until kReleaseStart, open over kReleaseSeconds, rise
constexpr double kSqueezeStart = 1.3, kRiseStart = 1.9;
constexpr double kLowerEnd = 1.5, kReleaseStart = 1.8, kReleaseSeconds = 0.5;
using Pose = std::array<double, kWalkActDim>;

double Clamp(double x, double lo, double hi) { return std::min(hi, std::max(lo, x)); }
double Smooth(double u) {
  u = Clamp(u, 0.0, 1.0);
  return u * u * (3 - 2 * u);
}
Eigen::Vector3d Vec(const mjtNum* x) { return Eigen::Vector3d(x[0], x[1], x[2]); }

// world -> heading frame of yaw
Eigen::Vector3d ToHeading(const Eigen::Vector3d& v, double yaw) {
  double c = std::cos(yaw), s = std::sin(yaw);
  return Eigen::Vector3d(c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z());
}

Pose Blend(const Pose& a, const Pose& b, double u) {
  Pose q;
  double w = Smooth(u);
  for (int j = 0; j < kWalkActDim; ++j) q[j] = (1 - w) * a[j] + w * b[j];
  return q;
}

// a pose in the stand frame: hinges, the root at (x, 0, z) pitched forward by `pitch`
struct Placed {
  Pose q{};
  double x = 0, z = 1, pitch = 0;
};

// writes the pose into `d` and runs the kinematics and the centre of mass
void PoseKinematics(const mjModel* m, mjData* d, const CarryIndex& ix, const Placed& p) {
  const world::AgentIndex& a = ix.walk.agent;
  mju_copy(d->qpos, m->qpos0, m->nq);
  d->qpos[a.root_qpos + 0] = p.x;
  d->qpos[a.root_qpos + 1] = 0;
  d->qpos[a.root_qpos + 2] = p.z;
  d->qpos[a.root_qpos + 3] = std::cos(p.pitch / 2);
  d->qpos[a.root_qpos + 4] = 0;
  d->qpos[a.root_qpos + 5] = std::sin(p.pitch / 2);
  d->qpos[a.root_qpos + 6] = 0;
  for (int j = 0; j < kWalkActDim; ++j) d->qpos[a.hinge_qpos[j]] = p.q[j];
  mj_kinematics(m, d);
  mj_comPos(m, d);  // the centre of mass, which mj_jacSite also reads
}

// lowest foot box corner and the feet's mean x (after PoseKinematics)
void FeetOnFloor(const mjModel* m, const mjData* d, const CarryIndex& ix, double* lowest,
                 double* mean_x) {
  const int l = ix.walk.left_foot_geom, r = ix.walk.right_foot_geom;
  *lowest = LowestBoxCornerZ(m, d, {l, r});
  *mean_x = 0.5 * (d->geom_xpos[3 * l] + d->geom_xpos[3 * r]);
}

// legs and trunk of a squat of depth alpha in [0, 1] (arms from `base`; ankles set later)
Pose Squat(const Pose& base, double alpha, double hinge) {
  Pose q = base;
  // a lifting squat: the knees bend about as much as the hips, the hips flex `hinge` further (a
  // stoop-squat: hips back, trunk forward over the box), and open so the knees pass beside the
  // box instead of folding the trunk over it
  q[kRHipY] = q[kLHipY] = 0.12 + 1.7 * alpha + hinge;
  q[kRKnee] = q[kLKnee] = 0.25 + 2.0 * alpha;
  q[kAbdY] = 0.05 + 0.35 * alpha;
  q[kRHipX] = q[kLHipX] = 0.45 * alpha;
  // the ankles roll back by the same angle so the soles stay flat (their x axes are mirrored)
  q[kRAnkX] = 0.45 * alpha;
  q[kLAnkX] = -0.45 * alpha;
  return q;
}

// the foot's pitch (rotation of its sole about y; 0 = flat) after PoseKinematics
double FootPitch(const mjData* d, int geom) {
  const mjtNum* R = d->geom_xmat + 9 * geom;
  return std::atan2(R[2], R[8]);  // x component of the foot's z axis
}

// sets both ankles so the soles are flat, puts the lowest corner on the floor and centres the
// feet at x = 0
void StandOnFloor(const mjModel* m, mjData* d, const CarryIndex& ix, Placed* p) {
  // the sole's pitch follows the ankle hinge one to one (the sign from the model's axes)
  const int foot = ix.walk.left_foot_geom;
  PoseKinematics(m, d, ix, *p);
  double e0 = FootPitch(d, foot);
  Placed probe = *p;
  probe.q[kLAnkY] += 0.05;
  PoseKinematics(m, d, ix, probe);
  double slope = (FootPitch(d, foot) - e0) / 0.05;
  if (std::abs(slope) > 0.5) {
    p->q[kLAnkY] = p->q[kRAnkY] = Clamp(p->q[kLAnkY] - e0 / slope, -0.75, 0.75);
  }
  p->x = 0;
  p->z = 1;
  PoseKinematics(m, d, ix, *p);
  double lowest, mean_x;
  FeetOnFloor(m, d, ix, &lowest, &mean_x);
  p->x = -mean_x;
  p->z = 1.0 - lowest;
  PoseKinematics(m, d, ix, *p);
}

// a squat of depth alpha whose centre of mass is over the middle of the feet (bisection on the
// pelvis pitch)
Placed BalancedSquat(const mjModel* m, mjData* d, const CarryIndex& ix, const Pose& base,
                     double alpha, double hinge) {
  Placed p;
  p.q = Squat(base, alpha, hinge);
  double lo = -0.2, hi = 1.0;
  for (int it = 0; it < 9; ++it) {
    p.pitch = 0.5 * (lo + hi);
    StandOnFloor(m, d, ix, &p);
    double com_x = d->subtree_com[3 * ix.walk.agent.pelvis_body];
    (com_x < 0 ? lo : hi) = p.pitch;  // behind the feet: lean further forward
  }
  p.pitch = 0.5 * (lo + hi);
  StandOnFloor(m, d, ix, &p);
  return p;
}

// damped Gauss-Newton on the 4 arm hinges of each side toward the hand targets (stand frame);
// returns the worst remaining distance
double SolveArms(const mjModel* m, mjData* d, const CarryIndex& ix, Placed* p,
                 const Eigen::Vector3d& left, const Eigen::Vector3d& right) {
  const world::AgentIndex& a = ix.walk.agent;
  std::vector<mjtNum> jac(3 * m->nv);
  double worst = 0;
  for (int it = 0; it < 40; ++it) {
    PoseKinematics(m, d, ix, *p);
    worst = 0;
    for (int side = 0; side < 2; ++side) {
      int site = side == 0 ? ix.left_hand_site : ix.right_hand_site;
      int first = side == 0 ? kLShX : kRShX, last = side == 0 ? kLElbow : kRElbow;
      Eigen::Vector3d err = (side == 0 ? left : right) - Vec(d->site_xpos + 3 * site);
      worst = std::max(worst, err.norm());
      mj_jacSite(m, d, jac.data(), nullptr, site);
      Eigen::Matrix<double, 3, 4> J;
      for (int j = first; j <= last; ++j) {
        for (int r = 0; r < 3; ++r) J(r, j - first) = jac[r * m->nv + a.hinge_qvel[j]];
      }
      Eigen::Matrix4d H = J.transpose() * J + 1e-3 * Eigen::Matrix4d::Identity();
      Eigen::Vector4d dq = H.ldlt().solve(J.transpose() * err);
      for (int j = first; j <= last; ++j) {
        int act = a.actuator[j];
        p->q[j] = Clamp(p->q[j] + dq[j - first], m->actuator_ctrlrange[2 * act],
                        m->actuator_ctrlrange[2 * act + 1]);
      }
    }
    if (worst < 2e-3) break;
  }
  PoseKinematics(m, d, ix, *p);
  return worst;
}

// SolveArms from the pose's own arms and from arms reaching forward and down (the
// Gauss-Newton descent stalls in poor minima from hanging arms); keeps the best
double SolveArmsFromSeeds(const mjModel* m, mjData* d, const CarryIndex& ix, Placed* p,
                          const Eigen::Vector3d& left, const Eigen::Vector3d& right) {
  Placed best = *p;
  double best_e = SolveArms(m, d, ix, &best, left, right);
  for (double flex : {0.6, 1.2}) {
    Placed trial = *p;
    for (int sh : {kRShX, kLShX}) {
      trial.q[sh] = 0.2;       // abduction
      trial.q[sh + 1] = flex;  // forward flexion
      trial.q[sh + 2] = 0.0;   // rotation
      trial.q[sh + 3] = 0.3;   // elbow
    }
    const double e = SolveArms(m, d, ix, &trial, left, right);
    if (e < best_e) {
      best_e = e;
      best = trial;
    }
  }
  *p = best;
  PoseKinematics(m, d, ix, *p);
  return best_e;
}

double HandRadius(const mjModel* m, const CarryIndex& ix) {
  return m->geom_size[3 * ix.left_hand_geom];
}

double PhaseDuration(CarryPhase p) {
  if (p == CarryPhase::kLift) return kLiftSeconds;
  if (p == CarryPhase::kPutDown) return kPutDownSeconds;
  return 0;
}

// at the stand point (not the walk target, which may lie past it): facing its way and slow, or
// within the arrival radius for arrive_dwell_s of this phase whatever the speed and heading
// (counts that time: call once per policy step)
bool Arrived(const CarryParams& p, const mjData* d, const CarryIndex& ix, CarryState* s) {
  double to_target, yaw_err;
  WalkErrors(d, ix.walk, s->walk, &to_target, &yaw_err);
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix.walk, &pos, &yaw);
  const double dist = (pos.head<2>() - s->stand_xy).norm();
  if (dist >= p.arrive_radius_m) return false;
  s->near_stand_s += kWalkPolicyDt;
  if (s->near_stand_s >= p.arrive_dwell_s - 1e-9) return true;
  const mjtNum* v = d->qvel + ix.walk.agent.root_qvel;
  return std::abs(yaw_err) < p.arrive_yaw_rad && std::hypot(v[0], v[1]) < p.arrive_speed_mps;
}

void Enter(CarryState* s, CarryPhase phase) {
  s->phase = phase;
  s->phase_time_s = 0;
  s->near_stand_s = 0;
}

double FaceYaw(const CarryState& s) { return std::atan2(s.face_dir.y(), s.face_dir.x()); }

Eigen::Vector3d Corner(const CarryBox& box, int c) {
  Eigen::Vector3d local((c & 1 ? 1 : -1) * box.half.x(), (c & 2 ? 1 : -1) * box.half.y(),
                        (c & 4 ? 1 : -1) * box.half.z());
  return box.pos + box.rot * local;
}

}  // namespace

const char* CarryPhaseName(CarryPhase p) {
  switch (p) {
    case CarryPhase::kApproach:
      return "approach";
    case CarryPhase::kLift:
      return "lift";
    case CarryPhase::kCarry:
      return "carry";
    case CarryPhase::kPutDown:
      return "put down";
    case CarryPhase::kRetreat:
      return "retreat";
  }
  return "?";
}

core::StatusOr<CarryIndex> MakeCarryIndex(const world::SimWorld& world, int a) {
  CarryIndex ix;
  SH_ASSIGN_OR_RETURN(ix.walk, MakeWalkIndex(world, a));
  const world::AgentIndex& ag = ix.walk.agent;
  ix.left_hand_site = ag.site[static_cast<int>(core::BodyJoint::kLeftHand)];
  ix.right_hand_site = ag.site[static_cast<int>(core::BodyJoint::kRightHand)];
  const mjModel* m = world.model();
  std::string p = world::AgentPrefix(a);
  ix.left_hand_geom = mj_name2id(m, mjOBJ_GEOM, (p + "left_hand_geom").c_str());
  ix.right_hand_geom = mj_name2id(m, mjOBJ_GEOM, (p + "right_hand_geom").c_str());
  ix.left_grip = mj_name2id(m, mjOBJ_ACTUATOR, (p + "left_grip").c_str());
  ix.right_grip = mj_name2id(m, mjOBJ_ACTUATOR, (p + "right_grip").c_str());
  if (ix.left_hand_site < 0 || ix.right_hand_site < 0 || ix.left_hand_geom < 0 ||
      ix.right_hand_geom < 0) {
    return absl::NotFoundError("carry task: humanoid '" + p + "' has no hand sites or geoms");
  }
  return ix;
}

CarryPoses SolveCarryPoses(const CarryParams& p, const mjModel* m, mjData* scratch,
                           const CarryIndex& ix, const LiftGeometry& g) {
  CarryPoses out;
  const Pose& nominal = WalkNominalPose();
  const double r = HandRadius(m, ix);
  // the shallowest balanced squat (centre of mass over the feet) from which the hands reach
  // their open points
  Placed stand;
  stand.q = nominal;
  StandOnFloor(m, scratch, ix, &stand);
  const Eigen::Vector3d open_l = g.left + (r + p.open_m) * g.left_out;
  const Eigen::Vector3d open_r = g.right + (r + p.open_m) * g.right_out;
  Placed squat;
  double e1 = 1e9;
  for (double alpha : {0.2, 0.4, 0.55, 0.7, 0.85, 1.0}) {
    Placed trial = BalancedSquat(m, scratch, ix, nominal, alpha, p.squat_hinge_rad);
    double e = SolveArmsFromSeeds(m, scratch, ix, &trial, open_l, open_r);
    if (e < e1 - 1e-4) {
      e1 = e;
      squat = trial;
    }
    if (e < 0.015) break;
  }
  out.squat_pelvis_z = squat.z;
  out.squat_pitch_rad = squat.pitch;
  out.squat_open = squat.q;
  double e2 = SolveArms(m, scratch, ix, &squat, g.left + (r - p.squeeze_m) * g.left_out,
                        g.right + (r - p.squeeze_m) * g.right_out);
  out.squat_squeeze = squat.q;
  // holding: standing, the box's near face hold_gap in front of the pelvis
  StandOnFloor(m, scratch, ix, &stand);
  const world::AgentIndex& a = ix.walk.agent;
  Eigen::Vector3d c = Vec(scratch->xpos + 3 * a.pelvis_body) +
                      Eigen::Vector3d(p.hold_gap_m + g.half_x, 0, p.hold_rise_m);
  Eigen::Vector3d off(g.held_dx, g.half_y + r - p.squeeze_m, g.held_dz);
  double e3 =
      SolveArms(m, scratch, ix, &stand, c + off, c + Eigen::Vector3d(off.x(), -off.y(), off.z()));
  out.hold = stand.q;
  out.hold_lean_rad = g.hold_lean_rad;
  out.ik_error_m = std::max({e1, e2, e3});
  return out;
}

LiftGeometry MakeLiftGeometry(const CarryParams& p, const mjData* d, const CarryIndex& ix,
                              const CarryState& s, const CarryBox& box) {
  // the stand frame: origin on the floor between the feet, x along the pelvis heading
  Eigen::Vector3d pelvis;
  double yaw;
  PelvisPose(d, ix.walk, &pelvis, &yaw);
  Eigen::Vector3d origin = 0.5 * (Vec(d->geom_xpos + 3 * ix.walk.left_foot_geom) +
                                  Vec(d->geom_xpos + 3 * ix.walk.right_foot_geom));
  origin.z() = 0;
  auto local = [&](const Eigen::Vector3d& w) { return ToHeading(w - origin, yaw); };
  LiftGeometry g;
  Eigen::Vector3d hl, hr;
  CarryHeldPoints(s, box, &hl, &hr);
  g.left = local(hl);
  g.right = local(hr);
  Eigen::Vector3d axis = box.rot.col(s.held_axis) * (s.held_left_local[s.held_axis] > 0 ? 1 : -1);
  g.left_out = ToHeading(axis, yaw);
  g.right_out = -g.left_out;
  Eigen::Vector3d centre = local(box.pos);
  g.half_x = s.half_stand.x();
  g.half_y = s.half_stand.y();
  g.held_dx = 0.5 * (g.left.x() + g.right.x()) - centre.x();
  g.held_dz = 0.5 * (g.left.z() + g.right.z()) - centre.z();
  g.hold_lean_rad = p.hold_lean_rad_per_kg * box.mass_kg;
  return g;
}

void ChooseStandFace(const CarryParams& p, const CarryBox& box, const Eigen::Vector2d& from_xy,
                     Eigen::Vector2d* stand_xy, Eigen::Vector2d* face_dir,
                     Eigen::Vector3d* half_in_stand) {
  Eigen::Vector2d to_from = from_xy - box.pos.head<2>();
  double best = -1e9;
  int best_axis = 0, best_sign = 1;
  for (int axis = 0; axis < 2; ++axis) {
    Eigen::Vector2d n(box.rot(0, axis), box.rot(1, axis));
    if (n.norm() < 1e-6) continue;
    n.normalize();
    for (int sign : {1, -1}) {
      double score = sign * n.dot(to_from);
      if (score > best) {
        best = score;
        best_axis = axis;
        best_sign = sign;
      }
    }
  }
  Eigen::Vector2d n(box.rot(0, best_axis), box.rot(1, best_axis));
  n = n.normalized() * best_sign;  // outward normal of the chosen face
  *face_dir = -n;
  *half_in_stand = Eigen::Vector3d(box.half[best_axis], box.half[1 - best_axis], box.half.z());
  *stand_xy = box.pos.head<2>() + n * (box.half[best_axis] + p.stand_gap_m);
}

void BeginCarry(const CarryParams& p, const CarryIndex& ix, const mjData* d, const CarryBox& box,
                const Eigen::Vector2d& dest_xy, CarryState* s) {
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix.walk, &pos, &yaw);
  Eigen::Vector2d stand, dir;
  Eigen::Vector3d half;
  ChooseStandFace(p, box, pos.head<2>(), &stand, &dir, &half);
  s->gait = p.walk;
  s->face_dir = dir;
  s->half_stand = half;
  // the held faces are the box faces to the carrier's left and right
  Eigen::Vector2d left(-dir.y(), dir.x());
  double best = 0;
  for (int axis = 0; axis < 2; ++axis) {
    double c = box.rot(0, axis) * left.x() + box.rot(1, axis) * left.y();
    if (std::abs(c) > std::abs(best)) {
      best = c;
      s->held_axis = axis;
    }
  }
  s->held_left_local = Eigen::Vector3d::Zero();
  s->held_left_local[s->held_axis] = (best > 0 ? 1 : -1) * box.half[s->held_axis];
  s->held_left_local.z() = (2 * p.grasp_frac - 1) * box.half.z();
  // along the carrier's forward axis: the face centre, or max_reach_depth behind the near face
  const int face_axis = 1 - s->held_axis;
  const double toward = box.rot(0, face_axis) * dir.x() + box.rot(1, face_axis) * dir.y();
  const double depth = box.half[face_axis];
  s->held_left_local[face_axis] =
      (toward > 0 ? -1 : 1) * (depth - std::min(depth, p.max_reach_depth_m));
  s->dest_xy = dest_xy;
  s->poses = CarryPoses();
  s->approach_on_line = false;
  Enter(s, CarryPhase::kApproach);
  SetCarryWalkTarget(s, stand, FaceYaw(*s), p.approach_lead_m * dir);
}

void StartLift(const CarryParams& p, const mjModel* m, mjData* scratch, const mjData* d,
               const CarryIndex& ix, const CarryBox& box, CarryState* s) {
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix.walk, &pos, &yaw);
  Enter(s, CarryPhase::kLift);
  SetCarryWalkTarget(s, pos.head<2>(), yaw);
  s->poses = SolveCarryPoses(p, m, scratch, ix, MakeLiftGeometry(p, d, ix, *s, box));
}

double LiftRiseStartSeconds() { return kRiseStart; }

double PutDownLowerEndSeconds() { return kLowerEnd; }

namespace {

// poses the agent at rest in the hinge pose `ref` (also its controls), the root at its current
// heading pitched forward by `pitch`, the feet's midpoint where it was and the lowest foot
// corner on the floor
void PoseOnFeet(const mjModel* m, mjData* d, const CarryIndex& ix, const double* ref,
                double pitch) {
  const world::AgentIndex& a = ix.walk.agent;
  Eigen::Vector3d pelvis;
  double yaw;
  PelvisPose(d, ix.walk, &pelvis, &yaw);
  const int l = ix.walk.left_foot_geom, r = ix.walk.right_foot_geom;
  auto feet_xy = [&] {
    return Eigen::Vector2d(0.5 * (d->geom_xpos[3 * l] + d->geom_xpos[3 * r]),
                           0.5 * (d->geom_xpos[3 * l + 1] + d->geom_xpos[3 * r + 1]));
  };
  const Eigen::Vector2d feet0 = feet_xy();
  mjtNum q_yaw[4] = {std::cos(yaw / 2), 0, 0, std::sin(yaw / 2)};
  mjtNum q_pitch[4] = {std::cos(pitch / 2), 0, std::sin(pitch / 2), 0};
  mju_mulQuat(d->qpos + a.root_qpos + 3, q_yaw, q_pitch);
  for (int j = 0; j < kWalkActDim; ++j) {
    d->qpos[a.hinge_qpos[j]] = ref[j];
    d->ctrl[a.actuator[j]] = ref[j];
  }
  mju_zero(d->qvel + a.root_qvel, 6);
  for (int j = 0; j < kWalkActDim; ++j) d->qvel[a.hinge_qvel[j]] = 0;
  mj_kinematics(m, d);
  const Eigen::Vector2d shift = feet0 - feet_xy();
  d->qpos[a.root_qpos + 0] += shift.x();
  d->qpos[a.root_qpos + 1] += shift.y();
  mj_kinematics(m, d);
  d->qpos[a.root_qpos + 2] -= LowestBoxCornerZ(m, d, {l, r}) - 0.001;
  mj_forward(m, d);
}

}  // namespace

void PoseInLift(const mjModel* m, mjData* d, const CarryIndex& ix, double t_s, CarryState* s) {
  s->phase_time_s = Clamp(t_s, 0.0, kRiseStart);
  double ref[kWalkActDim];
  CarryReference(*s, ref);
  PoseOnFeet(m, d, ix, ref, s->poses.squat_pitch_rad * Smooth(s->phase_time_s / kSqueezeStart));
}

void StartPutDown(const CarryParams& p, const mjData* d, const CarryIndex& ix, CarryState* s) {
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix.walk, &pos, &yaw);
  Enter(s, CarryPhase::kPutDown);
  s->gait = p.walk;
  SetCarryWalkTarget(s, pos.head<2>(), yaw);
}

void PoseInPutDown(const mjModel* m, mjData* d, const CarryIndex& ix, double t_s,
                   const CarryPoses& pose_with, CarryState* s) {
  s->phase_time_s = Clamp(t_s, 0.0, kLowerEnd);
  CarryState posed = *s;
  posed.poses = pose_with;
  double ref[kWalkActDim];
  CarryReference(posed, ref);
  PoseOnFeet(m, d, ix, ref, s->poses.squat_pitch_rad * (s->phase_time_s / kLowerEnd));
}

namespace {

// The grip servo: while the hands should hold, each hand near its held point is driven
// `squeeze_m` inside its face by an integral offset on its arm's targets; otherwise the
// offsets fade out.
void UpdateGrip(const CarryParams& p, const mjModel* m, const mjData* d, const CarryIndex& ix,
                const CarryBox& box, CarryState* s) {
  static const std::array<std::array<int, 4>, 2> kArms = *ArmJointIndices();
  std::array<bool, 2> active = {false, false};
  if (p.grip_gain > 0 && CarryHandsOnBox(*s)) {
    Eigen::Vector3d held[2];
    CarryHeldPoints(*s, box, &held[1], &held[0]);  // [0] right, [1] left
    const int axis = s->held_axis;
    const double left_sign = s->held_left_local[axis] >= 0 ? 1.0 : -1.0;
    const Eigen::Vector3d left_out = left_sign * box.rot.col(axis);
    const int sites[2] = {ix.right_hand_site, ix.left_hand_site};
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector3d inward = side == 1 ? -left_out : left_out;
      const Eigen::Vector3d target = held[side] + p.squeeze_m * inward;
      const Eigen::Vector3d miss = target - Vec(d->site_xpos + 3 * sites[side]);
      if (miss.norm() > p.grip_reach_m) continue;
      Eigen::Vector4d dq = ArmStepToward(m, d, ix.walk.agent, kArms[side], sites[side], miss);
      for (int k = 0; k < 4; ++k) {
        double& o = s->grip[kArms[side][k]];
        o = Clamp(o + p.grip_gain * dq[k], -p.grip_max_rad, p.grip_max_rad);
      }
      active[side] = true;
    }
  }
  for (int side = 0; side < 2; ++side) {
    if (active[side]) continue;
    for (int j : kArms[side]) s->grip[j] *= 0.8;
  }
}

}  // namespace

void UpdateCarry(const CarryParams& p, const mjModel* m, mjData* scratch, const mjData* d,
                 const CarryIndex& ix, const CarryBox& box, CarryState* s) {
  s->phase_time_s += kWalkPolicyDt;
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix.walk, &pos, &yaw);
  switch (s->phase) {
    case CarryPhase::kApproach:
      SteerApproach(p, d, ix, s);
      if (Arrived(p, d, ix, s)) StartLift(p, m, scratch, d, ix, box, s);
      break;
    case CarryPhase::kLift:
      if (s->phase_time_s >= kLiftSeconds) {
        Enter(s, CarryPhase::kCarry);
        s->gait.vmax_mps = std::min(p.walk.vmax_mps, p.carry_vmax_mps);
        s->face_dir = Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
        SteerCarry(pos.head<2>(), box.pos.head<2>(), true, s);
      }
      break;
    case CarryPhase::kCarry:
      SteerCarry(pos.head<2>(), box.pos.head<2>(), false, s);
      if (Arrived(p, d, ix, s) || CarryReachedDestination(p, box, *s)) StartPutDown(p, d, ix, s);
      break;
    case CarryPhase::kPutDown:
      if (s->phase_time_s >= kPutDownSeconds) {
        Enter(s, CarryPhase::kRetreat);
        Eigen::Vector2d fwd(std::cos(yaw), std::sin(yaw));
        SetCarryWalkTarget(s, pos.head<2>() - p.retreat_m * fwd, yaw);
      }
      break;
    case CarryPhase::kRetreat:
      break;
  }
  UpdateWalkCommand(s->gait, d, ix.walk, &s->walk);
  UpdateGrip(p, m, d, ix, box, s);
}

bool CarryHandsOnBox(const CarryState& s) {
  switch (s.phase) {
    case CarryPhase::kLift:
      return s.phase_time_s >= kSqueezeStart;
    case CarryPhase::kCarry:
      return true;
    case CarryPhase::kPutDown:
      return s.phase_time_s < kReleaseStart;
    default:
      return false;
  }
}

void SetCarryGrip(const CarryIndex& ix, const CarryState& s, mjData* d) {
  const double on = CarryHandsOnBox(s) ? 1.0 : 0.0;
  if (ix.left_grip >= 0) d->ctrl[ix.left_grip] = on;
  if (ix.right_grip >= 0) d->ctrl[ix.right_grip] = on;
}

void CarryHeldPoints(const CarryState& s, const CarryBox& box, Eigen::Vector3d* left,
                     Eigen::Vector3d* right) {
  Eigen::Vector3d r_local = s.held_left_local;
  r_local[s.held_axis] = -r_local[s.held_axis];
  *left = box.pos + box.rot * s.held_left_local;
  *right = box.pos + box.rot * r_local;
}

CarryBox ReadCarryBox(const mjModel* m, const mjData* d, int geom) {
  CarryBox b;
  b.pos = Vec(d->geom_xpos + 3 * geom);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) b.rot(r, c) = d->geom_xmat[9 * geom + 3 * r + c];
  }
  b.half = Vec(m->geom_size + 3 * geom);
  mjtNum vel[6];
  mj_objectVelocity(m, d, mjOBJ_GEOM, geom, vel, 0);  // world frame: angular, then linear
  b.angvel = Vec(vel);
  b.linvel = Vec(vel + 3);
  b.mass_kg = m->body_mass[m->geom_bodyid[geom]];
  b.geom = geom;
  return b;
}

double BoxLowestZ(const CarryBox& box) {
  double lowest = 1e9;
  for (int c = 0; c < 8; ++c) lowest = std::min(lowest, Corner(box, c).z());
  return lowest;
}

void CarryReference(const CarryState& s, double* q) {
  WalkReference(s.gait, s.walk.phase, s.walk.amplitude, s.walk.cmd, q);
  if (s.phase == CarryPhase::kApproach || s.phase == CarryPhase::kRetreat) return;
  const CarryPoses& k = s.poses;
  Pose stand;
  std::copy(q, q + kWalkActDim, stand.begin());
  Pose out = stand;
  const double t = s.phase_time_s;
  if (s.phase == CarryPhase::kLift) {
    if (t < kSqueezeStart) {
      out = Blend(stand, k.squat_open, t / kSqueezeStart);
    } else if (t < kRiseStart) {
      out =
          Blend(k.squat_open, k.squat_squeeze, (t - kSqueezeStart) / (kRiseStart - kSqueezeStart));
    } else {
      out = Blend(k.squat_squeeze, k.hold, (t - kRiseStart) / (kLiftSeconds - kRiseStart));
    }
  } else if (s.phase == CarryPhase::kCarry) {
    // legs from the gait; trunk and arms holding
    // the trunk leans back under the load from the carry's first step (leaning in over 0.5 s
    // held 78 of 128 boxes in the probe, at once 87); the arms keep their angles, so the box
    // leans back with the trunk
    out[kAbdY] = k.hold[kAbdY] - k.hold_lean_rad;
    for (int j = kRShX; j <= kLElbow; ++j) out[j] = k.hold[j];
  } else {  // kPutDown
    const double release_end = kReleaseStart + kReleaseSeconds;
    if (t < kLowerEnd) {
      Pose leaned = k.hold;  // from the carry's lean
      leaned[kAbdY] -= k.hold_lean_rad;
      out = Blend(leaned, k.squat_squeeze, t / kLowerEnd);
    } else if (t < kReleaseStart) {
      out = k.squat_squeeze;
    } else if (t < release_end) {
      out = Blend(k.squat_squeeze, k.squat_open, (t - kReleaseStart) / kReleaseSeconds);
    } else {
      out = Blend(k.squat_open, stand, (t - release_end) / (kPutDownSeconds - release_end));
    }
  }
  std::copy(out.begin(), out.end(), q);
}

void CarryTargets(const CarryIndex& ix, const CarryState& s, const float* action, double* ctrl28) {
  CarryReference(s, ctrl28);
  for (int j = 0; j < kWalkActDim; ++j) {
    double a = Clamp(static_cast<double>(action[j]), -kWalkActionClip, kWalkActionClip);
    ctrl28[j] =
        Clamp(ctrl28[j] + s.grip[j] + kWalkActionScale * a, ix.walk.ctrl_lo[j], ix.walk.ctrl_hi[j]);
  }
}

bool CarryArmsHeld(const CarryState& s) {
  return s.phase == CarryPhase::kLift || s.phase == CarryPhase::kCarry ||
         s.phase == CarryPhase::kPutDown;
}

void CarryBlindArms(const CarryState& s, float* walk_obs) {
  double swing[kWalkActDim];
  WalkReference(s.gait, s.walk.phase, s.walk.amplitude, s.walk.cmd, swing);
  const Pose& nominal = WalkNominalPose();
  for (int j = 0; j < kWalkActDim; ++j) {
    if (WalkActionUsed(j)) continue;
    walk_obs[kWalkObsHinges + j] = static_cast<float>(swing[j] - nominal[j]);
    walk_obs[kWalkObsHingeVel + j] = 0.f;
    walk_obs[kWalkObsPrevAction + j] = 0.f;
  }
}

void CarryObservation(const mjData* d, const CarryIndex& ix, const CarryState& s,
                      const CarryBox& box, float* obs) {
  WalkObservation(s.gait, d, ix.walk, s.walk, obs);
  if (CarryArmsHeld(s)) CarryBlindArms(s, obs);
  float* o = obs + kWalkObsDim;
  int k = 0;
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix.walk, &pos, &yaw);
  auto put3 = [&](const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) o[k++] = static_cast<float>(v[i]);
  };
  // positions relative to the pelvis, horizontal parts clipped to 3 m
  Eigen::Vector3d rel = ToHeading(box.pos - pos, yaw);
  double hd = std::hypot(rel.x(), rel.y());
  double far = hd > 3.0 ? 3.0 / hd : 1.0;
  auto near = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(v.x() * far, v.y() * far, v.z());
  };
  put3(near(rel));
  put3(ToHeading(box.rot.col(0), yaw));
  put3(ToHeading(box.rot.col(1), yaw));
  put3(ToHeading(box.linvel, yaw));
  put3(ToHeading(box.angvel, yaw));
  for (int c = 0; c < 8; ++c) put3(near(ToHeading(Corner(box, c) - pos, yaw)));
  put3(box.half);
  o[k++] = static_cast<float>(box.mass_kg / 10.0);
  Eigen::Vector3d dest =
      ToHeading(Eigen::Vector3d(s.dest_xy.x(), s.dest_xy.y(), pos.z()) - pos, yaw);
  double dd = std::hypot(dest.x(), dest.y());
  double dclip = dd > 3.0 ? 3.0 / dd : 1.0;
  o[k++] = static_cast<float>(dest.x() * dclip);
  o[k++] = static_cast<float>(dest.y() * dclip);
  o[k++] = static_cast<float>(std::min(10.0, (s.dest_xy - box.pos.head<2>()).norm()));
  for (int ph = 0; ph < kNumCarryPhases; ++ph) {
    o[k++] = static_cast<int>(s.phase) == ph ? 1.f : 0.f;
  }
  double dur = PhaseDuration(s.phase);
  o[k++] = static_cast<float>(dur > 0 ? std::min(1.0, s.phase_time_s / dur) : 0.0);
  Eigen::Vector3d hl, hr;
  CarryHeldPoints(s, box, &hl, &hr);
  put3(near(ToHeading(Vec(d->site_xpos + 3 * ix.left_hand_site) - hl, yaw)));
  put3(near(ToHeading(Vec(d->site_xpos + 3 * ix.right_hand_site) - hr, yaw)));
  bool lc, rc;
  HandBoxContacts(d, ix, box, &lc, &rc);
  o[k++] = lc ? 1.f : 0.f;
  o[k++] = rc ? 1.f : 0.f;
  Eigen::Vector3d face = ToHeading(Eigen::Vector3d(s.face_dir.x(), s.face_dir.y(), 0), yaw);
  o[k++] = static_cast<float>(face.x());
  o[k++] = static_cast<float>(face.y());
  o[k++] = static_cast<float>(BoxLowestZ(box));
  o[k++] = CarryHandsOnBox(s) ? 1.f : 0.f;
  // k == kCarryExtraObsDim (a test checks the layout's size)
}

void HandBoxContacts(const mjData* d, const CarryIndex& ix, const CarryBox& box, bool* left,
                     bool* right) {
  *left = *right = false;
  for (int c = 0; c < d->ncon && box.geom >= 0; ++c) {
    int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
    if (g1 != box.geom && g2 != box.geom) continue;
    int other = g1 == box.geom ? g2 : g1;
    *left |= other == ix.left_hand_geom;
    *right |= other == ix.right_hand_geom;
  }
}

}  // namespace simhuman::control
