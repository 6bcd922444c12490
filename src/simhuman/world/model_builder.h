#pragma once
/// Assembles one MJCF model from a scene catalog (objects as primitive geoms, static or on a
/// free joint) and the humanoids placed in it.

#include <string>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/world/embodiment.h"

namespace simhuman::world {

/// Physics options of the assembled model.
struct ModelOptions {
  double timestep_s = 0.005;
  int solver_iterations = 20;
  /// MuJoCo constraint solver: "newton" (default) or "pgs" (a faster, looser fit of the same
  /// contact problem; the walking task can train with it).
  std::string solver = "newton";
  /// Friction cone: "pyramidal" (default) or "elliptic" (truer to Coulomb; grasping uses it).
  std::string cone = "pyramidal";
  /// Ratio of frictional to normal constraint impedance (>= 1); above 1 friction slips less,
  /// which a held object needs (MuJoCo's documentation suggests about 10 for grasps).
  double impratio = 1;
  int offscreen_width = 640;  ///< framebuffer for headless rendering
  int offscreen_height = 480;
  /// MuJoCo's buffer sizes (MJCF <size>): contacts, constraint rows and the stack (mjtNum).
  /// Every mjData of the model allocates and clears them: njmax alone costs njmax^2 x 8 bytes
  /// (128 MB at the default, sized for rooms and teams). A run that outgrows them gets MuJoCo's
  /// CONTACTFULL/CNSTRFULL warning (contacts dropped), which the health checks report.
  int nconmax = 1500;
  int njmax = 4000;
  int nstack = 3000000;
};

/// Name prefix of agent `i` ("" for agent 0, "h1/" for agent 1, ...).
std::string AgentPrefix(int agent);

/// MJCF body name of catalog object `id` ("obj/<id>").
std::string ObjectBodyName(const std::string& id);

/// Default contact friction (sliding, torsional, rolling) of every geom.
inline constexpr double kDefaultSlidingFriction = 0.9;

/// Builds the MJCF text. Movable objects' geoms get condim 4 and friction "<f> 0.05 0.01", other
/// objects' "<f> 0.02 0.01", with f = CatalogObject::friction or kDefaultSlidingFriction; an
/// object with its own friction also gets geom priority 1, so that its contacts with other
/// geoms (table, floor, hands) use its coefficient rather than MuJoCo's default, the larger of the
/// two. Errors name the culprit (e.g. a non-finite size or friction).
core::StatusOr<std::string> BuildModelXml(const core::SceneCatalog& scene,
                                          const std::vector<AgentSpec>& agents,
                                          const ModelOptions& options);

}  // namespace simhuman::world
