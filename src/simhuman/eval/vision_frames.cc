#include "simhuman/eval/vision_frames.h"

#include <chrono>
#include <cmath>
#include <memory>

#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/control/policy/grasp_policy.h"
#include "simhuman/core/rng.h"
#include "simhuman/eval/tabletop_eval.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::eval {

namespace {

using Episode = TableWorld;

Eigen::Vector3d Jitter(core::Rng& rng, double r) {
  return Eigen::Vector3d(rng.Uniform(-r, r), rng.Uniform(-r, r), 0.0);
}

// renders one frame of `d` with its truth and hands it on
core::Status Shoot(perceive::HeadCamera& cam, const Episode& e, const mjData* d,
                   const Eigen::Vector3d& gaze, const std::string& stage, uint64_t seed,
                   const std::function<void(VisionFrame&)>& on_frame) {
  VisionFrame f;
  f.stage = stage;
  f.scene_seed = seed;
  f.camera = cam.Aim(*e.world, d, 0, gaze);
  const auto t0 = std::chrono::steady_clock::now();
  SH_RETURN_IF_ERROR(cam.Capture(d, f.camera, &f.rgb));
  f.render_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  SH_RETURN_IF_ERROR(cam.CaptureBodyIds(d, f.camera, &f.body_ids));
  f.truth = perceive::TableObjectsTruth(*e.world, e.catalog, d);
  perceive::CountPixels(f.body_ids, f.camera.width, f.camera.height, &f.truth);
  for (size_t i = 0; i < f.truth.size(); ++i) {
    if (f.truth[i].id == e.ts.task.object_id) f.task_object = static_cast<int>(i);
  }
  on_frame(f);
  return absl::OkStatus();
}

// `out`: `d` with the free body `body` turned by `angle` about the horizontal axis at `heading`
// through site `pivot` (the palm point: the object stays in the hand), its kinematics done
void TiltHeldObject(const mjModel* m, const mjData* d, int body, int pivot, double angle,
                    double heading, mjData* out) {
  mj_copyData(out, m, d);
  const int j = m->body_jntadr[body];
  mjtNum* q = out->qpos + m->jnt_qposadr[j];
  const Eigen::Vector3d axis(std::cos(heading), std::sin(heading), 0);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, axis));
  const Eigen::Vector3d p(d->site_xpos + 3 * pivot);
  const Eigen::Vector3d pos = p + turn * (Eigen::Vector3d(q[0], q[1], q[2]) - p);
  const Eigen::Quaterniond rot = turn * Eigen::Quaterniond(q[3], q[4], q[5], q[6]);
  q[0] = pos.x();
  q[1] = pos.y();
  q[2] = pos.z();
  q[3] = rot.w();
  q[4] = rot.x();
  q[5] = rot.y();
  q[6] = rot.z();
  mj_kinematics(m, out);
}

// a renderer draws the model it was given: each scene's world is another model
core::Status UseModel(const VisionFrameOptions& o, const mjModel* m,
                      std::unique_ptr<perceive::HeadCamera>* cam) {
  if (*cam) return (*cam)->SetModel(m);
  SH_ASSIGN_OR_RETURN(*cam, perceive::HeadCamera::Create(m, o.width, o.height, o.fovy_deg));
  return absl::OkStatus();
}

}  // namespace

core::Status CollectVisionFrames(const VisionFrameOptions& o,
                                 const std::function<void(VisionFrame&)>& on_frame) {
  std::unique_ptr<perceive::HeadCamera> cam;
  for (int i = 0; i < o.planning_scenes; ++i) {
    const uint64_t seed = core::DeriveSeed(o.seed, 0x7151, o.stream, static_cast<uint64_t>(i));
    SH_ASSIGN_OR_RETURN(Episode e, MakeTableWorld(seed, i % 2 == 0 ? "place" : "stack"));
    SH_RETURN_IF_ERROR(UseModel(o, e.world->model(), &cam));
    core::Rng rng(core::DeriveSeed(seed, 0x9a2e));
    for (int v = 0; v < o.planning_views; ++v) {
      const Eigen::Vector3d gaze = perceive::PlanningGaze() + Jitter(rng, o.gaze_jitter_m);
      SH_RETURN_IF_ERROR(Shoot(*cam, e, e.world->data(), gaze, "planning", seed, on_frame));
    }
  }
  if (o.placing_episodes <= 0) return absl::OkStatus();
  SH_ASSIGN_OR_RETURN(const control::GraspPolicyMaker make_grasp,
                      control::LoadGraspPolicy("scripted"));
  const control::manip::TabletopOptions pipeline;
  for (int i = 0; i < o.placing_episodes; ++i) {
    const uint64_t seed = core::DeriveSeed(o.seed, 0x7152, o.stream, static_cast<uint64_t>(i));
    const std::string kind = i % 2 == 0 ? "place" : "stack";
    SH_ASSIGN_OR_RETURN(Episode e, MakeTableWorld(seed, kind));
    SH_RETURN_IF_ERROR(UseModel(o, e.world->model(), &cam));
    SH_ASSIGN_OR_RETURN(control::manip::GraspIndex ix,
                        control::manip::MakeGraspIndex(*e.world, 0, true));
    SH_ASSIGN_OR_RETURN(control::manip::TabletopGoal goal, TabletopSceneGoal(e.ts, *e.world));
    const control::manip::GraspPolicyFactory grasp = [&](const control::manip::TabletopGoal& g) {
      return make_grasp(e.world->model(), e.world->data(), ix, g, pipeline);
    };
    core::Rng rng(core::DeriveSeed(seed, 0x9a2f));
    const Eigen::Vector3d aim = goal.target + Jitter(rng, o.position_noise_m);
    const Eigen::Vector3d start =
        Eigen::Map<const Eigen::Vector3d>(e.world->data()->xpos + 3 * goal.object_body);
    int step = 0, shot = 0;
    core::Status status;
    std::unique_ptr<mjData, void (*)(mjData*)> tilted(mj_makeData(e.world->model()), mj_deleteData);
    const int every = std::max(
        1, static_cast<int>(std::lround(o.placing_every_s / e.world->model()->opt.timestep)));
    auto hook = [&](const mjData* d) {
      if (++step % every != 0 || shot >= o.placing_frames || !status.ok()) return;
      const Eigen::Map<const Eigen::Vector3d> p(d->xpos + 3 * goal.object_body);
      // placing: lifted and over the destination
      const bool lifted = p.z() > start.z() + 0.03;
      const bool near = (p - goal.target).head<2>().norm() < o.placing_near_m;
      if (!lifted || !near) return;
      const Eigen::Vector3d gaze = aim + Jitter(rng, o.gaze_jitter_m);
      const mjData* shown = d;
      if (o.held_tilt_share > 0 && rng.Uniform() < o.held_tilt_share) {
        TiltHeldObject(e.world->model(), d, goal.object_body, ix.arm.palm_site,
                       rng.Uniform(0.0, o.held_tilt_max_deg * M_PI / 180), rng.Uniform(-M_PI, M_PI),
                       tilted.get());
        shown = tilted.get();
      }
      status =
          Shoot(*cam, e, shown, gaze, kind == "place" ? "placing" : "stacking", seed, on_frame);
      ++shot;
    };
    control::manip::RunTabletop(*e.world, ix, goal, grasp, pipeline, hook);
    SH_RETURN_IF_ERROR(status);
  }
  return absl::OkStatus();
}

}  // namespace simhuman::eval
