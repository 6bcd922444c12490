// A diagnostic driver for the tabletop pipeline (not a test, not a benchmark): runs the
// `tabletop` suite's episodes one by one, optionally only those moving one shape, prints each
// end reason and can film an episode as a contact sheet of the hand, so a grasp change can be
// tried on a fixed sample and looked at.
//
//   simhuman_tabletop_probe --seed 1 --from 0 --to 80 [--shape sphere] [--kind place]
//                           [--sheet-dir /tmp/sheets] [--frame-s 0.2] [--place-policy FILE]
//                           [--vision assets/vision/vision.pt [--touch 0] [--touch-grasp 0]
//                           [--silhouette 0]]
// The episodes are those of `simhuman eval --suite tabletop --seed S` (same seeds, same kinds).

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/control/manip/scripted_grasp.h"
#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/control/policy/place_policy.h"
#include "simhuman/core/rng.h"
#include "simhuman/eval/tabletop_eval.h"
#include "simhuman/eval/tabletop_vision.h"
#include "simhuman/render/image_io.h"
#include "simhuman/render/offscreen.h"
#include "simhuman/world/objects.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/tabletop.h"

namespace sh = simhuman;
using sh::control::manip::GraspShape;

namespace {

mjtNum ClockUs() {
  static const auto t0 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
}

const char* ShapeName(GraspShape s) {
  return s == GraspShape::kBox ? "box" : s == GraspShape::kCylinder ? "cylinder" : "sphere";
}

struct Args {
  uint64_t seed = 1;
  int from = 0, to = 40;
  std::string shape, kind, sheet_dir;
  int raise = -1;            // 1: the raise over the table's edge (SeatedRaiseViaRad); 0: none
  int repress_steps = -1;    // >= 0: ScriptedGraspOptions::repress_steps
  double reshape = -1;       // ArmMotionOptions::reshape_fraction
  double raise_tail_m = -1;  // >= 0: TabletopOptions::raise_tail_m
  int planner_seed = 0;      // > 0: PlannerOptions::seed of every arm plan
  double frame_s = 0.2;
  double cam_distance_m = 0.55, cam_azimuth_deg = 150, cam_elevation_deg = -25;
  double t_from = 0, t_to = 1e9;                           ///< frames only in this window (s)
  double trace_from = -1, trace_to = -1, trace_dt = 0.02;  ///< the trace's window and step (s)
  bool trace_contacts = false, trace_arm = false;
  // pipeline and scripted-grasp settings (negative or 0: the default)
  bool touch_gap0 = true, hold_behind = true;
  double behind_tol = 0.01, push_gain = 0.15, repress_gain = -1, repress_max = -1, carry_dip = -1;
  double over_margin = -1;
  int carry_over = -1;
  double tilt_guard_deg = -1, tilt_backoff = -1, thumb_clear = -1;
  bool hold_rotation = true, press_closing = true, carried_check = true, top_grasp = false;
  double rot_weight = -1, press_m = -1, terminal_speed = -1, comfort_reach = -1;
  double grip_frac = -1, grip_max = -1;
  double top_behind = -9, top_standoff = -1;
  double lower_segment = -1, extra_lean = -1, lower_speed = -1, release_s = -1;
  double palm_behind = -1, pregrasp_gap = -1, close_rate = -1, hold_rate = -1, margin = -9;
  double squeeze = -1, path_speed = 0, clearance = -1, min_inertia = -1, object_clearance = -1;
  int grasp_attempts = 0, guard_steps = -1;
  int shortcuts = -1, approach_steps = 0, thumb_delay = -1, grasp_steps = 0;
  bool no_spheres = false, profile = false;
  bool touch = true;        // with --vision: the hand's touch too (VisionLoopOptions::touch)
  bool silhouette = true;   // with --vision: the planning estimates fitted to their outlines
  bool touch_grasp = true;  // ... also while the hand grasps (VisionLoopOptions::touch_grasp)
  std::string zero_shot;    // a shape of world::ZeroShotShapes() replaces the task object
  std::string vision;       // a vision model file: the pipeline sees through the head camera
  std::string place = "scripted";  // a place policy file (simhuman train --task place)
};

// every flag takes one value; booleans are "1" (true) or anything else (false)
Args Parse(int argc, char** argv) {
  Args a;
  const std::map<std::string, double*> doubles = {{"--frame-s", &a.frame_s},
                                                  {"--cam-distance", &a.cam_distance_m},
                                                  {"--cam-elevation", &a.cam_elevation_deg},
                                                  {"--cam-azimuth", &a.cam_azimuth_deg},
                                                  {"--t-from", &a.t_from},
                                                  {"--t-to", &a.t_to},
                                                  {"--trace-from", &a.trace_from},
                                                  {"--trace-to", &a.trace_to},
                                                  {"--trace-dt", &a.trace_dt},
                                                  {"--rot-weight", &a.rot_weight},
                                                  {"--press-m", &a.press_m},
                                                  {"--terminal-speed", &a.terminal_speed},
                                                  {"--comfort-reach", &a.comfort_reach},
                                                  {"--grip-frac", &a.grip_frac},
                                                  {"--grip-max", &a.grip_max},
                                                  {"--squeeze", &a.squeeze},
                                                  {"--path-speed", &a.path_speed},
                                                  {"--clearance", &a.clearance},
                                                  {"--object-clearance", &a.object_clearance},
                                                  {"--min-inertia", &a.min_inertia},
                                                  {"--top-behind", &a.top_behind},
                                                  {"--top-standoff", &a.top_standoff},
                                                  {"--palm-behind", &a.palm_behind},
                                                  {"--pregrasp-gap", &a.pregrasp_gap},
                                                  {"--close-rate", &a.close_rate},
                                                  {"--extra-lean", &a.extra_lean},
                                                  {"--lower-segment", &a.lower_segment},

                                                  {"--lower-speed", &a.lower_speed},
                                                  {"--release-s", &a.release_s},
                                                  {"--reshape", &a.reshape},
                                                  {"--raise-tail", &a.raise_tail_m},

                                                  {"--hold-rate", &a.hold_rate},
                                                  {"--behind-margin", &a.margin},
                                                  {"--behind-tol", &a.behind_tol},
                                                  {"--push-gain", &a.push_gain},
                                                  {"--repress-gain", &a.repress_gain},
                                                  {"--repress-max", &a.repress_max},
                                                  {"--carry-dip", &a.carry_dip},
                                                  {"--over-margin", &a.over_margin},
                                                  {"--tilt-guard-deg", &a.tilt_guard_deg},
                                                  {"--tilt-backoff", &a.tilt_backoff},
                                                  {"--thumb-clear", &a.thumb_clear}};
  const std::map<std::string, int*> ints = {{"--from", &a.from},
                                            {"--to", &a.to},
                                            {"--shortcuts", &a.shortcuts},
                                            {"--carry-over", &a.carry_over},
                                            {"--planner-seed", &a.planner_seed},
                                            {"--repress-steps", &a.repress_steps},
                                            {"--raise", &a.raise},
                                            {"--approach-steps", &a.approach_steps},
                                            {"--thumb-delay", &a.thumb_delay},
                                            {"--grasp-steps", &a.grasp_steps},
                                            {"--grasp-attempts", &a.grasp_attempts},
                                            {"--guard-steps", &a.guard_steps}};
  const std::map<std::string, bool*> bools = {{"--trace-contacts", &a.trace_contacts},
                                              {"--trace-arm", &a.trace_arm},
                                              {"--hold-rotation", &a.hold_rotation},
                                              {"--press-closing", &a.press_closing},
                                              {"--carried-check", &a.carried_check},
                                              {"--top-grasp", &a.top_grasp},
                                              {"--no-spheres", &a.no_spheres},
                                              {"--touch-gap0", &a.touch_gap0},
                                              {"--hold-behind", &a.hold_behind},
                                              {"--profile", &a.profile},
                                              {"--touch", &a.touch},
                                              {"--silhouette", &a.silhouette},
                                              {"--touch-grasp", &a.touch_grasp}};
  const std::map<std::string, std::string*> strings = {
      {"--shape", &a.shape},         {"--kind", &a.kind},     {"--sheet-dir", &a.sheet_dir},
      {"--zero-shot", &a.zero_shot}, {"--vision", &a.vision}, {"--place-policy", &a.place},
  };
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--seed") {
      a.seed = std::strtoull(v.c_str(), nullptr, 10);
    } else if (doubles.count(k)) {
      *doubles.at(k) = std::atof(v.c_str());
    } else if (ints.count(k)) {
      *ints.at(k) = std::atoi(v.c_str());
    } else if (bools.count(k)) {
      *bools.at(k) = v == "1";
    } else if (strings.count(k)) {
      *strings.at(k) = v;
    } else {
      std::fprintf(stderr, "unknown flag %s\n", k.c_str());
      std::exit(2);
    }
  }
  return a;
}

// Every 20 ms within --trace-from/--trace-to: the object's and its support's tilt, the hand's
// turn and the object's turn in the hand since the trace began, and the force the human's
// bodies put on the object (world frame, N); with --trace-arm the arm's angles and torques.
sh::control::manip::StepHook TraceHook(const Args& a, const mjModel* m,
                                       const sh::control::manip::GraspIndex& ix,
                                       const sh::control::manip::TabletopGoal& g) {
  auto next_trace = std::make_shared<double>(a.trace_from);
  const int human_root = m->body_rootid[ix.arm.hand_body];
  auto rel0 = std::make_shared<Eigen::Matrix3d>(Eigen::Matrix3d::Zero());
  auto rh0 = std::make_shared<Eigen::Matrix3d>();
  return [a, m, &ix, g, human_root, next_trace, rel0, rh0](const mjData* d) {
    if (d->time + 1e-9 < *next_trace || d->time > a.trace_to) return;
    *next_trace += a.trace_dt;
    Eigen::Vector3d f_hand = Eigen::Vector3d::Zero();
    int n_hand = 0;
    for (int c = 0; c < d->ncon; ++c) {
      const mjContact& con = d->contact[c];
      const int b1 = m->geom_bodyid[con.geom1], b2 = m->geom_bodyid[con.geom2];
      int other;
      double sign;
      if (b1 == g.object_body) {
        other = b2;
        sign = -1;  // the contact force acts on geom2 along the frame; geom1 gets minus
      } else if (b2 == g.object_body) {
        other = b1;
        sign = 1;
      } else {
        const int sup = b1 == g.support_body ? b2 : b2 == g.support_body ? b1 : -1;
        if (a.trace_contacts && sup >= 0) {
          std::printf("    support touches %s\n", mj_id2name(m, mjOBJ_BODY, sup));
        }
        continue;
      }
      if (a.trace_contacts) std::printf("    contact with %s\n", mj_id2name(m, mjOBJ_BODY, other));
      if (m->body_rootid[other] != human_root) continue;
      mjtNum f6[6];
      mj_contactForce(m, d, c, f6);
      const Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>> fr(con.frame);
      f_hand += sign * (fr.transpose() * Eigen::Vector3d(f6[0], f6[1], f6[2]));
      ++n_hand;
    }
    auto tilt = [&](int b) {
      return b < 0 ? 0.0 : std::acos(std::clamp(d->xmat[9 * b + 8], -1.0, 1.0)) * 180 / M_PI;
    };
    // the object's rotation relative to the hand since the trace began, degrees
    const int hb = ix.arm.hand_body;
    const Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>> rh(d->xmat + 9 * hb),
        ro(d->xmat + 9 * g.object_body);
    const Eigen::Matrix3d rel = rh.transpose() * ro;
    if (rel0->isZero()) {
      std::printf("  trace: object %s, support %s\n", mj_id2name(m, mjOBJ_BODY, g.object_body),
                  g.support_body < 0 ? "table" : mj_id2name(m, mjOBJ_BODY, g.support_body));
      *rel0 = rel;
      *rh0 = rh;
    }
    const double turned = Eigen::AngleAxisd(rh0->transpose() * rh).angle() * 180 / M_PI;
    const double slip = Eigen::AngleAxisd(rel0->transpose() * rel).angle() * 180 / M_PI;
    std::printf(
        "  t %.2f tilt obj %5.1f sup %5.1f hand turned %5.1f slip %5.1f obj (%.3f %.3f %.3f)  hand "
        "force (%6.1f %6.1f %6.1f) n=%d\n",
        d->time, tilt(g.object_body), tilt(g.support_body), turned, slip,
        d->xipos[3 * g.object_body], d->xipos[3 * g.object_body + 1],
        d->xipos[3 * g.object_body + 2], f_hand.x(), f_hand.y(), f_hand.z(), n_hand);
    if (a.trace_contacts) {
      const int table = mj_name2id(m, mjOBJ_BODY, "obj/table000");
      if (table >= 0) {
        std::printf("    table tilt %.2f deg, origin (%.3f %.3f %.3f)\n", tilt(table),
                    d->xpos[3 * table], d->xpos[3 * table + 1], d->xpos[3 * table + 2]);
      }
      const mjtNum* palm = d->site_xpos + 3 * ix.arm.palm_site;
      // the palm's centre against the object: height above its base, and horizontally along
      // the palm's outward normal (gap to the side the half width gives) and across it
      const mjtNum* hr = d->xmat + 9 * ix.arm.hand_body;
      Eigen::Vector3d n(hr[1], hr[4], 0);
      if (!ix.arm.right) n = -n;
      n = n.norm() > 1e-9 ? n.normalized() : n;
      const Eigen::Vector3d to(d->xipos[3 * g.object_body] - palm[0],
                               d->xipos[3 * g.object_body + 1] - palm[1], 0);
      Eigen::Vector3d f(-hr[2], -hr[5], 0);  // the fingers' direction, level, square to n
      f -= f.dot(n) * n;
      f = f.norm() > 1e-9 ? f.normalized() : f;
      const double along = to.dot(n);
      std::printf(
          "    palm (%.3f %.3f %.3f): gap %.3f m along its normal, the object's axis "
          "%.3f m ahead along the fingers, %.3f m above the base\n",
          palm[0], palm[1], palm[2], along - g.half_width_m, to.dot(f),
          palm[2] - d->xpos[3 * g.object_body + 2]);
    }
    if (a.trace_arm) {
      std::printf("     arm q");
      for (int j = 0; j < 7; ++j) std::printf(" %6.2f", d->qpos[ix.arm.qpos[j]]);
      std::printf("  tau");
      for (int j = 0; j < 7; ++j) std::printf(" %6.1f", d->actuator_force[ix.arm.actuator[j]]);
      for (int j = 0; j < m->njnt; ++j) {
        const std::string name = mj_id2name(m, mjOBJ_JOINT, j) ? mj_id2name(m, mjOBJ_JOINT, j) : "";
        if (name.size() >= 9 && name.compare(name.size() - 9, 9, "abdomen_y") == 0) {
          std::printf("  lean %.1f deg", d->qpos[m->jnt_qposadr[j]] * 180 / M_PI);
        }
      }
      std::printf("\n");
    }
  };
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = Parse(argc, argv);
  const auto place = sh::control::LoadPlacePolicy(a.place);
  if (!place.ok()) {
    std::fprintf(stderr, "%s\n", std::string(place.status().message()).c_str());
    return 2;
  }
  int done = 0, ran = 0;
  for (int i = a.from; i < a.to; ++i) {
    const uint64_t seed = sh::core::DeriveSeed(a.seed, 0x7ab1e, static_cast<uint64_t>(i));
    const std::string kind = i % 2 == 0 ? "place" : "stack";
    if (!a.kind.empty() && kind != a.kind) continue;
    auto ts = sh::world::GenerateTabletop(seed, kind);
    if (!ts.ok()) return 1;
    if (!a.zero_shot.empty()) {
      if (sh::core::Status s = sh::world::MakeZeroShot(&*ts, a.zero_shot); !s.ok()) {
        std::fprintf(stderr, "%s\n", s.ToString().c_str());
        return 2;
      }
    }
    auto catalog = sh::world::BuildCatalog(ts->scene);
    auto human = sh::world::AgentFromHuman(ts->scene.humans[0], 0, *catalog);
    auto w = sh::world::SimWorld::Create(*catalog, {*human}, sh::world::DexterousModelOptions());
    if (!w.ok()) return 1;
    auto ix = sh::control::manip::MakeGraspIndex(**w, 0, true);
    auto goal = sh::eval::TabletopSceneGoal(*ts, **w);
    if (!goal.ok()) return 1;
    // with --vision the goal's geometry and the controllers' view come from the head camera
    static std::unique_ptr<sh::eval::TabletopVision> vision;
    if (!a.vision.empty()) {
      if (!vision) {
        sh::eval::VisionLoopOptions vo;
        vo.touch = a.touch;
        vo.silhouette = a.silhouette;
        vo.touch_grasp = a.touch_grasp;
        auto made = sh::eval::TabletopVision::Create(a.vision, (*w)->model(), vo);
        if (!made.ok()) {
          std::fprintf(stderr, "%s\n", made.status().ToString().c_str());
          return 2;
        }
        vision = std::move(*made);
      }
      const sh::control::manip::TabletopGoal truth = *goal;
      if (sh::core::Status s = vision->Begin(**w, *catalog, ts->task.object_id, ts->task.target_id,
                                             &*goal, ix->arm.hand_body);
          !s.ok()) {
        std::printf("ep %3d perception failure: %s\n", i, s.ToString().c_str());
        continue;
      }
      // task planning's errors: the moved object's base and half width, the target
      const Eigen::Vector3d eb = goal->planned_pos - truth.planned_pos;
      const Eigen::Vector3d et = goal->target - truth.target;
      const sh::perceive::SilhouetteFit& fit = vision->moved_fit();
      std::printf(
          "  planning error: base (%.2f %.2f %.2f) cm, half width %.2f cm, target (%.2f "
          "%.2f %.2f) cm; silhouette fit %s%s, mismatch %.0f -> %.0f of %d px, hidden "
          "%.2f\n",
          100 * eb.x(), 100 * eb.y(), 100 * eb.z(), 100 * (goal->half_width_m - truth.half_width_m),
          100 * et.x(), 100 * et.y(), 100 * et.z(),
          !fit.fitted    ? "not tried"
          : fit.accepted ? "kept"
                         : "refused",
          fit.sideways_only ? " (sideways only)" : "", fit.before, fit.after, fit.blob_pixels,
          fit.hidden);
    }
    const sh::control::manip::TabletopGoal& g = *goal;
    if (!a.shape.empty() && a.shape != ShapeName(g.shape)) continue;
    if (a.shape.empty() && a.no_spheres && g.shape == GraspShape::kSphere) continue;
    const mjModel* m = (*w)->model();
    sh::control::manip::TabletopOptions pipeline;
    pipeline.transport_checks_object = a.carried_check;
    pipeline.sphere_top_grasp = a.top_grasp;
    if (a.top_behind > -1) pipeline.top_palm_behind_m = a.top_behind;
    if (a.top_standoff >= 0) pipeline.top_standoff_m = a.top_standoff;
    if (a.palm_behind >= 0) pipeline.palm_behind_m = a.palm_behind;
    if (a.margin > -1) pipeline.palm_behind_margin_m = a.margin;
    if (a.pregrasp_gap >= 0) pipeline.pregrasp_gap_m = a.pregrasp_gap;
    if (a.extra_lean > 0) pipeline.lean_deg.push_back(a.extra_lean);
    if (a.lower_segment > 0) pipeline.lower_segment_m = a.lower_segment;
    if (a.lower_speed > 0) pipeline.lower_speed_mps = a.lower_speed;
    if (a.release_s > 0) pipeline.release_s = a.release_s;
    if (a.grasp_steps > 0) pipeline.grasp_policy_steps = a.grasp_steps;
    if (a.grasp_attempts > 0) pipeline.grasp_attempts = a.grasp_attempts;
    if (a.squeeze >= 0) pipeline.finger_squeeze_rad = a.squeeze;
    if (a.clearance >= 0) pipeline.carry_clearance_m = a.clearance;
    if (a.object_clearance >= 0) pipeline.motion.object_clearance_m = a.object_clearance;
    if (a.comfort_reach > 0) pipeline.comfort_reach_m = a.comfort_reach;
    if (a.grip_frac > 0) pipeline.grip_height_frac = a.grip_frac;
    if (a.shortcuts >= 0) pipeline.motion.planner.shortcut_iterations = a.shortcuts;
    if (a.grip_max > 0) pipeline.grip_max_m = a.grip_max;
    if (a.terminal_speed >= 0) pipeline.motion.terminal_palm_speed_mps = a.terminal_speed;
    if (a.min_inertia >= 0) pipeline.tracker.min_inertia = a.min_inertia;
    if (a.path_speed > 0) pipeline.motion.mean_path_speed = a.path_speed;
    if (a.raise == 1) pipeline.raise_via_rad = sh::control::manip::SeatedRaiseViaRad();
    if (a.raise == 0) pipeline.raise_via_rad.clear();
    if (a.reshape >= 0) pipeline.motion.reshape_fraction = a.reshape;
    if (a.raise_tail_m >= 0) pipeline.raise_tail_m = a.raise_tail_m;
    if (a.carry_dip >= 0) pipeline.carry_dip_m = a.carry_dip;
    if (a.carry_over >= 0) pipeline.carry_over_arc = a.carry_over == 1;
    if (a.over_margin >= 0) pipeline.carry_over.margin_m = a.over_margin;
    if (a.planner_seed > 0) pipeline.motion.planner.seed = static_cast<uint64_t>(a.planner_seed);
    sh::control::manip::ScriptedGraspOptions so;
    so.hold_rotation = a.hold_rotation;
    so.press_while_closing = a.press_closing;
    so.touch_ends_gap = a.touch_gap0;
    so.hold_behind = a.hold_behind;
    so.behind_tol_m = a.behind_tol;
    so.push_gain = a.push_gain;
    if (a.repress_gain >= 0) so.repress_gain = a.repress_gain;
    if (a.repress_max >= 0) so.repress_max_m = a.repress_max;
    if (a.repress_steps >= 0) so.repress_steps = a.repress_steps;
    if (a.tilt_guard_deg >= 0) so.tilt_guard_rad = a.tilt_guard_deg * M_PI / 180;
    if (a.tilt_backoff >= 0) so.tilt_backoff_m = a.tilt_backoff;
    if (a.guard_steps >= 0) so.tilt_guard_steps = a.guard_steps;
    if (a.thumb_clear >= 0) so.thumb_clear_step_m = a.thumb_clear;
    if (a.press_m >= 0) so.press_m = a.press_m;
    if (a.close_rate > 0) so.close_rate = static_cast<float>(a.close_rate);
    if (a.hold_rate >= 0) so.hold_rate = static_cast<float>(a.hold_rate);
    if (a.approach_steps > 0) so.approach_steps = a.approach_steps;
    if (a.thumb_delay >= 0) so.thumb_delay_steps = a.thumb_delay;
    if (a.rot_weight > 0) so.ik_rot_weight_m = a.rot_weight;
    const sh::control::manip::GraspPolicyFactory grasp =
        [&](const sh::control::manip::TabletopGoal& at) {
          if (a.trace_from >= 0) {
            const mjData* dd = (*w)->data();
            std::printf("  grasp begins at t %.2f\n", dd->time);
            // the digits' tips and the palm point from the object's centre of mass (world axes)
            const Eigen::Vector3d c(dd->xipos + 3 * at.object_body);
            for (const char* s : {"right_palm_centre", "right_index_tip", "right_middle_tip",
                                  "right_ring_tip", "right_little_tip", "right_thumb_tip"}) {
              const int id = mj_name2id(m, mjOBJ_SITE, s);  // the seated human is agent 0
              if (id < 0) continue;
              const Eigen::Vector3d p = Eigen::Vector3d(dd->site_xpos + 3 * id) - c;
              std::printf("    %-18s (%6.3f %6.3f %6.3f) |%.3f|\n", s, p.x(), p.y(), p.z(),
                          p.norm());
            }
          }
          return sh::control::manip::MakeScriptedGrasp(m, (*w)->data(), *ix, at, pipeline, so);
        };
    std::unique_ptr<sh::render::OffscreenRenderer> r;
    std::vector<std::vector<uint8_t>> frames;
    constexpr int kW = 320, kH = 240;
    double next = 0;
    sh::control::manip::StepHook hook;
    if (a.trace_from >= 0) hook = TraceHook(a, m, *ix, g);
    if (!a.sheet_dir.empty()) {
      auto made = sh::render::OffscreenRenderer::Create(m, kW, kH);
      if (made.ok()) r = std::move(*made);
      hook = [&](const mjData* d) {
        if (!r || d->time + 1e-9 < next) return;
        next += a.frame_s;
        if (d->time < a.t_from || d->time > a.t_to) return;
        sh::render::CameraSpec cam;
        const Eigen::Vector3d obj_pos(d->xipos + 3 * g.object_body);
        cam.lookat = obj_pos + Eigen::Vector3d(0, 0, 0.03);
        cam.distance_m = a.cam_distance_m;
        cam.azimuth_deg = a.cam_azimuth_deg;
        cam.elevation_deg = a.cam_elevation_deg;
        std::vector<uint8_t> rgb;
        char cap[32];
        std::snprintf(cap, sizeof(cap), "%.1f s", d->time);
        if (r->Render(d, cam, &rgb, cap).ok()) frames.push_back(std::move(rgb));
      };
    }
    if (vision) {
      hook = [inner = hook](const mjData* d) {
        (void)vision->OnStep(d);
        if (inner) inner(d);
      };
    }
    // the reach's directness: the palm's path until it first comes within 12 cm of the object,
    // against the straight line between its ends; and how far the elbow swings out to the side
    // on the way (along the chest's sideways axis, outward from the shoulder: the largest offset,
    // and the largest angle of the upper arm from hanging, seen from the front: 90 degrees is
    // the arm held out level to the side)
    // path, start x y z, elbow out, side angle, out now
    auto reach = std::make_shared<std::array<double, 7>>();
    (*reach)[1] = std::nan("");
    (*reach)[4] = -1;
    (*reach)[5] = -180;
    const int upper = m->dof_bodyid[ix->arm.dof[0]];
    const int lower = m->dof_bodyid[ix->arm.dof[3]];
    const int chest = m->body_parentid[upper];
    const double outward = ix->arm.right ? -1.0 : 1.0;
    hook = [inner = hook, reach, site = ix->arm.palm_site, ob = g.object_body, upper, lower, chest,
            outward](const mjData* d) {
      if (inner) inner(d);
      auto& rc = *reach;
      if (rc[0] < 0) return;
      const Eigen::Vector3d e =
          Eigen::Vector3d(d->xpos + 3 * lower) - Eigen::Vector3d(d->xpos + 3 * upper);
      const Eigen::Vector3d side(d->xmat[9 * chest + 1], d->xmat[9 * chest + 4],
                                 d->xmat[9 * chest + 7]);
      rc[6] = outward * e.dot(side);
      rc[4] = std::max(rc[4], rc[6]);
      rc[5] = std::max(rc[5], std::atan2(rc[6], -e.z()) * 180 / M_PI);
      const Eigen::Vector3d p(d->site_xpos + 3 * site);
      static thread_local Eigen::Vector3d last;
      if (std::isnan(rc[1])) {
        rc[1] = p.x(), rc[2] = p.y(), rc[3] = p.z();
      } else {
        rc[0] += (p - last).norm();
      }
      last = p;
      if ((p - Eigen::Vector3d(d->xipos + 3 * ob)).norm() < 0.12) {
        const double straight = (p - Eigen::Vector3d(rc[1], rc[2], rc[3])).norm();
        std::printf(
            "  reach path %.2f m, straight %.2f m, ratio %.2f, elbow out %.2f m, side angle %.0f "
            "deg, out at the end %.2f m\n",
            rc[0], straight, rc[0] / std::max(straight, 1e-3), rc[4], rc[5], rc[6]);
        rc[0] = -1;
      }
    };
    // the transport's directness: the object's path from when it first rose 5 cm until it comes
    // within 5 cm (horizontally) of over the target, against the straight line, and how far
    // below its start height it went on the way (path, start x y z, lowest dip, done)
    auto carry = std::make_shared<std::array<double, 6>>();
    (*carry)[1] = std::nan("");
    hook = [inner = hook, carry, ob = g.object_body, z0 = g.planned_pos.z(),
            target = g.target](const mjData* d) {
      if (inner) inner(d);
      auto& cr = *carry;
      if (cr[5] > 0) return;
      const Eigen::Vector3d o(d->xpos + 3 * ob);
      static thread_local Eigen::Vector3d last;
      if (std::isnan(cr[1])) {
        if (o.z() < z0 + 0.05) return;
        cr[1] = o.x(), cr[2] = o.y(), cr[3] = o.z();
        cr[4] = 0;
      } else {
        cr[0] += (o - last).norm();
        cr[4] = std::max(cr[4], cr[3] - o.z());
      }
      last = o;
      if ((o - target).head<2>().norm() < 0.05) {
        const double straight = (o - Eigen::Vector3d(cr[1], cr[2], cr[3])).norm();
        std::printf("  transport path %.2f m, straight %.2f m, ratio %.2f, dip %.2f m\n", cr[0],
                    straight, cr[0] / std::max(straight, 1e-3), cr[4]);
        cr[5] = 1;
      }
    };
    if (a.profile) mjcb_time = ClockUs;
    const auto res = sh::control::manip::RunTabletop(**w, *ix, g, grasp, pipeline, hook, *place);
    if (a.profile) {
      const mjData* dd = (*w)->data();
      auto us = [&](int t) { return dd->timer[t].duration / std::max(1, dd->timer[t].number); };
      std::printf(
          "  profile: wall %.2f s, %d steps, %.0f steps/s; mj_step %.1f us (fwd %.1f: pos %.1f "
          "[collision %.1f, make %.1f, project %.1f], vel %.1f, act %.1f, acc %.1f, constraint "
          "%.1f); "
          "nv %d, ncon %d, nefc %d, ngeom %d\n",
          res.wall_s, res.sim_steps, res.sim_steps / res.wall_s, us(mjTIMER_STEP),
          us(mjTIMER_FORWARD), us(mjTIMER_POSITION), us(mjTIMER_POS_COLLISION),
          us(mjTIMER_POS_MAKE), us(mjTIMER_POS_PROJECT), us(mjTIMER_VELOCITY),
          us(mjTIMER_ACTUATION), us(mjTIMER_ACCELERATION), us(mjTIMER_CONSTRAINT), m->nv, dd->ncon,
          dd->nefc, m->ngeom);
      for (int c = 0; c < dd->ncon; ++c) {
        std::printf("    %s - %s\n",
                    mj_id2name(m, mjOBJ_BODY, m->geom_bodyid[dd->contact[c].geom1]),
                    mj_id2name(m, mjOBJ_BODY, m->geom_bodyid[dd->contact[c].geom2]));
      }
    }
    ++ran;
    done += res.success;
    if (!res.success && res.plan_failure) {
      const Eigen::Vector3d t = sh::world::WorldToTable(g.planned_pos);
      const Eigen::Vector3d tt = sh::world::WorldToTable(g.target);
      std::printf("  object at table (%.2f, %.2f), target (%.2f, %.2f, %.2f)\n", t.x(), t.y(),
                  tt.x(), tt.y(), tt.z());
    }
    const Eigen::Vector3d at = sh::world::WorldToTable(g.planned_pos);
    std::printf("ep %3d %-5s %-8s w=%.3f h=%.3f m=%.2f at (%5.2f %5.2f) gap %5.3f  %s [%s %s]\n", i,
                kind.c_str(), ShapeName(g.shape), 2 * g.half_width_m, g.height_m,
                m->body_mass[g.object_body], at.x(), at.y(), res.release_gap_m,
                (std::string(sh::control::manip::TabletopStageName(res.failed_stage)) + ": " +
                 res.end_reason)
                    .c_str(),
                res.reach_route.c_str(), res.transport_route.c_str());
    std::fflush(stdout);
    if (!frames.empty()) {
      const std::string path = a.sheet_dir + "/ep" + std::to_string(i) + ".png";
      (void)sh::render::WriteContactSheet(path, frames, kW, kH, 6);
    }
  }
  std::printf("done %d / %d\n", done, ran);
  return 0;
}
