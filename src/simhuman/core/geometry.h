#pragma once
/// Plain geometry shared by world, plan and control: primitive shapes and rigid poses.
/// No MuJoCo here. Lengths in metres, quaternions in MuJoCo order (w, x, y, z).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace simhuman::core {

/// A rigid transform: world_from_local.
struct Pose {
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  Eigen::Quaterniond quat = Eigen::Quaterniond::Identity();
  Eigen::Vector3d Apply(const Eigen::Vector3d& p_local) const { return pos + quat * p_local; }
  Eigen::Vector3d ApplyInverse(const Eigen::Vector3d& p_world) const {
    return quat.conjugate() * (p_world - pos);
  }
  Pose Compose(const Pose& child) const { return {Apply(child.pos), quat * child.quat}; }
  /// A pose from a position and a yaw about +z (radians).
  static Pose FromYaw(const Eigen::Vector3d& pos, double yaw_rad);
};

enum class ShapeKind { kBox, kSphere, kCapsule, kCylinder, kFrustum, kMesh };

/// A triangle mesh (an object read from an OBJ file). Physics uses its convex hull.
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;  // the mesh's own frame, before Shape::size scaling
  std::vector<std::array<int, 3>> faces;  // indices into `vertices`
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  // vertex bounds
  std::string source;  // where it was read from, for messages
};

/// A solid in its parent's frame. `size` follows MuJoCo geom conventions where there is one:
/// box half-extents (x, y, z); sphere (r); capsule and cylinder (r, half-length along local z);
/// frustum, a truncated cone about local z (bottom radius at -z, half-length, top radius at +z;
/// a top radius of 0 is a cone); mesh: the per-axis scale of `mesh`'s vertices.
struct Shape {
  ShapeKind kind = ShapeKind::kBox;
  Pose pose;  // parent_from_shape
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  std::shared_ptr<const Mesh> mesh;  // kMesh only
};

/// The solid's bounds in its own frame (before `pose`): {min, max}. A mesh is bounded by its
/// scaled vertices' box.
std::pair<Eigen::Vector3d, Eigen::Vector3d> LocalShapeBounds(const Shape& shape);

/// The volume of the solid (m^3); a mesh's from its faces (divergence theorem).
double ShapeVolume(const Shape& shape);

/// `a` (radians) wrapped to (-pi, pi]. The one angle wrap of the code base.
double WrapAngle(double a);

/// The angle (radians, [0, pi]) whose cosine is `c`, with `c` clamped into [-1, 1] first (the
/// dot product of two unit vectors can round past 1). The one such angle of the code base.
double AngleFromCos(double c);

/// Nearest point of the solid `shape` (placed at `world_from_parent`) to `p_world`; returns
/// `p_world` itself when the point is inside the solid. A mesh answers with its bounding box.
Eigen::Vector3d NearestPointOnShape(const Shape& shape, const Pose& world_from_parent,
                                    const Eigen::Vector3d& p_world);

/// Nearest point over a union of shapes (at least one shape required).
Eigen::Vector3d NearestPointOnShapes(const std::vector<Shape>& shapes,
                                     const Pose& world_from_parent, const Eigen::Vector3d& p_world);

/// Samples points on the surface of `shape` with roughly `spacing_m` between neighbours, in the
/// parent frame. Deterministic.
std::vector<Eigen::Vector3d> SampleShapeSurface(const Shape& shape, double spacing_m);

/// Axis-aligned bounds (in the parent frame) of a set of shapes: {min, max}.
std::pair<Eigen::Vector3d, Eigen::Vector3d> ShapesBounds(const std::vector<Shape>& shapes);

}  // namespace simhuman::core
