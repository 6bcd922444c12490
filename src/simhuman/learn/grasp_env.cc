#include "simhuman/learn/grasp_env.h"

#include <algorithm>
#include <cmath>

#include "simhuman/control/manip/scripted_grasp.h"
#include "simhuman/world/objects.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::learn {
namespace {

using control::manip::ArmChain;
using control::manip::GraspShape;
using control::manip::kGraspDofs;
using control::manip::kGraspTouchParts;

constexpr char kObjectId[] = "grasp_object";

// the object: one free body with a box, a cylinder and a sphere geom; one is active per episode
core::CatalogObject MakeObject() {
  core::CatalogObject o;
  o.id = kObjectId;
  o.type = "box";
  o.color = "red";
  o.movable = true;
  o.mass_kg = 2.0;
  o.friction = 1.0;
  o.pose.pos = Eigen::Vector3d(0.8, -0.1, 0.75);
  core::Shape box, cyl, ball;
  box.kind = core::ShapeKind::kBox;
  box.size = Eigen::Vector3d(0.03, 0.03, 0.075);
  cyl.kind = core::ShapeKind::kCylinder;
  cyl.size = Eigen::Vector3d(0.04, 0.075, 0);
  ball.kind = core::ShapeKind::kSphere;
  ball.size = Eigen::Vector3d(0.05, 0, 0);
  for (core::Shape* s : {&box, &cyl, &ball}) {
    s->pose.pos = Eigen::Vector3d(0, 0, 0.075);
    o.shapes.push_back(*s);
  }
  return o;
}

// finger joints (index..little) of the 29 grasp dofs: 4 per finger after the arm's 7 and the
// palm arch
int FingerDof(int finger, int joint) { return ArmChain::kDofs + 1 + 4 * finger + joint; }

}  // namespace

core::StatusOr<std::unique_ptr<GraspTask>> GraspTask::Create(int num_envs, bool residual) {
  if (num_envs <= 0) return absl::InvalidArgumentError("grasp task: --envs must be positive");
  std::unique_ptr<GraspTask> t(new GraspTask());
  t->residual_ = residual;
  world::SceneSpec spec = world::TabletopBaseScene("grasp");
  SH_ASSIGN_OR_RETURN(core::SceneCatalog scene, world::BuildCatalog(spec));
  scene.objects.push_back(MakeObject());
  SH_ASSIGN_OR_RETURN(world::AgentSpec human, world::AgentFromHuman(spec.humans[0], 0, scene));
  const world::ModelOptions opt = world::DexterousModelOptions();
  SH_ASSIGN_OR_RETURN(t->world_, world::SimWorld::Create(scene, {human}, opt));
  SH_ASSIGN_OR_RETURN(t->ix_, control::manip::MakeGraspIndex(*t->world_, 0, true));
  // buffers sized for one seated human, a hand and a few objects (DexterousModelOptions)
  const mjModel* m = t->world_->model();
  t->object_body_ = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName(kObjectId).c_str());
  for (int k = 0; k < 3; ++k) {
    const std::string g = world::ObjectBodyName(kObjectId) + "/" + std::to_string(k);
    t->object_geom_[k] = mj_name2id(m, mjOBJ_GEOM, g.c_str());
  }
  for (int g = 0; g < m->ngeom; ++g) {
    const char* name = mj_id2name(m, mjOBJ_GEOM, g);
    if (m->geom_bodyid[g] == t->object_body_ && name &&
        std::string(name).find("/rim") != std::string::npos) {
      t->rim_geoms_.push_back(g);
    }
  }
  if (t->object_body_ < 0 || t->object_geom_[2] < 0 || t->rim_geoms_.size() != 16) {
    return absl::InternalError("grasp task: the object's body or geoms are missing");
  }
  t->object_qpos_ = m->jnt_qposadr[m->body_jntadr[t->object_body_]];
  t->object_dof_ = m->jnt_dofadr[m->body_jntadr[t->object_body_]];
  const int table = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName("table000").c_str());
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] == table) t->table_geoms_.push_back(g);
  }
  t->table_top_z_ = world::DefaultSizes("table").at("height");
  const mjData* d0 = t->world_->data();
  t->seated_qpos_.assign(d0->qpos, d0->qpos + m->nq);
  t->seated_ctrl_.assign(d0->ctrl, d0->ctrl + m->nu);
  t->envs_.resize(num_envs);
  for (Env& e : t->envs_) {
    e.m = mj_copyModel(nullptr, m);
    e.d = mj_makeData(e.m);
    e.scratch = mj_makeData(e.m);
  }
  return t;
}

GraspTask::~GraspTask() {
  for (Env& e : envs_) {
    if (e.scratch) mj_deleteData(e.scratch);
    if (e.d) mj_deleteData(e.d);
    if (e.m) mj_deleteModel(e.m);
  }
}

void GraspTask::Shape(Env& e) const {
  mjModel* m = e.m;
  const GraspProblem& p = e.problem;
  const int active = static_cast<int>(p.shape);
  double half_h = 0;
  for (int k = 0; k < 3; ++k) {
    const int g = object_geom_[k];
    const bool on = k == active;
    m->geom_contype[g] = m->geom_conaffinity[g] = on ? 1 : 0;
    m->geom_rgba[4 * g + 3] = on ? 1.0f : 0.0f;
    if (!on) continue;
    m->geom_friction[3 * g] = p.friction;
    if (p.shape == GraspShape::kBox) {
      const double s = 0.8 * p.width_m / 2;
      half_h = p.height_m / 2;
      m->geom_size[3 * g + 0] = m->geom_size[3 * g + 1] = s;
      m->geom_size[3 * g + 2] = half_h;
      m->geom_rbound[g] = std::sqrt(2 * s * s + half_h * half_h);
    } else if (p.shape == GraspShape::kCylinder) {
      const double r = p.width_m / 2;
      half_h = p.height_m / 2;
      m->geom_size[3 * g + 0] = r;
      m->geom_size[3 * g + 1] = half_h;
      m->geom_rbound[g] = std::sqrt(r * r + half_h * half_h);
    } else {
      half_h = 0.75 * p.height_m / 2;
      m->geom_size[3 * g] = half_h;
      m->geom_rbound[g] = half_h;
    }
    m->geom_pos[3 * g + 2] = half_h;
  }
  // the cylinder's two rest rings follow its size; off for the other shapes
  const bool cylinder = p.shape == GraspShape::kCylinder;
  for (size_t k = 0; k < rim_geoms_.size(); ++k) {
    const int g = rim_geoms_[k];
    m->geom_contype[g] = m->geom_conaffinity[g] = cylinder ? 1 : 0;
    if (!cylinder) continue;
    const double r = p.width_m / 2, rf = m->geom_size[3 * g];
    const double a = 2 * M_PI * static_cast<double>(k % 8) / 8;
    m->geom_pos[3 * g + 0] = (r - rf) * std::cos(a);
    m->geom_pos[3 * g + 1] = (r - rf) * std::sin(a);
    m->geom_pos[3 * g + 2] = k < 8 ? rf : p.height_m - rf;
  }
  // mass and inertia of the active solid (uniform density)
  const double mass = p.mass_kg;
  double ixx = 0, izz = 0;
  if (p.shape == GraspShape::kBox) {
    const double s = 0.8 * p.width_m, h = p.height_m;
    ixx = mass * (s * s + h * h) / 12;
    izz = mass * s * s / 6;
  } else if (p.shape == GraspShape::kCylinder) {
    const double r = p.width_m / 2, h = p.height_m;
    ixx = mass * (3 * r * r + h * h) / 12;
    izz = mass * r * r / 2;
  } else {
    ixx = izz = 0.4 * mass * half_h * half_h;
  }
  m->body_mass[object_body_] = mass;
  m->body_inertia[3 * object_body_ + 0] = m->body_inertia[3 * object_body_ + 1] = ixx;
  m->body_inertia[3 * object_body_ + 2] = izz;
  m->body_ipos[3 * object_body_ + 0] = m->body_ipos[3 * object_body_ + 1] = 0;
  m->body_ipos[3 * object_body_ + 2] = half_h;
}

void GraspTask::SetTableCollisions(Env& e, bool on) const {
  for (int g : table_geoms_) e.m->geom_contype[g] = e.m->geom_conaffinity[g] = on ? 1 : 0;
}

control::manip::TabletopGoal GraspTask::Goal(const Env& e) const {
  const GraspProblem& p = e.problem;
  control::manip::TabletopGoal g;
  g.object_body = object_body_;
  g.shape = p.shape;
  g.half_width_m = p.shape == GraspShape::kSphere ? 0.75 * p.height_m / 2
                   : p.shape == GraspShape::kBox  ? 0.4 * p.width_m
                                                  : p.width_m / 2;
  g.height_m = p.shape == GraspShape::kSphere ? 2 * g.half_width_m : p.height_m;
  g.planned_pos = p.planned_pos;
  return g;
}

bool GraspTask::PlaceArm(Env& e, core::Rng& rng) const {
  // where the pipeline's reach leaves the hand (tabletop_pipeline.h): the palm at the grip
  // height, the pre-grasp gap from the object's side, the object ahead of the palm's centre;
  // each jittered by a centimetre or so
  const control::manip::TabletopOptions pipe;
  const control::manip::TabletopGoal g = Goal(e);
  const Eigen::Vector3d centre =
      g.planned_pos + Eigen::Vector3d(0, 0, control::manip::GripHeightM(g, pipe));
  const double behind = control::manip::PalmBehindM(g, pipe);
  mju_copy(e.scratch->qpos, e.d->qpos, e.m->nq);
  const Eigen::VectorXd rest = ix_.arm.Get(e.d);
  for (int attempt = 0; attempt < 12; ++attempt) {
    // DASH's theta; approaches from behind the object (the far side) are rarely reachable
    const double yaw = rng.Uniform(-2.2, 1.2);
    const double standoff = g.half_width_m + pipe.pregrasp_gap_m + rng.Uniform(-0.015, 0.015);
    const control::manip::PalmPose pose =
        control::manip::SideGraspPose(centre + Eigen::Vector3d(0, 0, rng.Uniform(-0.01, 0.01)),
                                      standoff, yaw, true, behind + rng.Uniform(-0.01, 0.01));
    const control::manip::IkResult r =
        control::manip::SolvePalmIk(e.m, e.scratch, ix_.arm, pose, rest, rest);
    if (!r.converged) continue;
    if (control::manip::ArmContacts(e.m, e.scratch, ix_.arm, r.q) > 0) continue;
    ix_.arm.Set(e.d, r.q);
    return true;
  }
  return false;
}

void GraspTask::Reset(int i, uint64_t seed, float* obs) {
  core::Rng rng(seed);
  Env& e = envs_[i];
  for (int tries = 0; tries < 20; ++tries) {
    GraspProblem& p = e.problem;
    p.shape = static_cast<GraspShape>(rng.UniformInt(0, 2));
    p.width_m = rng.Uniform(0.06, 0.10);
    p.height_m = rng.Uniform(0.13, 0.18);
    p.mass_kg = rng.Uniform(1.0, 5.0);
    p.friction = rng.Uniform(0.8, 1.2);
    // DASH's region (table frame), the object within 2 cm of the planned position
    p.planned_pos =
        world::TableToWorld(Eigen::Vector3d(rng.Uniform(-0.10, 0.25), rng.Uniform(-0.10, 0.50), 0));
    p.actual_pos =
        p.planned_pos + Eigen::Vector3d(rng.Uniform(-0.02, 0.02), rng.Uniform(-0.02, 0.02), 0);
    SetTableCollisions(e, true);
    Shape(e);
    mju_copy(e.d->qpos, seated_qpos_.data(), e.m->nq);
    mju_zero(e.d->qvel, e.m->nv);
    mju_zero(e.d->xfrc_applied, 6 * e.m->nbody);
    mju_copy(e.d->ctrl, seated_ctrl_.data(), e.m->nu);
    e.d->time = 0;
    double* q = e.d->qpos + object_qpos_;
    q[0] = p.actual_pos.x();
    q[1] = p.actual_pos.y();
    q[2] = p.actual_pos.z();
    const double yaw = rng.Uniform(-M_PI, M_PI);
    q[3] = std::cos(yaw / 2);
    q[4] = q[5] = 0;
    q[6] = std::sin(yaw / 2);
    // the open hand: fingers straight, the thumb extended out of the palm's way
    control::manip::SetOpenHand(ix_, e.d);
    mj_forward(e.m, e.d);
    if (PlaceArm(e, rng)) break;
  }
  mj_forward(e.m, e.d);
  e.s = control::manip::GraspState();
  e.s.object_body = object_body_;
  e.s.shape = e.problem.shape;
  e.s.task_pos = e.problem.planned_pos;
  control::manip::HoldCurrentPose(e.d, ix_, &e.s);
  if (residual_) {
    const control::manip::TabletopOptions pipe;  // named: GCC 12 misreads a default temporary
    e.scripted = control::manip::MakeScriptedGrasp(e.m, e.d, ix_, Goal(e), pipe);
  }
  e.steps = 0;
  e.dropped_in_test = false;
  control::manip::GraspObservation(e.m, e.d, ix_, e.s, obs);
}

bool GraspTask::Dropped(int i) const {
  const Env& e = envs_[i];
  const Eigen::Vector3d c(e.d->xipos + 3 * object_body_);
  const Eigen::Vector3d palm(e.d->site_xpos + 3 * ix_.arm.palm_site);
  return (c - palm).norm() > 0.15 || c.z() < table_top_z_ - 0.05;
}

double GraspTask::Reward(Env& e, bool drop_test) {
  const mjData* d = e.d;
  const Eigen::Vector3d c(d->xipos + 3 * object_body_);
  // r_o: horizontal drift from where the object was planned to be
  const double r_o =
      -std::hypot(c.x() - e.problem.planned_pos.x(), c.y() - e.problem.planned_pos.y());
  // r_p: fingertips (thumb x 5) and palm near the object
  double r_p = 0;
  for (int k = 0; k < 5; ++k) {
    const double dist = (Eigen::Vector3d(d->site_xpos + 3 * ix_.tip_site[k]) - c).norm();
    r_p -= (k == 0 ? 5.0 : 1.0) * dist;
  }
  r_p -= 2.0 * (Eigen::Vector3d(d->site_xpos + 3 * ix_.arm.palm_site) - c).norm();
  // r_c: touching parts with the object (the thumb's three x 5)
  float touch[kGraspTouchParts];
  control::manip::GraspTouch(e.m, d, ix_, object_body_, touch);
  double r_c = 0;
  for (int t = 0; t < kGraspTouchParts; ++t)
    r_c += (t >= kGraspTouchParts - 3 ? 5.0 : 1.0) * touch[t];
  // r_s: the four fingers in similar poses
  double r_s = 0;
  for (int f = 0; f < 4; ++f) {
    const int g = (f + 1) % 4;
    double sq = 0;
    for (int j = 0; j < 4; ++j) {
      const double a = d->qpos[ix_.qpos[FingerDof(f, j)]], b = d->qpos[ix_.qpos[FingerDof(g, j)]];
      sq += (a - b) * (a - b);
    }
    r_s -= std::sqrt(sq);
  }
  double r_d = 0;
  if (drop_test && Dropped(static_cast<int>(&e - envs_.data()))) {
    r_d = -15;
    e.dropped_in_test = true;
  }
  return 0.1 * (10 * r_o + r_p + 2 * r_c + 1.5 * r_s + r_d);
}

void GraspTask::Step(int i, const float* action, float* obs, StepInfo* info) {
  Env& e = envs_[i];
  if (residual_) {
    float obs_now[control::manip::kGraspObsDim], base[control::manip::kGraspActDim];
    control::manip::GraspObservation(e.m, e.d, ix_, e.s, obs_now);
    e.scripted(obs_now, base);
    float sum[control::manip::kGraspActDim];
    control::manip::AddGraspResidual(base, action, sum);
    control::manip::ApplyGraspAction(ix_, sum, &e.s);
  } else {
    control::manip::ApplyGraspAction(ix_, action, &e.s);
  }
  const bool drop_test = e.steps >= kGraspSteps;
  if (e.steps == kGraspSteps) {
    // the drop test: the table no longer holds the object, a downward pull of half its weight
    SetTableCollisions(e, false);
    e.d->xfrc_applied[6 * object_body_ + 2] = -0.5 * 9.81 * e.problem.mass_kg;
  }
  for (int k = 0; k < kSubsteps; ++k) {
    control::manip::WriteGraspCtrl(e.m, e.d, ix_, e.s);
    mj_step(e.m, e.d);
  }
  ++e.steps;
  bool finite = true;
  for (int k = 0; k < e.m->nq && finite; ++k) finite = std::isfinite(e.d->qpos[k]);
  info->reward = finite ? static_cast<float>(Reward(e, drop_test)) : 0.0f;
  info->terminated = !finite;
  info->truncated = finite && e.steps >= kMaxSteps;
  info->success = info->truncated && !e.dropped_in_test && !Dropped(i);
  if (!finite) {
    mj_resetData(e.m, e.d);
    mj_forward(e.m, e.d);
  }
  control::manip::GraspObservation(e.m, e.d, ix_, e.s, obs);
}

}  // namespace simhuman::learn
