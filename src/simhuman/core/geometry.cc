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

Pose Pose::FromYaw(const Eigen::Vector3d& pos, double yaw_rad) {
  Pose p;
  p.pos = pos;
  p.quat = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  return p;
}

namespace {

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
  }
  std::vector<Eigen::Vector3d> out;
  out.reserve(local.size());
  for (const auto& p : local) out.push_back(s.pose.Apply(p));
  return out;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> ShapesBounds(const std::vector<Shape>& shapes) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Shape& s : shapes) {
    Eigen::Vector3d half = s.size;
    switch (s.kind) {
      case ShapeKind::kBox:
        half = s.size;
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
    }
    // corners of the local box, rotated
    for (int i = 0; i < 8; ++i) {
      Eigen::Vector3d c((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                        (i & 4) ? half.z() : -half.z());
      Eigen::Vector3d w = s.pose.Apply(c);
      lo = lo.cwiseMin(w);
      hi = hi.cwiseMax(w);
    }
  }
  return {lo, hi};
}

}  // namespace simhuman::core
