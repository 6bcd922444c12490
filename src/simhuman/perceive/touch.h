#pragma once
/// Touch: where a hand's skin touches the object it holds and which way each contact pushes (a
/// tactile array's contact locations and force directions), in the hand's own frame (the body's
/// joints carry them there). A held box or cylinder of known width is then placed by its side
/// faces: they lie where the hand touches them, and its up axis runs along them. DASH's hand
/// feels binary contact per phalanx; this reads where on the skin and which way.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

namespace simhuman::perceive {

/// One contact between the hand and the held object: a point on their touching surfaces and
/// the direction the object's surface faces there (outward, into the hand).
struct TouchContact {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
};

/// Per model geom: whether it belongs to `body` or a body below it (a hand and its fingers).
std::vector<bool> SubtreeGeoms(const mjModel* m, int body);

/// The contacts in `d` between the geoms flagged in `hand_geoms` and the geoms of
/// `object_body`, in the frame of `hand_body` (its pose in `d`).
std::vector<TouchContact> HandTouch(const mjModel* m, const mjData* d,
                                    const std::vector<bool>& hand_geoms, int hand_body,
                                    int object_body);

/// How RefineHeldByTouch weighs touch.
struct TouchRefineOptions {
  /// How strongly the estimate holds against touch (per contact's weight 1): in directions no
  /// contact constrains (e.g. a tilt about the normal of two opposite faces) it stays.
  double prior_weight = 0.05;
  /// A contact is on the object's side when its normal is within asin(side_cos) of square to
  /// the estimated up axis (an edge's normal, 45 degrees, is not).
  double side_cos = 0.34;
  /// Touch that would turn the up axis further than this, or move the centre further than
  /// max_shift_m, is not believed (contacts on an edge or a face other than the side taken for
  /// one): the estimate is left as it was. Both bounds are wide: a held object slips 3-7 cm in
  /// the grip between the grasp and the release (3 cm here gave stack 106 / 138 against 115
  /// with 8 cm; docs/BENCHMARKS.md, issue 16 session 49), and turns in it by up to 17 degrees
  /// (15 here gave place 125 / 134 and stack 115 / 138, against 126 and 118 with 25; session 50).
  double max_turn_rad = 0.44;
  double max_shift_m = 0.08;
};

/// Corrects an estimate of a held box's or cylinder's centre and up axis (all in one frame)
/// by touch. `radius`: its half width (box, square across) or radius. The up axis becomes the
/// direction most square to the side contacts' normals, and the centre moves across the axis so
/// that each touched side face lies `radius` from it; the centre along the axis is left as it
/// was. Returns whether it changed them (false: no side contact, or a correction beyond the
/// options' limits).
bool RefineHeldByTouch(const std::vector<TouchContact>& contacts, double radius,
                       const TouchRefineOptions& o, Eigen::Vector3d* centre, Eigen::Vector3d* up);

}  // namespace simhuman::perceive
