#pragma once
/// A generated table scene (world/tabletop.h: DASH's objects, ranges and task rules) built into
/// a world with the seated dexterous human, and its task as the pipeline's goal: what the
/// tabletop suites and the place training both start from.

#include <cstdint>
#include <memory>
#include <string>

#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::control::manip {

/// A generated table scene (GenerateTabletop(seed, kind)) built into a world with the seated
/// dexterous human, forwarded.
struct TableWorld {
  world::TabletopScene ts;
  core::SceneCatalog catalog;
  std::unique_ptr<world::SimWorld> world;
};
core::StatusOr<TableWorld> MakeTableWorld(uint64_t seed, const std::string& kind);

/// The pipeline's goal for a generated scene's task in `world` (built from that scene): the
/// object's body, shape, sizes and planned base position, the target and the support body.
core::StatusOr<TabletopGoal> TabletopSceneGoal(const world::TabletopScene& ts,
                                               const world::SimWorld& world);

/// `g`'s shape, height and half width from the object's catalog solids; a shape not made for the
/// grasp (cone, hourglass, mesh) is taken as a cylinder as wide as the object is where the hand
/// will grip it (and its grip height and success height set to match).
void SizeFromCatalog(const core::CatalogObject& o, TabletopGoal* g);

}  // namespace simhuman::control::manip
