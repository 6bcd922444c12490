#include "simhuman/control/mpc/reference_pose.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace simhuman::control {
namespace {

// deepest a sitting pelvis goes behind a seat's front edge (m, x scale)
constexpr double kMaxSitDepthM = 0.25;

constexpr double kDeg = M_PI / 180.0;
using world::kHumanoidDofs;

int JointIndex(const char* name) {
  const auto& names = world::HumanoidJointNames();
  for (int i = 0; i < kHumanoidDofs; ++i) {
    if (names[i] == name) return i;
  }
  return -1;
}

Eigen::Quaterniond YawQuat(double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
}

// a rotation whose local x (front) maps to `front_w` and local z (head) to `up_w`
Eigen::Quaterniond FrameQuat(const Eigen::Vector3d& front_w, const Eigen::Vector3d& up_w) {
  Eigen::Matrix3d R;
  R.col(0) = front_w.normalized();
  R.col(2) = up_w.normalized();
  R.col(1) = R.col(2).cross(R.col(0));
  return Eigen::Quaterniond(R).normalized();
}

double Yaw(const Eigen::Quaterniond& q) {
  Eigen::Vector3d f = q * Eigen::Vector3d::UnitX();
  return std::atan2(f.y(), f.x());
}

struct Problem {
  const world::SimWorld* world = nullptr;
  const world::AgentIndex* a = nullptr;
  const StepTask* task = nullptr;
  const ReferencePoseOptions* opt = nullptr;
  mjData* d = nullptr;
  std::array<double, kHumanoidDofs> base{};
  Eigen::Quaterniond base_quat = Eigen::Quaterniond::Identity();
  bool feet_on_floor = true;
  bool anchor_feet = false;
  bool balance = false;
  std::array<Eigen::Vector3d, 2> feet_anchor{};
  Eigen::Vector3d root_anchor = Eigen::Vector3d::Zero();  // pelvis anchor (xy) for get-close
  bool anchor_root_xy = false;
  double scale = 1.0;
};

// x = [root pos (3), root rotation increment (3), hinges (28)] around (p0, q0)
struct Vars {
  Eigen::Vector3d pos;
  Eigen::Quaterniond quat;
  std::array<double, kHumanoidDofs> h;
};

void Apply(const Problem& pr, const Vars& v, mjData* d) {
  const auto& a = *pr.a;
  for (int i = 0; i < 3; ++i) d->qpos[a.root_qpos + i] = v.pos[i];
  d->qpos[a.root_qpos + 3] = v.quat.w();
  d->qpos[a.root_qpos + 4] = v.quat.x();
  d->qpos[a.root_qpos + 5] = v.quat.y();
  d->qpos[a.root_qpos + 6] = v.quat.z();
  for (int j = 0; j < kHumanoidDofs; ++j) d->qpos[a.hinge_qpos[j]] = v.h[j];
  mj_kinematics(pr.world->model(), d);
  mj_comPos(pr.world->model(), d);
}

Vars Step(const Vars& v, const Eigen::VectorXd& dx, const mjModel* m, const world::AgentIndex& a) {
  Vars o = v;
  o.pos += dx.head<3>();
  Eigen::Vector3d w = dx.segment<3>(3);
  double n = w.norm();
  if (n > 1e-12) o.quat = (Eigen::Quaterniond(Eigen::AngleAxisd(n, w / n)) * v.quat).normalized();
  for (int j = 0; j < kHumanoidDofs; ++j) {
    int jid = m->dof_jntid[a.hinge_qvel[j]];
    o.h[j] = std::clamp(v.h[j] + dx[6 + j], m->jnt_range[2 * jid], m->jnt_range[2 * jid + 1]);
  }
  return o;
}

std::vector<double> Residual(const Problem& pr, const Vars& v) {
  Apply(pr, v, pr.d);
  const mjModel* m = pr.world->model();
  const mjData* d = pr.d;
  const auto& a = *pr.a;
  const auto& o = *pr.opt;
  std::vector<double> r;
  std::array<Eigen::Vector3d, core::kNumBodyJoints> pts;
  for (int i = 0; i < core::kNumBodyJoints; ++i) {
    const mjtNum* x = d->site_xpos + 3 * a.site[i];
    pts[i] = Eigen::Vector3d(x[0], x[1], x[2]);
  }
  for (const ContactTerm& t : pr.task->terms) {
    const Eigen::Vector3d& p = pts[static_cast<int>(t.joint)];
    if (t.type == plan::ContactType::kContact) {
      Eigen::Vector3d goal = t.Touch(p, pts) + t.aim_offset;
      for (int k = 0; k < 3; ++k) r.push_back(o.w_contact * (p[k] - goal[k]));
    } else {
      double dist = (p - t.Nearest(p, pts)).norm();
      r.push_back(o.w_not_contact * std::max(0.0, 0.18 * pr.scale - dist));
    }
  }
  // posture prior
  for (int j = 0; j < kHumanoidDofs; ++j) r.push_back(o.w_posture * (v.h[j] - pr.base[j]));
  Eigen::Quaterniond qe = pr.base_quat.conjugate() * v.quat;
  Eigen::AngleAxisd aa(qe);
  Eigen::Vector3d rot = aa.angle() * aa.axis();
  if (pr.task->posture == Posture::kSit || pr.task->posture == Posture::kStand) {
    // yaw is free-ish for standing/sitting; tilt is not
    for (int k = 0; k < 3; ++k) r.push_back(o.w_root_orientation * rot[k] * (k == 2 ? 0.3 : 1.0));
  } else {
    for (int k = 0; k < 3; ++k) r.push_back(o.w_root_orientation * rot[k]);
  }
  // feet
  std::array<int, 2> feet = {static_cast<int>(core::BodyJoint::kLeftFoot),
                             static_cast<int>(core::BodyJoint::kRightFoot)};
  if (pr.feet_on_floor) {
    for (int f = 0; f < 2; ++f) r.push_back(o.w_feet * (pts[feet[f]].z() - 0.0375 * pr.scale));
  }
  if (pr.anchor_feet) {
    for (int f = 0; f < 2; ++f) {
      r.push_back(o.w_feet * (pts[feet[f]].x() - pr.feet_anchor[f].x()));
      r.push_back(o.w_feet * (pts[feet[f]].y() - pr.feet_anchor[f].y()));
    }
  }
  if (pr.anchor_root_xy) {
    r.push_back(o.w_feet * (v.pos.x() - pr.root_anchor.x()));
    r.push_back(o.w_feet * (v.pos.y() - pr.root_anchor.y()));
  }
  if (pr.balance) {
    const mjtNum* com = d->subtree_com + 3 * a.pelvis_body;
    Eigen::Vector3d mid = 0.5 * (pts[feet[0]] + pts[feet[1]]);
    // the foot centre is a bit ahead of the ankle; aim slightly behind it
    r.push_back(o.w_balance * (com[0] - mid.x()));
    r.push_back(o.w_balance * (com[1] - mid.y()));
  }
  // keep body points out of the focus object (beyond their clearance)
  if (pr.task->focus && pr.task->focus->collides) {
    for (int i = 0; i < core::kNumBodyJoints; ++i) {
      Eigen::Vector3d np =
          core::NearestPointOnShapes(pr.task->focus->shapes, pr.task->focus->pose, pts[i]);
      double dist = (pts[i] - np).norm();
      double need = 0.8 * pr.scale * BodyPointClearance(static_cast<core::BodyJoint>(i));
      r.push_back(o.w_penetration * std::max(0.0, need - dist));
    }
  }
  (void)m;
  return r;
}

}  // namespace

std::array<double, kHumanoidDofs> BasePostureHinges(Posture p) {
  std::array<double, kHumanoidDofs> h{};
  auto set = [&](const char* n, double deg) { h[JointIndex(n)] = deg * kDeg; };
  switch (p) {
    case Posture::kStand:
      for (const char* n : {"right_knee", "left_knee"}) set(n, 5);
      for (const char* n : {"right_hip_y", "left_hip_y"}) set(n, 3);
      for (const char* n : {"right_elbow", "left_elbow"}) set(n, 10);
      break;
    case Posture::kLean:
      for (const char* n : {"right_hip_y", "left_hip_y"}) set(n, 30);
      for (const char* n : {"right_knee", "left_knee"}) set(n, 10);
      break;
    case Posture::kSit:
      for (const char* n : {"right_hip_y", "left_hip_y"}) set(n, 85);
      for (const char* n : {"right_knee", "left_knee"}) set(n, 90);
      for (const char* n : {"right_elbow", "left_elbow"}) set(n, 45);
      for (const char* n : {"right_shoulder_y", "left_shoulder_y"}) set(n, 15);
      set("abdomen_y", 5);
      break;
    case Posture::kLieBack:
      for (const char* n : {"right_knee", "left_knee"}) set(n, 5);
      for (const char* n : {"right_shoulder_x", "left_shoulder_x"}) set(n, 15);
      break;
    case Posture::kLieSide:
      for (const char* n : {"right_hip_y", "left_hip_y"}) set(n, 40);
      for (const char* n : {"right_knee", "left_knee"}) set(n, 60);
      for (const char* n : {"right_shoulder_y", "left_shoulder_y"}) set(n, 60);
      for (const char* n : {"right_elbow", "left_elbow"}) set(n, 60);
      break;
  }
  return h;
}

void SetAgentPose(const world::AgentIndex& a, const ReferencePose& pose, mjData* d) {
  for (int i = 0; i < 7; ++i) d->qpos[a.root_qpos + i] = pose.root[i];
  for (int j = 0; j < kHumanoidDofs; ++j) d->qpos[a.hinge_qpos[j]] = pose.hinges[j];
}

ReferencePose GetAgentPose(const world::AgentIndex& a, const mjData* d) {
  ReferencePose p;
  for (int i = 0; i < 7; ++i) p.root[i] = d->qpos[a.root_qpos + i];
  for (int j = 0; j < kHumanoidDofs; ++j) p.hinges[j] = d->qpos[a.hinge_qpos[j]];
  return p;
}

namespace {

// variables of the solve: root position and rotation increment, then the hinges
constexpr int kNumVars = 6 + kHumanoidDofs;

// where the agent is now: the starting point of every first guess
struct Start {
  Eigen::Vector3d pos;                                    // root position (m, world)
  double yaw = 0;                                         // pelvis yaw (rad)
  std::array<Eigen::Vector3d, core::kNumBodyJoints> pts;  // body points (m, world)
  double obj_yaw = 0;  // yaw of the focus object, the pelvis yaw without one (rad)
};

// Where the feet go to get up from a seat: each foot no farther forward (along the pelvis
// heading) than kFeetBehindKneeM behind its knee, as a person draws the feet back under the
// knees before rising; a foot already there stays.
std::array<Eigen::Vector3d, 2> FeetForRising(const Start& st, double s) {
  constexpr double kFeetBehindKneeM = 0.03;
  const Eigen::Vector3d fwd(std::cos(st.yaw), std::sin(st.yaw), 0);
  std::array<Eigen::Vector3d, 2> out;
  const core::BodyJoint feet[2] = {core::BodyJoint::kLeftFoot, core::BodyJoint::kRightFoot};
  const core::BodyJoint knees[2] = {core::BodyJoint::kLeftKnee, core::BodyJoint::kRightKnee};
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector3d& f = st.pts[static_cast<int>(feet[i])];
    const Eigen::Vector3d& k = st.pts[static_cast<int>(knees[i])];
    const double ahead = (f - k).dot(fwd) + kFeetBehindKneeM * s;
    out[i] = ahead > 0 ? Eigen::Vector3d(f - ahead * fwd) : f;
  }
  return out;
}

// top centre (world) of the first contact part of body joint `j` (the pelvis / head)
std::optional<Eigen::Vector3d> PartTop(const StepTask& task, core::BodyJoint j) {
  for (const ContactTerm& t : task.terms) {
    if (t.joint == j && t.part && t.type == plan::ContactType::kContact) {
      auto [lo, hi] = core::ShapesBounds(t.part->shapes);
      Eigen::Vector3d c((lo.x() + hi.x()) / 2, (lo.y() + hi.y()) / 2, hi.z());
      return t.object->pose.Apply(c);
    }
  }
  return std::nullopt;
}

// rise phase 2, seat-off: hips and knees still flexed, trunk over the feet, weight on the feet
void SetUpSeatOff(const Start& st, double s, Problem* pr, Vars* v) {
  pr->base = BasePostureHinges(Posture::kSit);
  pr->base[JointIndex("abdomen_y")] = 30 * kDeg;
  for (const char* n : {"right_hip_y", "left_hip_y"}) pr->base[JointIndex(n)] = 95 * kDeg;
  for (const char* n : {"right_knee", "left_knee"}) pr->base[JointIndex(n)] = 85 * kDeg;
  for (const char* n : {"right_shoulder_y", "left_shoulder_y"}) {
    pr->base[JointIndex(n)] = 45 * kDeg;
  }
  v->h = pr->base;
  pr->anchor_feet = true;
  pr->balance = true;
  pr->feet_on_floor = true;
  pr->feet_anchor = FeetForRising(st, s);
  pr->base_quat =
      YawQuat(st.yaw) * Eigen::Quaterniond(Eigen::AngleAxisd(25 * kDeg, Eigen::Vector3d::UnitY()));
  v->quat = pr->base_quat;
  v->pos = st.pos + YawQuat(st.yaw) * Eigen::Vector3d(0.12 * s, 0, 0.05 * s);
}

// rise phase 1, the first phase of getting up: still seated, pelvis tipped and trunk leaning
// forward, feet drawn back under the knees, so the weight can then move onto the feet
void SetUpLeanForward(const Start& st, double s, Problem* pr, Vars* v) {
  pr->base = BasePostureHinges(Posture::kSit);
  pr->base[JointIndex("abdomen_y")] = 30 * kDeg;
  for (const char* n : {"right_hip_y", "left_hip_y"}) pr->base[JointIndex(n)] = 110 * kDeg;
  for (const char* n : {"right_knee", "left_knee"}) pr->base[JointIndex(n)] = 105 * kDeg;
  for (const char* n : {"right_shoulder_y", "left_shoulder_y"}) {
    pr->base[JointIndex(n)] = 45 * kDeg;
  }
  v->h = pr->base;
  pr->feet_on_floor = true;
  pr->anchor_feet = true;  // feet drawn back under the knees while the seat takes the weight
  pr->feet_anchor = FeetForRising(st, s);
  pr->root_anchor = st.pos;
  pr->anchor_root_xy = true;
  pr->base_quat =
      YawQuat(st.yaw) * Eigen::Quaterniond(Eigen::AngleAxisd(20 * kDeg, Eigen::Vector3d::UnitY()));
  v->quat = pr->base_quat;
  v->pos = st.pos;
}

// standing (and leaning): balanced, on the way to the stand point or with the feet kept
void SetUpStand(const StepTask& task, const Start& st, double s, Problem* pr, Vars* v) {
  pr->balance = true;
  if (task.get_close) {
    // stand up / get close: stand on the way to the stand point, feet free
    Eigen::Vector3d to = task.stand_point - st.pos;
    to.z() = 0;
    double reach = std::min(to.norm(), 0.25 * s);
    pr->root_anchor = st.pos + (to.norm() > 1e-6 ? Eigen::Vector3d(to.normalized() * reach)
                                                 : Eigen::Vector3d::Zero());
    if (world::PelvisLowAsSeated(st.pos.z(), s)) {
      // getting up from a seat: stand over the feet
      pr->feet_anchor = FeetForRising(st, s);
      pr->root_anchor = 0.5 * (pr->feet_anchor[0] + pr->feet_anchor[1]);
      pr->anchor_feet = true;
    }
    pr->anchor_root_xy = true;
    v->pos = pr->root_anchor;
    v->quat = YawQuat(st.yaw);  // no turning in place without a walking skill
  } else {
    // reach etc.: feet stay where they are
    pr->anchor_feet = true;
    pr->feet_anchor = {st.pts[static_cast<int>(core::BodyJoint::kLeftFoot)],
                       st.pts[static_cast<int>(core::BodyJoint::kRightFoot)]};
    Eigen::Vector3d mid = 0.5 * (pr->feet_anchor[0] + pr->feet_anchor[1]);
    v->pos = Eigen::Vector3d(mid.x(), mid.y(), 0);
    v->pos -= YawQuat(st.yaw) * Eigen::Vector3d(0.04 * s, 0, 0);
  }
  v->pos.z() = world::kPelvisStandHeight * s - 0.01;
  pr->base_quat = v->quat;
}

// sitting: pelvis on the seat part (on a bed, on the front edge below the pillow), facing out
void SetUpSit(const StepTask& task, const Start& st, double s, Problem* pr, Vars* v) {
  const core::CatalogObject* focus = task.focus;
  auto top = PartTop(task, core::BodyJoint::kPelvis);
  Eigen::Vector3d seat = top ? *top : st.pos;
  v->quat = YawQuat(st.obj_yaw);
  // pelvis a little behind the seat centre, but on a deep seat (sofa, armchair) no deeper
  // than a person sits upright: kMaxSitDepthM behind the front edge, so the feet can be
  // drawn back under the knees to stand up again; thighs horizontal
  double back = 0.04 * s;
  for (const ContactTerm& t : task.terms) {
    if (t.joint != core::BodyJoint::kPelvis || !t.part || !top) continue;
    auto [lo, hi] = core::ShapesBounds(t.part->shapes);
    double centre_to_edge = 0.5 * (hi.x() - lo.x());
    back = std::min(back, kMaxSitDepthM * s - centre_to_edge);
    break;
  }
  v->pos = seat + YawQuat(st.obj_yaw) * Eigen::Vector3d(-back, 0, 0);
  // on a bed, sit on the front edge where lying back later puts the head on the pillow
  const core::CatalogPart* pillow = focus ? focus->FindPart("pillow") : nullptr;
  const core::CatalogPart* mattress = focus ? focus->FindPart("mattress") : nullptr;
  if (pillow && mattress) {
    auto [mlo, mhi] = core::ShapesBounds(mattress->shapes);
    auto [plo, phi] = core::ShapesBounds(pillow->shapes);
    double pillow_y = 0.5 * (plo.y() + phi.y());
    double dir = pillow_y > 0.5 * (mlo.y() + mhi.y()) ? 1.0 : -1.0;
    double y = std::clamp(pillow_y - dir * 0.62 * s, mlo.y() + 0.2, mhi.y() - 0.2);
    Eigen::Vector3d local(mhi.x() - 0.2 * s, y, mhi.z());
    seat = focus->pose.Apply(local);
    v->pos = seat;
  }
  v->pos.z() = seat.z() + 0.12 * s;
  pr->base_quat = v->quat;
  pr->feet_on_floor = true;
}

// lying on the back or the side: along the bed from the mattress to the pillow
void SetUpLie(const StepTask& task, const Start& st, double s, Problem* pr, Vars* v) {
  auto pelvis_top = PartTop(task, core::BodyJoint::kPelvis);
  auto head_top = PartTop(task, core::BodyJoint::kHead);
  Eigen::Vector3d mat = pelvis_top ? *pelvis_top : st.pos;
  Eigen::Vector3d head =
      head_top ? *head_top : mat + YawQuat(st.obj_yaw) * Eigen::Vector3d(0, 1, 0);
  Eigen::Vector3d h = head - mat;
  h.z() = 0;
  if (h.norm() < 1e-6) h = YawQuat(st.obj_yaw) * Eigen::Vector3d(0, 1, 0);
  h.normalize();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  // lie along the bed on the line nearest to where the agent is, as long as the head still
  // lands on the pillow: less to shuffle across the mattress
  for (const ContactTerm& t : task.terms) {
    if (t.joint != core::BodyJoint::kHead || !t.part) continue;
    Eigen::Vector3d across(-h.y(), h.x(), 0);
    auto [plo, phi] = core::ShapesBounds(t.part->shapes);
    Eigen::Vector3d half_w = t.object->pose.quat * (0.5 * (phi - plo));
    double room = std::max(0.0, std::abs(half_w.dot(across)) - 0.12 * s);
    double off = std::clamp((st.pos - head).dot(across), -room, room);
    head += across * off;
  }
  if (task.posture == Posture::kLieBack) {
    v->quat = FrameQuat(up, h);
    v->pos = head - h * 0.62 * s;
    v->pos.z() = mat.z() + 0.095 * s;
  } else {
    // on the side: front faces the side of the bed the agent came from
    Eigen::Vector3d side = YawQuat(st.obj_yaw) * Eigen::Vector3d::UnitX();
    side = (side - side.dot(h) * h).normalized();
    v->quat = FrameQuat(side, h);
    v->pos = head - h * 0.62 * s;
    v->pos.z() = mat.z() + 0.16 * s;
  }
  pr->base_quat = v->quat;
  pr->feet_on_floor = false;
}

// Lying, a hand whose target is nearer the head than the pelvis (a hand on the pillow, on the
// headboard, behind the head) starts, and is anchored, with the arm raised over the head, as
// a person puts it there. From the arms at the sides the solve otherwise stops where the hand
// first grazes the target's side at mattress level (a pillow's corner, 2-3 cm short of touching),
// which any shift of the lying body loses.
void RaiseArmsTowardHead(const StepTask& task, Problem* pr, Vars* v) {
  if (task.posture != Posture::kLieBack && task.posture != Posture::kLieSide) return;
  Apply(*pr, *v, pr->d);
  std::array<Eigen::Vector3d, core::kNumBodyJoints> pts;
  for (int i = 0; i < core::kNumBodyJoints; ++i) {
    const mjtNum* x = pr->d->site_xpos + 3 * pr->a->site[i];
    pts[i] = Eigen::Vector3d(x[0], x[1], x[2]);
  }
  const Eigen::Vector3d& head = pts[static_cast<int>(core::BodyJoint::kHead)];
  const Eigen::Vector3d& pelvis = pts[static_cast<int>(core::BodyJoint::kPelvis)];
  for (const ContactTerm& t : task.terms) {
    if (t.type != plan::ContactType::kContact) continue;
    const bool left = t.joint == core::BodyJoint::kLeftHand;
    if (!left && t.joint != core::BodyJoint::kRightHand) continue;
    const Eigen::Vector3d target = t.Nearest(pts[static_cast<int>(t.joint)], pts);
    if ((target - head).norm() >= (target - pelvis).norm()) continue;
    const std::string s = left ? "left_" : "right_";
    // overhead, elbow half bent: the hand comes to rest on top of the pillow above the head
    for (auto [n, deg] : {std::pair<const char*, double>{"shoulder_y", 160},
                          {"shoulder_x", 20},
                          {"shoulder_z", 0},
                          {"elbow", 45}}) {
      const int j = JointIndex((s + n).c_str());
      pr->base[j] = deg * kDeg;
      v->h[j] = deg * kDeg;
    }
  }
}

// the problem's posture, anchors and first guess for the task (or the rise phase), then the
// warm start when there is one
void SetUpProblem(const StepTask& task, const ReferencePoseOptions& options, const Start& st,
                  double s, Problem* pr, Vars* v) {
  if (options.rise == 2) {
    SetUpSeatOff(st, s, pr, v);
  } else if (options.rise == 1) {
    SetUpLeanForward(st, s, pr, v);
  }
  switch (options.rise ? Posture::kLean : task.posture) {
    case Posture::kLean:
      if (options.rise) break;
      [[fallthrough]];
    case Posture::kStand:
      SetUpStand(task, st, s, pr, v);
      break;
    case Posture::kSit:
      SetUpSit(task, st, s, pr, v);
      break;
    case Posture::kLieBack:
    case Posture::kLieSide:
      SetUpLie(task, st, s, pr, v);
      RaiseArmsTowardHead(task, pr, v);
      break;
  }

  if (options.warm_start) {
    const ReferencePose& w = *options.warm_start;
    v->pos = Eigen::Vector3d(w.root[0], w.root[1], w.root[2]);
    v->quat = Eigen::Quaterniond(w.root[3], w.root[4], w.root[5], w.root[6]).normalized();
    v->h = w.hinges;
  }
}

// sum of squares of a residual
double SquaredNorm(const std::vector<double>& r) {
  double s2 = 0;
  for (double x : r) s2 += x * x;
  return s2;
}

// forward-difference Jacobian of the residual at `v`, whose residual is `r0`; a step that a
// joint limit blocks is taken backwards, and a column stays zero when both ways are blocked
Eigen::MatrixXd ResidualJacobian(const Problem& pr, const Vars& v, const std::vector<double>& r0,
                                 const mjModel* m, const world::AgentIndex& a) {
  const int nr = static_cast<int>(r0.size());
  Eigen::MatrixXd J(nr, kNumVars);
  constexpr double kEps = 1e-5;
  for (int k = 0; k < kNumVars; ++k) {
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(kNumVars);
    dx[k] = kEps;
    Vars vk = Step(v, dx, m, a);
    std::vector<double> rk = Residual(pr, vk);
    double actual = (k >= 6) ? vk.h[k - 6] - v.h[k - 6] : kEps;
    if (std::abs(actual) < 1e-12) {
      dx[k] = -kEps;
      vk = Step(v, dx, m, a);
      rk = Residual(pr, vk);
      actual = (k >= 6) ? vk.h[k - 6] - v.h[k - 6] : -kEps;
    }
    for (int i = 0; i < nr; ++i) {
      J(i, k) = std::abs(actual) < 1e-12 ? 0.0 : (rk[i] - r0[i]) / actual;
    }
  }
  return J;
}

// Levenberg-Marquardt with forward-difference Jacobians from `v`, for at most `iterations`
// steps; leaves the best pose found in `v` and returns its cost (squared residual)
double MinimizeResidual(const Problem& pr, int iterations, const mjModel* m,
                        const world::AgentIndex& a, Vars* v) {
  double lambda = 1e-2;
  std::vector<double> r0 = Residual(pr, *v);
  double c0 = SquaredNorm(r0);
  for (int it = 0; it < iterations; ++it) {
    const int nr = static_cast<int>(r0.size());
    Eigen::MatrixXd J = ResidualJacobian(pr, *v, r0, m, a);
    Eigen::Map<Eigen::VectorXd> rv(r0.data(), nr);
    Eigen::MatrixXd H = J.transpose() * J;
    Eigen::VectorXd g = J.transpose() * rv;
    bool improved = false;
    for (int tries = 0; tries < 6 && !improved; ++tries) {
      Eigen::MatrixXd A = H;
      A.diagonal().array() += lambda * (1.0 + H.diagonal().array());
      Eigen::VectorXd dx = -A.ldlt().solve(g);
      // limit the step
      double mx = dx.cwiseAbs().maxCoeff();
      if (mx > 0.3) dx *= 0.3 / mx;
      Vars vn = Step(*v, dx, m, a);
      std::vector<double> rn = Residual(pr, vn);
      double cn = SquaredNorm(rn);
      if (cn < c0) {
        *v = vn;
        r0 = rn;
        c0 = cn;
        lambda = std::max(1e-6, lambda * 0.3);
        improved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
  return c0;
}

// the solved pose `v` with its residual and mean contact error; `d` holds `v`'s kinematics
ReferencePose MakeReferencePose(const world::SimWorld& world, int agent, const StepTask& task,
                                const Vars& v, double cost, const mjData* d) {
  ReferencePose out;
  for (int i = 0; i < 3; ++i) out.root[i] = v.pos[i];
  out.root[3] = v.quat.w();
  out.root[4] = v.quat.x();
  out.root[5] = v.quat.y();
  out.root[6] = v.quat.z();
  out.hinges = v.h;
  out.residual = std::sqrt(cost);
  double err = 0;
  int n = 0;
  auto pts = world.BodyPoints(d, agent);
  for (const ContactTerm& t : task.terms) {
    if (t.type != plan::ContactType::kContact) continue;
    Eigen::Vector3d p = pts[static_cast<int>(t.joint)];
    err += std::abs((p - t.Nearest(p, pts)).norm() - t.clearance_m);
    ++n;
  }
  out.contact_error_m = n ? err / n : 0.0;
  return out;
}

}  // namespace

ReferencePose SolveReferencePose(const world::SimWorld& world, int agent, const StepTask& task,
                                 const mjData* d_now, mjData* scratch,
                                 const ReferencePoseOptions& options) {
  const mjModel* m = world.model();
  const world::AgentIndex& a = world.agent(agent);
  mj_copyData(scratch, m, d_now);
  Problem pr;
  pr.world = &world;
  pr.a = &a;
  pr.task = &task;
  pr.opt = &options;
  pr.d = scratch;
  pr.base = BasePostureHinges(task.posture);
  pr.base_quat = Eigen::Quaterniond::Identity();
  pr.scale = a.scale;
  double s = a.scale;

  Start st;
  st.pos = Eigen::Vector3d(d_now->qpos[a.root_qpos], d_now->qpos[a.root_qpos + 1],
                           d_now->qpos[a.root_qpos + 2]);
  st.yaw = world::PelvisYaw(d_now, a);
  st.pts = world.BodyPoints(d_now, agent);

  Vars v;
  v.h = pr.base;
  v.pos = st.pos;
  v.quat = YawQuat(st.yaw);
  st.obj_yaw = task.focus ? plan::ObjectYaw(task.focus->pose) : st.yaw;

  SetUpProblem(task, options, st, s, &pr, &v);
  const double cost = MinimizeResidual(pr, options.iterations, m, a, &v);
  Apply(pr, v, scratch);
  (void)Yaw;
  return MakeReferencePose(world, agent, task, v, cost, scratch);
}

}  // namespace simhuman::control
