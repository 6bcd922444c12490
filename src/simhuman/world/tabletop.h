#pragma once
/// DASH tabletop scenes (Ye et al., SCA 2021, Appendix B "Quantitative evaluation setup"): a
/// seeded generator of boxes, cylinders and spheres (DASH draws 4-6; its region and spacing
/// keep 2-5) on a table in front of a seated human, with one task: place an object at a
/// location on the table, or stack it on another object.
///
/// The layout (world frame, metres) every generated scene shares:
///  - table000: a "table" of default sizes (0.75 high, 1.20 wide along y, 0.75 deep along x)
///    centred at (1.0, 0), yaw 180 degrees, so that its sitting side (+x of the table) faces
///    world -x; the board's near edge is at x = 0.625.
///  - chair001: a default "chair" at (0.38, 0.235), yaw 0 (facing +x): its seat's front edge
///    0.02 m behind the board's near edge.
///  - one human, posture "sit", kind "humanoid_right_hand", at the chair (0.38, 0.235), facing
///    +x (towards the table). Its right shoulder is 0.185 m to its right and, seated, about 0.98
///    m above the floor: nominally at (0.38, 0.05, 0.98), 0.23 m above the table top.
///
/// DASH's table frame ("the table frame" below): right-handed, z up, origin on the table top,
/// +x away from the seated human (world +x), +y to the human's left (world +y); DASH's ranges
/// are lopsided to the right-hand side, so the origin lies right of the right shoulder. It is at
/// world (0.795, -0.20, 0.75): 0.415 m in front of the right shoulder (0.17 m in from the
/// board's near edge) and 0.25 m to the shoulder's right. DASH samples object bases in
/// -0.10 <= x <= 0.25, -0.10 <= y <= 0.50, which is then the world rectangle
/// x in [0.695, 1.045], y in [-0.30, 0.30] on the table top: 0.07-0.42 m in from the board's
/// near edge (the largest sphere, radius 6.75 cm, stays on the board), centred on the board's
/// width, from 0.25 m left to 0.35 m right of the right shoulder: in front of the human and
/// mostly to its right. Horizontal distances from the right shoulder to the rectangle's corners:
/// 0.40 m (near left), 0.47 m (near right), 0.71 m (far left), 0.75 m (far right), 0.49 m to its
/// centre; with the 0.23 m height, 3-D distances to the table top are 0.46, 0.52, 0.75, 0.79 m
/// and 0.54 m. (A 0.35 x 0.60 m rectangle, diagonal 0.69 m, cannot lie within 0.35-0.65 m of a
/// point; the far corners are a forward lean away, the arm being 0.6 m long.)

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/world/model_builder.h"
#include "simhuman/world/scene.h"

namespace simhuman::world {

/// DASH's sampling ranges (Appendix B) and counts. Lengths in metres, masses in kg; positions in
/// the table frame (header comment). Plain data; Validate() before use.
struct TabletopOptions {
  int min_objects = 4;             ///< desired object count drawn uniformly in [min, max]
  int max_objects = 6;             ///< (fewer when placements keep failing, as in DASH)
  int max_resamples = 50;          ///< placements retried per object before it is dropped
  double min_separation_m = 0.25;  ///< between object centroids (and from a place target)
  double width_lo_m = 0.06, width_hi_m = 0.10;    ///< nominal width (a cylinder's diameter)
  double height_lo_m = 0.13, height_hi_m = 0.18;  ///< box and cylinder height
  double box_width_scale = 0.8;  ///< a box's side = scale x nominal width (square in plan)
  double sphere_scale = 0.75;    ///< a sphere's diameter = scale x a height drawn as above
  double mass_lo_kg = 1.0, mass_hi_kg = 5.0;
  double friction_lo = 0.8, friction_hi = 1.2;  ///< sliding friction (ObjectSpec::friction)
  /// Stacking: the bottom object is a box or a cylinder whose nominal width is drawn from
  /// [stack_bottom_min_width_m, width_hi_m] (DASH: 9 cm, "slightly thicker").
  double stack_bottom_min_width_m = 0.09;
  double region_x_lo_m = -0.10, region_x_hi_m = 0.25;  ///< object bases, table frame
  double region_y_lo_m = -0.10, region_y_hi_m = 0.50;
  /// Ours, not DASH's: a place target lies at least this far from the task object's start, so
  /// that no place task is done before it starts. At most half the region's shorter side.
  double place_min_move_m = 0.10;

  /// InvalidArgument naming the first bad option, its value and the valid range. The region
  /// must lie on the table's board, at least a largest object's half width in from its edges.
  core::Status Validate() const;
};

/// The task of a generated scene.
struct TabletopTask {
  std::string kind;       ///< "place" or "stack"
  std::string object_id;  ///< the object to move
  std::string target_id;  ///< stack: the bottom object; place: empty
  /// place: where the object's base goes (world; z = the table top); stack: the centre of the
  /// bottom object's top face (world).
  Eigen::Vector3d target_world = Eigen::Vector3d::Zero();
  /// The same target in the table frame (z = 0 on the table top).
  Eigen::Vector3d target_table = Eigen::Vector3d::Zero();
  /// stack: "put the <colour> <shape> on the <colour> <shape>"; place: empty (DASH leaves
  /// language out of its benchmark, and a location has no words yet).
  std::string command;
};

/// A generated scene and its task.
struct TabletopScene {
  SceneSpec scene;  ///< table000, chair001, then the objects; one seated human
  TabletopTask task;
  int desired_objects = 0;  ///< the count drawn before placement (scene may hold fewer)
};

/// The kinds GenerateTabletop() accepts: "place", "stack", "any" (either, with equal odds).
const std::vector<std::string>& TabletopTaskKinds();

/// A DASH Appendix B scene for `seed`. Draws a desired count n in [min_objects, max_objects];
/// then the task objects (stack: the bottom object first, a box or cylinder of nominal width
/// >= stack_bottom_min_width_m, then the object put on it); then the other objects. Each object
/// gets a shape (box, cylinder, sphere), colour (red, yellow, green, blue), sizes, mass and
/// friction drawn uniformly, and a base position drawn in the region at least min_separation_m
/// from every centroid so far; a rejected position is redrawn up to max_resamples times, after
/// which the object is dropped (so a scene may hold fewer than n). Last, for place, the target:
/// in the region, at least min_separation_m from the other objects' centroids and
/// place_min_move_m from the task object's; when max_resamples redraws find none, the last other
/// object is dropped and the search repeats. The task objects are unique by (shape, colour)
/// among all objects: an object drawing a task object's shape and colour redraws its colour.
/// Ids: "<type><index, 3 digits>" from 002, in drawing order. Deterministic for a seed
/// (core::Rng). Errors: InvalidArgument for an unknown `kind` (listing the valid ones) or bad
/// options (TabletopOptions::Validate()); Internal if a task object finds no position.
core::StatusOr<TabletopScene> GenerateTabletop(uint64_t seed, std::string_view kind,
                                               const TabletopOptions& options = {});

/// Shapes not in the generator, for zero-shot runs (DASH Section 5 shows an hourglass, a cone and
/// a mesh): "cone", "hourglass" and "mesh" (an OBJ file).
const std::vector<std::string>& ZeroShotShapes();

/// The OBJ file of a zero-shot "mesh" when none is named: a lathed, oval vase 16 cm tall
/// (scripts/make_vase_obj.py), read from the current directory.
inline constexpr char kZeroShotMeshFile[] = "assets/meshes/vase.obj";

/// The task object of `ts` becomes a `shape` of ZeroShotShapes() at the same place, with the
/// same colour, mass and friction: a cone or an hourglass as wide as the object was drawn
/// (its nominal width; the hourglass's waist 0.55 of it) and as tall; a mesh as `mesh_file`
/// gives it. Its id becomes "<shape><the same 3 digits>"; the task and its command follow.
/// Errors: InvalidArgument naming an unknown shape (listing the valid ones) or a mesh file that
/// cannot be read or used.
core::Status MakeZeroShot(TabletopScene* ts, std::string_view shape,
                          const std::string& mesh_file = kZeroShotMeshFile);

/// The built-in scene `tabletop_dash`: GenerateTabletop(3, "stack"), DASH's set-up.
SceneSpec TabletopDashScene();

/// The built-in scene `tabletop_zero_shot`: tabletop_dash with its object to stack made an
/// hourglass (MakeZeroShot) and its sphere a cone.
SceneSpec TabletopZeroShotScene();

/// The table, chair and seated human of the layout above, without objects; `name` as given.
SceneSpec TabletopBaseScene(const std::string& name);

/// Physics of a world with a dexterous hand (the tabletop suites, `run` at a table, the grasp
/// training task): 240 Hz as DASH, and elliptic friction cones with impratio 3, under which
/// grasped objects slip less (measured on 59 box and cylinder tasks: 30 done against 22 with
/// MuJoCo's default pyramidal cones; docs/BENCHMARKS.md).
ModelOptions DexterousModelOptions();

/// A table-frame point (x, y, z up from the table top) in the world of the layout above.
Eigen::Vector3d TableToWorld(const Eigen::Vector3d& p_table);

/// A world point in the table frame of the layout above.
Eigen::Vector3d WorldToTable(const Eigen::Vector3d& p_world);

/// The seated human's right shoulder (world), nominal: upright torso, the pelvis resting on the
/// chair's seat. Derived from kTabletopShoulderRightM and kTabletopShoulderAbovePelvisM.
Eigen::Vector3d TabletopRightShoulderWorld();

/// The humanoid's right shoulder relative to its pelvis origin, body frame, scale 1: metres to
/// the right (-y) and above (the humanoid's MJCF; tested against the compiled model).
inline constexpr double kTabletopShoulderRightM = 0.185;
inline constexpr double kTabletopShoulderAbovePelvisM = 0.41;
/// Seated, the pelvis origin sits this high above the seat (the pelvis capsule, radius 0.09 with
/// its axis 0.03 below the origin, resting on the seat).
inline constexpr double kTabletopPelvisAboveSeatM = 0.12;

}  // namespace simhuman::world
