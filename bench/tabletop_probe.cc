// A diagnostic driver for the tabletop pipeline (not a test, not a benchmark): runs the
// `tabletop` suite's episodes one by one, optionally only those moving one shape, prints each
// end reason and can film an episode as a contact sheet of the hand, so a grasp change can be
// tried on a fixed sample and looked at.
//
//   simhuman_tabletop_probe --seed 1 --from 0 --to 80 [--shape sphere] [--kind place]
//                           [--sheet-dir /tmp/sheets] [--frame-s 0.2]
// The episodes are those of `simhuman eval --suite tabletop --seed S` (same seeds, same kinds).

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "simhuman/control/manip/scripted_grasp.h"
#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/core/rng.h"
#include "simhuman/eval/tabletop_eval.h"
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
  double frame_s = 0.2;
  double cam_distance_m = 0.55, cam_azimuth_deg = 150, cam_elevation_deg = -25;
  double t_from = 0, t_to = 1e9;
  bool carried_check = true, top_grasp = false;
  int grasp_steps = 0;
  double squeeze = -1, path_speed = 0;
  bool no_spheres = false, profile = false;  ///< frames only in this window (s)
};

Args Parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--seed") {
      a.seed = std::strtoull(v.c_str(), nullptr, 10);
    } else if (k == "--from") {
      a.from = std::atoi(v.c_str());
    } else if (k == "--to") {
      a.to = std::atoi(v.c_str());
    } else if (k == "--shape") {
      a.shape = v;
    } else if (k == "--kind") {
      a.kind = v;
    } else if (k == "--sheet-dir") {
      a.sheet_dir = v;
    } else if (k == "--cam-distance") {
      a.cam_distance_m = std::atof(v.c_str());
    } else if (k == "--cam-elevation") {
      a.cam_elevation_deg = std::atof(v.c_str());
    } else if (k == "--cam-azimuth") {
      a.cam_azimuth_deg = std::atof(v.c_str());
    } else if (k == "--t-from") {
      a.t_from = std::atof(v.c_str());
    } else if (k == "--t-to") {
      a.t_to = std::atof(v.c_str());
    } else if (k == "--carried-check") {
      a.carried_check = v == "1";
    } else if (k == "--squeeze") {
      a.squeeze = std::atof(v.c_str());
    } else if (k == "--path-speed") {
      a.path_speed = std::atof(v.c_str());
    } else if (k == "--grasp-steps") {
      a.grasp_steps = std::atoi(v.c_str());
    } else if (k == "--profile") {
      a.profile = v == "1";
    } else if (k == "--no-spheres") {
      a.no_spheres = v == "1";
    } else if (k == "--top-grasp") {
      a.top_grasp = v == "1";
    } else if (k == "--frame-s") {
      a.frame_s = std::atof(v.c_str());
    } else {
      std::fprintf(stderr, "unknown flag %s\n", k.c_str());
      std::exit(2);
    }
  }
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = Parse(argc, argv);
  int done = 0, ran = 0;
  for (int i = a.from; i < a.to; ++i) {
    const uint64_t seed = sh::core::DeriveSeed(a.seed, 0x7ab1e, static_cast<uint64_t>(i));
    const std::string kind = i % 2 == 0 ? "place" : "stack";
    if (!a.kind.empty() && kind != a.kind) continue;
    auto ts = sh::world::GenerateTabletop(seed, kind);
    if (!ts.ok()) return 1;
    auto catalog = sh::world::BuildCatalog(ts->scene);
    auto human = sh::world::AgentFromHuman(ts->scene.humans[0], 0, *catalog);
    auto w = sh::world::SimWorld::Create(*catalog, {*human}, sh::world::DexterousModelOptions());
    if (!w.ok()) return 1;
    auto ix = sh::control::manip::MakeGraspIndex(**w, 0, true);
    auto goal = sh::eval::TabletopSceneGoal(*ts, **w);
    if (!goal.ok()) return 1;
    const sh::control::manip::TabletopGoal& g = *goal;
    if (!a.shape.empty() && a.shape != ShapeName(g.shape)) continue;
    if (a.shape.empty() && a.no_spheres && g.shape == GraspShape::kSphere) continue;
    const mjModel* m = (*w)->model();
    sh::control::manip::TabletopOptions pipeline;
    pipeline.transport_checks_object = a.carried_check;
    pipeline.sphere_top_grasp = a.top_grasp;
    if (a.grasp_steps > 0) pipeline.grasp_policy_steps = a.grasp_steps;
    if (a.squeeze >= 0) pipeline.finger_squeeze_rad = a.squeeze;
    if (a.path_speed > 0) pipeline.motion.mean_path_speed = a.path_speed;
    auto grasp = sh::control::manip::MakeScriptedGrasp(m, (*w)->data(), *ix, g, pipeline);
    std::unique_ptr<sh::render::OffscreenRenderer> r;
    std::vector<std::vector<uint8_t>> frames;
    constexpr int kW = 320, kH = 240;
    double next = 0;
    sh::control::manip::StepHook hook;
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
    if (a.profile) mjcb_time = ClockUs;
    const auto res = sh::control::manip::RunTabletop(**w, *ix, g, grasp, pipeline, hook);
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
    std::printf("ep %3d %-5s %-8s w=%.3f h=%.3f m=%.2f  %s\n", i, kind.c_str(), ShapeName(g.shape),
                2 * g.half_width_m, g.height_m, m->body_mass[g.object_body],
                (std::string(sh::control::manip::TabletopStageName(res.failed_stage)) + ": " +
                 res.end_reason)
                    .c_str());
    std::fflush(stdout);
    if (!frames.empty()) {
      const std::string path = a.sheet_dir + "/ep" + std::to_string(i) + ".png";
      (void)sh::render::WriteContactSheet(path, frames, kW, kH, 6);
    }
  }
  std::printf("done %d / %d\n", done, ran);
  return 0;
}
