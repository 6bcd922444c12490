#pragma once
/// Scenes: objects plus the humans that start in them. Read from our scene JSON, from a UniHSI
/// ScenePlan entry, or from a built-in name; turned into a core::SceneCatalog by BuildCatalog().
/// The formats are described in docs/FORMATS.md ("Scenes").

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/world/objects.h"

namespace simhuman::world {

/// Where one human starts. Plain data.
struct HumanSpec {
  Eigen::Vector2d pos_xy = Eigen::Vector2d::Zero();  // world, metres (the pelvis on the floor)
  double yaw_rad = 0.0;                              // facing direction about +z; 0 faces +x
  double scale = 1.0;             // body length scale: 1 = adult ~1.7 m, a child e.g. 0.7
  std::string posture = "stand";  // one of HumanPostures()
  std::string kind = "humanoid";  // an agent kind: world/embodiment.h EmbodimentNames()
};

/// A scene before it is built. Plain data.
struct SceneSpec {
  std::string name;
  std::vector<ObjectSpec> objects;
  std::vector<HumanSpec> humans;
};

/// Accepted human postures: "stand", "sit", "lie". Only standing humans are checked against
/// the objects for overlap; how "sit" and "lie" are initialised is up to the humanoid.
const std::vector<std::string>& HumanPostures();

/// Parses a scene, strictly. Two forms are accepted:
///  - ours: {"name", "objects": [{"id", "type", "pos", "yaw_deg", "scale", "size", "color",
///    "mass_kg", "movable", "friction"}], "humans": [{"pos", "yaw_deg", "scale", "posture",
///    "kind"}]};
///  - a UniHSI ScenePlan entry {"obj": {"000": {"id", "name", "rotate", "scale", "transfer",
///    "stand_point"}}, "chain of contacts" | "contact_pairs": [...]}, or a one-key wrapper of
///    it such as {"0000": {...}} (the contacts are ignored here; plan/ parses them).
/// Every object is built once to check it. Without "humans", one adult is placed by
/// DefaultHuman(). Errors (InvalidArgument) start with `source` (a file name or "<string>"),
/// name the JSON pointer of the culprit and list what would have been valid.
core::StatusOr<SceneSpec> ParseSceneJson(const nlohmann::json& json, std::string_view source);

/// A built-in scene (BuiltinSceneNames()) or a JSON file path. An unknown name that is not a
/// readable file is NotFound, listing the built-in names.
core::StatusOr<SceneSpec> LoadScene(const std::string& name_or_path);

/// living_room, bedroom, office, tabletop_demo, sit_demo, empty, carry_demo, carry_team_demo,
/// tabletop_dash.
std::vector<std::string> BuiltinSceneNames();

/// The built-in scene `name`, or NotFound listing the names.
core::StatusOr<SceneSpec> BuiltinScene(std::string_view name);

/// Builds every object (errors name the object id) and one catalog agent per human (its kind,
/// scale and body points).
/// Objects keep the order of the spec.
core::StatusOr<core::SceneCatalog> BuildCatalog(const SceneSpec& spec);

/// Our JSON form of `spec` (round-trips through ParseSceneJson); for resolved-config records.
nlohmann::json SceneToJson(const SceneSpec& spec);

/// World-frame axis-aligned bounds {min, max} of an object's solids at its pose.
std::pair<Eigen::Vector3d, Eigen::Vector3d> WorldBounds(const core::CatalogObject& object);

/// Pairs of object ids whose world bounds overlap by more than `tolerance_m` on every axis
/// (touching, e.g. a laptop resting on a table, is not an overlap).
std::vector<std::pair<std::string, std::string>> OverlappingObjects(const core::SceneCatalog& scene,
                                                                    double tolerance_m = 1e-6);

/// The default starting human for a scene: an adult standing 2 m in front of the first object
/// (along its +x), facing it; if that spot is blocked, the first clear spot found by turning
/// around the object in 30 degree steps (alternating sides) and then at 3 m. With no objects:
/// at the origin facing +x. "Clear" means a 0.35 m disc around the human misses every
/// object's world bounds.
HumanSpec DefaultHuman(const std::vector<core::CatalogObject>& objects);

}  // namespace simhuman::world
