#pragma once
/// Hand-built scene catalogs for the plan module's unit tests (test code only; not part of the
/// library). Numbers are chosen so metric results can be computed by hand.

#include <cmath>
#include <string>
#include <vector>

#include "simhuman/core/geometry.h"
#include "simhuman/core/scene_catalog.h"

namespace simhuman::plan::fixtures {

/// A box shape centred at `centre` (object frame) with half-extents `half`.
inline core::Shape Box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
  core::Shape s;
  s.kind = core::ShapeKind::kBox;
  s.pose.pos = centre;
  s.size = half;
  return s;
}

inline core::CatalogPart Part(std::string name, std::vector<std::string> aliases,
                              core::Shape shape) {
  core::CatalogPart p;
  p.name = std::move(name);
  p.aliases = std::move(aliases);
  p.shapes = {std::move(shape)};
  return p;
}

/// chair000 at `pose`. Object frame: seat top at z = 0.47 over x, y in [-0.25, 0.25];
/// LocalBounds x in [-0.25, 0.25], y in [-0.29, 0.29], z in [0, 1.03].
/// Parts: seat surface (box centre (0, 0, 0.45), half (0.25, 0.25, 0.02)), back surface,
/// left arm (+y), right arm (-y); four unnamed legs.
inline core::CatalogObject MakeChair(const core::Pose& pose) {
  core::CatalogObject o;
  o.id = "chair000";
  o.type = "chair";
  o.color = "red";
  o.pose = pose;
  o.parts.push_back(
      Part("seat surface", {"seat", "seat soft surface"}, Box({0, 0, 0.45}, {0.25, 0.25, 0.02})));
  o.parts.push_back(
      Part("back surface", {"back soft surface"}, Box({-0.23, 0, 0.75}, {0.02, 0.25, 0.28})));
  o.parts.push_back(Part("left arm", {"left armrest hard surface", "arm sofa style44", "armrest"},
                         Box({0, 0.27, 0.62}, {0.2, 0.02, 0.02})));
  o.parts.push_back(Part("right arm", {"right armrest hard surface", "arm sofa style48", "armrest"},
                         Box({0, -0.27, 0.62}, {0.2, 0.02, 0.02})));
  for (const core::CatalogPart& p : o.parts) o.shapes.push_back(p.shapes[0]);
  for (double x : {-0.22, 0.22}) {
    for (double y : {-0.22, 0.22}) o.shapes.push_back(Box({x, y, 0.215}, {0.02, 0.02, 0.215}));
  }
  return o;
}

/// bed001 at `pose`: mattress (box centre (0, 0, 0.3), half (1.0, 0.5, 0.15)) and pillow
/// (box centre (-0.8, 0, 0.5), half (0.15, 0.3, 0.05)).
inline core::CatalogObject MakeBed(const core::Pose& pose) {
  core::CatalogObject o;
  o.id = "bed001";
  o.type = "bed";
  o.pose = pose;
  o.parts.push_back(Part("mattress", {}, Box({0, 0, 0.3}, {1.0, 0.5, 0.15})));
  o.parts.push_back(Part("pillow", {}, Box({-0.8, 0, 0.5}, {0.15, 0.3, 0.05})));
  for (const core::CatalogPart& p : o.parts) o.shapes.push_back(p.shapes[0]);
  return o;
}

/// chair000 at the origin (yaw 0) and bed001 at (3, 0, 0) turned by 90 degrees; one agent.
inline core::SceneCatalog MakeTestScene() {
  core::SceneCatalog scene;
  scene.objects.push_back(MakeChair(core::Pose::FromYaw({0, 0, 0}, 0.0)));
  scene.objects.push_back(MakeBed(core::Pose::FromYaw({3, 0, 0}, M_PI / 2)));
  scene.agents.resize(1);
  return scene;
}

/// Path of a file in tests/data/plan/.
inline std::string PlanDataPath(const std::string& name) {
  return std::string(SIMHUMAN_SOURCE_DIR) + "/tests/data/plan/" + name;
}

}  // namespace simhuman::plan::fixtures
