#pragma once
/// Reading a Wavefront OBJ file into a core::Mesh (vertices and triangles; polygons are split
/// into fans; normals, texture coordinates, groups and materials are ignored).

#include <memory>
#include <string>

#include "simhuman/core/geometry.h"
#include "simhuman/core/status.h"

namespace simhuman::world {

/// Limits of what ReadObjMesh() accepts.
inline constexpr int kObjMaxVertices = 100000;
inline constexpr double kObjMaxExtentM = 5.0;    // largest side of the vertices' bounding box
inline constexpr double kObjMinExtentM = 0.005;  // smallest side

/// The mesh in `path`. Errors name the file and, for a malformed line, its number and what a
/// valid line looks like.
core::StatusOr<std::shared_ptr<const core::Mesh>> ReadObjMesh(const std::string& path);

/// The same from OBJ text; `source` names it in errors.
core::StatusOr<std::shared_ptr<const core::Mesh>> ParseObjMesh(const std::string& text,
                                                               const std::string& source);

}  // namespace simhuman::world
