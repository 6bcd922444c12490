#include "simhuman/perceive/vision/draw.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "simhuman/perceive/vision/silhouette.h"

namespace simhuman::perceive {

namespace {

using Rgb = std::array<uint8_t, 3>;

void Dot(const PinholeCamera& cam, int x, int y, int r, const Rgb& c, std::vector<uint8_t>* img) {
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int px = x + dx, py = y + dy;
      if (px < 0 || py < 0 || px >= cam.width || py >= cam.height) continue;
      uint8_t* p = img->data() + 3 * (static_cast<size_t>(py) * cam.width + px);
      p[0] = c[0];
      p[1] = c[1];
      p[2] = c[2];
    }
  }
}

void Line(const PinholeCamera& cam, double u0, double v0, double u1, double v1, int r, const Rgb& c,
          std::vector<uint8_t>* img) {
  const int n =
      std::max(1, static_cast<int>(std::ceil(std::max(std::abs(u1 - u0), std::abs(v1 - v0)))));
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    Dot(cam, static_cast<int>(u0 + t * (u1 - u0)), static_cast<int>(v0 + t * (v1 - v0)), r, c, img);
  }
}

Rgb ColourOf(int colour) {
  static const Rgb k[] = {{255, 40, 40}, {255, 230, 0}, {0, 220, 60}, {40, 90, 255}};
  return colour >= 0 && colour < 4 ? k[colour] : Rgb{255, 0, 255};
}

}  // namespace

void DrawEstimates(const PinholeCamera& cam, const std::vector<ObjectEstimate>& est,
                   const std::vector<Eigen::Vector3d>& truth, std::vector<uint8_t>* rgb) {
  for (const Eigen::Vector3d& t : truth) {
    double u, v;
    if (cam.Project(t, &u, &v))
      Dot(cam, static_cast<int>(u), static_cast<int>(v), 1, {0, 0, 0}, rgb);
  }
  for (int pass = 0; pass < 2; ++pass) {
    for (const ObjectEstimate& e : est) {
      const Rgb c = pass == 0 ? Rgb{255, 255, 255} : ColourOf(e.colour);
      const int r = pass == 0 ? 1 : 0;
      double u, v, ua, va, ub, vb;
      if (!cam.Project(e.centre, &u, &v)) continue;
      Line(cam, u - 4, v, u + 4, v, r, c, rgb);
      Line(cam, u, v - 4, u, v + 4, r, c, rgb);
      if (cam.Project(e.centre - 0.5 * e.height_m * e.up, &ua, &va) &&
          cam.Project(e.centre + 0.5 * e.height_m * e.up, &ub, &vb)) {
        Line(cam, ua + 6, va, ub + 6, vb, r, c, rgb);
      }
      // the shape as a mark beside the cross: box 2 dots, cylinder 3, sphere 1 (none in between)
      for (int k = 0; k <= e.shape; ++k)
        Dot(cam, static_cast<int>(u) - 7, static_cast<int>(v) - 4 + 3 * k, r, c, rgb);
    }
  }
}

void DrawOutlines(const PinholeCamera& cam, const std::vector<ObjectEstimate>& estimates,
                  std::vector<uint8_t>* rgb) {
  const int w = cam.width, h = cam.height;
  for (const ObjectEstimate& e : estimates) {
    std::vector<char> in(static_cast<size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x)
        in[y * w + x] = RayHitsUpright(e, cam.eye, cam.Ray(x + 0.5, y + 0.5));
    }
    for (int y = 1; y + 1 < h; ++y) {
      for (int x = 1; x + 1 < w; ++x) {
        const int i = y * w + x;
        if (!in[i] || (in[i - 1] && in[i + 1] && in[i - w] && in[i + w])) continue;
        for (int k = 0; k < 3; ++k) (*rgb)[3 * static_cast<size_t>(i) + k] = 255;
      }
    }
  }
}

}  // namespace simhuman::perceive
