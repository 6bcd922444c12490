#pragma once
/// A Chain-of-Contacts step turned into what a controller optimizes: contact terms with their
/// target geometry, the base posture the step implies, and where to stand for get-close steps.
/// Built from grounded plan steps; holds pointers into the SceneCatalog it was built from
/// (which must outlive it).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/span.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/plan/metrics.h"

namespace simhuman::control {

/// The base postures the reference-pose solver starts from.
enum class Posture { kStand, kSit, kLieBack, kLieSide, kLean };

const char* PostureName(Posture p);

/// One contact (or not-contact) requirement in controller terms.
struct ContactTerm {
  core::BodyJoint joint = core::BodyJoint::kPelvis;
  plan::ContactType type = plan::ContactType::kContact;
  const core::CatalogObject* object = nullptr;  ///< null when the target is a body joint
  const core::CatalogPart* part = nullptr;
  std::optional<core::BodyJoint> target_joint;  ///< "right foot on left knee"
  /// A hand on its own pelvis touched at the belly (plan::TouchesBelly): the target is
  /// plan::BellyPoint(), approached along its normal.
  bool at_belly = false;
  Eigen::Vector3d dir = Eigen::Vector3d::Zero();  ///< unit vector, zero for "none"
  double clearance_m = 0.05;  ///< joint-centre to surface distance when touching
  /// Added to the touching position when solving a reference pose: a controller's correction
  /// of a steady miss (zero unless a controller sets it).
  Eigen::Vector3d aim_offset = Eigen::Vector3d::Zero();

  /// Nearest point of the target to `p` (part surface or the target joint's position).
  /// `pts`: the agent's body points by id (at least the target joint's).
  Eigen::Vector3d Nearest(const Eigen::Vector3d& p, core::Span<const Eigen::Vector3d> pts) const;
  /// Where joint point `p` touches: Nearest() backed off by clearance_m along `dir`, else along
  /// the belly's normal (at_belly), else straight away from the target.
  Eigen::Vector3d Touch(const Eigen::Vector3d& p, core::Span<const Eigen::Vector3d> pts) const;
};

/// A step in controller terms.
struct StepTask {
  std::vector<ContactTerm> terms;
  Posture posture = Posture::kStand;
  bool get_close = false;                      ///< the step is a get-close / stand-up step
  const core::CatalogObject* focus = nullptr;  ///< main object of the step (may be null)
  Eigen::Vector3d stand_point = Eigen::Vector3d::Zero();  ///< for get-close steps
  double stand_yaw_rad = 0;
  /// Where a walking skill stops for a get-close step, and its heading there: the stand point
  /// facing the object, unless RefineApproach() turned it for the next step.
  Eigen::Vector3d walk_point = Eigen::Vector3d::Zero();
  double walk_yaw_rad = 0;
  plan::Direction side = plan::Direction::kFront;
  std::string label;
  /// A carry step in which this agent carries: the object (null otherwise) and its goal on the
  /// floor (unset for a step that only holds it).
  const core::CatalogObject* carry_object = nullptr;
  std::optional<core::Pose> carry_goal;
};

/// Adapts a get-close step's walk point to the step after it: when `next` sits or lies on the
/// object the walker is approaching, stop with the back to it where sitting down starts (a
/// seat: `kSitStartM` in front of its front face; a bed, to sit or lie: also beside the pillow
/// end, where sitting down and lying back puts the head on the pillow), so the contact controller
/// does not have to turn round. Both points stay within the get-close radius of the stand point, so
/// the plan's get-close test (position only by default) is unchanged. When `next` is one hand
/// touching a part of the object in front of the stand point (within 0.1-0.9 m), the walk point
/// moves (at most kReachMaxShiftM) so that the part's point is kReachAheadM ahead and
/// kReachAcrossM to that hand's side, still facing the object. No-op otherwise.
void RefineApproach(const StepTask& next, double scale, StepTask* get_close);
/// Adapts a get-close step that leaves the seat or bed `prev` rests on (standing up from it, the
/// stand point in front of it): the walk heading faces away from the object, as the human faces
/// when it rises, so a walker finishing the step does not turn round towards the seat it left
/// (the plan's get-close test is position only by default). No-op otherwise.
void RefineLeaving(const StepTask& prev, StepTask* get_close);
/// The same for the plan's first step, from where the human starts: when its pelvis (root
/// position, world) is low (below 3/4 of standing height at `scale`) and over the get-close
/// step's object, as a scene that starts it seated there has it, the step leaves that seat.
void RefineLeavingFromStart(const Eigen::Vector3d& pelvis, double scale, StepTask* get_close);
inline constexpr double kSitStartM = 0.36;
inline constexpr double kLieStartFromPillowM = 0.65;
inline constexpr double kReachAheadM = 0.45;
inline constexpr double kReachAcrossM = 0.15;
inline constexpr double kReachMaxShiftM = 0.25;

/// Centre-to-surface distance of each body point when it touches something (m, scale 1).
double BodyPointClearance(core::BodyJoint joint);

/// Builds the task of a grounded step for agent `agent`. `scale` is the humanoid's scale.
StepTask BuildStepTask(const plan::ContactStep& step, const core::SceneCatalog& scene, int agent,
                       double scale, const plan::PairParams& params);

}  // namespace simhuman::control
