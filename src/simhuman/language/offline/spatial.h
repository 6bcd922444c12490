#pragma once
/// Spatial relations for the offline planner: distances between a point and an object's
/// footprint, the viewer's frame ("left" and "in front of" are seen from the human's start
/// pose), the relation words ("next to", "left of", "on", ...) and whether one holds between two
/// objects. Metres and radians, world frame, horizontal plane unless said otherwise.

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "simhuman/language/offline/common.h"

namespace simhuman::language::offline {

/// Two candidates closer than this (m) to a reference, or this close in a left/right ordering,
/// are not told apart.
inline constexpr double kTieM = 0.05;

/// A point in the horizontal plane (world frame, m).
struct Point2 {
  double x = 0, y = 0;
};

/// Horizontal distance (m) from `p` to the object's footprint (its local bounds turned by its
/// yaw); to its origin when it has no shapes.
double FootprintDistance(const CatalogObject& o, Point2 p);
/// Horizontal distance (m) between the origins of `a` and `b`.
double CentreDistance(const CatalogObject& a, const CatalogObject& b);
/// Whether the straight way (horizontal) from `p` to the centre of the object's part `to`
/// passes through another named part of it (a sofa's arm or a chair's back between the human
/// and the seat). False when the object has no part `to`.
bool PartBlocksTheWay(const CatalogObject& o, const std::string& to, Point2 p);
/// Volume (m^3) of the object's local bounding box; 0 without shapes.
double Volume(const CatalogObject& o);
/// Height (m) of the object's local bounding box; 0 without shapes.
double Height(const CatalogObject& o);

/// The viewer's frame: where the human starts and which way it faces.
struct Viewer {
  double x = 0, y = 0, yaw = 0;
  /// (forward, left) coordinates of a world offset.
  std::pair<double, double> Local(double dx, double dy) const {
    return {std::cos(yaw) * dx + std::sin(yaw) * dy, -std::sin(yaw) * dx + std::cos(yaw) * dy};
  }
};

/// A spatial relation between an object and a reference object.
enum class Rel { kNear, kNearest, kFarthest, kLeftOf, kRightOf, kFrontOf, kBehind, kOn };

/// The relation a canonical word names ("near" and "at" -> kNear, "onto" and "on" -> kOn, ...);
/// nullopt for any other word.
std::optional<Rel> RelFromWord(const std::string& w);
/// The relation in words for messages ("next to", "left of", ...).
std::string RelText(Rel r);
/// The side relation of `a` seen from `ref` in the viewer's frame (the dominant axis).
Rel SideRelation(const CatalogObject& a, const CatalogObject& ref, const Viewer& v);
/// Whether side relation `r` (left of, right of, in front of, behind) holds for `a` relative to
/// `ref` in the viewer's frame, with kTieM slack; false for other relations.
bool HoldsSide(Rel r, const CatalogObject& a, const CatalogObject& ref, const Viewer& v);
/// The side of `ref` (front, back, left, right: its own frame) that lies in the viewer's
/// direction of side relation `r` (kLeftOf: the viewer's left, kFrontOf: towards the viewer,
/// ...); kNone for other relations.
plan::Direction ViewerSide(Rel r, const CatalogObject& ref, const Viewer& v);
/// Whether `a` rests on `ref`: its origin lies over ref's footprint and above the floor.
bool RestsOn(const CatalogObject& a, const CatalogObject& ref);

}  // namespace simhuman::language::offline
