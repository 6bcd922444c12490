#include "simhuman/world/carry.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace simhuman::world {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kSeatEdgeDropM = 0.02;   // hands just below a seat's top, on its side edges
constexpr double kBoardEdgeInM = 0.05;    // hands this far in from a table board's edge
constexpr double kBoardHalfSpanM = 0.25;  // hands at most this far either side of the centre
constexpr double kArmFaceDropM = 0.10;    // hands this far below the top of a sofa's arm

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// a hold from the stand point, the facing and two hand points with their parts; the hand on
// the carrier's left (as it faces the object) becomes the left hand
core::CarryHold MakeHold(const Vector2d& stand_xy, double facing_rad, const Vector3d& hand_a,
                         const std::string& part_a, const Vector3d& hand_b,
                         const std::string& part_b) {
  core::CarryHold h;
  h.stand_local = Vector3d(stand_xy.x(), stand_xy.y(), 0.0);
  h.facing_local_rad = facing_rad;
  const Vector2d left(-std::sin(facing_rad), std::cos(facing_rad));
  const bool a_left = (hand_a - hand_b).head<2>().dot(left) >= 0.0;
  h.left_hand_local = a_left ? hand_a : hand_b;
  h.right_hand_local = a_left ? hand_b : hand_a;
  h.left_part = a_left ? part_a : part_b;
  h.right_part = a_left ? part_b : part_a;
  h.held_local = 0.5 * (hand_a + hand_b);
  return h;
}

std::pair<Vector3d, Vector3d> PartBounds(const core::CatalogObject& o, const std::string& name) {
  const core::CatalogPart* p = o.FindPart(name);
  return core::ShapesBounds(p->shapes);
}

core::CarryInfo NotCarryable(const std::string& why) {
  core::CarryInfo info;
  info.not_carryable = why;
  return info;
}

core::CarryLayout Layout(std::vector<core::CarryHold> holds) {
  core::CarryLayout l;
  l.holds = std::move(holds);
  return l;
}

// boxes and long boxes: held by the faces across the long horizontal axis
core::CarryInfo BoxCarry(const core::CatalogObject& o) {
  const auto [lo, hi] = o.LocalBounds();
  const Vector3d c = 0.5 * (lo + hi);
  const double ex = hi.x() - lo.x(), ey = hi.y() - lo.y();
  const bool long_x = ex >= ey;
  const double length = long_x ? ex : ey, span = long_x ? ey : ex;
  // u: the long axis; v: across it; the part names of the faces at +v and -v
  const Vector3d u = long_x ? Vector3d(1, 0, 0) : Vector3d(0, 1, 0);
  const Vector3d v = long_x ? Vector3d(0, 1, 0) : Vector3d(-1, 0, 0);
  const std::string pos_v = long_x ? "left side" : "back side";
  const std::string neg_v = long_x ? "right side" : "front side";
  if (std::min(ex, ey) < kMinHoldSpanM) {
    return NotCarryable("it is too small to carry in both arms (" + Num(std::min(ex, ey)) +
                        " m across; at least " + Num(kMinHoldSpanM) +
                        " m): grasp it with one hand (put/place it)");
  }
  if (span > kMaxHoldSpanM) {
    return NotCarryable("it is too large to carry: its held faces are " + Num(span) +
                        " m apart and a carrier's hands span at most " + Num(kMaxHoldSpanM) + " m");
  }
  const double yaw_u = std::atan2(u.y(), u.x()), yaw_v = std::atan2(v.y(), v.x());
  auto at = [&](double along_u, double along_v) {
    return Vector3d(c.x() + along_u * u.x() + along_v * v.x(),
                    c.y() + along_u * u.y() + along_v * v.y(), c.z());
  };
  core::CarryInfo info;
  if (length <= kTeamObjectLengthM) {
    // one carrier at the -u end, hands on the +-v faces' centres
    const Vector3d stand = at(-(length / 2 + kCarryStandOffM), 0.0);
    info.layouts.push_back(Layout(
        {MakeHold(stand.head<2>(), yaw_u, at(0, span / 2), pos_v, at(0, -span / 2), neg_v)}));
    return info;
  }
  const double inset = std::min(kEndHoldInsetM, length / 4);
  const double end_u = length / 2 + kCarryStandOffM;
  const core::CarryHold front =
      MakeHold(at(end_u, 0).head<2>(), yaw_u + M_PI, at(length / 2 - inset, span / 2), pos_v,
               at(length / 2 - inset, -span / 2), neg_v);
  const core::CarryHold back =
      MakeHold(at(-end_u, 0).head<2>(), yaw_u, at(-(length / 2 - inset), span / 2), pos_v,
               at(-(length / 2 - inset), -span / 2), neg_v);
  const double side_v = span / 2 + kCarryStandOffM;
  const core::CarryHold left = MakeHold(at(0, side_v).head<2>(), yaw_v + M_PI, at(inset, span / 2),
                                        pos_v, at(-inset, span / 2), pos_v);
  const core::CarryHold right = MakeHold(at(0, -side_v).head<2>(), yaw_v, at(inset, -span / 2),
                                         neg_v, at(-inset, -span / 2), neg_v);
  info.layouts.push_back(Layout({front, back}));
  info.layouts.push_back(Layout({front, back, left}));
  info.layouts.push_back(Layout({front, back, left, right}));
  return info;
}

// one carrier in front (+x) of a seat, hands on the seat's side edges or the arm tops
core::CarryInfo SeatCarry(const core::CatalogObject& o, bool by_arms) {
  const auto [lo, hi] = o.LocalBounds();
  const Vector2d stand(hi.x() + kCarryStandOffM, 0.5 * (lo.y() + hi.y()));
  core::CarryInfo info;
  if (by_arms) {
    auto top = [&](const std::string& part) {
      const auto [plo, phi] = PartBounds(o, part);
      return Vector3d(0.5 * (plo.x() + phi.x()), 0.5 * (plo.y() + phi.y()), phi.z());
    };
    info.layouts.push_back(Layout(
        {MakeHold(stand, M_PI, top("left arm"), "left arm", top("right arm"), "right arm")}));
    return info;
  }
  const auto [slo, shi] = PartBounds(o, "seat surface");
  const double x = 0.5 * (slo.x() + shi.x()), z = shi.z() - kSeatEdgeDropM;
  info.layouts.push_back(Layout({MakeHold(stand, M_PI, Vector3d(x, shi.y(), z), "seat surface",
                                          Vector3d(x, slo.y(), z), "seat surface")}));
  return info;
}

// one carrier at the table's front edge, hands on the board's edge
core::CarryInfo TableCarry(const core::CatalogObject& o) {
  const auto [lo, hi] = o.LocalBounds();
  const auto [blo, bhi] = PartBounds(o, "board");
  const double cy = 0.5 * (blo.y() + bhi.y());
  const double half = std::min(kBoardHalfSpanM, 0.5 * (bhi.y() - blo.y()) - kBoardEdgeInM);
  const double x = bhi.x() - kBoardEdgeInM, z = bhi.z();
  const Vector2d stand(hi.x() + kCarryStandOffM, cy);
  core::CarryInfo info;
  info.layouts.push_back(Layout({MakeHold(stand, M_PI, Vector3d(x, cy + half, z), "board",
                                          Vector3d(x, cy - half, z), "board")}));
  return info;
}

// two carriers at the sofa's ends (its long axis is y), hands on the arms' outer faces
core::CarryInfo SofaCarry(const core::CatalogObject& o) {
  // named copies, not a structured binding: C++17 lambdas cannot capture those (clang refuses)
  const auto bounds = o.LocalBounds();
  const Vector3d lo = bounds.first, hi = bounds.second;
  auto end_hold = [&](const std::string& arm, double sign) {
    const auto [alo, ahi] = PartBounds(o, arm);
    const double cx = 0.5 * (alo.x() + ahi.x());
    const double dx = std::min(kEndHoldInsetM, 0.5 * (ahi.x() - alo.x()) - kBoardEdgeInM);
    const double y = sign > 0 ? ahi.y() : alo.y(), z = ahi.z() - kArmFaceDropM;
    const Vector2d stand(0.5 * (lo.x() + hi.x()),
                         sign > 0 ? hi.y() + kCarryStandOffM : lo.y() - kCarryStandOffM);
    return MakeHold(stand, sign > 0 ? -M_PI / 2 : M_PI / 2, Vector3d(cx + dx, y, z), arm,
                    Vector3d(cx - dx, y, z), arm);
  };
  core::CarryInfo info;
  info.layouts.push_back(Layout({end_hold("left arm", 1.0), end_hold("right arm", -1.0)}));
  return info;
}

}  // namespace

std::optional<double> DefaultMovableMassKg(std::string_view type) {
  static const std::vector<std::pair<std::string_view, double>> kMasses = {
      {"chair", 5.0}, {"armchair", 12.0},  {"sofa", 35.0},
      {"stool", 3.0}, {"high_stool", 5.0}, {"table", 12.0}};
  for (const auto& [t, kg] : kMasses) {
    if (t == type) return kg;
  }
  return std::nullopt;
}

core::CarryInfo MakeCarryInfo(const core::CatalogObject& object) {
  const std::string& t = object.type;
  if (t == "bed" || t == "laptop" || t == "marker") {
    return NotCarryable("a " + t + " is not carried");
  }
  if (t == "cylinder" || t == "sphere") {
    return NotCarryable("a " + t + " is grasped with one hand (put/place it), not carried");
  }
  if (!object.movable) {
    return NotCarryable(
        "it is static furniture; give it \"mass_kg\" or \"movable\": true in the "
        "scene to carry it");
  }
  if (t == "box" || t == "long_box") return BoxCarry(object);
  if (t == "chair" || t == "stool" || t == "high_stool") return SeatCarry(object, false);
  if (t == "armchair") return SeatCarry(object, true);
  if (t == "table") return TableCarry(object);
  if (t == "sofa") return SofaCarry(object);
  return NotCarryable("a " + t + " is not carried");
}

}  // namespace simhuman::world
