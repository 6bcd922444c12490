#pragma once
/// Procedural furniture with named parts: chairs, armchairs, sofas, stools, beds, tables,
/// laptops and boxes built from primitive solids, with human-plausible metric dimensions.
///
/// Object frame (as in core/scene_catalog.h): +z up, the origin on the floor (z = 0 is the
/// object's lowest point), +x the object's front, +y the object's left as the seated person
/// sees it (a person sitting on a chair faces +x and has +y on the left hand side).
///  - chair, armchair, sofa, stool, high_stool: origin under the centre of the seat, the seat's
///    front edge at x = +seat_depth/2, the back (if any) behind it at -x.
///  - bed: origin under the centre of the mattress; the bed is long along y, the long side at
///    +x is the front (where one sits on the edge before lying down), the pillow and the
///    headboard are at the +y end (the head end), the feet end is -y.
///  - table: origin under the centre of the board; +x is the side one sits at (the board is
///    `width` long along y and `depth` deep along x).
///  - laptop: origin under the centre of the keyboard base (z = 0 is the base's bottom, so a
///    laptop on a table has pos.z = table top); the user sits at +x, the screen is hinged at
///    the -x edge and faces +x.
///  - box: origin under the centre of the box; "front side" is the +x face, "left side" the
///    +y face.
///  - long_box: a box for a team (parts as the box), `length` along x, default 2.0 x 0.5 x 0.5
///    m and 25 kg.
///  - cylinder (upright) and sphere: origin under the centre; parts "top" and "body" (the
///    cylinder), "body" (the sphere).
/// Sizes are metres before `scale`; `scale` multiplies every length (and a derived box mass by
/// scale^3).

#include <Eigen/Core>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "simhuman/core/rng.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"

namespace simhuman::world {

/// What to build: a type, its placement and optional size overrides. Plain data.
struct ObjectSpec {
  std::string id;     // unique in the scene, e.g. "chair000"
  std::string type;   // one of ObjectTypes() ("high stool" is accepted for "high_stool")
  std::string color;  // palette name (ColorNames()); empty = DefaultColor(type)
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();  // world origin, m; z = height of the support
  double yaw_rad = 0.0;                           // about +z
  double scale = 1.0;                             // multiplies every length
  std::map<std::string, double> size;  // overrides of named size parameters, metres before scale
  std::optional<double> mass_kg;       // set: the object is movable (free) with this mass
  /// Sliding (lateral) contact friction coefficient of the object's solids, in
  /// [kMinFriction, kMaxFriction]; empty: the model's default (0.9).
  std::optional<double> friction;
  /// Type "mesh" only: the OBJ file of its shape (metres, +z up, resting on its lowest vertex;
  /// a relative path is read from the current directory). Physics uses its convex hull.
  std::string mesh;
};

/// Types that are always movable (small objects and boxes): they get a mass from their volume
/// when the scene gives none.
bool AlwaysMovable(std::string_view type);

/// The range of ObjectSpec::friction BuildObject() and the scene parser accept.
inline constexpr double kMinFriction = 0.1;
inline constexpr double kMaxFriction = 2.0;

/// One named size parameter of an object type: its default, the range RandomObjectSpec()
/// samples from (realistic furniture) and the wider range BuildObject() accepts.
struct SizeParam {
  std::string name;  // e.g. "seat_height"
  double default_m;
  double random_lo_m, random_hi_m;
  double valid_lo_m, valid_hi_m;
  std::string doc;  // one line for docs and error messages
};

/// Canonical type names: chair, armchair, sofa, stool, high_stool, bed, table, laptop, marker,
/// box, long_box, cylinder, sphere.
std::vector<std::string> ObjectTypes();

/// The canonical type for `name` (case-insensitive; ' ' and '-' read as '_', so "High stool"
/// gives "high_stool"); nullopt for an unknown type.
std::optional<std::string> CanonicalObjectType(std::string_view name);

/// The size parameters of `type` (canonical or not); empty for an unknown type.
std::vector<SizeParam> SizeParams(std::string_view type);

/// Default size of each parameter of `type`, metres; empty for an unknown type.
std::map<std::string, double> DefaultSizes(std::string_view type);

/// Randomization range {lo, hi} of each size parameter of `type`, metres; empty for an unknown
/// type.
std::map<std::string, std::pair<double, double>> SizeRanges(std::string_view type);

/// A spec of `type` with every size sampled uniformly from SizeRanges(), a random palette
/// colour, id "<type>000", at the origin, yaw 0, scale 1. Boxes get a mass in [2, 10] kg, long
/// boxes one in [15, 40] kg.
/// Deterministic for a given `rng` state. An unknown type gives a spec without sizes, which
/// BuildObject() then rejects.
ObjectSpec RandomObjectSpec(std::string_view type, core::Rng& rng);

/// Builds the object: parts (canonical names plus UniHSI/PartNet style aliases) and every solid
/// (parts and unnamed legs and frames) in `shapes`, pose from pos and yaw_rad, and the carrying
/// data (`carry`, world/carry.h). Only boxes, long boxes (25 kg unless given), cylinders and
/// spheres, and objects given a mass_kg, are movable. Errors (InvalidArgument) name
/// the object id and the culprit: an unknown type (listing valid types), an unknown size key
/// (listing the type's keys), a non-finite or out-of-range size, scale, position, yaw, mass or
/// friction, an unknown colour. The friction is carried to CatalogObject::friction. Thread-safe.
core::StatusOr<core::CatalogObject> BuildObject(const ObjectSpec& spec);

/// The palette: red, green, blue, yellow, white, black, brown, grey, orange, purple.
std::vector<std::string> ColorNames();

/// RGBA in [0, 1] of a palette colour (case-insensitive; "gray" reads as "grey"); nullopt if
/// the name is not in the palette.
std::optional<std::array<float, 4>> ColorRgba(std::string_view name);

/// The palette colour used when a spec has none (brown wood for chairs, stools and tables, ...);
/// "grey" for an unknown type.
std::string DefaultColor(std::string_view type);

}  // namespace simhuman::world
