#pragma once
/// Triangle meshes of MuJoCo geoms (planes, spheres, capsules, ellipsoids, cylinders, boxes and
/// mesh geoms), for exporters that need explicit triangles (glTF).

#include <mujoco/mujoco.h>

#include <cstdint>
#include <vector>

namespace simhuman::render {

/// An indexed triangle mesh: xyz positions and unit normals per vertex, counter-clockwise
/// triangles (seen from outside), in the geom's own frame (metres).
struct TriMesh {
  std::vector<float> position;  ///< 3 per vertex
  std::vector<float> normal;    ///< 3 per vertex
  std::vector<uint32_t> index;  ///< 3 per triangle

  int num_vertices() const { return static_cast<int>(position.size() / 3); }
};

/// The surface of geom `g` of `m` in the geom frame. Round shapes use `segments` divisions
/// around their axis (>= 3; half as many along it). A plane of size 0 (infinite) is drawn
/// `infinite_plane_half_m` metres to each side. A geom type without a surface (height fields
/// today) gives an empty mesh.
TriMesh GeomMesh(const mjModel* m, int g, int segments = 24, double infinite_plane_half_m = 10.0);

}  // namespace simhuman::render
