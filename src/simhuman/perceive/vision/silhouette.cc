#include "simhuman/perceive/vision/silhouette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace simhuman::perceive {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

// [t0, t1] of the ray o + t d inside the slab |x| <= h along one axis; false when it misses
bool Slab(double o, double d, double h, double* t0, double* t1) {
  if (std::abs(d) < 1e-12) {
    if (std::abs(o) > h) return false;
    *t0 = -kInf;
    *t1 = kInf;
    return true;
  }
  const double a = (-h - o) / d, b = (h - o) / d;
  *t0 = std::min(a, b);
  *t1 = std::max(a, b);
  return true;
}

// [t0, t1] inside the disc x^2 + y^2 <= r^2 (an infinite upright cylinder, or a sphere when the
// z terms are given)
bool Quadric(double a, double b, double c, double* t0, double* t1) {
  if (a < 1e-12) {
    if (c > 0) return false;
    *t0 = -kInf;
    *t1 = kInf;
    return true;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return false;
  const double s = std::sqrt(disc);
  *t0 = (-b - s) / (2 * a);
  *t1 = (-b + s) / (2 * a);
  return true;
}

// The estimate's parameters the fit moves: the centre's horizontal offset from where the network
// put it along the camera's horizontal view direction and across it (these move the outline's
// base up and down, and sideways, in the image: nearly independent of each other and of the
// size); width; height; yaw.
using Params = std::array<double, 5>;

struct Frame {
  Eigen::Vector3d origin, along, across;
  double base_z = 0;
};

ObjectEstimate Apply(const ObjectEstimate& e, const Params& p, const Frame& f) {
  ObjectEstimate o = e;
  o.width_m = p[2];
  o.height_m = e.shape == 2 ? p[2] : p[3];
  o.centre = f.origin + p[0] * f.along + p[1] * f.across;
  o.centre.z() = f.base_z + 0.5 * o.height_m;
  o.up = Eigen::Vector3d::UnitZ();
  o.yaw_rad = p[4];
  return o;
}

// The pixels around one blob: per pixel its rays, and what the frame shows there.
struct Window {
  std::vector<Eigen::Vector3d> rays;  // supersample^2 per pixel
  std::vector<char> in_blob, other;   // per pixel
  int per_pixel = 1;
  int blob_pixels = 0;
};

Window MakeWindow(const PinholeCamera& cam, const std::vector<uint8_t>& rgb,
                  const ColourTable& table, const Blob& blob, int margin, int ss) {
  Window w;
  w.per_pixel = ss * ss;
  w.blob_pixels = blob.pixels;
  std::vector<char> mine(static_cast<size_t>(cam.width) * cam.height, 0);
  for (int i : blob.index) mine[i] = 1;
  const int x0 = std::max(0, blob.x0 - margin), x1 = std::min(cam.width - 1, blob.x1 + margin);
  const int y0 = std::max(0, blob.y0 - margin), y1 = std::min(cam.height - 1, blob.y1 + margin);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const int i = y * cam.width + x;
      w.in_blob.push_back(mine[i]);
      w.other.push_back(!mine[i] && table.Classify(&rgb[3 * static_cast<size_t>(i)]) != 0);
      for (int sy = 0; sy < ss; ++sy) {
        for (int sx = 0; sx < ss; ++sx) {
          w.rays.push_back(cam.Ray(x + (sx + 0.5) / ss, y + (sy + 0.5) / ss));
        }
      }
    }
  }
  return w;
}

// the share of the outline of `e` that falls on other objects' pixels
double HiddenShare(const Window& w, const Eigen::Vector3d& eye, const ObjectEstimate& e) {
  int covered = 0, hidden = 0;
  for (size_t p = 0; p < w.in_blob.size(); ++p) {
    for (int k = 0; k < w.per_pixel; ++k) {
      if (!RayHitsUpright(e, eye, w.rays[p * w.per_pixel + k])) continue;
      ++covered;
      hidden += w.other[p];
    }
  }
  return covered > 0 ? static_cast<double>(hidden) / covered : 0.0;
}

// mismatched coverage: blob pixels the outline misses, and pixels showing nothing (the table)
// that it covers; pixels of other objects may hide it and count neither way. `coarse` casts one
// ray per pixel instead of all of them.
double Mismatch(const Window& w, const Eigen::Vector3d& eye, const ObjectEstimate& e,
                bool coarse = false) {
  double cost = 0;
  const int n = coarse ? 1 : w.per_pixel;
  const double inv = 1.0 / n;
  for (size_t p = 0; p < w.in_blob.size(); ++p) {
    if (w.other[p]) continue;
    int hits = 0;
    for (int k = 0; k < n; ++k) hits += RayHitsUpright(e, eye, w.rays[p * w.per_pixel + k]);
    const double cov = hits * inv;
    cost += w.in_blob[p] ? 1 - cov : cov;
  }
  return cost;
}

// the step of parameter k at a search scale
double Step(int k, double scale, const SilhouetteOptions& o) {
  return k == 4 ? std::max(o.first_yaw_step_deg * scale, o.last_yaw_step_deg) * kDeg
                : o.first_step_m * scale;
}

// pattern search from `p` over the parameters in `free`: single parameters and pairs of them
// moved together (an outline moved one way and resized the other keeps one edge where it is:
// single moves alone stall on such ridges), steps halving from first to last
Params Search(const Window& w, const Eigen::Vector3d& eye, const ObjectEstimate& e, const Frame& fr,
              const SilhouetteOptions& o, const std::vector<int>& free, Params p, double* best) {
  std::vector<std::array<double, 5>> dirs;
  for (size_t a = 0; a < free.size(); ++a) {
    for (double sa : {1.0, -1.0}) {
      std::array<double, 5> d{};
      d[free[a]] = sa;
      dirs.push_back(d);
      for (size_t b = a + 1; b < free.size(); ++b) {
        for (double sb : {1.0, -1.0}) {
          std::array<double, 5> d2 = d;
          d2[free[b]] = sb;
          dirs.push_back(d2);
        }
      }
    }
  }
  const Params start = p;
  auto cost = [&](const Params& q, bool coarse) {
    double prior = 0;
    for (int k = 0; k < 4; ++k) prior += std::pow(100 * (q[k] - start[k]), 2);
    return Mismatch(w, eye, Apply(e, q, fr), coarse) + o.prior_per_cm2 * prior;
  };
  for (double scale = 1; o.first_step_m * scale >= o.last_step_m * 0.999; scale *= 0.5) {
    // steps of a pixel or more see the outline's edges with one ray per pixel
    const bool coarse = o.first_step_m * scale > 2 * o.last_step_m;
    *best = cost(p, coarse);
    for (int round = 0; round < 40; ++round) {
      bool improved = false;
      for (const std::array<double, 5>& d : dirs) {
        Params q = p;
        for (int k = 0; k < 5; ++k) q[k] += d[k] * Step(k, scale, o);
        q[2] = std::max(q[2], 0.01);
        q[3] = std::max(q[3], 0.01);
        const double c = cost(q, coarse);
        if (c < *best - 1e-9) {
          *best = c;
          p = q;
          improved = true;
        }
      }
      if (!improved) break;
    }
  }
  return p;
}

bool Upright(const ObjectEstimate& e, double max_tilt_deg) {
  return e.shape == 2 || e.up.z() >= std::cos(max_tilt_deg * kDeg);
}

}  // namespace

bool RayHitsUpright(const ObjectEstimate& e, const Eigen::Vector3d& eye,
                    const Eigen::Vector3d& dir) {
  const Eigen::Vector3d o = eye - e.centre;
  double t0 = -kInf, t1 = kInf, a0, a1;
  auto clip = [&](double lo, double hi) {
    t0 = std::max(t0, lo);
    t1 = std::min(t1, hi);
  };
  if (e.shape == 2) {  // sphere
    const double r = 0.5 * e.width_m;
    if (!Quadric(dir.squaredNorm(), 2 * o.dot(dir), o.squaredNorm() - r * r, &a0, &a1)) {
      return false;
    }
    clip(a0, a1);
  } else {
    const double hh = 0.5 * e.height_m, r = 0.5 * e.width_m;
    if (!Slab(o.z(), dir.z(), hh, &a0, &a1)) return false;
    clip(a0, a1);
    if (e.shape == 0) {  // box: its faces turned by yaw about the vertical
      const double c = std::cos(e.yaw_rad), s = std::sin(e.yaw_rad);
      const double ox = c * o.x() + s * o.y(), oy = -s * o.x() + c * o.y();
      const double dx = c * dir.x() + s * dir.y(), dy = -s * dir.x() + c * dir.y();
      if (!Slab(ox, dx, r, &a0, &a1)) return false;
      clip(a0, a1);
      if (!Slab(oy, dy, r, &a0, &a1)) return false;
      clip(a0, a1);
    } else {  // cylinder
      const double a = dir.x() * dir.x() + dir.y() * dir.y();
      const double b = 2 * (o.x() * dir.x() + o.y() * dir.y());
      const double c = o.x() * o.x() + o.y() * o.y() - r * r;
      if (!Quadric(a, b, c, &a0, &a1)) return false;
      clip(a0, a1);
    }
  }
  return t0 <= t1 && t1 > 0;
}

std::vector<SilhouetteFit> FitRestingSilhouettes(const std::vector<uint8_t>& rgb,
                                                 const PinholeCamera& cam, const ColourTable& table,
                                                 const SilhouetteOptions& o,
                                                 std::vector<ObjectEstimate>* est) {
  std::vector<SilhouetteFit> fits(est->size());
  // the table plane: known, or the median base height of the upright estimates
  std::vector<double> bases;
  for (const ObjectEstimate& e : *est) {
    if (Upright(e, o.max_tilt_deg)) bases.push_back(e.centre.z() - 0.5 * e.height_m);
  }
  if (bases.empty()) return fits;
  std::nth_element(bases.begin(), bases.begin() + bases.size() / 2, bases.end());
  const double base_z = std::isnan(o.table_z) ? bases[bases.size() / 2] : o.table_z;
  const std::vector<Blob> blobs = FindBlobs(rgb, cam.width, cam.height, table, 1);
  const int ss = std::max(1, o.supersample);
  for (size_t i = 0; i < est->size(); ++i) {
    ObjectEstimate& e = (*est)[i];
    if (!Upright(e, o.max_tilt_deg)) continue;
    const Blob* blob = nullptr;
    for (const Blob& b : blobs) {
      if (b.colour == e.colour && std::abs(b.cu - e.u) < 0.01 && std::abs(b.cv - e.v) < 0.01) {
        blob = &b;
      }
    }
    if (blob == nullptr) continue;
    SilhouetteFit& f = fits[i];
    f.fitted = true;
    f.blob_pixels = blob->pixels;
    // the margin: the largest shift believed, in pixels at the object's distance
    const double dist = std::max(0.1, (e.centre - cam.eye).norm());
    const double px_per_m = 0.5 * cam.height / (std::tan(0.5 * cam.fovy_deg * kDeg) * dist);
    const int margin = static_cast<int>(std::ceil((o.max_shift_m + o.max_resize_m) * px_per_m)) + 2;
    const Window w = MakeWindow(cam, rgb, table, *blob, margin, ss);
    Frame fr;
    fr.origin = e.centre;
    fr.along = Eigen::Vector3d(cam.forward.x(), cam.forward.y(), 0).normalized();
    fr.across = Eigen::Vector3d(-fr.along.y(), fr.along.x(), 0);
    fr.base_z = base_z;
    Params p0{0, 0, e.width_m, e.height_m, e.yaw_rad};
    std::vector<int> free = {0, 1, 2};
    if (e.shape != 2) free.push_back(3);
    if (e.shape == 0) free.push_back(4);
    // the network's estimate with its base put on the table plane
    f.before = Mismatch(w, cam.eye, Apply(e, p0, fr));
    double with_prior = 0;
    Params p = Search(w, cam.eye, e, fr, o, free, p0, &with_prior);
    f.hidden = HiddenShare(w, cam.eye, Apply(e, p, fr));
    if (f.hidden > o.max_hidden) {
      f.sideways_only = true;
      p = Search(w, cam.eye, e, fr, o, {1, 2}, p0, &with_prior);
    }
    f.after = Mismatch(w, cam.eye, Apply(e, p, fr));
    const double shift = std::hypot(p[0], p[1]);
    const bool resized =
        std::abs(p[2] - p0[2]) > o.max_resize_m || std::abs(p[3] - p0[3]) > o.max_resize_m;
    if (shift > o.max_shift_m || resized || f.after > o.max_mismatch * blob->pixels) continue;
    f.accepted = true;
    ObjectEstimate fitted = Apply(e, p, fr);
    if (fitted.shape == 0) {
      while (fitted.yaw_rad > M_PI / 4) fitted.yaw_rad -= M_PI / 2;
      while (fitted.yaw_rad <= -M_PI / 4) fitted.yaw_rad += M_PI / 2;
    }
    e = fitted;
  }
  return fits;
}

}  // namespace simhuman::perceive
