#include "simhuman/language/offline/spatial.h"

#include <algorithm>
#include <cmath>

#include "simhuman/core/footprint.h"
#include "simhuman/plan/metrics.h"

namespace simhuman::language::offline {

// horizontal distance from `p` to the object's footprint (its local bounds turned by its yaw)
double FootprintDistance(const CatalogObject& o, Point2 p) {
  return core::FootprintDistance(o, Eigen::Vector2d(p.x, p.y));
}

double CentreDistance(const CatalogObject& a, const CatalogObject& b) {
  return std::hypot(a.pose.pos.x() - b.pose.pos.x(), a.pose.pos.y() - b.pose.pos.y());
}

bool PartBlocksTheWay(const CatalogObject& o, const std::string& to, Point2 p) {
  const core::CatalogPart* target = o.FindPart(to);
  if (target == nullptr) return false;
  const Eigen::Vector3d goal = o.pose.Apply(target->shapes.front().pose.pos);
  const Eigen::Vector2d from(p.x, p.y);
  const double len = (goal.head<2>() - from).norm();
  const int n = std::max(1, static_cast<int>(std::ceil(len / 0.02)));
  for (const core::CatalogPart& part : o.parts) {
    if (&part == target) continue;
    for (const core::Shape& shape : part.shapes) {
      // the way at the height of this shape's centre
      const double z = o.pose.Apply(shape.pose.pos).z();
      for (int k = 0; k <= n; ++k) {
        const Eigen::Vector2d q = from + (goal.head<2>() - from) * (static_cast<double>(k) / n);
        const Eigen::Vector3d w(q.x(), q.y(), z);
        if ((core::NearestPointOnShape(shape, o.pose, w) - w).norm() < 1e-9) return true;
      }
    }
  }
  return false;
}

double Volume(const CatalogObject& o) {
  if (o.shapes.empty()) return 0.0;
  const auto [lo, hi] = o.LocalBounds();
  const Eigen::Vector3d d = hi - lo;
  return d.x() * d.y() * d.z();
}

double Height(const CatalogObject& o) {
  if (o.shapes.empty()) return 0.0;
  const auto [lo, hi] = o.LocalBounds();
  return hi.z() - lo.z();
}

plan::Direction ViewerSide(Rel r, const CatalogObject& ref, const Viewer& v) {
  const double c = std::cos(v.yaw), s = std::sin(v.yaw);
  double wx = 0, wy = 0;
  switch (r) {
    case Rel::kLeftOf:
      wx = -s, wy = c;
      break;
    case Rel::kRightOf:
      wx = s, wy = -c;
      break;
    case Rel::kFrontOf:
      wx = -c, wy = -s;
      break;
    case Rel::kBehind:
      wx = c, wy = s;
      break;
    default:
      return plan::Direction::kNone;
  }
  // the reference's side closest to that world direction
  plan::Direction best = plan::Direction::kFront;
  double best_dot = -2;
  for (plan::Direction d : {plan::Direction::kFront, plan::Direction::kBack, plan::Direction::kLeft,
                            plan::Direction::kRight}) {
    const Eigen::Vector3d u = plan::DirectionVector(d, ref.pose);
    const double dot = u.x() * wx + u.y() * wy;
    if (dot > best_dot) {
      best_dot = dot;
      best = d;
    }
  }
  return best;
}

std::optional<Rel> RelFromWord(const std::string& w) {
  if (w == "near" || w == "at") return Rel::kNear;
  if (w == "nearest") return Rel::kNearest;
  if (w == "farthest") return Rel::kFarthest;
  if (w == "left_of") return Rel::kLeftOf;
  if (w == "right_of") return Rel::kRightOf;
  if (w == "front_of") return Rel::kFrontOf;
  if (w == "behind") return Rel::kBehind;
  if (w == "on" || w == "onto") return Rel::kOn;
  return std::nullopt;
}

std::string RelText(Rel r) {
  switch (r) {
    case Rel::kNear:
      return "next to";
    case Rel::kNearest:
      return "nearest to";
    case Rel::kFarthest:
      return "farthest from";
    case Rel::kLeftOf:
      return "left of";
    case Rel::kRightOf:
      return "right of";
    case Rel::kFrontOf:
      return "in front of";
    case Rel::kBehind:
      return "behind";
    case Rel::kOn:
      return "on";
  }
  return "";
}

// the side relation of `a` seen from `ref` in the viewer's frame (the dominant axis)
Rel SideRelation(const CatalogObject& a, const CatalogObject& ref, const Viewer& v) {
  auto [f, l] = v.Local(a.pose.pos.x() - ref.pose.pos.x(), a.pose.pos.y() - ref.pose.pos.y());
  if (std::abs(l) >= std::abs(f)) return l > 0 ? Rel::kLeftOf : Rel::kRightOf;
  return f > 0 ? Rel::kBehind : Rel::kFrontOf;
}

bool HoldsSide(Rel r, const CatalogObject& a, const CatalogObject& ref, const Viewer& v) {
  auto [f, l] = v.Local(a.pose.pos.x() - ref.pose.pos.x(), a.pose.pos.y() - ref.pose.pos.y());
  switch (r) {
    case Rel::kLeftOf:
      return l > kTieM && l >= std::abs(f) - kTieM;
    case Rel::kRightOf:
      return -l > kTieM && -l >= std::abs(f) - kTieM;
    case Rel::kBehind:
      return f > kTieM && f >= std::abs(l) - kTieM;
    case Rel::kFrontOf:
      return -f > kTieM && -f >= std::abs(l) - kTieM;
    default:
      return false;
  }
}

// `a` rests on `ref`: its origin lies over ref's footprint and above the floor
bool RestsOn(const CatalogObject& a, const CatalogObject& ref) {
  if (a.id == ref.id) return false;
  return a.pose.pos.z() > 0.05 &&
         FootprintDistance(ref, Point2{a.pose.pos.x(), a.pose.pos.y()}) < 1e-6;
}

}  // namespace simhuman::language::offline
