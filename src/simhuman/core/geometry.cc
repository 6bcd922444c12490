#include "simhuman/core/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simhuman/core/check.h"

namespace simhuman::core {

double WrapAngle(double a) {
  a = std::remainder(a, 2.0 * M_PI);  // [-pi, pi]
  return a <= -M_PI ? a + 2.0 * M_PI : a;
}

double AngleFromCos(double c) { return std::acos(std::clamp(c, -1.0, 1.0)); }

Pose Pose::FromYaw(const Eigen::Vector3d& pos, double yaw_rad) {
  Pose p;
  p.pos = pos;
  p.quat = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  return p;
}

namespace {

// nearest point of a segment a-b to p (2D)
Eigen::Vector2d NearestOnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 const Eigen::Vector2d& p) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

// a frustum is a solid of revolution: the nearest point lies in the plane through the axis and
// q, on the trapezoid (0, -h) (rb, -h) (rt, h) (0, h) of that plane's half (rho >= 0)
Eigen::Vector3d NearestOnFrustum(const Shape& s, const Eigen::Vector3d& q) {
  const double rb = s.size.x(), h = s.size.y(), rt = s.size.z();
  const Eigen::Vector2d xy(q.x(), q.y());
  const double rho = xy.norm();
  if (std::abs(q.z()) <= h && rho <= rb + (rt - rb) * (q.z() + h) / (2 * h)) return q;
  const Eigen::Vector2d p(rho, q.z());
  const Eigen::Vector2d candidates[3] = {NearestOnSegment({0, -h}, {rb, -h}, p),
                                         NearestOnSegment({rb, -h}, {rt, h}, p),
                                         NearestOnSegment({0, h}, {rt, h}, p)};
  Eigen::Vector2d best = candidates[0];
  for (const Eigen::Vector2d& c : candidates) {
    if ((c - p).squaredNorm() < (best - p).squaredNorm()) best = c;
  }
  const Eigen::Vector2d dir = rho > 1e-12 ? Eigen::Vector2d(xy / rho) : Eigen::Vector2d::UnitX();
  return {best.x() * dir.x(), best.x() * dir.y(), best.y()};
}

// nearest point of a solid in the shape's own frame
Eigen::Vector3d NearestLocal(const Shape& s, const Eigen::Vector3d& q) {
  switch (s.kind) {
    case ShapeKind::kBox:
      return q.cwiseMax(-s.size).cwiseMin(s.size);
    case ShapeKind::kSphere: {
      double n = q.norm();
      return n <= s.size.x() ? q : Eigen::Vector3d(q * (s.size.x() / n));
    }
    case ShapeKind::kCapsule: {
      Eigen::Vector3d axis_pt(0, 0, std::clamp(q.z(), -s.size.y(), s.size.y()));
      Eigen::Vector3d d = q - axis_pt;
      double n = d.norm();
      return n <= s.size.x() ? q : Eigen::Vector3d(axis_pt + d * (s.size.x() / n));
    }
    case ShapeKind::kCylinder: {
      double z = std::clamp(q.z(), -s.size.y(), s.size.y());
      Eigen::Vector2d r(q.x(), q.y());
      double n = r.norm();
      if (n > s.size.x()) r *= s.size.x() / n;
      return {r.x(), r.y(), z};
    }
    case ShapeKind::kFrustum:
      return NearestOnFrustum(s, q);
    case ShapeKind::kMesh: {
      const auto [lo, hi] = LocalShapeBounds(s);
      return q.cwiseMax(lo).cwiseMin(hi);
    }
  }
  return q;
}

}  // namespace

Eigen::Vector3d NearestPointOnShape(const Shape& shape, const Pose& world_from_parent,
                                    const Eigen::Vector3d& p_world) {
  Pose world_from_shape = world_from_parent.Compose(shape.pose);
  Eigen::Vector3d local = world_from_shape.ApplyInverse(p_world);
  return world_from_shape.Apply(NearestLocal(shape, local));
}

Eigen::Vector3d NearestPointOnShapes(const std::vector<Shape>& shapes,
                                     const Pose& world_from_parent,
                                     const Eigen::Vector3d& p_world) {
  SH_CHECK(!shapes.empty(), "NearestPointOnShapes needs at least one shape");
  Eigen::Vector3d best = p_world;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const Shape& s : shapes) {
    Eigen::Vector3d c = NearestPointOnShape(s, world_from_parent, p_world);
    double d2 = (c - p_world).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

std::vector<Eigen::Vector3d> SampleShapeSurface(const Shape& s, double spacing_m) {
  SH_CHECK(spacing_m > 0, "spacing must be positive");
  std::vector<Eigen::Vector3d> local;
  auto steps = [&](double len) {
    return std::max(1, static_cast<int>(std::ceil(len / spacing_m)));
  };
  switch (s.kind) {
    case ShapeKind::kBox: {
      // six faces on a grid
      for (int axis = 0; axis < 3; ++axis) {
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        int n1 = steps(2 * s.size[a1]), n2 = steps(2 * s.size[a2]);
        for (int sign = -1; sign <= 1; sign += 2) {
          for (int i = 0; i <= n1; ++i) {
            for (int j = 0; j <= n2; ++j) {
              Eigen::Vector3d p;
              p[axis] = sign * s.size[axis];
              p[a1] = -s.size[a1] + 2 * s.size[a1] * i / n1;
              p[a2] = -s.size[a2] + 2 * s.size[a2] * j / n2;
              local.push_back(p);
            }
          }
        }
      }
      break;
    }
    case ShapeKind::kSphere: {
      double r = s.size.x();
      int n_lat = steps(M_PI * r);
      for (int i = 0; i <= n_lat; ++i) {
        double th = M_PI * i / n_lat;
        int n_lon = std::max(1, steps(2 * M_PI * r * std::sin(th)));
        for (int j = 0; j < n_lon; ++j) {
          double ph = 2 * M_PI * j / n_lon;
          local.emplace_back(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                             r * std::cos(th));
        }
      }
      break;
    }
    case ShapeKind::kCapsule:
    case ShapeKind::kCylinder: {
      double r = s.size.x(), h = s.size.y();
      int n_z = steps(2 * h), n_c = std::max(3, steps(2 * M_PI * r));
      for (int i = 0; i <= n_z; ++i) {
        double z = -h + 2 * h * i / n_z;
        for (int j = 0; j < n_c; ++j) {
          double ph = 2 * M_PI * j / n_c;
          local.emplace_back(r * std::cos(ph), r * std::sin(ph), z);
        }
      }
      // caps: flat discs for cylinders, hemispheres approximated by discs raised by r for
      // capsules (adequate for nearest-point observations)
      int n_r = steps(r);
      for (int sign = -1; sign <= 1; sign += 2) {
        double zc = sign * (s.kind == ShapeKind::kCapsule ? h + r : h);
        local.emplace_back(0, 0, zc);
        for (int i = 1; i <= n_r; ++i) {
          double rr = r * i / n_r;
          int n = std::max(3, steps(2 * M_PI * rr));
          for (int j = 0; j < n; ++j) {
            double ph = 2 * M_PI * j / n;
            local.emplace_back(rr * std::cos(ph), rr * std::sin(ph), zc);
          }
        }
      }
      break;
    }
    case ShapeKind::kFrustum: {
      const double rb = s.size.x(), h = s.size.y(), rt = s.size.z();
      const int n_z = steps(std::hypot(2 * h, rb - rt));
      for (int i = 0; i <= n_z; ++i) {
        const double t = static_cast<double>(i) / n_z, r = rb + (rt - rb) * t;
        const int n_c = std::max(3, steps(2 * M_PI * r));
        for (int j = 0; j < n_c; ++j) {
          const double ph = 2 * M_PI * j / n_c;
          local.emplace_back(r * std::cos(ph), r * std::sin(ph), -h + 2 * h * t);
        }
      }
      for (int sign = -1; sign <= 1; sign += 2) {
        const double r_end = sign < 0 ? rb : rt;
        const int n_r = steps(r_end);
        local.emplace_back(0, 0, sign * h);
        for (int i = 1; i <= n_r && r_end > 0; ++i) {
          const double rr = r_end * i / n_r;
          const int n = std::max(3, steps(2 * M_PI * rr));
          for (int j = 0; j < n; ++j) {
            const double ph = 2 * M_PI * j / n;
            local.emplace_back(rr * std::cos(ph), rr * std::sin(ph), sign * h);
          }
        }
      }
      break;
    }
    case ShapeKind::kMesh: {
      // each triangle on a barycentric grid
      SH_CHECK(s.mesh != nullptr, "a mesh shape without its mesh");
      for (const auto& f : s.mesh->faces) {
        const Eigen::Vector3d a = s.mesh->vertices[f[0]].cwiseProduct(s.size);
        const Eigen::Vector3d b = s.mesh->vertices[f[1]].cwiseProduct(s.size);
        const Eigen::Vector3d c = s.mesh->vertices[f[2]].cwiseProduct(s.size);
        const int n = steps(std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}));
        for (int i = 0; i <= n; ++i) {
          for (int j = 0; i + j <= n; ++j) {
            local.push_back(a + (b - a) * i / n + (c - a) * j / n);
          }
        }
      }
      break;
    }
  }
  std::vector<Eigen::Vector3d> out;
  out.reserve(local.size());
  for (const auto& p : local) out.push_back(s.pose.Apply(p));
  return out;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> LocalShapeBounds(const Shape& s) {
  Eigen::Vector3d half = s.size;
  switch (s.kind) {
    case ShapeKind::kBox:
      break;
    case ShapeKind::kSphere:
      half = Eigen::Vector3d::Constant(s.size.x());
      break;
    case ShapeKind::kCapsule:
      half = Eigen::Vector3d(s.size.x(), s.size.x(), s.size.y() + s.size.x());
      break;
    case ShapeKind::kCylinder:
      half = Eigen::Vector3d(s.size.x(), s.size.x(), s.size.y());
      break;
    case ShapeKind::kFrustum: {
      const double r = std::max(s.size.x(), s.size.z());
      half = Eigen::Vector3d(r, r, s.size.y());
      break;
    }
    case ShapeKind::kMesh:
      SH_CHECK(s.mesh != nullptr, "a mesh shape without its mesh");
      return {s.mesh->lo.cwiseProduct(s.size), s.mesh->hi.cwiseProduct(s.size)};
  }
  return {-half, half};
}

double ShapeVolume(const Shape& s) {
  const Eigen::Vector3d& z = s.size;
  switch (s.kind) {
    case ShapeKind::kBox:
      return 8 * z.x() * z.y() * z.z();
    case ShapeKind::kSphere:
      return 4.0 / 3 * M_PI * z.x() * z.x() * z.x();
    case ShapeKind::kCylinder:
      return M_PI * z.x() * z.x() * 2 * z.y();
    case ShapeKind::kCapsule:
      return M_PI * z.x() * z.x() * (2 * z.y() + 4.0 / 3 * z.x());
    case ShapeKind::kFrustum:
      return M_PI * 2 * z.y() / 3 * (z.x() * z.x() + z.x() * z.z() + z.z() * z.z());
    case ShapeKind::kMesh: {
      SH_CHECK(s.mesh != nullptr, "a mesh shape without its mesh");
      double v6 = 0;  // six times the signed volume
      for (const auto& f : s.mesh->faces) {
        v6 += s.mesh->vertices[f[0]].cwiseProduct(z).dot(
            s.mesh->vertices[f[1]].cwiseProduct(z).cross(s.mesh->vertices[f[2]].cwiseProduct(z)));
      }
      return std::abs(v6) / 6;
    }
  }
  return 0;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> ShapesBounds(const std::vector<Shape>& shapes) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Shape& s : shapes) {
    const auto [l, h] = LocalShapeBounds(s);
    // corners of the local box, placed
    for (int i = 0; i < 8; ++i) {
      Eigen::Vector3d c((i & 1) ? h.x() : l.x(), (i & 2) ? h.y() : l.y(), (i & 4) ? h.z() : l.z());
      Eigen::Vector3d w = s.pose.Apply(c);
      lo = lo.cwiseMin(w);
      hi = hi.cwiseMax(w);
    }
  }
  return {lo, hi};
}

}  // namespace simhuman::core
