// Probe of the carrying skill's lift (issue 17): a human standing at a box's stand point lifts
// it, with zero action or a policy, and the probe prints what happens (box height, hand forces,
// centre of mass against the feet) and optionally writes a contact sheet per episode.
//
//   build/simhuman_carry_probe [--episodes N] [--seed S] [--side M] [--mass KG]
//                              [--policy FILE] [--seconds T] [--sheet DIR]
//                              [--stand-gap M] [--grasp-frac F] [--reach-depth M] [--pose-at T]
//                              [--torsion M] [--contacts 1] [--grip 1] [--gait human]
//                              [--mpc SAMPLES] [--mpc-sigma S] [--mpc-horizon T]
#include <torch/torch.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
  double stand_gap = -1, grasp_frac = -1, hold_rise = -9, hold_gap = -1;
  double pose_at = -1;  // >= 0: start posed inside the lift at this time (s)
  double reach_depth = -1;
  double torsion = -1;    // >= 0: the box's torsional friction (condim 3 at 0)
  bool contacts = false;  // print every contact and its normal force
  bool hold = false;      // start holding the box (the carry phase's reference-state start)
  bool grip = false;      // the hands grip the box while they hold it ("humanoid_grip")
  std::string gait;       // the walking reference gait (control::WalkGait)
  int mpc = 0;            // > 0: the lift MPC with this many samples drives the action
  double mpc_sigma = -1, mpc_horizon = -1, mpc_whands = -1, mpc_wtrack = -1, mpc_wbal = -1;
  std::string policy, sheet;
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

}  // namespace

int main(int argc, char** argv) {
  const Args a = Parse(argc, argv);
  std::optional<sh::control::LoadedPolicy> pol;
  if (!a.policy.empty()) {
    auto p = sh::control::LoadPolicyFile(a.policy);
    if (!p.ok()) {
      std::fprintf(stderr, "%s\n", std::string(p.status().message()).c_str());
      return 1;
    }
    pol = std::move(*p);
  }
  auto t = sh::learn::CarryTask::Create(1, a.gait, a.grip);
  if (!t.ok()) {
    std::fprintf(stderr, "%s\n", std::string(t.status().message()).c_str());
    return 1;
  }
  (*t)->SetEvaluation(100000);
  if (a.stand_gap >= 0) (*t)->params().stand_gap_m = a.stand_gap;
  if (a.grasp_frac >= 0) (*t)->params().grasp_frac = a.grasp_frac;
  if (a.hold_rise > -9) (*t)->params().hold_rise_m = a.hold_rise;
  if (a.hold_gap >= 0) (*t)->params().hold_gap_m = a.hold_gap;
  if (a.reach_depth >= 0) (*t)->params().max_reach_depth_m = a.reach_depth;
  const auto& ix = (*t)->index();
  const int od = (*t)->obs_dim(), ad = (*t)->act_dim();
  std::vector<float> obs(od), act(ad, 0.f);
  sh::core::Rng rng(a.seed);
  int lifted = 0, lift_ok = 0;
  for (int ep = 0; ep < a.episodes; ++ep) {
    (*t)->Reset(0, a.seed * 1000 + ep, obs.data());
    const double side = a.side > 0 ? a.side : rng.Uniform(0.25, 0.75);
    const double mass = a.mass > 0 ? a.mass : rng.Uniform(2.0, 13.0);
    Eigen::Vector3d pelvis;
    double yaw;
    sh::control::PelvisPose((*t)->data(0), ix.walk, &pelvis, &yaw);
    const Eigen::Vector3d fwd(std::cos(yaw), std::sin(yaw), 0);
    const sh::control::CarryParams params = (*t)->params();
    Eigen::Vector3d box_pos = pelvis + (params.stand_gap_m + 0.5 * side) * fwd;
    box_pos.z() = 0;
    (*t)->SetBox(0, side, mass, box_pos, yaw, (box_pos + 2.0 * fwd).head<2>(), obs.data());
    if (a.hold)
      (*t)->StartHoldingNow(0, obs.data());
    else
      (*t)->StartLiftNow(0, obs.data(), a.pose_at);
    const mjModel* m = (*t)->model(0);
    if (a.torsion >= 0) {  // a probe of the grip: the model is this probe's own
      mjModel* mm = const_cast<mjModel*>(m);
      mm->geom_friction[3 * (*t)->box_geom() + 1] = a.torsion;
      mm->geom_condim[(*t)->box_geom()] = a.torsion > 0 ? 4 : 3;
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
      mpc = std::make_unique<sh::control::CarryMpc>(m, ix, (*t)->params(), (*t)->box_geom(), mo);
    }
    std::unique_ptr<sh::render::OffscreenRenderer> r;
    std::vector<std::vector<uint8_t>> frames;
    constexpr int kW = 320, kH = 240;
    if (!a.sheet.empty()) {
      auto made = sh::render::OffscreenRenderer::Create(m, kW, kH);
      if (made.ok()) r = std::move(*made);
    }
    std::printf("ep %d: side %.2f m, mass %.1f kg, ik error %.3f m\n", ep, side, mass,
                (*t)->state(0).poses.ik_error_m);
    double max_low = 0;
    std::string end = "time";
    const int steps = static_cast<int>(a.seconds * 30);
    for (int k = 0; k < steps; ++k) {
      if (pol) {
        torch::NoGradGuard ng;
        torch::Tensor o = torch::from_blob(obs.data(), {1, od}).narrow(1, 0, pol->meta.obs_dim);
        torch::Tensor ac = pol->actor->forward(pol->norm.Normalize(o)).contiguous();
        std::copy(ac.data_ptr<float>(), ac.data_ptr<float>() + ad, act.begin());
        // a walking policy never trained its arm outputs: they stay zero
        if (pol->meta.obs_dim != od) {
          for (int j = 0; j < ad; ++j) {
            if (!sh::control::WalkActionUsed(j)) act[j] = 0.f;
          }
        }
      }
      if (mpc) mpc->Act((*t)->data(0), (*t)->state(0), act.data());
      sh::learn::StepInfo info;
      const CarryPhase before = (*t)->state(0).phase;
      (*t)->Step(0, act.data(), obs.data(), &info);
      if (before == CarryPhase::kLift && (*t)->state(0).phase == CarryPhase::kCarry) {
        const mjData* d = (*t)->data(0);
        const auto box = sh::control::ReadCarryBox(m, d, (*t)->box_geom());
        double fl, fr;
        HandForces(m, d, ix, (*t)->box_geom(), &fl, &fr);
        const bool ok = sh::control::BoxLowestZ(box) > 0.05 && fl > 5 && fr > 5 &&
                        d->xpos[3 * ix.walk.agent.pelvis_body + 2] > 0.8;
        lift_ok += ok;
        std::printf(
            "  lift end: box low %.3f, hands %.0f %.0f N, pelvis z %.2f, tilt %.0f deg: %s\n",
            sh::control::BoxLowestZ(box), fl, fr, d->xpos[3 * ix.walk.agent.pelvis_body + 2],
            std::acos(std::min(1.0, box.rot(2, 2))) * 180 / M_PI, ok ? "LIFTED" : "no");
      }
      const mjData* d = (*t)->data(0);
      const auto box = sh::control::ReadCarryBox(m, d, (*t)->box_geom());
      const double low = sh::control::BoxLowestZ(box);
      if ((*t)->state(0).phase == CarryPhase::kCarry) max_low = std::max(max_low, low);
      if (a.contacts && k % 8 == 0) {
        for (int c = 0; c < d->ncon; ++c) {
          const mjContact& con = d->contact[c];
          mjtNum f[6];
          mj_contactForce(m, d, c, f);
          std::printf("    con %s - %s  f %.0f\n", mj_id2name(m, mjOBJ_GEOM, con.geom1),
                      mj_id2name(m, mjOBJ_GEOM, con.geom2), f[0]);
        }
      }
      if (k % 8 == 0 || info.terminated) {
        double fl, fr;
        HandForces(m, d, ix, (*t)->box_geom(), &fl, &fr);
        Eigen::Vector3d held_l, held_r;
        sh::control::CarryHeldPoints((*t)->state(0), box, &held_l, &held_r);
        const double miss_l =
            (Eigen::Vector3d(d->site_xpos + 3 * ix.left_hand_site) - held_l).norm();
        const double miss_r =
            (Eigen::Vector3d(d->site_xpos + 3 * ix.right_hand_site) - held_r).norm();
        std::printf("  miss %.2f %.2f", miss_l, miss_r);
        std::printf(
            "  t %.2f %-8s pelvis z %.2f  box low %.3f tilt %3.0f  hands %4.0f %4.0f N  com ahead "
            "%+.3f\n",
            d->time, sh::control::CarryPhaseName((*t)->state(0).phase),
            d->xpos[3 * ix.walk.agent.pelvis_body + 2], low,
            std::acos(std::min(1.0, box.rot(2, 2))) * 180 / M_PI, fl, fr, ComAhead(d, ix));
      }
      if (r && k % 8 == 0) {
        sh::render::CameraSpec cam;
        cam.lookat = Eigen::Vector3d(box_pos.x(), box_pos.y(), 0.6) - 0.3 * fwd;
        cam.distance_m = 2.8;
        cam.azimuth_deg = yaw * 180 / M_PI + 90 + 30;
        cam.elevation_deg = -12;
        std::vector<uint8_t> rgb;
        char cap[48];
        std::snprintf(cap, sizeof(cap), "%.1f s %s", d->time,
                      sh::control::CarryPhaseName((*t)->state(0).phase));
        if (r->Render(d, cam, &rgb, cap).ok()) frames.push_back(std::move(rgb));
      }
      if (info.terminated) {
        end = sh::learn::CarryFailureName((*t)->last_failure(0));
        break;
      }
    }
    lifted += max_low > 0.05 && end == "time";
    {
      const mjData* d = (*t)->data(0);
      const auto box = sh::control::ReadCarryBox(m, d, (*t)->box_geom());
      std::printf(
          "  end: %s, box highest in carry %.3f m, at the end %.3f m; box %.2f m from "
          "its destination (%.2f at the start)\n",
          end.c_str(), max_low, sh::control::BoxLowestZ(box),
          ((*t)->state(0).dest_xy - box.pos.head<2>()).norm(),
          ((*t)->state(0).dest_xy - box_pos.head<2>()).norm());
    }
    if (!frames.empty()) {
      (void)sh::render::WriteContactSheet(a.sheet + "/lift" + std::to_string(ep) + ".png", frames,
                                          kW, kH, 6);
    }
  }
  std::printf("lift stage ok: %d / %d; lifted and standing to the end: %d / %d\n", lift_ok,
              a.episodes, lifted, a.episodes);
  return 0;
}
