#include "simhuman/control/manip/tabletop_pipeline.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "simhuman/core/geometry.h"

namespace simhuman::control::manip {

namespace {

// no arm pose or no path was found (as opposed to bad input or a broken simulation)
bool PlanFailed(const core::StatusOr<ArmMotion>& r) {
  return !r.ok() && (absl::IsFailedPrecondition(r.status()) || absl::IsNotFound(r.status()));
}

// "palm, 3 fingers, thumb": the hand parts touching the object (HandTouchParts() order: two
// palm parts, three phalanges for each of four fingers, then the thumb's)
std::string GripSummary(const float* touch) {
  const bool palm = touch[0] > 0 || touch[1] > 0;
  int fingers = 0;
  for (int f = 0; f < 4; ++f) {
    fingers += touch[2 + 3 * f] > 0 || touch[3 + 3 * f] > 0 || touch[4 + 3 * f] > 0;
  }
  bool thumb = false;
  for (int k = 14; k < kGraspTouchParts; ++k) thumb = thumb || touch[k] > 0;
  return std::string(palm ? "palm" : "no palm") + ", " + std::to_string(fingers) +
         (fingers == 1 ? " finger, " : " fingers, ") + (thumb ? "thumb" : "no thumb");
}

Eigen::Matrix3d Rot(const mjData* d, int body) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * body);
}

// one run's state: the world, the arm, the fingers' targets and the counters
class Run {
 public:
  Run(world::SimWorld& w, const GraspIndex& ix, const TabletopGoal& g, const TabletopOptions& o,
      const StepHook& hook, const PlacePolicyFn& place)
      : w_(w), m_(w.model()), d_(w.data()), ix_(ix), g_(g), o_(o), hook_(hook), place_(place) {
    scratch_ = mj_makeData(m_);
    for (int i = 0; i < kGraspDofs; ++i) s_.target[i] = d_->qpos[ix_.qpos[i]];
    s_.object_body = g_.object_body;
    s_.shape = g_.shape;
    s_.task_pos = g_.planned_pos;
    const std::string spine = world::AgentPrefix(ix_.arm.agent) + "abdomen_y";
    lean_act_ = mj_name2id(m_, mjOBJ_ACTUATOR, spine.c_str());
    twist_act_ =
        mj_name2id(m_, mjOBJ_ACTUATOR, (world::AgentPrefix(ix_.arm.agent) + "abdomen_z").c_str());
  }
  ~Run() { mj_deleteData(scratch_); }

  /// The whole pipeline; with `stop_at_place`, up to where placing begins (that state kept there)
  TabletopResult Go(const GraspPolicyFactory& make_policy, PlaceStart* stop_at_place = nullptr);
  /// Placing, release and settle from a kept state
  TabletopResult GoFrom(const PlaceStart& start);

 private:
  // one physics step: the arm by the tracker (or the grasp targets), the fingers by their
  // targets
  bool Step(const std::function<void()>& arm_ctrl) {
    mj_step1(m_, d_);
    if (arm_ctrl) {
      arm_ctrl();
    } else {
      WriteGraspCtrl(m_, d_, ix_, s_);
    }
    for (int i = ArmChain::kDofs; i < kGraspDofs; ++i) d_->ctrl[ix_.actuator[i]] = s_.target[i];
    mj_step2(m_, d_);
    ++steps_;
    if (hook_) hook_(d_);
    for (int k = 0; k < m_->nv; ++k) {
      if (!std::isfinite(d_->qvel[k])) return false;
    }
    // contacts dropped for want of buffer (world::ModelOptions' sizes): the physics is wrong
    if (d_->warning[mjWARN_CONTACTFULL].number > 0 || d_->warning[mjWARN_CNSTRFULL].number > 0) {
      step_error_ = "MuJoCo's contact buffers are full (nconmax " + std::to_string(m_->nconmax) +
                    ", njmax " + std::to_string(m_->njmax) + "): contacts were dropped";
      return false;
    }
    return true;
  }
  // why the last Step failed
  std::string StepError() const { return step_error_; }
  bool Follow(ArmTracker& tr, const Trajectory& traj, double extra_s) {
    tr.Reset();
    const double t0 = d_->time;
    while (d_->time - t0 < traj.duration_s() + extra_s) {
      if (!Step([&] { tr.Control(traj, d_->time - t0, d_); })) return false;
    }
    return true;
  }
  // the arm angles that put the palm at `p` with the hand's current rotation
  Eigen::VectorXd IkTo(const Eigen::Vector3d& p, const Eigen::VectorXd& from,
                       const Eigen::Matrix3d* rot = nullptr) {
    mju_copy(scratch_->qpos, d_->qpos, m_->nq);
    PalmPose pose;
    pose.pos = p;
    pose.rot = rot ? *rot : Rot(d_, ix_.arm.hand_body);
    IkOptions io;
    io.max_iterations = 40;
    return SolvePalmIk(m_, scratch_, ix_.arm, pose, from, from, io).q;
  }
  // moves the palm by `delta` (world) over `duration_s`, straight, by IK every ik_every_steps,
  // the hand keeping its rotation; with `turn`, the hand also turns by it (world frame), then
  // holds still for `settle_s`. `held`: the object is in the hand (the tracker's integral, which
  // carries its load, is kept: TabletopOptions::keep_load_integral)
  bool MovePalm(ArmTracker& tr, const Eigen::Vector3d& delta, double duration_s,
                const std::function<bool()>& stop, const Eigen::Matrix3d* turn = nullptr,
                bool held = false, double settle_s = 0) {
    const Eigen::Vector3d p0(d_->site_xpos + 3 * ix_.arm.palm_site);
    const Eigen::Matrix3d r0 = Rot(d_, ix_.arm.hand_body);
    const Eigen::Quaterniond full(turn ? *turn : Eigen::Matrix3d::Identity());
    Eigen::VectorXd q = ix_.arm.Get(d_);
    const double t0 = d_->time;
    if (!(held && o_.keep_load_integral)) tr.Reset();
    while (d_->time - t0 < duration_s) {
      const double a = std::min(1.0, (d_->time - t0) / duration_s);
      const double smooth = a * a * (3 - 2 * a);
      // a new IK target every ik_every_steps (the servos smooth between): the solve is the
      // pipeline's costliest part
      if (steps_ % std::max(1, o_.ik_every_steps) == 0) {
        const Eigen::Matrix3d r =
            Eigen::Quaterniond::Identity().slerp(smooth, full).toRotationMatrix() * r0;
        // the rotation is the one the move started with (the measured one would follow a
        // hand that sags under the object: the wrist then gives way step by step)
        q = IkTo(p0 + smooth * delta, q, &r);
      }
      if (!Step([&] { tr.Hold(q, d_); })) return false;
      if (stop && stop()) return true;
    }
    const double t1 = d_->time;
    while (d_->time - t1 < settle_s) {
      if (!Step([&] { tr.Hold(q, d_); })) return false;
    }
    return true;
  }
  Eigen::Vector3d ObjectCom() const { return Eigen::Vector3d(d_->xipos + 3 * g_.object_body); }
  bool InHand() const {
    const Eigen::Vector3d palm(d_->site_xpos + 3 * ix_.arm.palm_site);
    return (ObjectCom() - palm).norm() < 0.13;
  }
  // the object bears on something that is not the hand (the table, the bottom object)
  bool Supported() const {
    for (int c = 0; c < d_->ncon; ++c) {
      const int g1 = d_->contact[c].geom1, g2 = d_->contact[c].geom2;
      const int b1 = m_->geom_bodyid[g1], b2 = m_->geom_bodyid[g2];
      const int other = b1 == g_.object_body ? g2 : b2 == g_.object_body ? g1 : -1;
      if (other >= 0 && ix_.touch_of_geom[other] < 0 &&
          std::find(ix_.arm.bodies.begin(), ix_.arm.bodies.end(), m_->geom_bodyid[other]) ==
              ix_.arm.bodies.end()) {
        return true;
      }
    }
    return false;
  }
  TabletopResult Fail(TabletopStage stage, const std::string& why, bool plan = false) {
    TabletopResult r;
    r.failed_stage = stage;
    r.end_reason = why;
    r.plan_failure = plan;
    return r;
  }
  // the trunk leans forward by o_.lean_deg[k] while the arm holds its angles
  bool LeanTo(ArmTracker& tr, int k) {
    d_->ctrl[lean_act_] = o_.lean_deg[k] * M_PI / 180;
    lean_ = k;
    const Eigen::VectorXd arm_now = ix_.arm.Get(d_);
    for (int j = 0; j < 96; ++j) {
      if (!Step([&] { tr.Hold(arm_now, d_); })) return false;
    }
    return true;
  }
  // the trunk turns about the spine to `rad` while the arm holds its angles
  bool TwistTo(ArmTracker& tr, double rad) {
    d_->ctrl[twist_act_] = rad;
    const Eigen::VectorXd arm_now = ix_.arm.Get(d_);
    for (int j = 0; j < 96; ++j) {
      if (!Step([&] { tr.Hold(arm_now, d_); })) return false;
    }
    return true;
  }
  // the turns of o_.twist_deg (radians) that bring the shoulder nearer to `goal` in the
  // horizontal, nearest first (the shoulder turned about the spine's axis as it stands)
  std::vector<double> TwistsToward(const Eigen::Vector3d& goal) const;
  // after the furthest lean, the trunk's turns in turn until `plan` succeeds or none is left;
  // false when the simulation failed
  bool TryTwists(ArmTracker& tr, const Eigen::Vector3d& goal,
                 const std::function<core::StatusOr<ArmMotion>()>& plan,
                 core::StatusOr<ArmMotion>* motion);
  std::optional<TabletopResult> Reach(ArmTracker& tr);
  // TabletopOptions::raise_tail_m: the hand raised through the raise vias, then onto the last
  // part of `motion` (a reach planned from the hanging arm), or when no path joins it, `motion`
  // planned anew by `replan` from the raised hand; nothing when the vias have no straight way
  std::optional<TabletopResult> RaiseOnto(ArmTracker& tr, const ArmMotionOptions& mo,
                                          const std::function<core::StatusOr<ArmMotion>()>& replan,
                                          core::StatusOr<ArmMotion>* motion);
  std::optional<TabletopResult> Transport(ArmTracker& tr);
  std::optional<TabletopResult> GraspAndLift(ArmTracker& tr, const GraspPolicyFn& policy);
  bool LetGo(ArmTracker& tr);
  TabletopResult Place(ArmTracker& tr);
  // the descent over the target in segments (each asks the place policy, then aligns), `drop`
  // at most, until the object bears on its support; a failure when the object leaves the hand
  std::optional<TabletopResult> Lower(ArmTracker& tr, double drop);
  // the held object's base above the target, as the controllers see it
  double GapAboveTarget() const;
  TabletopResult Finish(TabletopResult r) const;  // the counters and times filled in
  bool Align(ArmTracker& tr, const PlaceAdjust& adjust);
  // the place policy's corrections for the next segment (none without a policy)
  PlaceAdjust AskPlacePolicy(double lowered_frac);
  std::optional<std::string> ReadyForRetry(ArmTracker& tr);
  static constexpr double kTailDriftM = 0.01;   // RaiseOnto: the tail's allowance for drift
  static constexpr double kRetrySettleS = 0.5;  // the object comes to rest before the next look

  world::SimWorld& w_;
  const mjModel* m_;
  mjData* d_;
  mjData* scratch_ = nullptr;
  const GraspIndex& ix_;
  TabletopGoal g_;  // a copy: a new attempt plans from where the object now stands
  const TabletopOptions& o_;
  StepHook hook_;
  PlacePolicyFn place_;
  GraspState s_;
  int steps_ = 0;
  int attempts_ = 0;  // grasps begun
  std::chrono::steady_clock::time_point wall0_ = std::chrono::steady_clock::now();
  double cpu0_ = ThreadCpuSeconds();
  double release_gap_m_ = -1;     // the object's base above the target when the release began
  double release_tilt_deg_ = -1;  // the object's tilt when the release began
  int lean_act_ = -1;             // the trunk's forward lean actuator (abdomen_y), -1 without one
  int lean_ = -1;                 // the index into o_.lean_deg the trunk last leaned to, -1 upright
  int twist_act_ = -1;            // the trunk's turn about the spine (abdomen_z), -1 without one
  Eigen::VectorXd raised_from_;   // the hanging arm's angles before the hand rose (else empty)
  std::string reach_route_;       // TabletopResult::reach_route
  std::string transport_route_;   // TabletopResult::transport_route
  std::string step_error_ = "unstable simulation";
};

std::vector<double> Run::TwistsToward(const Eigen::Vector3d& goal) const {
  std::vector<std::pair<double, double>> by_distance;  // {distance, twist}
  if (twist_act_ < 0) return {};
  const int joint = m_->actuator_trnid[2 * twist_act_];
  const Eigen::Vector3d anchor(d_->xanchor + 3 * joint), axis(d_->xaxis + 3 * joint);
  const Eigen::Vector3d shoulder(d_->site_xpos + 3 * ix_.shoulder_site);
  auto distance = [&](double rad) {
    const Eigen::Vector3d p = anchor + Eigen::AngleAxisd(rad, axis) * (shoulder - anchor);
    return (p - goal).head<2>().norm();
  };
  const double now = distance(0);
  for (double deg : o_.twist_deg) {
    const double rad = deg * M_PI / 180 - d_->ctrl[twist_act_];
    if (distance(rad) < now) by_distance.emplace_back(distance(rad), deg * M_PI / 180);
  }
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<double> out;
  for (const auto& [dist, rad] : by_distance) out.push_back(rad);
  return out;
}

bool Run::TryTwists(ArmTracker& tr, const Eigen::Vector3d& goal,
                    const std::function<core::StatusOr<ArmMotion>()>& plan,
                    core::StatusOr<ArmMotion>* motion) {
  for (double rad : TwistsToward(goal)) {
    if (!PlanFailed(*motion)) break;
    if (!TwistTo(tr, rad)) return false;
    *motion = plan();
  }
  return true;
}

std::optional<TabletopResult> Run::Reach(ArmTracker& tr) {
  // the hand pre-shapes first (0.25 s), then the arm moves with it open
  const bool top = TopGrasp(g_, o_);
  mju_copy(scratch_->qpos, d_->qpos, m_->nq);
  if (top) {
    SetClawHand(ix_, scratch_);
  } else {
    SetOpenHand(ix_, scratch_);
  }
  for (int i = ArmChain::kDofs; i < kGraspDofs; ++i) s_.target[i] = scratch_->qpos[ix_.qpos[i]];
  const Eigen::VectorXd still = ix_.arm.Get(d_);
  for (int k = 0; k < 60; ++k) {
    if (!Step([&] { tr.Hold(still, d_); })) return Fail(TabletopStage::kReach, StepError());
  }
  reach_route_ = "hanging";
  const bool low_hand = d_->site_xpos[3 * ix_.arm.palm_site + 2] < g_.planned_pos.z();
  if (!o_.raise_via_rad.empty() && low_hand && o_.raise_tail_m <= 0) {
    const core::StatusOr<ArmMotion> raise =
        PlanArmThrough(m_, d_, scratch_, ix_.arm, RaiseVias(o_), o_.motion);
    if (raise.ok()) raised_from_ = still;
    if (raise.ok()) reach_route_ = "raised";
    if (raise.ok() && !Follow(tr, raise->trajectory, 0.05))
      return Fail(TabletopStage::kReach, StepError());
  }
  Eigen::Vector3d centre = g_.planned_pos + Eigen::Vector3d(0, 0, GripHeightM(g_, o_));
  // palm poses around the object at the given approach angles
  auto poses = [&](const std::vector<double>& thetas) {
    std::pair<std::vector<PalmPose>, std::vector<Eigen::Vector3d>> out;
    for (double theta : thetas) {
      out.first.push_back(SideGraspPose(centre, g_.half_width_m + o_.pregrasp_gap_m, theta,
                                        ix_.arm.right, PalmBehindM(g_, o_)));
      out.second.push_back(ix_.arm.right ? out.first.back().rot.col(1)
                                         : Eigen::Vector3d(-out.first.back().rot.col(1)));
    }
    return out;
  };
  // a sphere from above, the fingers pointing any way round
  auto top_poses = [&]() {
    std::pair<std::vector<PalmPose>, std::vector<Eigen::Vector3d>> out;
    const Eigen::Vector3d top_pt = g_.planned_pos + Eigen::Vector3d(0, 0, 2 * g_.half_width_m);
    for (int k = 0; k < o_.top_yaws; ++k) {
      out.first.push_back(TopGraspPose(top_pt, o_.top_standoff_m,
                                       -M_PI + 2 * M_PI * k / o_.top_yaws, ix_.arm.right,
                                       o_.top_palm_behind_m));
      out.second.push_back(-Eigen::Vector3d::UnitZ());
    }
    return out;
  };
  // a box is taken flat on one of its side faces (its yaw plus quarter turns, and a little
  // either side) when the arm can; from all around (as round objects) when it cannot
  std::vector<double> faces, around;
  if (g_.shape == GraspShape::kBox) {
    const double yaw = ObserveObject(g_, d_, false).yaw_rad;
    for (int k = 0; k < 4; ++k) {
      for (double off : {0.0, -1.0, 1.0, -2.0, 2.0})
        faces.push_back(yaw + k * M_PI / 2 + off * o_.box_face_spread_rad);
    }
  }
  for (int k = 0; k < o_.approach_angles; ++k)
    around.push_back(-M_PI + 2 * M_PI * k / o_.approach_angles);
  std::pair<std::vector<PalmPose>, std::vector<Eigen::Vector3d>> face_goals, around_goals;
  ArmMotionOptions mo = o_.motion;
  mo.approach_body = g_.object_body;
  mo.ik_from = raised_from_;
  auto plan = [&]() {
    if (!faces.empty()) {
      core::StatusOr<ArmMotion> on_face =
          PlanArmMotion(m_, d_, scratch_, ix_.arm, face_goals.first, face_goals.second, mo);
      // no free pose on a face, or no path to the ones found: from all around
      if (on_face.ok() ||
          !(absl::IsFailedPrecondition(on_face.status()) || absl::IsNotFound(on_face.status())))
        return on_face;
    }
    return PlanArmMotion(m_, d_, scratch_, ix_.arm, around_goals.first, around_goals.second, mo);
  };
  // a far object or target: the trunk leans forward first, as a seated person does, so that
  // the arm ends well inside its reach at both; then more while no arm pose reaches the object
  const int lean_act = lean_act_;
  const Eigen::Vector3d shoulder(d_->site_xpos + 3 * ix_.shoulder_site);
  const double far =
      std::max(std::hypot(centre.x() - shoulder.x(), centre.y() - shoulder.y()),
               std::hypot(g_.target.x() - shoulder.x(), g_.target.y() - shoulder.y()));
  auto lean_to = [&](int k) { return LeanTo(tr, k); };
  const int leans = lean_act >= 0 ? static_cast<int>(o_.lean_deg.size()) : 0;
  int lean = -1;  // upright
  if (leans > 0 && far > o_.comfort_reach_m) {
    lean = 0;
    while (lean + 1 < leans &&
           far - o_.lean_shoulder_m * std::sin(o_.lean_deg[lean] * M_PI / 180) > o_.comfort_reach_m)
      ++lean;
    if (!lean_to(lean)) return Fail(TabletopStage::kReach, StepError());
  }
  // a plan at the grip height; when no arm pose or path reaches it, the object higher up (the
  // arm lies on the table on the way to a far object's middle; a seated person takes it higher,
  // the forearm clear of the table)
  const double grip = centre.z() - g_.planned_pos.z();
  const double high = g_.height_m - o_.grip_below_top_m;
  auto plan_at_heights = [&]() {
    centre.z() = g_.planned_pos.z() + grip;
    face_goals = poses(faces);
    around_goals = top ? top_poses() : poses(around);
    core::StatusOr<ArmMotion> r = plan();
    if (PlanFailed(r) && !top && high > grip + 0.01) {
      centre.z() = g_.planned_pos.z() + high;
      face_goals = poses(faces);
      around_goals = poses(around);
      core::StatusOr<ArmMotion> higher = plan();
      if (higher.ok()) return higher;
    }
    return r;
  };
  core::StatusOr<ArmMotion> motion = plan_at_heights();
  // leaning further while no arm pose is free or no path reaches one
  for (++lean; lean < leans && PlanFailed(motion); ++lean) {
    if (!lean_to(lean)) return Fail(TabletopStage::kReach, StepError());
    motion = plan_at_heights();
  }
  if (PlanFailed(motion) && !TryTwists(tr, centre, plan_at_heights, &motion)) {
    return Fail(TabletopStage::kReach, StepError());
  }
  if (!motion.ok()) {
    return Fail(TabletopStage::kReach, std::string(motion.status().message()), true);
  }
  if (!o_.raise_via_rad.empty() && low_hand && o_.raise_tail_m > 0) {
    mo.ik_from = still;  // for a reach planned anew from the raised hand
    if (auto failed = RaiseOnto(tr, mo, plan_at_heights, &motion)) return failed;
  }
  if (!Follow(tr, motion->trajectory, 0.05)) return Fail(TabletopStage::kReach, StepError());
  return std::nullopt;
}

std::optional<TabletopResult> Run::RaiseOnto(
    ArmTracker& tr, const ArmMotionOptions& mo,
    const std::function<core::StatusOr<ArmMotion>()>& replan, core::StatusOr<ArmMotion>* motion) {
  const core::StatusOr<ArmMotion> raise =
      PlanArmThrough(m_, d_, scratch_, ix_.arm, RaiseVias(o_), mo);
  if (!raise.ok()) return std::nullopt;  // no straight way up: the reach from the hanging arm
  const JointPath tail =
      PathTail(m_, d_, scratch_, ix_.arm, (*motion)->trajectory.path(), o_.raise_tail_m);
  if (!Follow(tr, raise->trajectory, 0.05)) return Fail(TabletopStage::kReach, StepError());
  // the clearance the reach kept (PlanArmMotion lets a reach only avoid touching when none keeps
  // it)
  ArmMotionOptions join = mo;
  if (!(*motion)->clearance_kept) join.object_clearance_m = 0;
  // to the tail's start, stopping there, then along it
  JointPath start;
  start.waypoints = {tail.waypoints.front()};
  ArmMotionOptions to_start = join;
  to_start.terminal_palm_speed_mps = 0;
  // the hand stops short of the object: it keeps clear of it too (exempt, it could topple it)
  to_start.approach_body = -1;
  to_start.object_clearance_m = mo.object_clearance_m;
  core::StatusOr<ArmMotion> onto = PlanArmOnto(m_, d_, scratch_, ix_.arm, start, to_start);
  if (onto.ok()) {
    if (!Follow(tr, onto->trajectory, 0.05)) return Fail(TabletopStage::kReach, StepError());
    // the tail was checked when it was planned; the trunk has since moved by a few mm, which a
    // path that grazes the object within the tolerance does not allow for
    join.contact_tolerance_m += kTailDriftM;
    onto = PlanArmOnto(m_, d_, scratch_, ix_.arm, tail, join);
  }
  if (onto.ok()) {
    onto->goal_index = (*motion)->goal_index;
    onto->clearance_kept = (*motion)->clearance_kept;
    *motion = std::move(onto);
    reach_route_ = "raised-onto";
    return std::nullopt;
  }
  // no way onto it from the raised hand: a reach planned from there
  reach_route_ = "raised-replanned";
  *motion = replan();
  if (!motion->ok())
    return Fail(TabletopStage::kReach, std::string(motion->status().message()), true);
  return std::nullopt;
}

std::optional<TabletopResult> Run::Transport(ArmTracker& tr) {
  // where the object sits in the hand, kept while the hand turns about the vertical
  const Eigen::Matrix3d rh = Rot(d_, ix_.arm.hand_body);
  const Eigen::Vector3d ph(d_->xpos + 3 * ix_.arm.hand_body);
  const ObjectView seen = ObserveObject(g_, d_, true);
  const Eigen::Vector3d r_obj = rh.transpose() * (seen.base - ph);
  const Eigen::Vector3d r_palm =
      rh.transpose() * (Eigen::Vector3d(d_->site_xpos + 3 * ix_.arm.palm_site) - ph);
  const Eigen::Vector3d base_goal = g_.target + Eigen::Vector3d(0, 0, o_.carry_clearance_m);
  // the hand turns so that an object that tilted in the grip arrives upright
  Eigen::Matrix3d upright = Eigen::Matrix3d::Identity();
  if (g_.shape != GraspShape::kSphere) {
    upright =
        Eigen::Quaterniond::FromTwoVectors(seen.up, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  const std::vector<PalmPose> goals =
      TransportPalmGoals(rh, r_obj, r_palm, upright, base_goal, o_.approach_angles);
  ArmMotionOptions mo = o_.motion;
  mo.terminal_palm_speed_mps = 0;  // DASH: transport ends at rest over the target
  mo.ignore_bodies.push_back(g_.object_body);
  if (o_.transport_checks_object) mo.carried_body = g_.object_body;
  mo.carried_min_z = std::min(d_->xpos[3 * g_.object_body + 2], base_goal.z()) - o_.carry_dip_m;
  // the goals' turns first, else any turn about the target's vertical (the object's yaw is free)
  bool any_turn_planned = false;  // the goal index then names no pose of `goals`
  auto plan = [&]() {
    core::StatusOr<ArmMotion> r = PlanArmMotion(m_, d_, scratch_, ix_.arm, goals, {}, mo);
    any_turn_planned = false;
    if (!PlanFailed(r)) return r;
    any_turn_planned = true;
    PalmPose any_turn = goals.front();
    any_turn.yaw_free_about = base_goal;
    ArmMotionOptions any_mo = mo;
    any_mo.ik.tol_rot_rad = std::max(mo.ik.tol_rot_rad, o_.transport_tilt_tol_rad);
    core::StatusOr<ArmMotion> turned =
        PlanArmMotion(m_, d_, scratch_, ix_.arm, {any_turn}, {}, any_mo);
    return turned.ok() ? turned : r;
  };
  core::StatusOr<ArmMotion> motion = plan();
  // a target beyond the arm from the trunk's lean at the reach: the trunk leans further, the
  // object held (the reach chose its lean for both, and a seated person leans on when short)
  for (int lean = lean_ + 1;
       lean_act_ >= 0 && lean < static_cast<int>(o_.lean_deg.size()) && PlanFailed(motion);
       ++lean) {
    if (!LeanTo(tr, lean)) return Fail(TabletopStage::kTransport, StepError());
    motion = plan();
  }
  if (PlanFailed(motion) && !TryTwists(tr, base_goal, plan, &motion)) {
    return Fail(TabletopStage::kTransport, StepError());
  }
  if (!motion.ok()) {
    return Fail(TabletopStage::kTransport, std::string(motion.status().message()), true);
  }
  transport_route_ = "searched";
  if (o_.carry_over_arc && !any_turn_planned && motion->goal_index >= 0) {
    // the same goal over an arc, the posture toward the plan's end (from the palm as it is now)
    const PalmPose palm{Eigen::Vector3d(d_->site_xpos + 3 * ix_.arm.palm_site),
                        Rot(d_, ix_.arm.hand_body), std::nullopt};
    auto arc = PlanCarryOver(m_, d_, scratch_, ix_.arm, palm, goals[motion->goal_index],
                             r_obj - r_palm, o_.carry_over, mo, motion->goal_q);
    if (arc.ok()) motion = std::move(arc), transport_route_ = "over";
  }
  if (!Follow(tr, motion->trajectory, 0.2)) return Fail(TabletopStage::kTransport, StepError());
  if (!InHand())
    return Fail(TabletopStage::kTransport, "drop in transport: the object fell out of the hand");
  return std::nullopt;
}

// grasp: the policy at 40 Hz, the grip then held by targets the fingers cannot reach (DASH's
// tracking-error trick), and the lift; a grasp miss when the object does not rise with the hand
std::optional<TabletopResult> Run::GraspAndLift(ArmTracker& tr, const GraspPolicyFn& policy) {
  HoldCurrentPose(d_, ix_, &s_);
  const int substeps = std::max(1, static_cast<int>(std::lround(0.025 / m_->opt.timestep)));
  std::vector<float> obs(kGraspObsDim), act(kGraspActDim);
  for (int k = 0; k < o_.grasp_policy_steps; ++k) {
    GraspObservation(m_, d_, ix_, s_, obs.data());
    policy(obs.data(), act.data());
    ApplyGraspAction(ix_, act.data(), &s_);
    for (int j = 0; j < substeps; ++j) {
      if (!Step({})) return Fail(TabletopStage::kGrasp, StepError());
    }
  }
  // what touched the object when the grasp ended (said in a grasp miss's end reason)
  float touch[kGraspTouchParts];
  GraspTouch(m_, d_, ix_, g_.object_body, touch);
  const std::string grip = GripSummary(touch);
  for (int i = ArmChain::kDofs; i < kGraspDofs; ++i) {
    const double e = s_.target[i] - d_->qpos[ix_.qpos[i]];
    s_.target[i] = std::clamp(s_.target[i] + (e > 0   ? 1
                                              : e < 0 ? -1
                                                      : 0) *
                                                 o_.finger_squeeze_rad,
                              ix_.lo[i], ix_.hi[i]);
  }
  const double z0 = ObjectCom().z();
  if (!MovePalm(tr, Eigen::Vector3d(0, 0, o_.lift_m), 0.8, {}, nullptr, true)) {
    return Fail(TabletopStage::kLift, StepError());
  }
  if (!InHand() || ObjectCom().z() - z0 < 0.5 * o_.lift_m) {
    return Fail(TabletopStage::kGrasp,
                "grasp miss: the object did not rise with the hand (touching it at the end of "
                "the grasp: " +
                    grip + ")");
  }
  return std::nullopt;
}

// the held object upright with its centre of mass over the target, turning the hand about that
// centre: up to align_passes moves, reading the object's pose before each; `adjust` (a place
// policy's) moves the aim and the upright direction
bool Run::Align(ArmTracker& tr, const PlaceAdjust& adjust) {
  const Eigen::Vector3d aim = g_.target + Eigen::Vector3d(adjust.aim.x(), adjust.aim.y(), 0);
  const Eigen::Vector3d up_goal = PlaceUpGoal(adjust);
  for (int k = 0; k < o_.align_passes; ++k) {
    const ObjectView seen = ObserveObject(g_, d_, true);
    const Eigen::Vector3d c = seen.centre;
    Eigen::Vector3d err = aim - c;
    err.z() = 0;
    const Eigen::Matrix3d turn =
        g_.shape == GraspShape::kSphere
            ? Eigen::Matrix3d::Identity()
            : Eigen::Quaterniond::FromTwoVectors(seen.up, up_goal).toRotationMatrix();
    if (err.norm() < o_.align_tol_m && Eigen::AngleAxisd(turn).angle() < o_.align_tilt_rad) break;
    const Eigen::Vector3d p(d_->site_xpos + 3 * ix_.arm.palm_site);
    if (!MovePalm(tr, c + turn * (p - c) - p + err, o_.align_s, {}, &turn, true,
                  o_.align_settle_s)) {
      return false;
    }
  }
  return true;
}

PlaceAdjust Run::AskPlacePolicy(double lowered_frac) {
  if (!place_) return {};
  float obs[kPlaceObsDim], act[kPlaceActDim];
  PlaceObservation(m_, d_, ix_, g_, ObserveObject(g_, d_, true), lowered_frac, Supported(), obs);
  place_(obs, act);
  return PlaceAdjustFromAction(act);
}

// the fingers open over release_s while the arm holds, then the palm backs away from the object
// and rises
bool Run::LetGo(ArmTracker& tr) {
  const Eigen::VectorXd hold = ix_.arm.Get(d_);
  mju_copy(scratch_->qpos, d_->qpos, m_->nq);
  if (TopGrasp(g_, o_)) {
    SetClawHand(ix_, scratch_);  // what came down over the object clears it
  } else {
    SetOpenHand(ix_, scratch_);
  }
  std::array<double, kGraspDofs> from = s_.target;
  const double t0 = d_->time;
  while (d_->time - t0 < o_.release_s) {
    const double a = std::min(1.0, (d_->time - t0) / o_.release_s);
    for (int i = ArmChain::kDofs; i < kGraspDofs; ++i) {
      s_.target[i] = from[i] + a * (scratch_->qpos[ix_.qpos[i]] - from[i]);
    }
    if (!Step([&] { tr.Hold(hold, d_); })) return false;
  }
  const Eigen::Vector3d out_of_palm = Rot(d_, ix_.arm.hand_body).col(1) * (ix_.arm.right ? 1 : -1);
  return MovePalm(tr, -0.06 * out_of_palm + Eigen::Vector3d(0, 0, 0.08), 0.6, {});
}

// after a miss: lets go, waits for the object to come to rest, and takes where the controllers
// now see it as the next attempt's plan; an error says why there is no next attempt
std::optional<std::string> Run::ReadyForRetry(ArmTracker& tr) {
  if (!LetGo(tr)) return std::string(StepError());
  const Eigen::VectorXd still = ix_.arm.Get(d_);
  const double t0 = d_->time;
  while (d_->time - t0 < kRetrySettleS) {
    if (!Step([&] { tr.Hold(still, d_); })) return std::string(StepError());
  }
  const ObjectView seen = ObserveObject(g_, d_, false);
  if (g_.shape != GraspShape::kSphere && seen.up.z() < std::cos(M_PI / 6))
    return std::string("the object tipped over");
  if (std::abs(seen.base.z() - g_.planned_pos.z()) > 0.02)
    return std::string("the object left its support");
  g_.planned_pos = seen.base;
  s_.task_pos = seen.base;
  return std::nullopt;
}

TabletopResult Run::Finish(TabletopResult r) const {
  r.final_pos = ObjectCom();
  r.sim_steps = steps_;
  r.grasp_attempts = attempts_;
  r.reach_route = reach_route_;
  r.transport_route = transport_route_;
  r.release_tilt_deg = release_tilt_deg_;
  r.release_gap_m = release_gap_m_;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  r.cpu_s = ThreadCpuSeconds() - cpu0_;
  return r;
}

TabletopResult Run::Go(const GraspPolicyFactory& make_policy, PlaceStart* stop_at_place) {
  core::StatusOr<ArmTracker> tracker = ArmTracker::Create(m_, ix_.arm, o_.tracker);
  if (!tracker.ok()) return Fail(TabletopStage::kReach, std::string(tracker.status().message()));
  ArmTracker& tr = *tracker;
  auto finish = [&](TabletopResult r) { return Finish(std::move(r)); };
  if (2 * g_.half_width_m > o_.max_grip_width_m) {
    std::string name = mj_id2name(m_, mjOBJ_BODY, g_.object_body)
                           ? mj_id2name(m_, mjOBJ_BODY, g_.object_body)
                           : "the object";
    if (name.rfind("obj/", 0) == 0) name = name.substr(4);
    char why[256];
    std::snprintf(why, sizeof(why),
                  "too wide for the hand: %s is %.1f cm across where the hand would hold it; "
                  "the hand closes around objects up to %.1f cm",
                  name.c_str(), 200 * g_.half_width_m, 100 * o_.max_grip_width_m);
    return finish(Fail(TabletopStage::kGrasp, why));
  }
  for (;;) {
    if (auto f = Reach(tr)) {
      // a later attempt that finds no way to the object stays the grasp miss it follows
      if (attempts_ > 0 && f->plan_failure) {
        f->failed_stage = TabletopStage::kGrasp;
        f->plan_failure = false;
        f->end_reason = "grasp miss, then no new reach: " + f->end_reason;
      }
      return finish(*f);
    }
    ++attempts_;
    std::optional<TabletopResult> miss = GraspAndLift(tr, make_policy(g_));
    if (!miss) break;
    if (miss->failed_stage != TabletopStage::kGrasp || attempts_ >= o_.grasp_attempts)
      return finish(*miss);
    if (std::optional<std::string> why = ReadyForRetry(tr)) {
      miss->end_reason += "; no new attempt: " + *why;
      return finish(*miss);
    }
  }
  if (auto f = Transport(tr)) return finish(*f);
  if (stop_at_place) {
    stop_at_place->data.reset(mj_makeData(m_), mj_deleteData);
    mj_copyData(stop_at_place->data.get(), m_, d_);
    stop_at_place->grasp = s_;
    stop_at_place->tracker = tr;
    stop_at_place->goal = g_;
    stop_at_place->lean = lean_;
    stop_at_place->steps = steps_;
    stop_at_place->attempts = attempts_;
    TabletopResult r = Fail(TabletopStage::kPlace, "stopped where placing begins");
    return finish(r);
  }
  return finish(Place(tr));
}

TabletopResult Run::GoFrom(const PlaceStart& start) {
  mj_copyData(d_, m_, start.data.get());
  s_ = start.grasp;
  g_ = start.goal;
  lean_ = start.lean;
  steps_ = start.steps;
  attempts_ = start.attempts;
  ArmTracker tr = *start.tracker;
  return Finish(Place(tr));
}

// place: the object upright (it tilts in the grip on the way) with its centre of mass over the
// target, then down until it bears on its support, straightened again every `lower_segment_m`
// (it tilts in the grip on the way down too); release, retract, settle, and DASH's success rule
std::optional<TabletopResult> Run::Lower(ArmTracker& tr, double drop) {
  const double segment = o_.lower_segment_m > 0 ? o_.lower_segment_m : drop;
  for (double lowered = 0; lowered < drop - 1e-9 && (lowered == 0 || !Supported());
       lowered += segment) {
    const PlaceAdjust adjust = AskPlacePolicy(lowered / drop);
    if (!Align(tr, adjust)) return Fail(TabletopStage::kPlace, StepError());
    if (!InHand()) {
      return Fail(TabletopStage::kPlace,
                  "drop at place: the object fell out of the hand over the target");
    }
    const double dz = std::min(segment, drop - lowered);
    if (!MovePalm(
            tr, Eigen::Vector3d(0, 0, -dz), dz / (o_.lower_speed_mps * adjust.speed_scale),
            [&] { return Supported(); }, nullptr, true)) {
      return Fail(TabletopStage::kPlace, StepError());
    }
  }
  return std::nullopt;
}

double Run::GapAboveTarget() const { return ObserveObject(g_, d_, true).base.z() - g_.target.z(); }

TabletopResult Run::Place(ArmTracker& tr) {
  const double drop = o_.carry_clearance_m + 0.04;
  if (auto f = Lower(tr, drop)) return *f;
  release_gap_m_ = GapAboveTarget();
  release_tilt_deg_ = core::AngleFromCos(Rot(d_, g_.object_body)(2, 2)) * 180 / M_PI;
  // release and retract
  if (!LetGo(tr)) return Fail(TabletopStage::kRelease, StepError());
  // settle
  const Eigen::VectorXd rest = ix_.arm.Get(d_);
  const double t1 = d_->time;
  while (d_->time - t1 < o_.settle_s) {
    if (!Step([&] { tr.Hold(rest, d_); })) return Fail(TabletopStage::kSettle, StepError());
  }
  const Eigen::Vector3d c = ObjectCom();
  mjtNum vel[6];
  mj_objectVelocity(m_, d_, mjOBJ_BODY, g_.object_body, vel, 0);
  const double speed = Eigen::Vector3d(vel[3], vel[4], vel[5]).norm();
  const double up = Rot(d_, g_.object_body)(2, 2);
  const double dxy = std::hypot(c.x() - g_.target.x(), c.y() - g_.target.y());
  TabletopResult r;
  if (g_.shape != GraspShape::kSphere && up < std::cos(M_PI / 6)) {
    r = Fail(TabletopStage::kPlace, "topple at place: the object tipped over");
  } else if (dxy > 0.10) {
    r = Fail(TabletopStage::kPlace, "missed the target: " + std::to_string(dxy) + " m away");
  } else if (c.z() < g_.target.z() + g_.min_com_above_target_m) {
    r = Fail(TabletopStage::kPlace, "fell off its support");
  } else if (speed > 0.05) {
    r = Fail(TabletopStage::kSettle, "not at rest after the release");
  } else {
    r.success = true;
    r.end_reason = "success";
  }
  return r;
}

}  // namespace

TabletopResult RunTabletop(world::SimWorld& world, const GraspIndex& ix, const TabletopGoal& goal,
                           const GraspPolicyFactory& make_policy, const TabletopOptions& options,
                           const StepHook& hook, const PlacePolicyFn& place_policy) {
  Run run(world, ix, goal, options, hook, place_policy);
  return run.Go(make_policy);
}

TabletopResult RunTabletopToPlace(world::SimWorld& world, const GraspIndex& ix,
                                  const TabletopGoal& goal, const GraspPolicyFactory& make_policy,
                                  const TabletopOptions& options, PlaceStart* start) {
  *start = PlaceStart();
  Run run(world, ix, goal, options, {}, {});
  return run.Go(make_policy, start);
}

TabletopResult RunTabletopPlace(world::SimWorld& world, const GraspIndex& ix,
                                const PlaceStart& start, const TabletopOptions& options,
                                const PlacePolicyFn& place_policy) {
  if (!start.ready()) {
    TabletopResult r;
    r.failed_stage = TabletopStage::kPlace;
    r.end_reason = "no state where placing begins (RunTabletopToPlace did not reach it)";
    return r;
  }
  Run run(world, ix, start.goal, options, {}, place_policy);
  return run.GoFrom(start);
}

}  // namespace simhuman::control::manip
