#pragma once
/// Animated glTF 2.0 binary (.glb) export of a recorded run (docs/FORMATS.md "glTF export"):
/// one node per MuJoCo body that has visible geoms (named after the body), its geoms as the
/// primitives of one mesh, one material per colour, and one animation whose channels move every
/// body that moves (translation + rotation, linear). MuJoCo's z-up world becomes glTF's y-up:
/// a point at MuJoCo (x, y, z) is at glTF (x, z, -y); metres stay metres.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "simhuman/core/status.h"
#include "simhuman/render/bvh_export.h"

namespace simhuman::render {

/// MuJoCo world (z up) to glTF (y up): (x, y, z) -> (x, z, -y).
Eigen::Vector3d MujocoToGltf(const Eigen::Vector3d& p);

/// The same change of axes for a rotation: q -> c q c*, with c the -90 degree turn about x.
Eigen::Quaterniond MujocoToGltf(const Eigen::Quaterniond& q);

/// Options of SceneGlb.
struct GltfOptions {
  double fps = 30;           ///< animation samples per second, in (0, 1000]
  int segments = 24;         ///< divisions of round shapes (GeomMesh), 3..256
  double floor_half_m = 10;  ///< the floor plane is cut to this half-size (metres, > 0)
  bool animate_all = false;  ///< channels for every body, not only the ones that move
};

/// The scene of `m` moving through `frames` as a .glb file's bytes. Geoms of alpha 0 and of
/// groups >= 3 (hidden in MuJoCo's viewer by default) are left out. Samples start at the first
/// recorded time (animation time 0) and end at the last. Errors: InvalidArgument for bad
/// options, no frames or rows whose size is not m->nq.
core::StatusOr<std::string> SceneGlb(const mjModel* m, const QposFrames& frames,
                                     const GltfOptions& options = {});

}  // namespace simhuman::render
