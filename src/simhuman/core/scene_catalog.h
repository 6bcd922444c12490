#pragma once
/// A plain description of a scene's objects and their named parts, exported by world/ and used
/// by plan/ (grounding, metrics) and control/ (contact targets). No MuJoCo here.
///
/// Object frame convention: +z up, +x is the object's "front" (the way a seated person faces,
/// the side one approaches a bed or table from), +y is the left of a person seated in it.
/// Yaw rotates about +z.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/geometry.h"

namespace simhuman::core {

/// A named part of an object: a union of solid primitives in the object frame.
struct CatalogPart {
  std::string name;                  // canonical, e.g. "seat surface"
  std::vector<std::string> aliases;  // other accepted names, e.g. "seat", "seat soft surface"
  std::vector<Shape> shapes;         // in the object frame; never empty
};

/// One carrier's hold on a carryable object, in the object frame (metres). The carrier stands
/// at `stand_local` (on the floor) facing `facing_local_rad`, and puts its left and right hands
/// on `left_part` / `right_part` at the hand points (on the parts' surfaces).
struct CarryHold {
  std::string left_part;   ///< canonical part name
  std::string right_part;  ///< canonical part name
  Eigen::Vector3d left_hand_local = Eigen::Vector3d::Zero();
  Eigen::Vector3d right_hand_local = Eigen::Vector3d::Zero();
  /// CooHOI's held point: the midpoint of the two hand points (the centre of the object for one
  /// carrier, the centre of its end for a carrier at an end).
  Eigen::Vector3d held_local = Eigen::Vector3d::Zero();
  Eigen::Vector3d stand_local = Eigen::Vector3d::Zero();  ///< z = 0
  double facing_local_rad = 0.0;                          ///< heading about +z, object frame
};

/// How a team of one size holds an object: one CarryHold per carrier, in carrier order.
struct CarryLayout {
  std::vector<CarryHold> holds;
  int carriers() const { return static_cast<int>(holds.size()); }
};

/// Whether and how an object can be carried by simulated humans. Filled by world/ for every
/// built object (world/carry.h); empty (not carryable) for objects built by hand.
struct CarryInfo {
  std::vector<CarryLayout> layouts;  ///< one per supported team size, ascending; empty: none
  std::string not_carryable;         ///< why the object cannot be carried (layouts empty)

  bool carryable() const { return !layouts.empty(); }
  /// Fewest and most carriers the object has held points for; 0 when not carryable.
  int min_carriers() const;
  int max_carriers() const;
  /// The layout for a team of `carriers`, or nullptr when there is none of that size.
  const CarryLayout* ForTeam(int carriers) const;
};

/// The mass (kg) a team of `carriers` simulated humans may lift: 13 kg alone (what CooHOI's
/// single agent manages), 20 kg per carrier in a team of 2-4 holding a long object at its ends
/// and sides (CooHOI's two-agent range tops at 40 kg). 0 for fewer than one carrier.
double TeamCapacityKg(int carriers);

/// Half the side of the square floor every scene stands on (metres; the floor is centred on the
/// world origin). Objects, destinations and stand points must lie on it.
inline constexpr double kFloorHalfSizeM = 30.0;

/// One object of a scene.
struct CatalogObject {
  std::string id;     // unique, e.g. "chair000"
  std::string type;   // built-in type, e.g. "chair", "bed", "box"
  std::string color;  // colour name, e.g. "red" (may be empty)
  Pose pose;          // world_from_object; updated from the simulation for movable objects
  bool movable = false;
  bool collides = true;            ///< false for markers (visual targets that bodies pass through)
  double mass_kg = 0.0;            // movable objects only
  std::optional<double> friction;  ///< sliding friction of its solids; empty: model default 0.9
  std::vector<CatalogPart> parts;  // named parts
  std::vector<Shape> shapes;       // every solid of the object (parts and unnamed, e.g. legs)
  CarryInfo carry;                 ///< held points, stand points and team sizes (carrying)

  /// The part whose name or alias matches `name` (case-insensitive; trailing digits of
  /// ScenePlan names such as "mattress25" are ignored). nullptr when none matches.
  const CatalogPart* FindPart(std::string_view name) const;
  /// Canonical part names, for error messages.
  std::vector<std::string> PartNames() const;
  /// Bounds of all shapes in the object frame: {min, max}.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> LocalBounds() const;
};

/// One simulated human as plans see it: its kind, size and the body points a plan may name.
struct CatalogAgent {
  std::string kind = "humanoid";  ///< an embodiment name (world/embodiment.h)
  double scale = 1.0;             ///< body length scale (1 = adult)
  BodyPointCatalog body_points = StandardBodyPointCatalog();
};

/// All objects of a scene plus its simulated humans (one adult humanoid unless set).
struct SceneCatalog {
  std::vector<CatalogObject> objects;
  std::vector<CatalogAgent> agents = {CatalogAgent{}};

  int num_agents() const { return static_cast<int>(agents.size()); }

  const CatalogObject* Find(std::string_view id) const;
  CatalogObject* Find(std::string_view id);
  std::vector<std::string> ObjectIds() const;
};

/// What NormalizeName() does with digits at the end of a name.
enum class TrailingDigits {
  kDrop,  ///< removed: ScenePlan numbers its parts ("mattress25" matches "mattress")
  kKeep,  ///< kept: exact names ("arm sofa style44" differs from "arm sofa style48"), enum values
};

/// The one canonical form of a part, object, joint or enum name for matching: lower case,
/// '_' -> ' ', surrounding spaces removed, and with TrailingDigits::kDrop trailing digits too
/// (with any spaces among them): "Seat_Soft_Surface42" -> "seat soft surface", or
/// "seat soft surface42" with kKeep. Only ' ' counts as a space.
std::string NormalizeName(std::string_view name, TrailingDigits digits = TrailingDigits::kDrop);

}  // namespace simhuman::core
