#include "simhuman/learn/gait_clip.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "simhuman/learn/walk_env.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::learn {

absl::Status GaitClipOptions::Validate() const {
  if (!(seconds > 0 && seconds <= 3600)) {
    return absl::InvalidArgumentError("gait clip: seconds must be in (0, 3600]");
  }
  if (!(fps > 0 && fps <= 1000)) {
    return absl::InvalidArgumentError("gait clip: fps must be in (0, 1000]");
  }
  if (!(speed_mps >= -0.4 && speed_mps <= params.vmax_mps)) {
    return absl::InvalidArgumentError("gait clip: speed must be in [-0.4, " +
                                      std::to_string(params.vmax_mps) + "] m/s");
  }
  return absl::OkStatus();
}

core::StatusOr<MotionClip> GaitClip(const GaitClipOptions& o) {
  SH_RETURN_IF_ERROR(o.Validate());
  SH_ASSIGN_OR_RETURN(std::unique_ptr<world::SimWorld> sim,
                      world::SimWorld::Create(core::SceneCatalog(), {world::AgentSpec()}, {}));
  const mjModel* m = sim->model();
  mjData* d = sim->data();
  const world::AgentIndex& a = sim->agent(0);
  int feet[2] = {mj_name2id(m, mjOBJ_GEOM, "left_foot_geom"),
                 mj_name2id(m, mjOBJ_GEOM, "right_foot_geom")};
  if (feet[0] < 0 || feet[1] < 0) return absl::InternalError("gait clip: no foot geoms");
  MotionClip clip;
  clip.fps = o.fps;
  clip.source = "simhuman clip gait (speed " + std::to_string(o.speed_mps) + " m/s)";
  const int n = static_cast<int>(std::floor(o.seconds * o.fps + 1e-9)) + 1;
  control::WalkCommand cmd{o.speed_mps, 0, 0};
  mj_resetData(m, d);
  for (int f = 0; f < n; ++f) {
    double t = f / o.fps;
    ClipFrame fr;
    control::WalkReference(o.params, std::fmod(t / o.params.gait_period_s, 1.0), 1.0, cmd,
                           fr.q_rad.data());
    fr.root_pos_m = {o.speed_mps * t, 0, world::kPelvisStandHeight};
    // kinematics at the nominal height, then lower the pelvis until the lower foot touches
    for (int k = 0; k < 3; ++k) d->qpos[a.root_qpos + k] = fr.root_pos_m[k];
    for (int j = 0; j < world::kHumanoidDofs; ++j) d->qpos[a.hinge_qpos[j]] = fr.q_rad[j];
    mj_kinematics(m, d);
    fr.root_pos_m[2] -= LowestBoxCornerZ(m, d, {feet[0], feet[1]});
    clip.frames.push_back(fr);
  }
  return clip;
}

}  // namespace simhuman::learn
