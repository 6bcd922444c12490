#include "simhuman/render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simhuman/core/check.h"

namespace simhuman::render {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

}  // namespace

void ToMjvCamera(const CameraSpec& spec, mjvCamera* cam) {
  mjv_defaultCamera(cam);
  cam->type = mjCAMERA_FREE;
  for (int i = 0; i < 3; ++i) cam->lookat[i] = spec.lookat[i];
  cam->distance = spec.distance_m;
  cam->azimuth = spec.azimuth_deg;
  cam->elevation = spec.elevation_deg;
}

CameraSpec FrameBodies(const mjModel* m, const mjData* d, const std::vector<int>& body_ids,
                       double azimuth_deg, double elevation_deg, double margin, double aspect) {
  SH_CHECK(m != nullptr && d != nullptr, "FrameBodies needs a model and data");
  SH_CHECK(margin > 0, "FrameBodies: margin must be > 0");
  SH_CHECK(aspect > 0, "FrameBodies: aspect must be > 0");

  std::vector<char> selected(m->nbody, 0);
  if (body_ids.empty()) {
    for (int b = 1; b < m->nbody; ++b) selected[b] = 1;
  } else {
    for (int b : body_ids) {
      SH_CHECK(b >= 0 && b < m->nbody, "FrameBodies: body id out of range");
      selected[b] = 1;
    }
  }

  // bounding box of the selected geoms' bounding spheres (and of geom-less bodies' origins)
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kInf);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-kInf);
  std::vector<char> has_geom(m->nbody, 0);
  for (int g = 0; g < m->ngeom; ++g) {
    const int b = m->geom_bodyid[g];
    if (!selected[b] || m->geom_type[g] == mjGEOM_PLANE) continue;
    has_geom[b] = 1;
    const Eigen::Vector3d c(d->geom_xpos[3 * g], d->geom_xpos[3 * g + 1], d->geom_xpos[3 * g + 2]);
    const double r = m->geom_rbound[g];
    lo = lo.cwiseMin(c - Eigen::Vector3d::Constant(r));
    hi = hi.cwiseMax(c + Eigen::Vector3d::Constant(r));
  }
  for (int b = 0; b < m->nbody; ++b) {
    if (!selected[b] || has_geom[b]) continue;
    const Eigen::Vector3d p(d->xpos[3 * b], d->xpos[3 * b + 1], d->xpos[3 * b + 2]);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }

  CameraSpec spec;
  spec.azimuth_deg = azimuth_deg;
  spec.elevation_deg = elevation_deg;
  if (!(lo.array() <= hi.array()).all()) {
    // nothing to frame: the whole model
    spec.lookat = Eigen::Vector3d(m->stat.center[0], m->stat.center[1], m->stat.center[2]);
    spec.distance_m = 1.5 * m->stat.extent * margin;
    return spec;
  }
  spec.lookat = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 0.05);

  // the sphere fits a view cone of half-angle a at distance radius / sin(a)
  const double half_fovy = 0.5 * m->vis.global.fovy * kDegToRad;
  const double half_fovx = std::atan(std::tan(half_fovy) * aspect);
  const double half_fov = std::min(half_fovy, half_fovx);
  spec.distance_m = margin * radius / std::sin(half_fov);
  return spec;
}

CameraSmoother::CameraSmoother(double time_constant_s) : time_constant_s_(time_constant_s) {
  SH_CHECK(time_constant_s >= 0, "CameraSmoother: time constant must be >= 0");
}

CameraSpec CameraSmoother::Update(const CameraSpec& target, double dt_s) {
  if (!initialized_ || time_constant_s_ == 0) {
    state_ = target;
    initialized_ = true;
    return state_;
  }
  const double alpha = 1.0 - std::exp(-std::max(dt_s, 0.0) / time_constant_s_);
  state_.lookat += alpha * (target.lookat - state_.lookat);
  state_.distance_m += alpha * (target.distance_m - state_.distance_m);
  state_.elevation_deg += alpha * (target.elevation_deg - state_.elevation_deg);
  // shortest way round for the azimuth
  const double daz = std::remainder(target.azimuth_deg - state_.azimuth_deg, 360.0);
  state_.azimuth_deg += alpha * daz;
  return state_;
}

}  // namespace simhuman::render
