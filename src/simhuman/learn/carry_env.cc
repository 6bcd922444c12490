#include "simhuman/learn/carry_env.h"

#include <algorithm>
#include <cmath>

#include "simhuman/control/arm_servo.h"
#include "simhuman/control/policy/carry_support.h"
#include "simhuman/core/check.h"
#include "simhuman/core/geometry.h"
#include "simhuman/learn/walk_env.h"
#include "simhuman/world/model_builder.h"
#include "simhuman/world/objects.h"

namespace simhuman::learn {
namespace {

using control::CarryPhase;
using control::kWalkActDim;

constexpr double kDeg = M_PI / 180.0;
constexpr double kSuccessRadius = 0.2;
constexpr int kSuccessHold = 30;  // policy steps at rest after the put-down (1 s)
constexpr double kStartAtBoxFraction = 0.5;
constexpr double kStartInSquatFraction = 0.6;  // of the episodes that start at the box
// a stage's reward for its success (the lift handing the box over held, the box delivered):
// about 40 steps' worth of the rest
constexpr double kStageSuccessBonus = 20.0;
constexpr double kMaxApproachSeconds = 20;
// a carry that has not reached its stand point by then stalled (the put-down starts within
// CarryParams::arrive_dwell_s of reaching it)
constexpr double kMaxCarrySeconds = 15;  // training destinations lie 1-3 m away
// the delivery stage carries up to 10 m (curriculum 1) at about 0.7 m/s
constexpr double kMaxDeliverCarrySeconds = 25;
constexpr double kBuiltBoxSide = 0.5;  // the box is built as this cube; ShapeBox scales it
// the squats' ankle strategy (control::BalanceAnkles): 0.6-1.2 and 0.2-0.5 s measured alike
constexpr double kSupportBalanceGain = 0.8, kSupportBalanceDampingS = 0.25;

Eigen::Vector3d Vec(const mjtNum* x) { return Eigen::Vector3d(x[0], x[1], x[2]); }

bool Squatting(CarryPhase p) { return p == CarryPhase::kLift || p == CarryPhase::kPutDown; }

}  // namespace

const char* CarryFailureName(CarryFailure f) {
  switch (f) {
    case CarryFailure::kNone:
      return "none";
    case CarryFailure::kFall:
      return "fall";
    case CarryFailure::kKick:
      return "kicked the box";
    case CarryFailure::kDrop:
      return "dropped the box";
    case CarryFailure::kLost:
      return "lost the box";
    case CarryFailure::kStalled:
      return "stalled (training: approach over 20 s or carry over 15 s)";
    case CarryFailure::kNotLifted:
      return "not lifted (the lift ended without the box held up)";
    case CarryFailure::kNotPlaced:
      return "not put down (the put-down ended without the box at the destination)";
    case CarryFailure::kNonFinite:
      return "non-finite state";
  }
  return "?";
}

const char* CarryStageTask(CarryStage stage) {
  switch (stage) {
    case CarryStage::kLift:
      return "carry-lift";
    case CarryStage::kDeliver:
      return "carry-deliver";
    case CarryStage::kAll:
      break;
  }
  return "carry";
}

bool Delivered(const mjData* d, const control::CarryIndex& ix, const control::CarryBox& box,
               const Eigen::Vector2d& dest_xy) {
  return control::BoxLowestZ(box) < 0.03 && box.linvel.norm() < 0.1 &&
         (box.pos.head<2>() - dest_xy).norm() < kSuccessRadius &&
         d->xpos[3 * ix.walk.agent.pelvis_body + 2] > 0.8;
}

bool LiftHandedOver(const mjData* d, const control::CarryIndex& ix, const control::CarryBox& box) {
  const world::AgentIndex& a = ix.walk.agent;
  bool left, right;
  control::HandBoxContacts(d, ix, box, &left, &right);
  // a cube: its most upright axis within 30 degrees of vertical
  const double up = box.rot.row(2).cwiseAbs().maxCoeff();
  return control::BoxLowestZ(box) > 0.3 && up > std::cos(30 * kDeg) && left && right &&
         d->xpos[3 * a.pelvis_body + 2] > 0.8 &&
         d->xmat[9 * a.torso_body + 8] > std::cos(30 * kDeg);
}

core::StatusOr<std::unique_ptr<CarryTask>> CarryTask::Create(int num_envs, std::string_view gait,
                                                             bool grip, CarryStage stage) {
  if (num_envs <= 0) return absl::InvalidArgumentError("carry task: --envs must be positive");
  std::unique_ptr<CarryTask> t(new CarryTask());
  t->stage_ = stage;
  SH_ASSIGN_OR_RETURN(t->params_.walk, control::WalkGait(gait));
  world::ObjectSpec box;
  box.id = "box000";
  box.type = "box";
  box.pos = Eigen::Vector3d(0, 0, 0);
  box.size = {{"depth", kBuiltBoxSide}, {"width", kBuiltBoxSide}, {"height", kBuiltBoxSide}};
  box.mass_kg = 5.0;
  SH_ASSIGN_OR_RETURN(core::CatalogObject obj, world::BuildObject(box));
  core::SceneCatalog scene;
  scene.objects.push_back(obj);
  world::ModelOptions opt;
  opt.timestep_s = control::kWalkPhysicsDt;
  world::AgentSpec agent;
  if (grip) agent.kind = "humanoid_grip";
  SH_ASSIGN_OR_RETURN(t->world_, world::SimWorld::Create(scene, {agent}, opt));
  SH_ASSIGN_OR_RETURN(t->ix_, control::MakeCarryIndex(*t->world_, 0));
  mjModel* m = t->world_->mutable_model();
  m->nconmax = 96;
  m->njmax = 600;
  m->nstack = 200000;
  t->box_body_ = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName("box000").c_str());
  t->box_geom_ = mj_name2id(m, mjOBJ_GEOM, "obj/box000/0");
  if (t->box_body_ < 0 || t->box_geom_ < 0 || m->body_jntnum[t->box_body_] != 1 ||
      m->geom_type[t->box_geom_] != mjGEOM_BOX) {
    return absl::InternalError("carry task: the box is not a free body with one box geom");
  }
  t->box_qpos_ = m->jnt_qposadr[m->body_jntadr[t->box_body_]];
  if (m->geom_condim[t->box_geom_] != 4) {
    return absl::InternalError("carry task: the box has no torsional friction (condim 4)");
  }
  const world::AgentIndex& a = t->ix_.walk.agent;
  t->allowed_floor_.assign(m->nbody, 0);
  for (int b : {a.left_foot_body, a.right_foot_body, m->geom_bodyid[t->ix_.left_hand_geom],
                m->geom_bodyid[t->ix_.right_hand_geom], t->box_body_}) {
    t->allowed_floor_[b] = 1;
  }
  t->envs_.resize(num_envs);
  for (Env& e : t->envs_) {
    e.m = mj_copyModel(nullptr, m);
    e.d = mj_makeData(e.m);
    e.scratch = mj_makeData(e.m);
  }
  return t;
}

void CarryTask::set_held_start_fraction(double f) {
  SH_CHECK(f >= 0 && f <= 1, "the held-start fraction lies in [0, 1]");
  held_start_fraction_ = f;
}

void CarryTask::set_put_down_start_fraction(double f) {
  SH_CHECK(f >= 0 && f <= 1, "the put-down-start fraction lies in [0, 1]");
  put_down_start_fraction_ = f;
}

CarryTask::~CarryTask() {
  for (Env& e : envs_) {
    if (e.scratch) mj_deleteData(e.scratch);
    if (e.d) mj_deleteData(e.d);
    if (e.m) mj_deleteModel(e.m);
  }
}

void CarryTask::ShapeBox(Env& e, double side_m, double mass_kg) const {
  mjModel* m = e.m;
  const double h = 0.5 * side_m;
  // every geom of the box body (its face slabs and core tile the built cube) scales with it: a
  // box drawn and observed small must not keep the built cube's slabs around it
  const mjModel* built = world_->model();
  const double s = side_m / kBuiltBoxSide;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] != box_body_) continue;
    for (int k = 0; k < 3; ++k) {
      m->geom_size[3 * g + k] = s * built->geom_size[3 * g + k];
      m->geom_pos[3 * g + k] = s * built->geom_pos[3 * g + k];
    }
    m->geom_rbound[g] = s * built->geom_rbound[g];
  }
  for (int k = 0; k < 3; ++k) m->geom_size[3 * box_geom_ + k] = h;
  m->geom_pos[3 * box_geom_ + 2] = h;  // the body origin is on the floor under the centre
  m->geom_rbound[box_geom_] = std::sqrt(3.0) * h;
  m->body_ipos[3 * box_body_ + 2] = h;
  m->body_mass[box_body_] = mass_kg;
  const double inertia = mass_kg * side_m * side_m / 6.0;
  for (int k = 0; k < 3; ++k) m->body_inertia[3 * box_body_ + k] = inertia;
}

void CarryTask::SetBox(int i, double side_m, double mass_kg, const Eigen::Vector3d& pos,
                       double yaw_rad, const Eigen::Vector2d& dest_xy, float* obs) {
  Env& e = envs_[i];
  ShapeBox(e, side_m, mass_kg);
  mjData* d = e.d;
  d->qpos[box_qpos_ + 0] = pos.x();
  d->qpos[box_qpos_ + 1] = pos.y();
  d->qpos[box_qpos_ + 2] = pos.z();
  d->qpos[box_qpos_ + 3] = std::cos(yaw_rad / 2);
  d->qpos[box_qpos_ + 4] = d->qpos[box_qpos_ + 5] = 0;
  d->qpos[box_qpos_ + 6] = std::sin(yaw_rad / 2);
  const int dof = e.m->jnt_dofadr[e.m->body_jntadr[box_body_]];
  for (int k = 0; k < 6; ++k) d->qvel[dof + k] = 0;
  mj_forward(e.m, d);
  control::CarryBox box = control::ReadCarryBox(e.m, d, box_geom_);
  e.s = control::CarryState();
  e.s.walk.phase = e.rng.Uniform();
  control::BeginCarry(params_, ix_, d, box, dest_xy, &e.s);
  control::UpdateWalkCommand(params_.walk, d, ix_.walk, &e.s.walk);
  e.steps = e.done_hold = 0;
  e.success = false;
  e.failure = CarryFailure::kNone;
  control::CarryObservation(d, ix_, e.s, box, obs);
}

void CarryTask::StartLiftNow(int i, float* obs, double pose_at_s) {
  Env& e = envs_[i];
  control::CarryBox box = control::ReadCarryBox(e.m, e.d, box_geom_);
  control::StartLift(params_, e.m, e.scratch, e.d, ix_, box, &e.s);
  if (pose_at_s >= 0) control::PoseInLift(e.m, e.d, ix_, pose_at_s, &e.s);
  control::UpdateWalkCommand(params_.walk, e.d, ix_.walk, &e.s.walk);
  control::CarryObservation(e.d, ix_, e.s, box, obs);
}

void CarryTask::StartHoldingNow(int i, float* obs) { StartHeld(i, -1, obs); }

void CarryTask::StartPutDownNow(int i, double t_s, float* obs) {
  StartHeld(i, std::max(t_s, 0.0), obs);
}

void CarryTask::StartHeld(int i, double put_down_at_s, float* obs) {
  Env& e = envs_[i];
  mjData* d = e.d;
  const world::AgentIndex& a = ix_.walk.agent;
  control::CarryBox box = control::ReadCarryBox(e.m, d, box_geom_);
  control::StartLift(params_, e.m, e.scratch, d, ix_, box, &e.s);
  e.s.phase_time_s = control::kLiftSeconds - 1e-6;
  // posed with the hands touching the held faces (the keyframe's press would start the
  // episode with the hands inside the box); the grip servo presses from there
  control::CarryParams touch = params_;
  touch.squeeze_m = 0;
  const control::CarryPoses touch_poses = control::SolveCarryPoses(
      touch, e.m, e.scratch, ix_, control::MakeLiftGeometry(touch, d, ix_, e.s, box));
  if (put_down_at_s >= 0) {
    control::StartPutDown(params_, d, ix_, &e.s);
    control::PoseInPutDown(e.m, d, ix_, put_down_at_s, touch_poses, &e.s);
  } else {
    double ref[kWalkActDim];
    control::CarryReference(e.s, ref);
    static const std::array<std::array<int, 4>, 2> kArms = *control::ArmJointIndices();
    for (const auto& arm : kArms) {
      for (int j : arm) ref[j] = touch_poses.hold[j];
    }
    Eigen::Vector3d pelvis;
    double yaw;
    control::PelvisPose(d, ix_.walk, &pelvis, &yaw);
    d->qpos[a.root_qpos + 3] = std::cos(yaw / 2);
    d->qpos[a.root_qpos + 4] = d->qpos[a.root_qpos + 5] = 0;
    d->qpos[a.root_qpos + 6] = std::sin(yaw / 2);
    for (int j = 0; j < kWalkActDim; ++j) {
      d->qpos[a.hinge_qpos[j]] = ref[j];
      d->ctrl[a.actuator[j]] = ref[j];
    }
    mju_zero(d->qvel, e.m->nv);
    mj_kinematics(e.m, d);
    d->qpos[a.root_qpos + 2] -=
        LowestBoxCornerZ(e.m, d, {ix_.walk.left_foot_geom, ix_.walk.right_foot_geom}) - 0.001;
    mj_kinematics(e.m, d);
  }
  // the box: its held points' middle between the hands, its held faces squeezed by squeeze_m
  const Eigen::Vector3d hl(d->site_xpos + 3 * ix_.left_hand_site);
  const Eigen::Vector3d hr(d->site_xpos + 3 * ix_.right_hand_site);
  Eigen::Vector3d local_mid = e.s.held_left_local;
  local_mid[e.s.held_axis] = 0;
  Eigen::Vector3d centre = 0.5 * (hl + hr) - box.rot * local_mid;
  // (low in the put-down squat, the box rests on the floor instead)
  centre.z() = std::max(centre.z(), box.pos.z() - control::BoxLowestZ(box) + 0.001);
  // the free joint moves the body, whose origin need not be the box geom's centre
  const Eigen::Vector3d body_off = Eigen::Vector3d(d->xpos + 3 * box_body_) - box.pos;
  for (int k = 0; k < 3; ++k) d->qpos[box_qpos_ + k] = centre[k] + body_off[k];
  mj_forward(e.m, d);
  box = control::ReadCarryBox(e.m, d, box_geom_);
  if (put_down_at_s >= 0) e.s.dest_xy = box.pos.head<2>();
  control::UpdateWalkCommand(e.s.gait, d, ix_.walk, &e.s.walk);
  control::CarryObservation(d, ix_, e.s, box, obs);
}

void CarryTask::Reset(int i, uint64_t seed, float* obs) {
  Env& e = envs_[i];
  e.rng = core::Rng(seed);
  mjData* d = e.d;
  mj_resetData(e.m, d);
  const world::AgentIndex& a = ix_.walk.agent;
  const double c = std::clamp(curriculum_, 0.0, 1.0);
  // the box: a cube, side and mass growing with the curriculum
  const double side = e.rng.Uniform(0.4 - 0.15 * c, 0.6 + 0.15 * c);
  const double mass = e.rng.Uniform(2.0, 5.0 + 8.0 * c);
  const double box_yaw = e.rng.Uniform(-M_PI, M_PI);
  // a fraction of the training episodes start holding the box (the carry phase's
  // reference-state initialisation); of the others half start at the box, ready to lift (the
  // lift is practised from the first iteration, not only after a walk), the rest 1-2 m (up to
  // 5 m) away, facing the box within +-(30 + 150 c) degrees. Evaluation draws neither number
  // and a zero fraction draws none, so those episodes are as they were before held starts.
  // A share start inside the put-down, drawn first (a zero share draws nothing).
  // The stages start at the box, lifting or holding it, and draw no start-type number.
  const bool staged = stage_ != CarryStage::kAll;
  const bool put_down = !staged && !evaluation_ && put_down_start_fraction_ > 0 &&
                        e.rng.Uniform() < put_down_start_fraction_;
  const bool held = stage_ == CarryStage::kDeliver ||
                    (!staged && !put_down && !evaluation_ && held_start_fraction_ > 0 &&
                     e.rng.Uniform() < held_start_fraction_);
  const bool at_box =
      staged || put_down || held || (!evaluation_ && e.rng.Uniform() < kStartAtBoxFraction);
  Eigen::Vector2d start;
  double yaw;
  if (at_box) {
    const int face = static_cast<int>(e.rng.Uniform(0.0, 3.999));
    const double dir = box_yaw + face * M_PI / 2;
    start =
        (0.5 * side + params_.stand_gap_m + 0.05) * Eigen::Vector2d(std::cos(dir), std::sin(dir));
    yaw = dir + M_PI + e.rng.Uniform(-0.1, 0.1);
  } else {
    const double dist = e.rng.Uniform(1.0, 2.0 + 3.0 * c);
    const double bearing = e.rng.Uniform(-M_PI, M_PI);
    start = dist * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
    const double face = std::atan2(-start.y(), -start.x());
    yaw = face + e.rng.Uniform(-1.0, 1.0) * (30.0 + 150.0 * c) * kDeg;
  }
  d->qpos[a.root_qpos + 0] = start.x();
  d->qpos[a.root_qpos + 1] = start.y();
  d->qpos[a.root_qpos + 3] = std::cos(yaw / 2);
  d->qpos[a.root_qpos + 4] = d->qpos[a.root_qpos + 5] = 0;
  d->qpos[a.root_qpos + 6] = std::sin(yaw / 2);
  const auto& nominal = control::WalkNominalPose();
  for (int j = 0; j < kWalkActDim; ++j) {
    double q =
        std::clamp(nominal[j] + e.rng.Normal(0.03), ix_.walk.ctrl_lo[j], ix_.walk.ctrl_hi[j]);
    d->qpos[a.hinge_qpos[j]] = q;
    d->ctrl[a.actuator[j]] = q;
  }
  mj_forward(e.m, d);
  const double lowest =
      LowestBoxCornerZ(e.m, d, {ix_.walk.left_foot_geom, ix_.walk.right_foot_geom});
  d->qpos[a.root_qpos + 2] -= lowest - 0.001;
  const double dest_dist = e.rng.Uniform(1.0, 3.0 + 7.0 * c);
  const double dest_dir = e.rng.Uniform(-M_PI, M_PI);
  SetBox(i, side, mass, Eigen::Vector3d(0, 0, 0), box_yaw,
         dest_dist * Eigen::Vector2d(std::cos(dest_dir), std::sin(dest_dir)), obs);
  if (put_down) {
    StartPutDownNow(i, e.rng.Uniform(0.0, control::PutDownLowerEndSeconds()), obs);
  } else if (held) {
    StartHoldingNow(i, obs);
  } else if (at_box) {
    // and some of them part-way down into the squat (reference-state initialisation)
    const double pose_at = e.rng.Uniform() < kStartInSquatFraction
                               ? e.rng.Uniform(0.0, control::LiftRiseStartSeconds())
                               : -1.0;
    StartLiftNow(i, obs, pose_at);
  }
}

CarryFailure CarryTask::Check(const Env& e, const control::CarryBox& box) const {
  const mjData* d = e.d;
  const world::AgentIndex& a = ix_.walk.agent;
  const CarryPhase ph = e.s.phase;
  const bool squat = Squatting(ph);
  if (d->xpos[3 * a.pelvis_body + 2] < (squat ? 0.3 : 0.55) ||
      d->xpos[3 * a.head_body + 2] < (squat ? 0.45 : 0.8)) {
    return CarryFailure::kFall;
  }
  // a lifting squat bends the trunk to horizontal; walking keeps it within 70 degrees
  if (!squat && d->xmat[9 * a.torso_body + 8] < std::cos(70 * kDeg)) return CarryFailure::kFall;
  for (int c = 0; c < d->ncon; ++c) {
    int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
    int floor = ix_.walk.floor_geom;
    int other = g1 == floor ? g2 : (g2 == floor ? g1 : -1);
    if (other >= 0 && !allowed_floor_[e.m->geom_bodyid[other]]) return CarryFailure::kFall;
  }
  const double low = control::BoxLowestZ(box);
  const double speed = std::hypot(box.linvel.x(), box.linvel.y());
  if (!control::CarryHandsOnBox(e.s) && low < 0.3 && speed > 1.0) return CarryFailure::kKick;
  if (ph == CarryPhase::kCarry && e.s.phase_time_s > 1.0 && low < 0.03) return CarryFailure::kDrop;
  // training only: evaluation walks and carries up to 20 m, within its own time limit
  if (!evaluation_ && ((ph == CarryPhase::kApproach && e.s.phase_time_s > kMaxApproachSeconds) ||
                       (ph == CarryPhase::kCarry &&
                        e.s.phase_time_s > (stage_ == CarryStage::kDeliver ? kMaxDeliverCarrySeconds
                                                                           : kMaxCarrySeconds)))) {
    return CarryFailure::kStalled;
  }
  Eigen::Vector3d pelvis = Vec(d->xpos + 3 * a.pelvis_body);
  if (ph == CarryPhase::kCarry && (box.pos - pelvis).head<2>().norm() > 1.2) {
    return CarryFailure::kLost;
  }
  return CarryFailure::kNone;
}

double CarryTask::Reward(Env& e, const control::CarryBox& box, const float* action, double power) {
  const mjData* d = e.d;
  const world::AgentIndex& a = ix_.walk.agent;
  const control::CarryState& s = e.s;
  CarryRewardTerms& t = e.terms;
  Eigen::Vector3d pos;
  double yaw;
  control::PelvisPose(d, ix_.walk, &pos, &yaw);
  const mjtNum* v = d->qvel + a.root_qvel;
  const double c = std::cos(yaw), sn = std::sin(yaw);
  const double vx = c * v[0] + sn * v[1], vy = -sn * v[0] + c * v[1];
  const control::WalkCommand& cmd = s.walk.cmd;
  // walking: velocity tracking, progress, facing
  double vel = std::exp(-((vx - cmd.vx) * (vx - cmd.vx) + (vy - cmd.vy) * (vy - cmd.vy)) / 0.25);
  double cmd_speed = std::hypot(cmd.vx, cmd.vy);
  double prog =
      cmd_speed > 0.05 ? std::clamp((vx * cmd.vx + vy * cmd.vy) / cmd_speed, -0.5, cmd_speed) : 0.0;
  double facing = 0.5 * (1.0 + std::cos(s.walk.facing_rad - yaw));
  t.walk = vel + 1.5 * prog + 0.5 * facing;
  // the whole-body reference of the phase
  double ref[kWalkActDim];
  control::CarryReference(s, ref);
  double err = 0;
  for (int j = 0; j < kWalkActDim; ++j) {
    double dq = d->qpos[a.hinge_qpos[j]] - ref[j];
    err += dq * dq;
  }
  t.pose = std::exp(-err / 1.0);
  t.posture = Squatting(s.phase) ? 1.0 : std::exp(-(1.0 - d->xmat[9 * a.torso_body + 8]) / 0.0603);
  // hands at the held points while they should hold
  t.hands = 0;
  if (control::CarryHandsOnBox(s)) {
    Eigen::Vector3d hl, hr;
    control::CarryHeldPoints(s, box, &hl, &hr);
    const double r = e.m->geom_size[3 * ix_.left_hand_geom];
    double dl = std::max(0.0, (Vec(d->site_xpos + 3 * ix_.left_hand_site) - hl).norm() - r);
    double dr = std::max(0.0, (Vec(d->site_xpos + 3 * ix_.right_hand_site) - hr).norm() - r);
    bool lc, rc;
    control::HandBoxContacts(d, ix_, box, &lc, &rc);
    t.hands = std::exp(-20.0 * (dl * dl + dr * dr)) + 0.25 * (lc + rc);
  }
  const double low = control::BoxLowestZ(box);
  const double to_dest = (s.dest_xy - box.pos.head<2>()).norm();
  t.lifted = s.phase == CarryPhase::kCarry || (s.phase == CarryPhase::kLift && s.phase_time_s > 2.2)
                 ? std::clamp(low / 0.15, 0.0, 1.0)
                 : 0.0;
  t.to_dest = s.phase == CarryPhase::kCarry || s.phase == CarryPhase::kPutDown
                  ? std::exp(-0.5 * to_dest * to_dest) + std::exp(-10.0 * to_dest * to_dest)
                  : 0.0;
  t.placed = s.phase == CarryPhase::kRetreat || (s.phase == CarryPhase::kPutDown && low < 0.02)
                 ? 2.0 * std::exp(-10.0 * to_dest * to_dest) * (low < 0.02 ? 1.0 : 0.0)
                 : 0.0;
  double rate = 0;
  for (int j = 0; j < kWalkActDim; ++j) {
    double ac = std::clamp(static_cast<double>(action[j]), -control::kWalkActionClip,
                           control::kWalkActionClip);
    double dd = ac - s.walk.prev_action[j];
    rate += dd * dd;
    e.s.walk.prev_action[j] = static_cast<float>(ac);
  }
  t.action_rate = rate / kWalkActDim;
  t.power = power;
  t.total = 0.1 * (t.walk + 1.5 * t.pose + 0.5 * t.posture + t.hands + t.lifted + t.to_dest +
                   t.placed + 0.5 - 0.02 * t.action_rate - 2e-5 * t.power);
  return t.total;
}

void CarryTask::Step(int i, const float* action, float* obs, StepInfo* info) {
  Env& e = envs_[i];
  mjData* d = e.d;
  const world::AgentIndex& a = ix_.walk.agent;
  double ctrl[kWalkActDim];
  control::CarryTargets(ix_, e.s, action, ctrl);
  control::SetCarryGrip(ix_, e.s, d);
  double power = 0;
  const bool support = squat_support_ && Squatting(e.s.phase);
  for (int k = 0; k < control::kWalkSubsteps; ++k) {
    for (int j = 0; j < kWalkActDim; ++j) d->ctrl[a.actuator[j]] = ctrl[j];
    if (support) {
      double tau[kWalkActDim], held[kWalkActDim];
      control::StaticSupportTorques(e.m, d, ix_, tau);
      std::copy(ctrl, ctrl + kWalkActDim, held);
      control::AddSupportToTargets(e.m, ix_, tau, held);
      control::BalanceAnkles(e.m, d, ix_, kSupportBalanceGain, kSupportBalanceDampingS, held);
      for (int j = 0; j < kWalkActDim; ++j) d->ctrl[a.actuator[j]] = held[j];
    }
    mj_step(e.m, d);
    for (int j = 0; j < kWalkActDim; ++j) {
      power += std::abs(d->actuator_force[a.actuator[j]] * d->qvel[a.hinge_qvel[j]]);
    }
  }
  power /= control::kWalkSubsteps;
  ++e.steps;
  if (!world::AllFinite(d->qpos, e.m->nq) || !world::AllFinite(d->qvel, e.m->nv)) {
    std::fill(obs, obs + control::kCarryObsDim, 0.f);
    e.failure = CarryFailure::kNonFinite;
    *info = StepInfo{0.f, true, false, e.success};
    return;
  }
  control::CarryBox box = control::ReadCarryBox(e.m, d, box_geom_);
  double reward = Reward(e, box, action, power);
  e.failure = Check(e, box);
  const CarryPhase phase_before = e.s.phase;
  // success: after the put-down, the box at rest on the floor at the destination
  const double to_dest = (e.s.dest_xy - box.pos.head<2>()).norm();
  const bool placed = e.s.phase == CarryPhase::kRetreat && to_dest < kSuccessRadius &&
                      control::BoxLowestZ(box) < 0.02 && box.linvel.norm() < 0.1;
  e.done_hold = placed ? e.done_hold + 1 : 0;
  if (e.done_hold >= kSuccessHold) e.success = true;
  control::UpdateCarry(params_, e.m, e.scratch, d, ix_, box, &e.s);
  control::CarryObservation(d, ix_, e.s, box, obs);
  // a stage ends with its last phase: the lift handed over held or not lifted, the box put down
  // at the destination or not
  const CarryPhase last = stage_ == CarryStage::kLift ? CarryPhase::kLift : CarryPhase::kPutDown;
  const bool stage_ended = stage_ != CarryStage::kAll && phase_before == last && e.s.phase != last;
  if (stage_ended && e.failure == CarryFailure::kNone) {
    const bool ok = stage_ == CarryStage::kLift ? LiftHandedOver(d, ix_, box)
                                                : Delivered(d, ix_, box, e.s.dest_xy);
    if (ok) {
      e.success = true;
      reward += kStageSuccessBonus;
    } else {
      e.failure = stage_ == CarryStage::kLift ? CarryFailure::kNotLifted : CarryFailure::kNotPlaced;
    }
  }
  info->reward = static_cast<float>(reward);
  info->terminated = e.failure != CarryFailure::kNone;
  info->truncated = e.steps >= max_steps_ || e.done_hold >= 2 * kSuccessHold || stage_ended;
  info->success = e.success;
}

}  // namespace simhuman::learn
