// Probe of the carrying skill (issue 17): a human standing at a box's stand point lifts it, or
// starts holding it (--hold 1) and carries it, with zero action, a policy, the MPC or a walking
// policy, and the probe prints what happens (box height, hand forces, centre of mass against the
// feet), a table per episode, and optionally writes a contact sheet per episode.
//
//   build/simhuman_carry_probe [--episodes N] [--seed S] [--side M] [--mass KG]
//                              [--policy FILE] [--seconds T] [--sheet DIR]
//                              [--stand-gap M] [--grasp-frac F] [--reach-depth M] [--pose-at T]
//                              [--torsion M] [--contacts 1] [--grip 1] [--gait human]
//                              [--mpc SAMPLES] [--mpc-sigma S] [--mpc-horizon T]
//                              [--walker FILE] [--dest M] [--vmax MPS]
//                              [--hold-rise M] [--hold-gap M] [--lean RAD_PER_KG]
//                              [--open M] [--hinge RAD]
//
// --walker FILE drives the carry and retreat phases with a walking policy (task "walk", e.g.
// assets/policies/walk.pt): the action is the walker's output for the first kWalkObsDim entries
// of the carry observation (the walking observation, whose arm entries the carry task shows
// "blind" while it holds the arms: control::CarryBlindArms), with its arm outputs zeroed
// (WalkTargets ignores them), so the arms keep the holding reference and the grip servo. The
// gait is the file's. --dest is the destination's distance ahead of the box (m), --vmax the
// walking command's top speed (m/s; the gait's, and at most CarryParams::carry_vmax_mps while
// carrying, by default). With --policy as well, the policy drives the other phases.
#include <torch/torch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "simhuman/control/policy/carry_mpc.h"
#include "simhuman/control/policy/policy_net.h"
#include "simhuman/learn/carry_env.h"
#include "simhuman/render/image_io.h"
#include "simhuman/render/offscreen.h"

namespace sh = simhuman;
using sh::control::CarryPhase;

namespace {

struct Args {
  int episodes = 4;
  uint64_t seed = 1;
  double side = -1, mass = -1;  // < 0: drawn
  double seconds = 6;
  double stand_gap = -1, grasp_frac = -1, hold_rise = -9, hold_gap = -1, lean = -1;
  double open = -1, hinge = -1;  // the lift's open hands and stoop (CarryParams)
  double pose_at = -1;           // >= 0: start posed inside the lift at this time (s)
  double reach_depth = -1;
  double torsion = -1;    // >= 0: the box's torsional friction (condim 3 at 0)
  bool contacts = false;  // print every contact and its normal force
  bool hold = false;      // start holding the box (the carry phase's reference-state start)
  bool grip = false;      // the hands grip the box while they hold it ("humanoid_grip")
  bool support = false;   // quasi-static support in the squats (carry_support.h)
  std::string gait;       // the walking reference gait (control::WalkGait)
  int mpc = 0;            // > 0: the lift MPC with this many samples drives the action
  double mpc_sigma = -1, mpc_horizon = -1, mpc_whands = -1, mpc_wtrack = -1, mpc_wbal = -1;
  std::string policy, sheet;
  std::string walker;   // a walking policy drives the carry phase
  double dest_m = 2.0;  // destination ahead of the box, m
  double vmax = -1;     // > 0: the walking command's top speed, m/s (carrying too)
};

Args Parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string k = argv[i];
    const char* v = argv[i + 1];
    if (k == "--episodes")
      a.episodes = std::atoi(v);
    else if (k == "--seed")
      a.seed = std::strtoull(v, nullptr, 10);
    else if (k == "--side")
      a.side = std::atof(v);
    else if (k == "--mass")
      a.mass = std::atof(v);
    else if (k == "--seconds")
      a.seconds = std::atof(v);
    else if (k == "--policy")
      a.policy = v;
    else if (k == "--stand-gap")
      a.stand_gap = std::atof(v);
    else if (k == "--grasp-frac")
      a.grasp_frac = std::atof(v);
    else if (k == "--hold-rise")
      a.hold_rise = std::atof(v);
    else if (k == "--hold-gap")
      a.hold_gap = std::atof(v);
    else if (k == "--lean")
      a.lean = std::atof(v);
    else if (k == "--open")
      a.open = std::atof(v);
    else if (k == "--hinge")
      a.hinge = std::atof(v);
    else if (k == "--pose-at")
      a.pose_at = std::atof(v);
    else if (k == "--reach-depth")
      a.reach_depth = std::atof(v);
    else if (k == "--contacts")
      a.contacts = std::atoi(v) != 0;
    else if (k == "--torsion")
      a.torsion = std::atof(v);
    else if (k == "--hold")
      a.hold = std::atoi(v) != 0;
    else if (k == "--support")
      a.support = std::atoi(v) != 0;
    else if (k == "--grip")
      a.grip = std::atoi(v) != 0;
    else if (k == "--gait")
      a.gait = v;
    else if (k == "--mpc")
      a.mpc = std::atoi(v);
    else if (k == "--mpc-sigma")
      a.mpc_sigma = std::atof(v);
    else if (k == "--mpc-whands")
      a.mpc_whands = std::atof(v);
    else if (k == "--mpc-wtrack")
      a.mpc_wtrack = std::atof(v);
    else if (k == "--mpc-wbal")
      a.mpc_wbal = std::atof(v);
    else if (k == "--mpc-horizon")
      a.mpc_horizon = std::atof(v);
    else if (k == "--sheet")
      a.sheet = v;
    else if (k == "--walker")
      a.walker = v;
    else if (k == "--dest")
      a.dest_m = std::atof(v);
    else if (k == "--vmax")
      a.vmax = std::atof(v);
    else {
      std::fprintf(stderr, "unknown option %s\n", k.c_str());
      std::exit(2);
    }
  }
  return a;
}

void HandForces(const mjModel* m, const mjData* d, const sh::control::CarryIndex& ix, int box,
                double* left, double* right) {
  *left = *right = 0;
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& con = d->contact[c];
    // the box body may hold several geoms (faces, rims): any of them counts
    const int body = m->geom_bodyid[box];
    const bool first = m->geom_bodyid[con.geom1] == body;
    if (!first && m->geom_bodyid[con.geom2] != body) continue;
    const int other = first ? con.geom2 : con.geom1;
    mjtNum f[6];
    mj_contactForce(m, d, c, f);
    // a hand or its forearm: a hug presses with both
    const int ob = m->geom_bodyid[other];
    if (ob == m->geom_bodyid[ix.left_hand_geom] ||
        ob == m->body_parentid[m->geom_bodyid[ix.left_hand_geom]])
      *left += f[0];
    if (ob == m->geom_bodyid[ix.right_hand_geom] ||
        ob == m->body_parentid[m->geom_bodyid[ix.right_hand_geom]])
      *right += f[0];
  }
}

// centre of mass minus the feet's middle, along the heading (m)
double ComAhead(const mjData* d, const sh::control::CarryIndex& ix) {
  Eigen::Vector3d pos;
  double yaw;
  sh::control::PelvisPose(d, ix.walk, &pos, &yaw);
  const int l = ix.walk.left_foot_geom, r = ix.walk.right_foot_geom;
  const int pb = ix.walk.agent.pelvis_body;
  double dx = d->subtree_com[3 * pb] - 0.5 * (d->geom_xpos[3 * l] + d->geom_xpos[3 * r]);
  double dy =
      d->subtree_com[3 * pb + 1] - 0.5 * (d->geom_xpos[3 * l + 1] + d->geom_xpos[3 * r + 1]);
  return std::cos(yaw) * dx + std::sin(yaw) * dy;
}

constexpr int kWalkActDim = sh::control::kWalkActDim;

// A walking policy driving the carry phase.
struct Walker {
  sh::control::LoadedPolicy policy;
};

// Loads a walking policy (task "walk", the walking dimensions); errors name the file.
std::optional<Walker> LoadWalker(const std::string& path, std::string* error) {
  auto p = sh::control::LoadPolicyFile(path);
  if (!p.ok()) {
    *error = "--walker: " + std::string(p.status().message());
    return std::nullopt;
  }
  const sh::control::PolicyMeta& meta = p->meta;
  if (meta.task != "walk" || meta.obs_dim != sh::control::kWalkObsDim ||
      meta.act_dim != kWalkActDim) {
    *error = "--walker " + path + ": a '" + meta.task + "' policy with " +
             std::to_string(meta.obs_dim) + " observations and " + std::to_string(meta.act_dim) +
             " actions; a walker needs task 'walk' with " +
             std::to_string(sh::control::kWalkObsDim) + " and " + std::to_string(kWalkActDim);
    return std::nullopt;
  }
  Walker w;
  w.policy = std::move(*p);
  return w;
}

// The walker's action for the carry observation `obs` (its walking part; arm outputs zeroed).
void WalkerAction(Walker& w, const float* obs, float* act) {
  std::array<float, sh::control::kWalkObsDim> o;
  std::copy(obs, obs + sh::control::kWalkObsDim, o.begin());
  torch::NoGradGuard ng;
  torch::Tensor x = torch::from_blob(o.data(), {1, sh::control::kWalkObsDim});
  torch::Tensor y = w.policy.actor->forward(w.policy.norm.Normalize(x)).contiguous();
  const float* raw = y.data_ptr<float>();
  for (int j = 0; j < kWalkActDim; ++j) act[j] = sh::control::WalkActionUsed(j) ? raw[j] : 0.f;
}

// The largest contact normal force (N) between the box and the human's hands, and between the
// box and any other body of the human (the forearms of a held start may lie inside small boxes),
// with that body's name. Reads the contacts of the last mj_forward or mj_step.
void StartBoxForces(const mjModel* m, const mjData* d, const sh::control::CarryIndex& ix, int box,
                    double* hands, double* other, std::string* other_body) {
  *hands = *other = 0;
  *other_body = "-";
  const int box_body = m->geom_bodyid[box];
  const int lh = m->geom_bodyid[ix.left_hand_geom], rh = m->geom_bodyid[ix.right_hand_geom];
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& con = d->contact[c];
    const bool first = m->geom_bodyid[con.geom1] == box_body;
    if (!first && m->geom_bodyid[con.geom2] != box_body) continue;
    const int ob = m->geom_bodyid[first ? con.geom2 : con.geom1];
    if (ob == 0) continue;  // the floor
    mjtNum f[6];
    mj_contactForce(m, d, c, f);
    if (ob == lh || ob == rh) {
      *hands = std::max(*hands, f[0]);
    } else if (f[0] > *other) {
      *other = f[0];
      const char* name = mj_id2name(m, mjOBJ_BODY, ob);
      *other_body = name ? name : "?";
    }
  }
}

// Which way the trunk leans (the torso's up axis in the heading frame).
const char* LeanName(const mjData* d, const sh::control::CarryIndex& ix) {
  Eigen::Vector3d pelvis;
  double yaw;
  sh::control::PelvisPose(d, ix.walk, &pelvis, &yaw);
  const mjtNum* R = d->xmat + 9 * ix.walk.agent.torso_body;
  const double ahead = std::cos(yaw) * R[2] + std::sin(yaw) * R[5];
  const double left = -std::sin(yaw) * R[2] + std::cos(yaw) * R[5];
  if (std::abs(ahead) >= std::abs(left)) return ahead > 0 ? "forward" : "backward";
  return left > 0 ? "left" : "right";
}

struct EpisodeResult {
  double side = 0, mass = 0;
  std::string end = "time";
  double end_s = 0;
  double progress_m = 0;  // the box's distance to its destination: at the start minus at the end
  bool held = false;      // at the end the box is off the floor, near the pelvis, the human up
  std::string lean;       // the trunk's lean at the end
  double pelvis_z = 0;    // at the end, m (a standing human's is about 0.95)
  double start_hands_n = 0, start_other_n = 0;
  std::string start_other_body;
  bool lift_ok = false, lifted = false;
  bool success = false;  // the task's own success: put down within 0.2 m of the destination
};

struct Probe {
  Args a;
  sh::learn::CarryTask* t = nullptr;
  std::optional<sh::control::LoadedPolicy> pol;
  std::optional<Walker> walker;
};

// The action of one step: the walker in the carry phase, else the policy, the MPC, or zero.
void ChooseAction(Probe& p, std::vector<float>& obs, std::vector<float>& act,
                  sh::control::CarryMpc* mpc) {
  sh::learn::CarryTask& t = *p.t;
  const int od = t.obs_dim(), ad = t.act_dim();
  std::fill(act.begin(), act.end(), 0.f);
  const CarryPhase ph = t.state(0).phase;  // the walker walks the carry and the retreat, as in eval
  if (p.walker && (ph == CarryPhase::kCarry || ph == CarryPhase::kRetreat)) {
    WalkerAction(*p.walker, obs.data(), act.data());
    return;
  }
  if (p.pol) {
    torch::NoGradGuard ng;
    torch::Tensor o = torch::from_blob(obs.data(), {1, od}).narrow(1, 0, p.pol->meta.obs_dim);
    torch::Tensor ac = p.pol->actor->forward(p.pol->norm.Normalize(o)).contiguous();
    std::copy(ac.data_ptr<float>(), ac.data_ptr<float>() + ad, act.begin());
    // a walking policy never trained its arm outputs: they stay zero
    if (p.pol->meta.obs_dim != od) {
      for (int j = 0; j < ad; ++j) {
        if (!sh::control::WalkActionUsed(j)) act[j] = 0.f;
      }
    }
  }
  if (mpc) mpc->Act(t.data(0), t.state(0), act.data());
}

// One status line (every 8 steps and at the end).
void PrintStatus(Probe& p, const sh::control::CarryBox& box) {
  sh::learn::CarryTask& t = *p.t;
  const mjModel* m = t.model(0);
  const mjData* d = t.data(0);
  const auto& ix = t.index();
  double fl, fr;
  HandForces(m, d, ix, t.box_geom(), &fl, &fr);
  Eigen::Vector3d held_l, held_r;
  sh::control::CarryHeldPoints(t.state(0), box, &held_l, &held_r);
  const double miss_l = (Eigen::Vector3d(d->site_xpos + 3 * ix.left_hand_site) - held_l).norm();
  const double miss_r = (Eigen::Vector3d(d->site_xpos + 3 * ix.right_hand_site) - held_r).norm();
  std::printf("  miss %.2f %.2f", miss_l, miss_r);
  {  // the box's pitch: its up axis along the heading (+: its top turned forward)
    Eigen::Vector3d pelvis;
    double yaw;
    sh::control::PelvisPose(d, ix.walk, &pelvis, &yaw);
    std::printf(" up-fwd %+.2f", std::cos(yaw) * box.rot(0, 2) + std::sin(yaw) * box.rot(1, 2));
  }
  std::printf(
      "  t %.2f %-8s pelvis z %.2f  box low %.3f tilt %3.0f  hands %4.0f %4.0f N  com ahead "
      "%+.3f  to dest %.2f\n",
      d->time, sh::control::CarryPhaseName(t.state(0).phase),
      d->xpos[3 * ix.walk.agent.pelvis_body + 2], sh::control::BoxLowestZ(box),
      std::acos(std::min(1.0, box.rot(2, 2))) * 180 / M_PI, fl, fr, ComAhead(d, ix),
      (t.state(0).dest_xy - box.pos.head<2>()).norm());
}

// The contact-sheet frame of the current state (the camera follows a held box's carrier).
void RenderFrame(Probe& p, sh::render::OffscreenRenderer* r, const Eigen::Vector3d& box_pos,
                 double yaw, std::vector<std::vector<uint8_t>>* frames) {
  const mjData* d = p.t->data(0);
  const Eigen::Vector3d fwd(std::cos(yaw), std::sin(yaw), 0);
  sh::render::CameraSpec cam;
  cam.lookat = Eigen::Vector3d(box_pos.x(), box_pos.y(), 0.6) - 0.3 * fwd;
  if (p.a.hold) {
    const int pb = p.t->index().walk.agent.pelvis_body;
    cam.lookat = Eigen::Vector3d(d->xpos[3 * pb], d->xpos[3 * pb + 1], 0.8);
  }
  cam.distance_m = 2.8;
  cam.azimuth_deg = yaw * 180 / M_PI + 90 + 30;
  cam.elevation_deg = -12;
  std::vector<uint8_t> rgb;
  char cap[48];
  std::snprintf(cap, sizeof(cap), "%.1f s %s", d->time,
                sh::control::CarryPhaseName(p.t->state(0).phase));
  if (r->Render(d, cam, &rgb, cap).ok()) frames->push_back(std::move(rgb));
}

// Places the box, starts the episode (holding it or lifting) and runs it.
EpisodeResult RunEpisode(Probe& p, int ep, double side, double mass) {
  const Args& a = p.a;
  sh::learn::CarryTask& t = *p.t;
  const auto& ix = t.index();
  std::vector<float> obs(t.obs_dim()), act(t.act_dim(), 0.f);
  EpisodeResult res;
  res.side = side;
  res.mass = mass;
  t.Reset(0, a.seed * 1000 + ep, obs.data());
  Eigen::Vector3d pelvis;
  double yaw;
  sh::control::PelvisPose(t.data(0), ix.walk, &pelvis, &yaw);
  const Eigen::Vector3d fwd(std::cos(yaw), std::sin(yaw), 0);
  Eigen::Vector3d box_pos = pelvis + (t.params().stand_gap_m + 0.5 * side) * fwd;
  box_pos.z() = 0;
  t.SetBox(0, side, mass, box_pos, yaw, (box_pos + a.dest_m * fwd).head<2>(), obs.data());
  if (a.hold)
    t.StartHoldingNow(0, obs.data());
  else
    t.StartLiftNow(0, obs.data(), a.pose_at);
  const mjModel* m = t.model(0);
  StartBoxForces(m, t.data(0), ix, t.box_geom(), &res.start_hands_n, &res.start_other_n,
                 &res.start_other_body);
  if (a.torsion >= 0) {  // a probe of the grip: the model is this probe's own
    mjModel* mm = const_cast<mjModel*>(m);
    const int body = m->geom_bodyid[t.box_geom()];
    for (int g = 0; g < m->ngeom; ++g) {  // every geom of the box (faces, rims and core)
      if (m->geom_bodyid[g] != body) continue;
      mm->geom_friction[3 * g + 1] = a.torsion;
      mm->geom_condim[g] = a.torsion > 0 ? 4 : 3;
    }
  }
  std::unique_ptr<sh::control::CarryMpc> mpc;
  if (a.mpc > 0) {
    sh::control::CarryMpcOptions mo;
    mo.samples = a.mpc;
    if (a.mpc_sigma > 0) mo.sigma = a.mpc_sigma;
    if (a.mpc_horizon > 0) mo.horizon_s = a.mpc_horizon;
    if (a.mpc_whands >= 0) mo.w_hands = a.mpc_whands;
    if (a.mpc_wtrack >= 0) mo.w_track = a.mpc_wtrack;
    if (a.mpc_wbal >= 0) mo.w_balance = a.mpc_wbal;
    mo.seed = a.seed * 1000 + ep;
    mpc = std::make_unique<sh::control::CarryMpc>(m, ix, t.params(), t.box_geom(), mo);
  }
  std::unique_ptr<sh::render::OffscreenRenderer> r;
  std::vector<std::vector<uint8_t>> frames;
  constexpr int kW = 320, kH = 240;
  if (!a.sheet.empty()) {
    auto made = sh::render::OffscreenRenderer::Create(m, kW, kH);
    if (made.ok()) r = std::move(*made);
  }
  const double dest0 =
      (t.state(0).dest_xy - sh::control::ReadCarryBox(m, t.data(0), t.box_geom()).pos.head<2>())
          .norm();
  std::printf(
      "ep %d: side %.2f m, mass %.1f kg, ik error %.3f m; start: hands press up to %.0f N, "
      "other bodies up to %.0f N (%s)\n",
      ep, side, mass, t.state(0).poses.ik_error_m, res.start_hands_n, res.start_other_n,
      res.start_other_body.c_str());
  if (a.contacts) {  // the box body's geoms (its faces and core)
    const int body = m->geom_bodyid[t.box_geom()];
    for (int g = 0; g < m->ngeom; ++g) {
      if (m->geom_bodyid[g] != body) continue;
      const mjtNum* sz = m->geom_size + 3 * g;
      const mjtNum* gp = m->geom_pos + 3 * g;
      std::printf("    geom %s: half %.3f %.3f %.3f at %.3f %.3f %.3f, contype %d\n",
                  mj_id2name(m, mjOBJ_GEOM, g), sz[0], sz[1], sz[2], gp[0], gp[1], gp[2],
                  m->geom_contype[g]);
    }
  }
  double max_low = 0;
  const int steps = static_cast<int>(a.seconds * 30);
  for (int k = 0; k < steps; ++k) {
    ChooseAction(p, obs, act, mpc.get());
    sh::learn::StepInfo info;
    const CarryPhase before = t.state(0).phase;
    t.Step(0, act.data(), obs.data(), &info);
    res.success = res.success || info.success;
    const mjData* d = t.data(0);
    const auto box = sh::control::ReadCarryBox(m, d, t.box_geom());
    if (before == CarryPhase::kLift && t.state(0).phase == CarryPhase::kCarry) {
      double fl, fr;
      HandForces(m, d, ix, t.box_geom(), &fl, &fr);
      res.lift_ok = sh::control::BoxLowestZ(box) > 0.05 && fl > 5 && fr > 5 &&
                    d->xpos[3 * ix.walk.agent.pelvis_body + 2] > 0.8;
      std::printf("  lift end: box low %.3f, hands %.0f %.0f N, pelvis z %.2f, tilt %.0f deg: %s\n",
                  sh::control::BoxLowestZ(box), fl, fr, d->xpos[3 * ix.walk.agent.pelvis_body + 2],
                  std::acos(std::min(1.0, box.rot(2, 2))) * 180 / M_PI,
                  res.lift_ok ? "LIFTED" : "no");
    }
    const double low = sh::control::BoxLowestZ(box);
    if (t.state(0).phase == CarryPhase::kCarry) max_low = std::max(max_low, low);
    if (a.contacts && k % 8 == 0) {
      for (int c = 0; c < d->ncon; ++c) {
        const mjContact& con = d->contact[c];
        mjtNum f[6];
        mj_contactForce(m, d, c, f);
        std::printf("    con %s - %s  f %.0f\n", mj_id2name(m, mjOBJ_GEOM, con.geom1),
                    mj_id2name(m, mjOBJ_GEOM, con.geom2), f[0]);
      }
    }
    if (k % 8 == 0 || info.terminated) PrintStatus(p, box);
    if (r && k % 8 == 0) RenderFrame(p, r.get(), box_pos, yaw, &frames);
    if (info.terminated) {
      res.end = sh::learn::CarryFailureName(t.last_failure(0));
      break;
    }
    if (info.success || info.truncated) {
      res.end = info.success ? "success" : "truncated";
      break;
    }
  }
  const mjData* d = t.data(0);
  const auto box = sh::control::ReadCarryBox(m, d, t.box_geom());
  const Eigen::Vector3d pelvis_end(d->xpos + 3 * ix.walk.agent.pelvis_body);
  res.end_s = d->time;
  res.lifted = max_low > 0.05 && res.end == "time";
  res.progress_m = dest0 - (t.state(0).dest_xy - box.pos.head<2>()).norm();
  res.held = res.end == "time" && sh::control::BoxLowestZ(box) > 0.1 &&
             (box.pos - pelvis_end).head<2>().norm() < 0.8 && pelvis_end.z() > 0.8;
  res.lean = LeanName(d, ix);
  res.pelvis_z = pelvis_end.z();
  std::printf(
      "  end: %s at %.2f s, box highest in carry %.3f m, at the end %.3f m; box %.2f m from "
      "its destination (%.2f at the start); trunk leans %s\n",
      res.end.c_str(), res.end_s, max_low, sh::control::BoxLowestZ(box),
      (t.state(0).dest_xy - box.pos.head<2>()).norm(), dest0, res.lean.c_str());
  if (!frames.empty()) {
    (void)sh::render::WriteContactSheet(a.sheet + "/lift" + std::to_string(ep) + ".png", frames, kW,
                                        kH, 6);
  }
  return res;
}

// The per-episode table and the summary.
void PrintSummary(const Args& a, const std::vector<EpisodeResult>& rs) {
  std::printf(
      "\n| ep | side m | mass kg | start arm force N | end | at s | pelvis z m | box progress m "
      "| held |\n");
  int lift_ok = 0, lifted = 0, held = 0, delivered = 0;
  double progress = 0;
  for (size_t i = 0; i < rs.size(); ++i) {
    const EpisodeResult& r = rs[i];
    std::printf("| %zu | %.2f | %.1f | %.0f (%s) | %s%s%s | %.2f | %.2f | %+.2f | %s |\n", i,
                r.side, r.mass, r.start_other_n, r.start_other_body.c_str(), r.end.c_str(),
                r.end == "time" ? "" : ", leaning ", r.end == "time" ? "" : r.lean.c_str(), r.end_s,
                r.pelvis_z, r.progress_m, r.held ? "yes" : "no");
    lift_ok += r.lift_ok;
    lifted += r.lifted;
    held += r.held;
    delivered += r.success;
    progress += r.progress_m;
  }
  const int n = static_cast<int>(rs.size());
  std::printf("lift stage ok: %d / %d; lifted and standing to the end: %d / %d\n", lift_ok, n,
              lifted, n);
  std::printf("delivered (put down within 0.2 m of the destination, standing): %d / %d\n",
              delivered, n);
  if (a.walker.empty()) return;
  std::printf("walker: held and standing at %.1f s: %d / %d; mean box progress %.2f m\n", a.seconds,
              held, n, n > 0 ? progress / n : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  Probe p;
  p.a = Parse(argc, argv);
  const Args& a = p.a;
  if (!a.walker.empty() && a.mpc > 0) {
    std::fprintf(stderr, "--walker drives the carry phase alone: drop --mpc\n");
    return 2;
  }
  if (!a.policy.empty()) {
    auto pol = sh::control::LoadPolicyFile(a.policy);
    if (!pol.ok()) {
      std::fprintf(stderr, "%s\n", std::string(pol.status().message()).c_str());
      return 1;
    }
    p.pol = std::move(*pol);
  }
  std::string gait = a.gait;
  if (!a.walker.empty()) {
    std::string error;
    p.walker = LoadWalker(a.walker, &error);
    if (!p.walker) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    const std::string& own = p.walker->policy.meta.variant;
    if (!a.gait.empty() && a.gait != own) {
      std::fprintf(stderr, "--gait '%s' differs from the gait '%s' that %s walks with\n",
                   a.gait.c_str(), own.c_str(), a.walker.c_str());
      return 2;
    }
    gait = own;
  }
  auto t = sh::learn::CarryTask::Create(1, gait, a.grip);
  if (!t.ok()) {
    std::fprintf(stderr, "%s\n", std::string(t.status().message()).c_str());
    return 1;
  }
  p.t = t->get();
  p.t->SetEvaluation(100000);
  p.t->set_squat_support(a.support);
  sh::control::CarryParams& params = p.t->params();
  if (a.stand_gap >= 0) params.stand_gap_m = a.stand_gap;
  if (a.grasp_frac >= 0) params.grasp_frac = a.grasp_frac;
  if (a.hold_rise > -9) params.hold_rise_m = a.hold_rise;
  if (a.hold_gap >= 0) params.hold_gap_m = a.hold_gap;
  if (a.lean >= 0) params.hold_lean_rad_per_kg = a.lean;
  if (a.open >= 0) params.open_m = a.open;
  if (a.hinge >= 0) params.squat_hinge_rad = a.hinge;
  if (a.reach_depth >= 0) params.max_reach_depth_m = a.reach_depth;
  if (a.vmax > 0) params.walk.vmax_mps = params.carry_vmax_mps = a.vmax;
  sh::core::Rng rng(a.seed);
  std::vector<EpisodeResult> results;
  for (int ep = 0; ep < a.episodes; ++ep) {
    const double side = a.side > 0 ? a.side : rng.Uniform(0.25, 0.75);
    const double mass = a.mass > 0 ? a.mass : rng.Uniform(2.0, 13.0);
    results.push_back(RunEpisode(p, ep, side, mass));
  }
  PrintSummary(a, results);
  return 0;
}
