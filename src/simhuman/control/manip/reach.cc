#include "simhuman/control/manip/reach.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "simhuman/control/manip/arm_collision.h"

namespace simhuman::control::manip {
namespace {

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// body `b`'s orientation in `d` (after kinematics)
Eigen::Quaterniond BodyQuat(const mjData* d, int b) {
  return Eigen::Quaterniond(d->xquat[4 * b], d->xquat[4 * b + 1], d->xquat[4 * b + 2],
                            d->xquat[4 * b + 3]);
}

// the object carried in the hand: where its free joint is and its pose in the hand's frame
struct Carried {
  int body = -1, qpos = -1;
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();  // in the hand frame
  Eigen::Quaterniond rot = Eigen::Quaterniond::Identity();

  // fixed from the hand and object poses in `d`
  static Carried From(const mjModel* m, const mjData* d, const ArmChain& arm, int body) {
    Carried c;
    const int j = body >= 0 ? m->body_jntadr[body] : -1;
    if (j < 0 || m->jnt_type[j] != mjJNT_FREE) return c;
    c.body = body;
    c.qpos = m->jnt_qposadr[j];
    const Eigen::Quaterniond qh = BodyQuat(d, arm.hand_body), qo = BodyQuat(d, body);
    c.pos = qh.conjugate() *
            (Eigen::Vector3d(d->xpos + 3 * body) - Eigen::Vector3d(d->xpos + 3 * arm.hand_body));
    c.rot = qh.conjugate() * qo;
    return c;
  }
  // moves the object in `s` with the hand (after mj_kinematics of the arm's pose)
  void Place(mjData* s, const ArmChain& arm) const {
    const Eigen::Quaterniond qh = BodyQuat(s, arm.hand_body);
    const Eigen::Vector3d p = Eigen::Vector3d(s->xpos + 3 * arm.hand_body) + qh * pos;
    const Eigen::Quaterniond q = qh * rot;
    for (int k = 0; k < 3; ++k) s->qpos[qpos + k] = p[k];
    s->qpos[qpos + 3] = q.w();
    s->qpos[qpos + 4] = q.x();
    s->qpos[qpos + 5] = q.y();
    s->qpos[qpos + 6] = q.z();
  }
};

// contacts of the arm with anything but the ignored bodies (the object in hand), and of the
// carried object with anything but the arm (ArmCollider::Count)
int Contacts(const mjModel* m, mjData* s, const ArmChain& arm, const Eigen::VectorXd& q,
             const ArmMotionOptions& o, const Carried& carried, const ArmCollider& collider) {
  arm.Set(s, q);
  mj_kinematics(m, s);
  if (carried.body >= 0) {
    carried.Place(s, arm);
    mj_kinematics(m, s);
    if (s->xpos[3 * carried.body + 2] < o.carried_min_z) return 1;
  }
  return collider.Count(s, o.ignore_bodies, o.contact_tolerance_m, o.object_clearance_m,
                        o.approach_body);
}

// the palm's positional Jacobian over the arm's joints at arm angles `q` (the rest of the body
// as in `s`)
Eigen::MatrixXd PalmJacobian(const mjModel* m, mjData* s, const ArmChain& arm,
                             const Eigen::VectorXd& q) {
  arm.Set(s, q);
  mj_kinematics(m, s);
  mj_comPos(m, s);
  std::vector<mjtNum> jacp(3 * m->nv);
  mj_jacSite(m, s, jacp.data(), nullptr, arm.palm_site);
  Eigen::MatrixXd J(3, ArmChain::kDofs);
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    for (int k = 0; k < 3; ++k) J(k, i) = jacp[k * m->nv + arm.dof[i]];
  }
  return J;
}

// What a plan checks arm poses against: `d`'s state copied into the scratch `s`, the object
// carried in the hand (o.carried_body) and the arm's collision pairs; Valid() is Contacts() == 0
struct PoseCheck {
  PoseCheck(const mjModel* m, const mjData* d, mjData* s, const ArmChain& arm,
            const ArmMotionOptions& o)
      : carried(Carried::From(m, d, arm, o.carried_body)), collider(m, arm, carried.body) {
    mju_copy(s->qpos, d->qpos, m->nq);
  }
  ValidityFn Valid(const mjModel* m, mjData* s, const ArmChain& arm,
                   const ArmMotionOptions& o) const {
    return [this, m, s, &arm, &o](const Eigen::VectorXd& q) {
      return Contacts(m, s, arm, q, o, carried, collider) == 0;
    };
  }
  Carried carried;
  ArmCollider collider;
};

// the arm's joint ranges as vectors
void ArmBounds(const ArmChain& arm, Eigen::VectorXd* lo, Eigen::VectorXd* hi) {
  lo->resize(ArmChain::kDofs);
  hi->resize(ArmChain::kDofs);
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    (*lo)[i] = arm.lo[i];
    (*hi)[i] = arm.hi[i];
  }
}

struct Candidate {
  Eigen::VectorXd q;
  int goal;
  double wrist;
};

struct FreePoseCount {
  int unreached = 0, colliding = 0;
};

// Collision-free arm poses for the palm poses `goals`, appended to `free`: pass 0 solves each
// pose once from the current arm, pass 1 from ik_restarts spread-out seeds; `count` tells how
// many poses had no solution and how many only colliding ones.
void CollectFreePoses(const mjModel* m, mjData* s, const ArmChain& arm,
                      const std::vector<PalmPose>& goals, const Eigen::VectorXd& start,
                      const Eigen::VectorXd& rest, const ArmMotionOptions& o,
                      const Carried& carried, const ArmCollider& collider, int pass,
                      std::vector<Candidate>* free, FreePoseCount* count) {
  *count = {};
  for (size_t g = 0; g < goals.size(); ++g) {
    bool reached = false, found = false;
    const int first = pass == 0 ? 0 : 1, last = pass == 0 ? 0 : o.ik_restarts;
    for (int k = first; k <= last && !found; ++k) {
      Eigen::VectorXd seed = start;
      for (int i = 0; k > 0 && i < ArmChain::kDofs; ++i) {
        const double u = std::fmod(0.5 + k * 0.618034 + i * 0.414214, 1.0);
        seed[i] = arm.lo[i] + (0.15 + 0.7 * u) * (arm.hi[i] - arm.lo[i]);
      }
      const IkResult r = SolvePalmIk(m, s, arm, goals[g], seed, rest, o.ik);
      if (!r.converged) continue;
      reached = true;
      if (Contacts(m, s, arm, r.q, o, carried, collider) > 0) continue;
      free->push_back({r.q, static_cast<int>(g), r.q.tail<3>().norm()});
      found = true;
    }
    if (!found) ++(reached ? count->colliding : count->unreached);
  }
}

// the arm's current angles; a joint pressed against its (soft) limit may sit a hair beyond
// it: a plan starts from the limit
Eigen::VectorXd ArmStart(const ArmChain& arm, const mjData* d) {
  Eigen::VectorXd q = arm.Get(d);
  for (int i = 0; i < ArmChain::kDofs; ++i) q[i] = std::clamp(q[i], arm.lo[i], arm.hi[i]);
  return q;
}

// the retiming of an arm path at the model's time step and `o`'s speeds (ending at rest)
RetimeOptions ArmRetime(const mjModel* m, const ArmMotionOptions& o) {
  RetimeOptions ro;
  ro.dt_s = m->opt.timestep;
  ro.mean_speed = o.mean_path_speed;
  ro.max_velocity = Eigen::VectorXd::Constant(ArmChain::kDofs, o.max_joint_speed);
  return ro;
}

// PlanArmMotion with the clearance of `o` as given
core::StatusOr<ArmMotion> PlanArmMotionOnce(const mjModel* m, const mjData* d, mjData* s,
                                            const ArmChain& arm, const std::vector<PalmPose>& goals,
                                            const std::vector<Eigen::Vector3d>& approach_dirs,
                                            const ArmMotionOptions& o) {
  SH_RETURN_IF_ERROR(o.planner.Validate());
  if (goals.empty()) return absl::InvalidArgumentError("plan failure: no palm poses to reach");
  if (!approach_dirs.empty() && approach_dirs.size() != goals.size()) {
    return absl::InvalidArgumentError(
        "approach directions: " + std::to_string(approach_dirs.size()) + " for " +
        std::to_string(goals.size()) + " palm poses");
  }
  const auto t0 = std::chrono::steady_clock::now();
  const PoseCheck check(m, d, s, arm, o);
  const Carried& carried = check.carried;
  const ArmCollider& collider = check.collider;
  const Eigen::VectorXd start = ArmStart(arm, d);
  // the goals' IK starts from `seed`; the wrist's rest is straight (forearm, flexion,
  // deviation at 0), the shoulder and elbow keep where they are
  const Eigen::VectorXd seed = o.ik_from.size() == ArmChain::kDofs ? arm.Clamp(o.ik_from) : start;
  Eigen::VectorXd rest = seed;
  rest.tail<3>().setZero();
  std::vector<Candidate> free;
  FreePoseCount count;
  // every pose from the current arm first; only when none is free (or no path reaches the ones
  // found), again from spread-out seeds (an arm reaching far forward is often beyond a local
  // solve from a hanging arm, or its first solution collides), so the common case costs one
  // solve per pose
  CollectFreePoses(m, s, arm, goals, seed, rest, o, carried, collider, 0, &free, &count);
  bool restarted = false;
  if (free.empty() && o.ik_restarts > 0) {
    CollectFreePoses(m, s, arm, goals, seed, rest, o, carried, collider, 1, &free, &count);
    restarted = true;
  }
  if (free.empty()) {
    return absl::FailedPreconditionError(
        "plan failure: no collision-free arm pose for any of " + std::to_string(goals.size()) +
        " palm poses (" + std::to_string(count.unreached) + " out of the arm's reach, " +
        std::to_string(count.colliding) + " in collision)");
  }
  Eigen::VectorXd lo, hi;
  ArmBounds(arm, &lo, &hi);
  const ValidityFn valid = check.Valid(m, s, arm, o);
  PlannerOptions po = o.planner;
  if (po.start_escape_rad <= 0) po.start_escape_rad = 0.05;  // a start resting on the table
  // DASH: the pose with the wrist nearest its rest; the planner may reach any of the best few
  auto best = [](std::vector<Candidate> c) {
    std::sort(c.begin(), c.end(),
              [](const Candidate& a, const Candidate& b) { return a.wrist < b.wrist; });
    if (c.size() > 4) c.resize(4);
    return c;
  };
  free = best(free);
  auto search = [&]() {
    std::vector<Eigen::VectorXd> qs;
    for (const Candidate& c : free) qs.push_back(c.q);
    return PlanJointPath(start, qs, lo, hi, valid, po);
  };
  core::StatusOr<PlanResult> plan = search();
  if (!plan.ok() && absl::IsNotFound(plan.status()) && !restarted && o.ik_restarts > 0) {
    // the poses found from the current arm lie where no path reaches them: others, once
    std::vector<Candidate> more;
    FreePoseCount ignored;
    CollectFreePoses(m, s, arm, goals, seed, rest, o, carried, collider, 1, &more, &ignored);
    if (!more.empty()) {
      free = best(more);
      plan = search();
    }
  }
  if (!plan.ok()) {
    return core::Annotate(plan.status(), "plan failure");
  }
  JointPath path = plan->path;
  const Candidate& reached = free[plan->goal_index];
  // the final part arrives along the palm's approach direction
  const Eigen::MatrixXd J = PalmJacobian(m, s, arm, reached.q);
  const Eigen::Vector3d approach = reached.goal < static_cast<int>(approach_dirs.size())
                                       ? approach_dirs[reached.goal]
                                       : Eigen::Vector3d::Zero();
  if (approach.norm() > 1e-9 && path.Length() > 1e-6) {
    const Eigen::VectorXd tangent = ApproachTangent(J, approach.normalized());
    if (tangent.norm() > 1e-9) {
      core::StatusOr<JointPath> shaped = ReshapeTail(path, tangent, o.reshape_fraction);
      if (shaped.ok() && PathValid(*shaped, valid, po.resolution_rad)) path = *shaped;
    }
  }
  RetimeOptions ro = ArmRetime(m, o);
  if (o.terminal_palm_speed_mps > 0 && path.Length() > 1e-6) {
    core::StatusOr<double> v =
        PathSpeedForPalmSpeed(J, EndDirection(path), o.terminal_palm_speed_mps);
    if (v.ok()) ro.terminal_speed = std::min(*v, o.max_joint_speed);
  }
  if (path.Length() < 1e-6) {
    // already there: a still trajectory of one step
    path.waypoints.push_back(path.waypoints.back());
  }
  core::StatusOr<Trajectory> traj = Retime(path, ro);
  if (!traj.ok()) return core::Annotate(traj.status(), "plan failure: retiming");
  return ArmMotion{*std::move(traj), reached.goal, reached.q, static_cast<int>(free.size()),
                   Seconds(t0)};
}

}  // namespace

core::StatusOr<ArmMotion> PlanArmMotion(const mjModel* m, const mjData* d, mjData* s,
                                        const ArmChain& arm, const std::vector<PalmPose>& goals,
                                        const std::vector<Eigen::Vector3d>& approach_dirs,
                                        const ArmMotionOptions& o) {
  core::StatusOr<ArmMotion> r = PlanArmMotionOnce(m, d, s, arm, goals, approach_dirs, o);
  if (r.ok() || o.object_clearance_m <= 0 ||
      !(absl::IsFailedPrecondition(r.status()) || absl::IsNotFound(r.status()))) {
    return r;
  }
  // no pose or path keeps the clearance: one that only avoids touching
  ArmMotionOptions touching = o;
  touching.object_clearance_m = 0;
  core::StatusOr<ArmMotion> closer =
      PlanArmMotionOnce(m, d, s, arm, goals, approach_dirs, touching);
  if (closer.ok()) closer->clearance_kept = false;
  return closer;
}

core::StatusOr<ArmMotion> PlanArmThrough(const mjModel* m, const mjData* d, mjData* s,
                                         const ArmChain& arm,
                                         const std::vector<Eigen::VectorXd>& vias,
                                         const ArmMotionOptions& o) {
  SH_RETURN_IF_ERROR(o.planner.Validate());
  if (vias.empty()) return absl::InvalidArgumentError("plan failure: no arm angles to pass");
  const auto t0 = std::chrono::steady_clock::now();
  const PoseCheck check(m, d, s, arm, o);
  const ValidityFn valid = check.Valid(m, s, arm, o);
  Eigen::VectorXd from = ArmStart(arm, d);
  JointPath path;
  path.waypoints.push_back(from);
  for (size_t k = 0; k < vias.size(); ++k) {
    if (vias[k].size() != ArmChain::kDofs) {
      return absl::InvalidArgumentError("plan failure: via " + std::to_string(k) + " has " +
                                        std::to_string(vias[k].size()) + " arm angles, not " +
                                        std::to_string(ArmChain::kDofs));
    }
    const Eigen::VectorXd via = arm.Clamp(vias[k]);
    if (!valid(via)) {
      return absl::FailedPreconditionError("plan failure: via " + std::to_string(k) +
                                           " is in collision");
    }
    // straight in joint space (a search could wander anywhere between two vias)
    if (!SegmentValid(from, via, valid, o.planner.resolution_rad)) {
      return absl::NotFoundError("plan failure: no straight path to via " + std::to_string(k));
    }
    path.waypoints.push_back(via);
    from = via;
  }
  if (path.Length() < 1e-6) path.waypoints.push_back(path.waypoints.back());
  core::StatusOr<Trajectory> traj = Retime(path, ArmRetime(m, o));
  if (!traj.ok()) return core::Annotate(traj.status(), "plan failure: retiming");
  return ArmMotion{*std::move(traj), -1, from, 0, Seconds(t0)};
}

core::StatusOr<ArmMotion> PlanArmAlong(const mjModel* m, const mjData* d, mjData* s,
                                       const ArmChain& arm, const std::vector<PalmPose>& palm_path,
                                       const ArmMotionOptions& o, const ArmAlongOptions& along) {
  SH_RETURN_IF_ERROR(o.planner.Validate());
  if (palm_path.empty()) return absl::InvalidArgumentError("plan failure: no palm poses to follow");
  if (along.rest_to.size() != 0 && along.rest_to.size() != ArmChain::kDofs) {
    return absl::InvalidArgumentError("plan failure: rest_to has " +
                                      std::to_string(along.rest_to.size()) + " arm angles, not " +
                                      std::to_string(ArmChain::kDofs));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const PoseCheck check(m, d, s, arm, o);
  const ValidityFn valid = check.Valid(m, s, arm, o);
  const Eigen::VectorXd start = ArmStart(arm, d);
  Eigen::VectorXd from = start;
  JointPath path;
  path.waypoints.push_back(from);
  const std::string of = " of " + std::to_string(palm_path.size());
  IkOptions via_ik = o.ik;
  via_ik.tol_rot_rad = std::max(o.ik.tol_rot_rad, along.via_tol_rot_rad);
  for (size_t k = 0; k < palm_path.size(); ++k) {
    const std::string which = "plan failure: palm pose " + std::to_string(k) + of;
    const bool last = k + 1 == palm_path.size();
    const double u = double(k + 1) / palm_path.size();
    const Eigen::VectorXd rest =
        along.rest_to.size() == 0 ? from : Eigen::VectorXd((1 - u) * start + u * along.rest_to);
    const IkResult r = SolvePalmIk(m, s, arm, palm_path[k], from, rest, last ? o.ik : via_ik);
    if (!r.converged) return absl::FailedPreconditionError(which + " is out of the arm's reach");
    const double jump = (r.q - from).cwiseAbs().maxCoeff();
    if (jump > along.max_step_rad) {
      return absl::FailedPreconditionError(which + " makes a joint jump by " +
                                           std::to_string(jump) + " rad");
    }
    if (!valid(r.q)) return absl::FailedPreconditionError(which + " is in collision");
    if (!SegmentValid(from, r.q, valid, o.planner.resolution_rad)) {
      return absl::NotFoundError("plan failure: no straight path to palm pose " +
                                 std::to_string(k) + of);
    }
    path.waypoints.push_back(r.q);
    from = r.q;
  }
  if (path.Length() < 1e-6) path.waypoints.push_back(path.waypoints.back());
  core::StatusOr<Trajectory> traj = Retime(path, ArmRetime(m, o));
  if (!traj.ok()) return core::Annotate(traj.status(), "plan failure: retiming");
  return ArmMotion{*std::move(traj), -1, from, 0, Seconds(t0)};
}

JointPath PathTail(const mjModel* m, const mjData* d, mjData* s, const ArmChain& arm,
                   const JointPath& path, double palm_m, double step_rad) {
  if (path.size() < 2 || step_rad <= 0) return path;
  mju_copy(s->qpos, d->qpos, m->nq);
  auto palm = [&](const Eigen::VectorXd& q) {
    arm.Set(s, q);
    mj_kinematics(m, s);
    return Eigen::Vector3d(s->site_xpos + 3 * arm.palm_site);
  };
  const std::vector<double> cum = CumulativeLengths(path);
  const double length = cum.back();
  const Eigen::Vector3d end = palm(path.waypoints.back());
  double cut = -1;
  for (double at = length - step_rad; at > 0; at -= step_rad) {
    if ((palm(PointAt(path, at, &cum)) - end).norm() >= palm_m) {
      cut = at;
      break;
    }
  }
  if (cut <= 0) return path;
  JointPath tail;
  tail.waypoints.push_back(PointAt(path, cut, &cum));
  for (int i = 0; i < path.size(); ++i) {
    if (cum[i] > cut + 1e-9) tail.waypoints.push_back(path.waypoints[i]);
  }
  return tail;
}

namespace {

// PlanArmOnto with the clearance of `o` as given
core::StatusOr<ArmMotion> PlanArmOntoOnce(const mjModel* m, const mjData* d, mjData* s,
                                          const ArmChain& arm, const JointPath& tail,
                                          const ArmMotionOptions& o) {
  SH_RETURN_IF_ERROR(o.planner.Validate());
  if (tail.size() < 1) return absl::InvalidArgumentError("plan failure: an empty tail to join");
  const auto t0 = std::chrono::steady_clock::now();
  const PoseCheck check(m, d, s, arm, o);
  const ValidityFn valid = check.Valid(m, s, arm, o);
  if (!valid(tail.waypoints.front()) || !PathValid(tail, valid, o.planner.resolution_rad)) {
    return absl::FailedPreconditionError("plan failure: the tail is in collision");
  }
  Eigen::VectorXd lo, hi;
  ArmBounds(arm, &lo, &hi);
  PlannerOptions po = o.planner;
  if (po.start_escape_rad <= 0) po.start_escape_rad = 0.05;
  core::StatusOr<PlanResult> plan =
      PlanJointPath(ArmStart(arm, d), {tail.waypoints.front()}, lo, hi, valid, po);
  if (!plan.ok()) return core::Annotate(plan.status(), "plan failure");
  JointPath path = plan->path;
  for (int i = 1; i < tail.size(); ++i) path.waypoints.push_back(tail.waypoints[i]);
  const Eigen::VectorXd goal = path.waypoints.back();
  RetimeOptions ro = ArmRetime(m, o);
  if (o.terminal_palm_speed_mps > 0 && path.Length() > 1e-6) {
    core::StatusOr<double> v = PathSpeedForPalmSpeed(PalmJacobian(m, s, arm, goal),
                                                     EndDirection(path), o.terminal_palm_speed_mps);
    if (v.ok()) ro.terminal_speed = std::min(*v, o.max_joint_speed);
  }
  if (path.Length() < 1e-6) path.waypoints.push_back(path.waypoints.back());
  core::StatusOr<Trajectory> traj = Retime(path, ro);
  if (!traj.ok()) return core::Annotate(traj.status(), "plan failure: retiming");
  return ArmMotion{*std::move(traj), -1, goal, 0, Seconds(t0)};
}

}  // namespace

core::StatusOr<ArmMotion> PlanArmOnto(const mjModel* m, const mjData* d, mjData* s,
                                      const ArmChain& arm, const JointPath& tail,
                                      const ArmMotionOptions& o) {
  core::StatusOr<ArmMotion> r = PlanArmOntoOnce(m, d, s, arm, tail, o);
  if (r.ok() || o.object_clearance_m <= 0 ||
      !(absl::IsFailedPrecondition(r.status()) || absl::IsNotFound(r.status()))) {
    return r;
  }
  // the tail was planned in another state (the objects may have moved a little since): one that
  // only avoids touching them
  ArmMotionOptions touching = o;
  touching.object_clearance_m = 0;
  core::StatusOr<ArmMotion> closer = PlanArmOntoOnce(m, d, s, arm, tail, touching);
  if (closer.ok()) closer->clearance_kept = false;
  return closer;
}

core::StatusOr<ArmTracker> ArmTracker::Create(const mjModel* m, const ArmChain& arm,
                                              const TrackerGains& gains) {
  SH_RETURN_IF_ERROR(gains.Validate());
  std::vector<int> dofs(arm.dof, arm.dof + ArmChain::kDofs);
  SH_ASSIGN_OR_RETURN(InverseDynamics id, InverseDynamics::Create(m, dofs));
  return ArmTracker(m, arm, JointTracker(ArmChain::kDofs, gains), std::move(id));
}

void ArmTracker::Drive(const Eigen::VectorXd& q_ref, const Eigen::VectorXd& qd_ref,
                       const Eigen::VectorXd& qdd_ref, mjData* d) {
  Eigen::VectorXd q(ArmChain::kDofs), qd(ArmChain::kDofs);
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    q[i] = d->qpos[arm_.qpos[i]];
    qd[i] = d->qvel[arm_.dof[i]];
  }
  const Eigen::VectorXd acc =
      tracker_.DesiredAcceleration(q, qd, q_ref, qd_ref, qdd_ref, m_->opt.timestep);
  Eigen::VectorXd tau = id_.Torque(d, acc);
  const double floor = tracker_.gains().min_inertia;
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    if (floor > 0) tau[i] += std::max(0.0, floor - d->qM[m_->dof_Madr[arm_.dof[i]]]) * acc[i];
    const int a = arm_.actuator[i];
    d->ctrl[a] = q[i] + tau[i] / m_->actuator_gainprm[mjNGAIN * a];
  }
}

void ArmTracker::Control(const Trajectory& traj, double t_s, mjData* d) {
  const double t = std::clamp(t_s, 0.0, traj.duration_s());
  const auto p = traj.Sample(t);
  if (t_s >= traj.duration_s()) {
    Drive(p.q, Eigen::VectorXd::Zero(ArmChain::kDofs), Eigen::VectorXd::Zero(ArmChain::kDofs), d);
  } else {
    Drive(p.q, p.qdot, p.qddot, d);
  }
}

void ArmTracker::Hold(const Eigen::VectorXd& q, mjData* d) {
  Drive(q, Eigen::VectorXd::Zero(ArmChain::kDofs), Eigen::VectorXd::Zero(ArmChain::kDofs), d);
}

}  // namespace simhuman::control::manip
