#include "simhuman/control/mpc/mpc_controller.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>

#include "simhuman/control/arm_servo.h"
#include "simhuman/control/mpc/getting_up.h"
#include "simhuman/control/rollout.h"
#include "simhuman/core/rng.h"

namespace simhuman::control {
namespace {

constexpr int kDofs = world::kHumanoidDofs;
constexpr double kRefTableDt = 0.02;
// how long past its reference a sit-up may take before the rise starts anyway (s)
constexpr double kSitUpGraceS = 3.0;

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// importance of each body point in reference tracking
constexpr std::array<double, core::kNumBodyJoints> kTrackWeight = {
    2.0,            // pelvis
    1.5,            // torso
    1.5,            // head
    0.4, 0.4, 0.4,  // left shoulder, elbow, hand
    0.4, 0.4, 0.4,  // right shoulder, elbow, hand
    0.6, 1.0, 1.0,  // left hip, knee, foot
    0.6, 1.0, 1.0,  // right hip, knee, foot
};

bool IsHand(core::BodyJoint j) {
  return j == core::BodyJoint::kLeftHand || j == core::BodyJoint::kRightHand;
}

}  // namespace

absl::StatusOr<std::unique_ptr<MpcController>> MpcController::Create(const world::SimWorld* world,
                                                                     int agent,
                                                                     const MpcConfig& config,
                                                                     uint64_t seed) {
  SH_RETURN_IF_ERROR(config.Validate());
  if (agent < 0 || agent >= world->num_agents()) {
    return absl::InvalidArgumentError("agent index " + std::to_string(agent) + " out of range");
  }
  std::unique_ptr<MpcController> c(new MpcController());
  c->world_ = world;
  c->agent_ = agent;
  c->config_ = config;
  c->seed_ = seed;
  c->plan_model_ = mj_copyModel(nullptr, world->model());
  c->plan_model_->opt.timestep = config.plan_dt_s;
  for (int t = 0; t < config.threads; ++t) c->thread_data_.push_back(mj_makeData(c->plan_model_));
  c->scratch_ = mj_makeData(world->model());
  const mjModel* m = world->model();
  const world::AgentIndex& a = world->agent(agent);
  const auto& names = world::HumanoidJointNames();
  for (int j = 0; j < kDofs; ++j) {
    c->lo_[j] = m->actuator_ctrlrange[2 * a.actuator[j]];
    c->hi_[j] = m->actuator_ctrlrange[2 * a.actuator[j] + 1];
    bool arm = names[j].find("shoulder") != std::string::npos ||
               names[j].find("elbow") != std::string::npos;
    bool neck = names[j].find("neck") != std::string::npos;
    c->noise_scale_[j] = arm ? 1.5 : (neck ? 0.5 : 1.0);
  }
  SH_ASSIGN_OR_RETURN(c->arm_dofs_, ArmJointIndices());
  return c;
}

MpcController::~MpcController() {
  for (mjData* d : thread_data_) mj_deleteData(d);
  if (scratch_) mj_deleteData(scratch_);
  if (plan_model_) mj_deleteModel(plan_model_);
}

void MpcController::Interp(const Knots& knots, double t0, double span, double t, double* out) {
  const int k = static_cast<int>(knots.size());
  double u = std::clamp((t - t0) / span, 0.0, 1.0) * (k - 1);
  int i = std::min(static_cast<int>(u), k - 2);
  double f = u - i;
  for (int j = 0; j < kDofs; ++j) out[j] = (1 - f) * knots[i][j] + f * knots[i + 1][j];
}

ReferencePose MpcController::RefPose(double t) const {
  // piecewise smoothstep between keyframes
  double u = t - ramp_t0_;
  size_t seg = 0;
  while (seg + 1 < key_s_.size() && u > key_s_[seg + 1]) ++seg;
  if (keys_.size() == 1 || seg + 1 >= keys_.size()) return keys_.back();
  double len = key_s_[seg + 1] - key_s_[seg];
  double f = Smoothstep(len > 0 ? (u - key_s_[seg]) / len : 1.0);
  const ReferencePose& a = keys_[seg];
  const ReferencePose& b = keys_[seg + 1];
  ReferencePose p;
  for (int k = 0; k < 3; ++k) p.root[k] = a.root[k] + f * (b.root[k] - a.root[k]);
  Eigen::Quaterniond qa(a.root[3], a.root[4], a.root[5], a.root[6]);
  Eigen::Quaterniond qb(b.root[3], b.root[4], b.root[5], b.root[6]);
  Eigen::Quaterniond q = qa.slerp(f, qb);
  p.root[3] = q.w();
  p.root[4] = q.x();
  p.root[5] = q.y();
  p.root[6] = q.z();
  for (int j = 0; j < kDofs; ++j) p.hinges[j] = a.hinges[j] + f * (b.hinges[j] - a.hinges[j]);
  return p;
}

std::array<double, kDofs> MpcController::RefHinges(double t) const { return RefPose(t).hinges; }

void MpcController::RefPoints(double t,
                              std::array<Eigen::Vector3d, core::kNumBodyJoints>* pts) const {
  int n = static_cast<int>(ref_table_.size());
  if (n == 1) {
    *pts = ref_table_[0];
    return;
  }
  double u = std::clamp((t - ramp_t0_) / kRefTableDt, 0.0, static_cast<double>(n - 1));
  int i = std::min(static_cast<int>(u), n - 2);
  double f = u - i;
  for (int b = 0; b < core::kNumBodyJoints; ++b) {
    (*pts)[b] = (1 - f) * ref_table_[i][b] + f * ref_table_[i + 1][b];
  }
}

double MpcController::SegmentSeconds(const ReferencePose& a, const ReferencePose& b) const {
  double dq = 0;
  for (int j = 0; j < kDofs; ++j) dq = std::max(dq, std::abs(b.hinges[j] - a.hinges[j]));
  double dx = std::hypot(b.root[0] - a.root[0], b.root[1] - a.root[1]);
  double dz = std::abs(b.root[2] - a.root[2]);
  return std::clamp(std::max({dq / config_.ramp_speed_rad_s, dx / 0.35, dz / 0.4}),
                    config_.min_ramp_s, config_.max_ramp_s);
}

void MpcController::SetReference(double now, const std::vector<ReferencePose>& keys,
                                 const mjData* d) {
  const world::AgentIndex& a = world_->agent(agent_);
  reference_changed_ = true;
  keys_ = keys;
  key_s_.assign(1, 0.0);
  for (size_t i = 1; i < keys_.size(); ++i) {
    key_s_.push_back(key_s_.back() + SegmentSeconds(keys_[i - 1], keys_[i]));
  }
  ramp_s_ = std::max(key_s_.back(), 1e-3);
  ramp_t0_ = now;
  goal_ = keys_.back();
  // reference body points along the ramp
  ref_table_.clear();
  mj_copyData(scratch_, world_->model(), d);
  int n = static_cast<int>(std::ceil(ramp_s_ / kRefTableDt)) + 1;
  for (int i = 0; i < n; ++i) {
    SetAgentPose(a, RefPose(now + i * kRefTableDt), scratch_);
    mj_kinematics(world_->model(), scratch_);
    ref_table_.push_back(world_->BodyPoints(scratch_, agent_));
  }
}

void MpcController::StartStep(const Observation& obs, const StepTask& step_task) {
  const world::AgentIndex& a = world_->agent(agent_);
  // getting up while lying on a bed sits up on its front edge first (getting_up.h); Act()
  // starts the rise from there
  StepTask task = step_task;
  std::vector<ReferencePose> sit_up;
  get_up_.reset();
  if (!LegsHangDown(obs.body_points, a.scale) || TrunkTiltedMoreThan(obs.body_points, 60.0) ||
      sit_up_again_) {
    if (std::optional<StepTask> sit = EdgeSitBeforeRising(step_task, a.scale)) {
      get_up_ = step_task;
      task = *sit;
      sit_up = SitUpKeys(*world_, agent_, obs.data, scratch_);
    }
  }
  task_ = task;
  step_index_ = obs.step_index;
  next_aim_s_ = 0;
  progress_floor_ = 0;
  ReferencePose start = GetAgentPose(a, obs.data);
  ReferencePose goal = SolveReferencePose(*world_, agent_, task_, obs.data, scratch_);
  if (get_up_)
    SitWhereLying(task_, obs.body_points[static_cast<int>(core::BodyJoint::kPelvis)], &goal);
  std::vector<ReferencePose> keys = {start};
  keys.insert(keys.end(), sit_up.begin(), sit_up.end());
  bool rising = false;
  // getting up from a seat goes through a lean-forward pose with the weight over the feet
  bool seated =
      world::PelvisLowAsSeated(obs.data->qpos[a.root_qpos + 2], a.scale) || rise_from_seat_;
  rise_from_seat_ = false;
  sit_up_again_ = false;
  bool to_stand = task_.posture == Posture::kStand || task_.posture == Posture::kLean;
  if (seated && to_stand) {
    // lean forward while seated, then lift off over the feet, then extend
    ReferencePoseOptions rise;
    rise.rise = 1;
    keys.push_back(SolveReferencePose(*world_, agent_, task_, obs.data, scratch_, rise));
    rise.rise = 2;
    rise.w_balance = 30.0;  // the seat-off pose must have the weight over the feet
    keys.push_back(SolveReferencePose(*world_, agent_, task_, obs.data, scratch_, rise));
    rising = true;
  }
  // lying down from standing sits on the edge first (as a person does), instead of toppling
  // backwards onto the mattress
  bool to_lie = task_.posture == Posture::kLieBack || task_.posture == Posture::kLieSide;
  if (!seated && to_lie) {
    StepTask sit = task_;
    sit.posture = Posture::kSit;
    sit.terms.erase(
        std::remove_if(sit.terms.begin(), sit.terms.end(),
                       [](const ContactTerm& t) { return t.joint != core::BodyJoint::kPelvis; }),
        sit.terms.end());
    keys.push_back(SolveReferencePose(*world_, agent_, sit, obs.data, scratch_));
  }
  keys.push_back(goal);
  SetReference(obs.time_s, keys, obs.data);
  // when getting up, standing balance takes over once the reference lifts off the seat
  stand_balance_from_s_ = rising ? key_s_[2] : 1e9;
  // seat height gates the balance term while sitting down
  seat_top_z_ = -1;
  for (const ContactTerm& t : task_.terms) {
    if (t.joint == core::BodyJoint::kPelvis && t.part && t.type == plan::ContactType::kContact) {
      auto [lo, hi] = core::ShapesBounds(t.part->shapes);
      seat_top_z_ = t.object->pose.pos.z() + hi.z();
    }
  }
  // the nominal starts at the reference
  nominal_.assign(config_.knots, {});
  nominal_t0_ = obs.time_s;
  double span = config_.horizon_s;
  for (int k = 0; k < config_.knots; ++k) {
    nominal_[k] = RefHinges(obs.time_s + span * k / (config_.knots - 1));
  }
}

double MpcController::Rollout(int thread, const Knots& knots, double t0,
                              const mjData* start) const {
  const mjModel* m = plan_model_;
  mjData* d = thread_data_[thread];
  const world::AgentIndex& a = world_->agent(agent_);
  CopyRolloutStart(m, start, d);

  const int steps =
      std::max(1, static_cast<int>(std::lround(config_.horizon_s / config_.plan_dt_s)));
  const double scale = a.scale;
  const bool standing = task_.posture == Posture::kStand || task_.posture == Posture::kLean;
  const bool sitting = task_.posture == Posture::kSit;
  std::array<double, kDofs> raw, u;
  std::array<Eigen::Vector3d, core::kNumBodyJoints> pts, ref;
  Eigen::Vector3d com_prev = Eigen::Vector3d::Zero();
  // an arm the hand servo holds on its contact is not pulled back to the reference's elbow and
  // hand points (that would undo the servo's offsets); its contact term places the hand
  std::array<double, core::kNumBodyJoints> track_weight = kTrackWeight;
  for (int side = 0; side < 2; ++side) {
    if (!servo_active_[side]) continue;
    track_weight[static_cast<int>(side == 0 ? core::BodyJoint::kRightElbow
                                            : core::BodyJoint::kLeftElbow)] = 0;
    track_weight[static_cast<int>(side == 0 ? core::BodyJoint::kRightHand
                                            : core::BodyJoint::kLeftHand)] = 0;
  }
  double cost = 0;
  for (int h = 0; h < steps; ++h) {
    double t = d->time;
    Interp(knots, t0, config_.horizon_s, t, raw.data());
    WithServo(raw.data(), u.data());
    for (int j = 0; j < kDofs; ++j) d->ctrl[a.actuator[j]] = u[j];
    mj_step(m, d);
    if (!world::AllFinite(d->qpos, m->nq) || !world::AllFinite(d->qvel, m->nv)) {
      return std::numeric_limits<double>::infinity();
    }
    // positions below are those of time t (mj_step computes kinematics before integrating)
    for (int b = 0; b < core::kNumBodyJoints; ++b) {
      const mjtNum* x = d->site_xpos + 3 * a.site[b];
      pts[b] = Eigen::Vector3d(x[0], x[1], x[2]);
    }
    RefPoints(t, &ref);
    double c = 0;
    const double progress = std::max(progress_floor_, Smoothstep((t - ramp_t0_) / ramp_s_));
    // reference tracking
    double track = 0;
    for (int b = 0; b < core::kNumBodyJoints; ++b) {
      track += track_weight[b] * SmoothL1((pts[b] - ref[b]).norm(), 0.05);
    }
    c += config_.w_track * track;
    // contact terms with adaptive weights
    for (size_t k = 0; k < task_.terms.size(); ++k) {
      const ContactTerm& term = task_.terms[k];
      const Eigen::Vector3d& p = pts[static_cast<int>(term.joint)];
      // contacts pull gently early in the reference ramp and fully at its end, so the body
      // follows the reference instead of diving at the target
      double w = config_.w_contact * (0.3 + term_weights_[k]) * (0.25 + 0.75 * progress);
      if (term.type == plan::ContactType::kContact) {
        c += w * SmoothL1((p - term.Touch(p, pts)).norm(), 0.03);
      } else {
        c += w * std::max(0.0, 0.18 * scale - (p - term.Nearest(p, pts)).norm());
      }
    }
    // balance: capture point over the middle of the feet, while standing (or not yet seated)
    const mjtNum* comp = d->subtree_com + 3 * a.pelvis_body;
    Eigen::Vector3d com(comp[0], comp[1], comp[2]);
    const Eigen::Vector3d& pelvis = pts[static_cast<int>(core::BodyJoint::kPelvis)];
    // standing balance while the weight is on the feet; a low pelvis (sitting down, or the
    // start of getting up) keeps the seated form
    bool low = pelvis.z() < 0.62 * scale && t - ramp_t0_ < stand_balance_from_s_;
    bool balance = (standing && !low) || (sitting && pelvis.z() > seat_top_z_ + 0.2 * scale);
    if (h > 0) {
      Eigen::Vector3d v = (com - com_prev) / config_.plan_dt_s;
      Eigen::Vector3d cp = com + v * std::sqrt(std::max(com.z(), 0.1) / 9.81);
      Eigen::Vector3d mid = 0.5 * (pts[static_cast<int>(core::BodyJoint::kLeftFoot)] +
                                   pts[static_cast<int>(core::BodyJoint::kRightFoot)]);
      if (balance) {
        double off = (cp.head<2>() - mid.head<2>()).norm();
        // plus a steep wall near the edge of the support (feet ~0.1 m around their middle)
        double out = std::max(0.0, off - 0.12 * scale);
        c += config_.w_balance * (SmoothL1(off, 0.05) + 200.0 * out * out);
      } else if (sitting || low) {
        // seated: the capture point stays between the seat contact and the feet
        Eigen::Vector2d a2 = pelvis.head<2>(), b2 = mid.head<2>(), p2 = cp.head<2>();
        Eigen::Vector2d ab = b2 - a2;
        double along = std::clamp((p2 - a2).dot(ab) / std::max(ab.squaredNorm(), 1e-9), 0.0, 1.0);
        c += config_.w_balance * SmoothL1((p2 - (a2 + along * ab)).norm(), 0.05);
      }
      c += config_.w_com_velocity * v.squaredNorm();
    }
    com_prev = com;
    // trunk orientation (pelvis to head) as in the reference
    {
      Eigen::Vector3d trunk = pts[static_cast<int>(core::BodyJoint::kHead)] - pelvis;
      Eigen::Vector3d trunk_ref = ref[static_cast<int>(core::BodyJoint::kHead)] -
                                  ref[static_cast<int>(core::BodyJoint::kPelvis)];
      c += config_.w_upright * (1.0 - trunk.normalized().dot(trunk_ref.normalized()));
    }
    // effort, servo targets near the reference, joint speeds
    double effort = 0, dev = 0, vel = 0;
    auto qref = RefHinges(t);
    for (int j = 0; j < kDofs; ++j) {
      double lim = m->actuator_forcerange[2 * a.actuator[j] + 1];
      double f = d->actuator_force[a.actuator[j]] / lim;
      effort += f * f;
      dev += (raw[j] - qref[j]) * (raw[j] - qref[j]);
      double qd = d->qvel[a.hinge_qvel[j]];
      vel += qd * qd;
    }
    c += config_.w_effort * effort + config_.w_ctrl * dev + config_.w_velocity * vel;
    // falling
    double head_z = pts[static_cast<int>(core::BodyJoint::kHead)].z();
    // falling: the head well below where the reference has it
    double safe = ref[static_cast<int>(core::BodyJoint::kHead)].z() - 0.3 * scale;
    if (head_z < safe) c += config_.w_fall * (safe - head_z);
    cost += c * (h == steps - 1 ? 3.0 : 1.0);
  }
  return cost * config_.plan_dt_s;
}

absl::Status MpcController::Act(const Observation& obs) {
  if (!obs.task) return absl::InvalidArgumentError("mpc: observation has no task");
  for (const ContactTerm& t : obs.task->terms) {
    for (core::BodyJoint j : {t.joint, t.target_joint.value_or(t.joint)}) {
      if (static_cast<int>(j) >= core::kNumBodyJoints) {
        return absl::InvalidArgumentError(
            "mpc: body point '" + world_->catalog().agents.at(agent_).body_points.Name(j) +
            "' of human " + std::to_string(agent_) +
            " is not one the MPC drives; it drives the 15 standard body points (" +
            core::JoinNames(core::BodyJointNames()) + ")");
      }
    }
  }
  if (obs.step_index != step_index_) StartStep(obs, *obs.task);
  const world::AgentIndex& a = world_->agent(agent_);
  const double now = obs.time_s;
  // sat up on the bed's edge, the legs down: now rise as from any seat; not there kSitUpGraceS
  // after the reference: sit on the edge again from here
  if (get_up_ && now >= ramp_t0_ + ramp_s_) {
    const bool on_edge =
        !TrunkTiltedMoreThan(obs.body_points, 30.0) && LegsHangDown(obs.body_points, a.scale);
    if (on_edge || now >= ramp_t0_ + ramp_s_ + kSitUpGraceS) {
      const StepTask stand = *get_up_;
      rise_from_seat_ = on_edge;
      sit_up_again_ = !on_edge;
      StartStep(obs, stand);
    }
  }

  // adaptive contact weights (Eq. 9) from the current distances
  std::vector<double> rewards;
  for (const ContactTerm& t : task_.terms) {
    const Eigen::Vector3d& p = obs.body_points[static_cast<int>(t.joint)];
    double dist = (p - t.Nearest(p, obs.body_points)).norm();
    rewards.push_back(t.type == plan::ContactType::kContact ? std::exp(-5.0 * dist)
                                                            : 1.0 - std::exp(-5.0 * dist));
  }
  term_weights_ = plan::AdaptiveWeights(rewards, 1e-3);
  for (double& w : term_weights_) w *= static_cast<double>(term_weights_.size());

  // fall monitor: while standing on its feet, a trunk tilted more than 35 degrees away from
  // the reference's switches to recovery (stand up straight over the feet, quickly); back to
  // the step once within 12 degrees again
  std::array<Eigen::Vector3d, core::kNumBodyJoints> ref_now;
  RefPoints(now, &ref_now);
  const auto& bp = obs.body_points;
  auto trunk = [](core::Span<const Eigen::Vector3d> p) {
    return Eigen::Vector3d(p[static_cast<int>(core::BodyJoint::kHead)] -
                           p[static_cast<int>(core::BodyJoint::kPelvis)])
        .normalized();
  };
  double cos_dev = trunk(bp).dot(recovering_ ? Eigen::Vector3d::UnitZ() : trunk(ref_now));
  bool standing = task_.posture == Posture::kStand || task_.posture == Posture::kLean;
  bool on_feet = bp[static_cast<int>(core::BodyJoint::kPelvis)].z() > 0.62 * a.scale;
  if (standing && on_feet && !recovering_ && cos_dev < std::cos(35.0 * M_PI / 180.0)) {
    recovering_ = true;
    StepTask recover;
    recover.posture = Posture::kStand;
    ReferencePose up = SolveReferencePose(*world_, agent_, recover, obs.data, scratch_);
    SetReference(now, {GetAgentPose(a, obs.data), up}, obs.data);
  } else if (recovering_ && cos_dev > std::cos(12.0 * M_PI / 180.0)) {
    recovering_ = false;
    StartStep(obs, task_);
  }

  if (!recovering_) CorrectAim(obs);
  ServoHands(obs);

  // behind real time (the live server): keep the current plan while it is young enough
  if (obs.behind_real_time && !reference_changed_ && iteration_ > 0 &&
      now - nominal_t0_ + config_.replan_s <= config_.max_replan_s + 1e-9) {
    ++skipped_replans_;
    return absl::OkStatus();
  }
  reference_changed_ = false;

  // shift the nominal to start now
  const int K = config_.knots;
  const double span = config_.horizon_s;
  Knots shifted(K);
  for (int k = 0; k < K; ++k) {
    double t = now + span * k / (K - 1);
    if (t <= nominal_t0_ + span) {
      Interp(nominal_, nominal_t0_, span, t, shifted[k].data());
    } else {
      shifted[k] = RefHinges(t);
    }
  }
  Knots reference(K);
  for (int k = 0; k < K; ++k) reference[k] = RefHinges(now + span * k / (K - 1));

  // candidates
  const int n = config_.samples;
  std::vector<Knots> cand(n);
  cand[0] = shifted;
  cand[1] = reference;
  const int n_small = static_cast<int>(std::round(config_.small_noise_fraction * (n - 2)));
  std::array<double, kDofs> noise;
  for (int j = 0; j < kDofs; ++j) {
    noise[j] = config_.noise_rad * (recovering_ ? 1.5 : 1.0) * noise_scale_[j];
  }
  // an arm the hand servo holds on its contact is perturbed little: its hand stays put
  for (int side = 0; side < 2; ++side) {
    if (!servo_active_[side]) continue;
    for (int j : arm_dofs_[side]) noise[j] *= 0.2;
  }
  for (int c = 2; c < n; ++c) {
    core::Rng rng(
        core::DeriveSeed(seed_, static_cast<uint64_t>(iteration_), static_cast<uint64_t>(c)));
    double sigma = c - 2 < n_small ? 0.3 : 1.0;
    cand[c] = shifted;
    for (int k = 1; k < K; ++k) {
      for (int j = 0; j < kDofs; ++j) {
        cand[c][k][j] = std::clamp(shifted[k][j] + rng.Normal(sigma * noise[j]), lo_[j], hi_[j]);
      }
    }
  }
  std::vector<double> costs(n, 0.0);
  const int threads = std::min(config_.threads, n);
  auto work = [&](int th) {
    for (int c = th; c < n; c += threads) costs[c] = Rollout(th, cand[c], now, obs.data);
  };
  if (threads == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    for (int th = 1; th < threads; ++th) pool.emplace_back(work, th);
    work(0);
    for (auto& t : pool) t.join();
  }
  int best = 0;
  for (int c = 1; c < n; ++c) {
    if (costs[c] < costs[best]) best = c;
  }
  nominal_ = cand[best];
  nominal_t0_ = now;
  last_cost_ = costs[best];
  ++iteration_;
  return absl::OkStatus();
}

void MpcController::CorrectAim(const Observation& obs) {
  const double now = obs.time_s;
  if (config_.aim_gain <= 0 || now < ramp_t0_ + ramp_s_ + 0.2 || now < next_aim_s_) return;
  next_aim_s_ = now + 0.3;
  const double scale = world_->agent(agent_).scale;
  bool changed = false;
  for (ContactTerm& t : task_.terms) {
    if (t.type != plan::ContactType::kContact || !IsHand(t.joint)) continue;
    const Eigen::Vector3d& p = obs.body_points[static_cast<int>(t.joint)];
    Eigen::Vector3d miss = t.Touch(p, obs.body_points) - p;
    // a miss this large is not a steady sag but a reach still under way (or out of range)
    if (miss.norm() < 0.01 * scale || miss.norm() > 0.15 * scale) continue;
    t.aim_offset += config_.aim_gain * miss;
    double cap = 0.12 * scale;
    if (t.aim_offset.norm() > cap) t.aim_offset *= cap / t.aim_offset.norm();
    changed = true;
  }
  if (!changed) return;
  // re-solve the goal with the corrected aim and move the reference there from the old goal
  ReferencePoseOptions warm;
  warm.warm_start = &goal_;
  ReferencePose goal = SolveReferencePose(*world_, agent_, task_, obs.data, scratch_, warm);
  SetReference(now, {goal_, goal}, obs.data);
  stand_balance_from_s_ = 1e9;
  progress_floor_ = 1.0;
}

void MpcController::ServoHands(const Observation& obs) {
  const world::AgentIndex& a = world_->agent(agent_);
  const mjModel* m = world_->model();
  std::array<bool, 2> active = {false, false};
  // the reference has arrived at the goal (aim corrections restart a short ramp from there)
  const bool arrived = progress_floor_ >= 1.0 || obs.time_s >= ramp_t0_ + ramp_s_;
  if (config_.hand_servo_gain > 0 && arrived && !recovering_) {
    bool kinematics = false;
    for (const ContactTerm& t : task_.terms) {
      if (t.type != plan::ContactType::kContact || !IsHand(t.joint)) continue;
      const Eigen::Vector3d& p = obs.body_points[static_cast<int>(t.joint)];
      Eigen::Vector3d miss = t.Touch(p, obs.body_points) - p;
      // a miss this large is a reach still under way (or out of range): the MPC's job
      if (miss.norm() > 0.15 * a.scale) continue;
      const int side = t.joint == core::BodyJoint::kRightHand ? 0 : 1;
      if (!kinematics) {
        std::memcpy(scratch_->qpos, obs.data->qpos, sizeof(mjtNum) * m->nq);
        mj_kinematics(m, scratch_);
        mj_comPos(m, scratch_);
        kinematics = true;
      }
      Eigen::Vector4d dq =
          ArmStepToward(m, scratch_, a, arm_dofs_[side], a.site[static_cast<int>(t.joint)], miss);
      for (int k = 0; k < 4; ++k) {
        double& o = servo_[arm_dofs_[side][k]];
        o = std::clamp(o + config_.hand_servo_gain * dq[k], -config_.hand_servo_max_rad,
                       config_.hand_servo_max_rad);
      }
      active[side] = true;
    }
  }
  servo_active_ = active;
  // an arm with no hand contact to hold lets its offsets fade out smoothly
  for (int side = 0; side < 2; ++side) {
    if (active[side]) continue;
    for (int j : arm_dofs_[side]) servo_[j] *= 0.9;
  }
}

void MpcController::WithServo(const double* knot, double* out) const {
  for (int j = 0; j < kDofs; ++j) out[j] = std::clamp(knot[j] + servo_[j], lo_[j], hi_[j]);
}

void MpcController::Targets(double time_s, core::Span<double> ctrl) const {
  SH_CHECK(ctrl.size() >= kDofs, "an MPC agent has the humanoid body's actuators first");
  std::array<double, kDofs> raw;
  Interp(nominal_, nominal_t0_, config_.horizon_s, time_s, raw.data());
  WithServo(raw.data(), ctrl.data());
}

}  // namespace simhuman::control
