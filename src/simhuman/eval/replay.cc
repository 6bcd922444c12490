#include "simhuman/eval/replay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "simhuman/eval/episode.h"
#include "simhuman/render/auto_camera.h"
#include "simhuman/render/camera.h"
#include "simhuman/render/image_io.h"
#include "simhuman/render/offscreen.h"
#include "simhuman/render/video.h"

namespace simhuman::eval {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

std::string Caption(const plan::ContactChain& chain, int step, double t) {
  int n = static_cast<int>(chain.steps.size());
  int i = std::clamp(step, 0, n - 1);
  char buf[48];
  std::snprintf(buf, sizeof(buf), " t=%.2f s", t);
  return "step " + std::to_string(i + 1) + "/" + std::to_string(n) + " " +
         StepText(chain.steps[i]) + buf;
}

// indices of `count` frames evenly spaced over [0, n), first and last included
std::vector<size_t> EvenlySpaced(size_t n, int count) {
  std::vector<size_t> out;
  if (n == 0 || count <= 0) return out;
  if (count == 1) return {0};  // (the spacing below divides by count - 1)
  if (static_cast<size_t>(count) >= n) {
    for (size_t i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  for (int k = 0; k < count; ++k) {
    out.push_back(static_cast<size_t>(std::lround(static_cast<double>(k) * (n - 1) / (count - 1))));
  }
  return out;
}

// the humans' mean facing (degrees about +z), the way the preferred view looks at
double FacingDeg(const world::SimWorld& world, const mjData* d) {
  double x = 0, y = 0;
  for (int a = 0; a < world.num_agents(); ++a) {
    const double yaw = world::PelvisYaw(d, world.agent(a));
    x += std::cos(yaw);
    y += std::sin(yaw);
  }
  return std::atan2(y, x) * kRadToDeg;
}

// a camera that frames every human and keeps their body points in view (hands count double:
// at a table they are what the step is about)
std::unique_ptr<render::AutoCamera> MakeAutoCamera(const world::SimWorld& world,
                                                   const ReplayOptions& options) {
  std::vector<int> bodies, sites;
  std::vector<double> weights;
  for (int a = 0; a < world.num_agents(); ++a) {
    const world::AgentIndex& ag = world.agent(a);
    bodies.insert(bodies.end(), ag.bodies.begin(), ag.bodies.end());
    for (size_t p = 0; p < ag.site.size(); ++p) {
      sites.push_back(ag.site[p]);
      const bool hand = p == static_cast<size_t>(core::BodyJoint::kLeftHand) ||
                        p == static_cast<size_t>(core::BodyJoint::kRightHand);
      weights.push_back(hand ? 2.0 : 1.0);
    }
  }
  render::AutoCameraOptions o;
  o.margin = options.margin;
  o.smooth_s = options.smooth_s;
  o.aspect = static_cast<double>(options.width) / options.height;
  return std::make_unique<render::AutoCamera>(world.model(), bodies, sites, weights, o);
}

}  // namespace

absl::Status RenderReplay(const world::SimWorld& world, const plan::ContactChain& chain,
                          const control::Trajectory& trajectory, const ReplayOptions& options) {
  const mjModel* m = world.model();
  const size_t n = trajectory.qpos.size();
  if (n == 0) return absl::InvalidArgumentError("replay: the trajectory has no frames");
  for (size_t f = 0; f < n; ++f) {
    if (static_cast<int>(trajectory.qpos[f].size()) != m->nq) {
      return absl::InvalidArgumentError("replay: frame " + std::to_string(f) + " has " +
                                        std::to_string(trajectory.qpos[f].size()) +
                                        " qpos entries, the model has " + std::to_string(m->nq));
    }
  }
  if (chain.steps.empty()) return absl::InvalidArgumentError("replay: the plan has no steps");
  if (options.video_path.empty() && options.sheet_path.empty()) return absl::OkStatus();

  absl::StatusOr<std::unique_ptr<render::OffscreenRenderer>> renderer =
      render::OffscreenRenderer::Create(m, options.width, options.height, [&] {
        render::RendererOptions r;
        r.font_scale = options.font_scale;
        r.sky = options.sky;
        r.shadows = options.shadows;
        return r;
      }());
  if (!renderer.ok()) return renderer.status();

  absl::Status first_error;
  std::unique_ptr<render::VideoWriter> video;
  if (!options.video_path.empty()) {
    int fps = std::max(1, static_cast<int>(std::lround(trajectory.fps)));
    absl::StatusOr<std::unique_ptr<render::VideoWriter>> v =
        render::VideoWriter::Open(options.video_path, options.width, options.height, fps);
    if (v.ok()) {
      video = *std::move(v);
    } else {
      first_error = v.status();
    }
  }
  std::vector<size_t> sheet_idx;
  if (!options.sheet_path.empty()) sheet_idx = EvenlySpaced(n, options.sheet_frames);
  if (!video && sheet_idx.empty()) return first_error;

  std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m));
  // the bodies to frame: every agent's
  std::vector<int> bodies;
  for (int a = 0; a < world.num_agents(); ++a) {
    const auto& b = world.agent(a).bodies;
    bodies.insert(bodies.end(), b.begin(), b.end());
  }
  auto pose = [&](size_t f) {
    std::copy(trajectory.qpos[f].begin(), trajectory.qpos[f].end(), d->qpos);
    mj_kinematics(m, d.get());
    // light (and camera) poses: without them the sun has no direction and casts no shadow
    mj_camlight(m, d.get());
  };
  // side-front view of the first agent as it starts
  pose(0);
  double facing_deg =
      world.num_agents() > 0 ? world::PelvisYaw(d.get(), world.agent(0)) * kRadToDeg : 0.0;
  double azimuth = facing_deg + 180.0 - options.side_angle_deg;
  double aspect = static_cast<double>(options.width) / options.height;
  render::CameraSmoother smoother(options.smooth_s);
  const double dt = 1.0 / std::max(1.0, trajectory.fps);
  std::unique_ptr<render::AutoCamera> auto_camera;
  if (options.auto_camera && !bodies.empty()) auto_camera = MakeAutoCamera(world, options);

  std::vector<std::vector<uint8_t>> sheet;
  std::vector<uint8_t> rgb;
  size_t next_sheet = 0;
  // without a video only the sheet frames are drawn, but the camera still follows every frame
  for (size_t f = 0; f < n; ++f) {
    pose(f);
    render::CameraSpec cam =
        auto_camera
            ? auto_camera->Update(d.get(), FacingDeg(world, d.get()), dt)
            : smoother.Update(render::FrameBodies(m, d.get(), bodies, azimuth,
                                                  options.elevation_deg, options.margin, aspect),
                              dt);
    bool for_sheet = next_sheet < sheet_idx.size() && sheet_idx[next_sheet] == f;
    if (!video && !for_sheet) continue;
    int step = f < trajectory.step_index.size() ? trajectory.step_index[f] : 0;
    double t = f < trajectory.time_s.size() ? trajectory.time_s[f] : f * dt;
    absl::Status st = (*renderer)->Render(d.get(), cam, &rgb, Caption(chain, step, t));
    if (!st.ok()) return st;
    if (video) {
      absl::Status vs = video->AddFrame(rgb);
      if (!vs.ok()) {
        if (first_error.ok()) first_error = vs;
        video.reset();
      }
    }
    while (next_sheet < sheet_idx.size() && sheet_idx[next_sheet] == f) {
      sheet.push_back(rgb);
      ++next_sheet;
    }
  }
  if (video) {
    absl::Status vs = video->Close();
    if (!vs.ok() && first_error.ok()) first_error = vs;
  }
  if (!sheet.empty()) {
    absl::Status ss =
        render::WriteContactSheet(options.sheet_path, sheet, options.width, options.height,
                                  options.sheet_cols, options.sheet_downscale);
    if (!ss.ok() && first_error.ok()) first_error = ss;
  }
  return first_error;
}

}  // namespace simhuman::eval
