#include "simhuman/render/auto_camera.h"

#include <algorithm>
#include <cmath>

#include "simhuman/core/check.h"

namespace simhuman::render {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
// a hit this close before the point is the point's own surface, not an occluder
constexpr double kHitSlackM = 0.08;
// penalties (per unit: the whole way round, 60 degrees of elevation)
constexpr double kSidePenalty = 0.5;
constexpr double kElevationPenalty = 0.25;

}  // namespace

Eigen::Vector3d CameraPosition(const CameraSpec& spec) {
  const double az = spec.azimuth_deg * kDegToRad, el = spec.elevation_deg * kDegToRad;
  const Eigen::Vector3d forward(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                                std::sin(el));
  return spec.lookat - spec.distance_m * forward;
}

double VisibleFraction(const mjModel* m, const mjData* d, const CameraSpec& spec,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<double>& weights, const std::vector<char>& subject) {
  const Eigen::Vector3d eye = CameraPosition(spec);
  // the geom groups MuJoCo draws by default (0, 1, 2)
  const mjtByte groups[mjNGROUP] = {1, 1, 1, 0, 0, 0};
  double seen = 0, total = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    total += w;
    const Eigen::Vector3d to = points[i] - eye;
    const double len = to.norm();
    if (len < 1e-6) continue;
    const Eigen::Vector3d dir = to / len;
    int geom = -1;
    const double hit = mj_ray(m, d, eye.data(), dir.data(), groups, 1, -1, &geom);
    const bool hidden =
        geom >= 0 && hit >= 0 && hit < len - kHitSlackM && !subject[m->geom_bodyid[geom]];
    if (!hidden) seen += w;
  }
  return total > 0 ? seen / total : 1.0;
}

AutoCamera::AutoCamera(const mjModel* m, std::vector<int> bodies, std::vector<int> sites,
                       std::vector<double> site_weights, const AutoCameraOptions& options)
    : m_(m),
      bodies_(std::move(bodies)),
      sites_(std::move(sites)),
      weights_(std::move(site_weights)),
      options_(options),
      smoother_(options.smooth_s) {
  SH_CHECK(m_ != nullptr && !bodies_.empty(), "AutoCamera needs a model and bodies to frame");
  SH_CHECK(weights_.empty() || weights_.size() == sites_.size(), "AutoCamera: one weight per site");
  SH_CHECK(!options_.elevations_deg.empty() && options_.azimuth_steps > 0,
           "AutoCamera: no candidate directions");
  subject_.assign(m_->nbody, 0);
  std::vector<char> roots(m_->nbody, 0);
  for (int b : bodies_) {
    SH_CHECK(b > 0 && b < m_->nbody, "AutoCamera: body id out of range");
    roots[m_->body_rootid[b]] = 1;
  }
  for (int b = 1; b < m_->nbody; ++b) subject_[b] = roots[m_->body_rootid[b]];
  for (int s : sites_) SH_CHECK(s >= 0 && s < m_->nsite, "AutoCamera: site id out of range");
}

ViewScore AutoCamera::Score(const mjData* d, const CameraSpec& framing, double az, double el,
                            double facing_deg) const {
  CameraSpec spec = framing;
  spec.azimuth_deg = az;
  spec.elevation_deg = el;
  ViewScore s;
  if (CameraPosition(spec).z() < options_.min_camera_height_m) {
    s.total = -1e9;
    return s;
  }
  std::vector<Eigen::Vector3d> points;
  for (int site : sites_)
    points.emplace_back(d->site_xpos[3 * site], d->site_xpos[3 * site + 1],
                        d->site_xpos[3 * site + 2]);
  s.visible = VisibleFraction(m_, d, spec, points, weights_, subject_);
  // the camera looks opposite to the subject's facing to see its front
  const double preferred_az = facing_deg + 180.0 - options_.preferred_side_deg;
  const double side = std::abs(std::remainder(az - preferred_az, 360.0)) / 180.0;
  const double elev = std::abs(el - options_.preferred_elevation_deg) / 60.0;
  s.total = s.visible - kSidePenalty * side - kElevationPenalty * elev;
  return s;
}

CameraSpec AutoCamera::Update(const mjData* d, double facing_deg, double dt_s) {
  const CameraSpec framing =
      FrameBodies(m_, d, bodies_, az_, el_, options_.margin, options_.aspect);
  since_select_s_ += dt_s;
  if (!chosen_ || since_select_s_ >= options_.reselect_s) {
    since_select_s_ = 0;
    const double preferred_az = facing_deg + 180.0 - options_.preferred_side_deg;
    std::vector<double> azimuths = {preferred_az};
    for (int k = 0; k < options_.azimuth_steps; ++k) {
      azimuths.push_back(preferred_az + 360.0 * k / options_.azimuth_steps);
    }
    double best_az = az_, best_el = el_;
    ViewScore best;
    best.total = -1e18;
    for (double el : options_.elevations_deg) {
      for (double az : azimuths) {
        const ViewScore s = Score(d, framing, az, el, facing_deg);
        if (s.total > best.total) {
          best = s;
          best_az = az;
          best_el = el;
        }
      }
    }
    // keep the current direction unless another is clearly better
    const ViewScore current = chosen_ ? Score(d, framing, az_, el_, facing_deg) : ViewScore{};
    if (!chosen_ || best.total > current.total + options_.switch_gain) {
      az_ = best_az;
      el_ = best_el;
      score_ = best;
    } else {
      score_ = current;
    }
    chosen_ = true;
  }
  CameraSpec target = framing;
  target.azimuth_deg = az_;
  target.elevation_deg = el_;
  return smoother_.Update(target, dt_s);
}

}  // namespace simhuman::render
