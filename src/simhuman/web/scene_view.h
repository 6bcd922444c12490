#pragma once
/// What the web viewer (assets/web/viewer.js) draws, taken from a compiled model: the bodies
/// with their geoms, which of them move, their poses per frame, and the contact targets of the
/// current plan step. Shared by the replay file and the live server.

#include <mujoco/mujoco.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::web {

/// Floats per body and frame in a pose block: position x y z (m, world), quaternion w x y z.
inline constexpr int kPoseFloats = 7;
/// Floats per contact target: the body point (x y z) and the point it should reach (x y z).
inline constexpr int kTargetFloats = 6;

/// The drawable part of a model.
struct SceneView {
  /// {"bodies": [{"name", "agent" (-1: not a human), "moving", "pos", "quat", "geoms": [{"type":
  /// "box"|"sphere"|"capsule"|"cylinder"|"ellipsoid"|"plane"|"mesh", "size": [3], "pos": [3] and
  /// "quat": [4] in the body frame, "rgba": [4]; a mesh adds "vertices": [3 n] in its own frame
  /// and "faces": [3 m] vertex indices}]}]}. Only bodies with a visible geom are listed; a
  /// static body's pos/quat is its world pose, a moving one's comes from the frames.
  nlohmann::json json;
  /// Model body ids of the listed moving bodies, in the order of a pose block.
  std::vector<int> moving_bodies;
};

/// Describes `m` with the static poses of `d` (after mj_kinematics or a step).
SceneView DescribeScene(const world::SimWorld& world, const mjData* d);

/// Appends the world poses of `view.moving_bodies` in `d` (kPoseFloats each) to `out`.
void AppendPoses(const SceneView& view, const mjData* d, std::vector<float>* out);

/// Appends the contact targets of plan step `step` (clamped into the chain) for every human in
/// the state `d` (kTargetFloats each) to `out`: for each contact pair the body point and the
/// nearest point of its target part or joint, and for a get-close step the pelvis and the
/// point the human walks to. `catalog` is scratch space (a copy of world.catalog(), synced to
/// `d` here). Returns how many targets were appended.
int AppendTargets(const world::SimWorld& world, const plan::ContactChain& chain, int step,
                  const mjData* d, core::SceneCatalog* catalog, std::vector<float>* out);

/// Standard base64 of `floats` (little-endian float32, as JavaScript's Float32Array reads it
/// on every platform we run on).
std::string FloatsBase64(const std::vector<float>& floats);

/// `j` as text that can sit inside an HTML <script> element: "</" is written "<\/".
std::string JsonForScript(const nlohmann::json& j);

}  // namespace simhuman::web
