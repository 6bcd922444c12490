#pragma once
/// Carrying data of built objects: held points, stand points and team sizes
/// (core::CarryInfo), and the default masses that make furniture movable.
///
/// The rules (docs/FORMATS.md, "Carrying"):
///  - only movable objects are carried; static furniture stays static unless the scene gives it
///    `mass_kg` or `"movable": true` (then DefaultMovableMassKg());
///  - a carrier stands kCarryStandOffM beyond the object's bounds (CooHOI's stand point), on
///    the floor, facing the object;
///  - boxes and long boxes are held by their two side faces: one carrier at the back (-x) end of
///    a box up to kTeamObjectLengthM long, hands on the side faces' centres; longer boxes are
///    team objects: two carriers at the two ends of the long axis (hands on the side faces
///    kEndHoldInsetM in from the end), a third at the middle of the +across side, a fourth at
///    the middle of the -across side;
///  - a box is carryable when its held faces are kMinHoldSpanM to kMaxHoldSpanM apart
///    (narrower: grasp it with one hand; wider: a carrier's arms do not reach round it);
///  - chair, stool, high stool: one carrier in front, hands on the seat's side edges; armchair:
///    one carrier in front, hands on the arm tops; table: one carrier at the front edge, hands
///    on the board's edge; sofa: two carriers at the two ends of its long (y) axis, hands on
///    the outer faces of the arms;
///  - beds, laptops, markers, cylinders and spheres are not carried in both arms.

#include <optional>
#include <string_view>

#include "simhuman/core/scene_catalog.h"

namespace simhuman::world {

/// A carrier's stand point lies this far beyond the object's bounds (CooHOI: 0.2 m).
inline constexpr double kCarryStandOffM = 0.2;
/// Boxes longer than this (metres, along their long horizontal axis) are carried by a team.
inline constexpr double kTeamObjectLengthM = 1.2;
/// Hands of an end carrier go this far in from the end (at most a quarter of the length).
inline constexpr double kEndHoldInsetM = 0.25;
/// The held faces of a box must be at least this far apart (metres) to carry it in both arms.
inline constexpr double kMinHoldSpanM = 0.2;
/// ... and at most this far (a carrier's hands reach round at most this much).
inline constexpr double kMaxHoldSpanM = 0.8;

/// The carrying data of a built object (BuildObject() calls it): held points per team size, or
/// the reason it cannot be carried. Uses the object's type, movability, parts and bounds.
/// Thread-safe.
core::CarryInfo MakeCarryInfo(const core::CatalogObject& object);

/// The mass (kg) that `"movable": true` gives furniture of `type` without `mass_kg`: chair 5,
/// armchair 12, sofa 35, stool 3, high_stool 5, table 12; nullopt for every other type (boxes,
/// long boxes, cylinders and spheres are movable anyway; beds, laptops and markers are not
/// made movable this way).
std::optional<double> DefaultMovableMassKg(std::string_view type);

}  // namespace simhuman::world
