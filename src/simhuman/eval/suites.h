#pragma once
/// The benchmark suites of `simhuman eval`, as a registry: each suite is a name, the controller
/// kind that runs it, the success check it adds to the plan's own (UniHSI's step completion) and,
/// for plan suites, a randomized, seeded episode generator (the protocols are documented in
/// docs/EVAL_PROTOCOLS.md). A new suite is one generator and one registry line (suites.cc).

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"
#include "simhuman/world/scene.h"

namespace simhuman::eval {

/// A success condition an episode checks at its end, beyond the plan's own.
enum class ExtraCheck {
  kNone,
  /// lie: the horizontal pelvis -> head direction lies within kLieAxisTolDeg of the bed's long
  /// axis pointing to the pillow end (the bed's local +y, world/objects.h).
  kLieAlongBed,
  /// reach: the hand (EpisodeSpec::joint) is within kReachTolM of the marker's point.
  kHandAtPoint,
};

/// The lie suite's alignment tolerance (degrees).
inline constexpr double kLieAxisTolDeg = 30.0;
/// Below this horizontal pelvis-to-head length (m, times the human's scale) the body is upright
/// and has no lying direction: the lie check fails.
inline constexpr double kLieMinSpanM = 0.25;
/// The reach suite's final hand-to-point tolerance (m); stricter than the plan's 0.1 m.
inline constexpr double kReachTolM = 0.05;
/// The object type and part the reach suite's target uses (a small non-colliding sphere).
inline constexpr char kMarkerType[] = "marker";
inline constexpr char kMarkerPart[] = "point";

/// One generated episode: a scene with its humans, a plan and an optional extra check. Plain
/// data.
struct EpisodeSpec {
  std::string suite;  ///< the suite's registry name
  uint64_t seed = 0;  ///< the episode seed it was generated from
  std::string
      variant;  ///< what was drawn, e.g. "sofa", "bed", "left hand", "chair: get close, sit"
  world::SceneSpec scene;
  nlohmann::json plan;  ///< simhuman plan form (plan/contact_chain.h)
  ExtraCheck extra = ExtraCheck::kNone;
  std::string object_id;  ///< the suite's object (the bed for kLieAlongBed, the marker, ...)
  core::BodyJoint joint = core::BodyJoint::kPelvis;  ///< the reaching hand for kHandAtPoint
  int agent = 0;                                     ///< the human the extra check looks at
};

/// What runs a suite's episodes.
enum class SuiteController {
  kMpc,          ///< plan episodes; get-close steps walked by the walking policy when given
  kWalkPolicy,   ///< the walking policy alone (eval/walk_eval.h); needs --policy
  kPlanner,      ///< commands through a planner, no simulation (eval/language_suite.h)
  kCarryPolicy,  ///< the carrying policy on CooHOI's protocol (learn/carry_eval.h)
  kTabletop,     ///< DASH's pick-and-place pipeline on generated tables (eval/tabletop_eval.h)
  kVision,       ///< the vision module on held-out tables (eval/vision_eval.h)
};

/// Draws one episode of a plan suite into `spec` (scene, plan, variant, object_id, joint) from
/// `rng`. Errors (Internal) only when an object of the protocol cannot be built.
using EpisodeGenerator = core::Status (*)(core::Rng& rng, EpisodeSpec* spec);

/// One registered suite.
struct SuiteDef {
  std::string name;  ///< "sit", "lie-far", "walk", ...
  SuiteController controller = SuiteController::kMpc;
  ExtraCheck extra = ExtraCheck::kNone;
  EpisodeGenerator make = nullptr;  ///< plan suites only
  std::string description;          ///< one line, for help and error messages
};

/// Every registered suite: the plan suites "sit", "lie", "reach", "sceneplan-simple",
/// "sit-far", "lie-far", "reach-far" (the far suites start the human 1-6 m from the middle of the
/// object's front face (within +-60 deg of its front direction, any heading) and put a get-close
/// (front) step before the plan: sit-far [sit]; lie-far [sit on the edge], [lie] with the lie
/// check; reach-far touches a marker (random yaw, 0.7-1.5 m high) with one hand, with the reach
/// check; they need the walking policy), then "walk", "walk-step" and "language".
const std::vector<SuiteDef>& Suites();

/// Registry names in registry order.
std::vector<std::string> SuiteNames();

/// The suite called `name` (exact, lower case); nullptr when unknown.
const SuiteDef* FindSuite(std::string_view name);

/// The episode of the plan suite `suite` for episode seed `seed` (the eval uses DeriveSeed(run
/// seed, i) for episode i). A pure function: the same arguments give the same spec, whatever
/// else ran before. Draws come from core::Rng(core::DeriveSeed(seed, kSceneStream)). Errors:
/// InvalidArgument for a name that is not a plan suite (listing those), Internal when an object
/// of the protocol cannot be built (a world/ change broke a size range).
core::StatusOr<EpisodeSpec> MakeEpisodeSpec(std::string_view suite, uint64_t seed);

/// The seed stream MakeEpisodeSpec() draws scenes from (controllers use other streams).
inline constexpr uint64_t kSceneStream = 0;

/// The outcome of an extra check.
struct ExtraResult {
  bool pass = true;
  std::string metric;  ///< "lie_axis_error_deg", "hand_distance_m"; empty for kNone
  double value = 0;    ///< the measured value of `metric`
};

/// The 15 body points of one human, indexed by static_cast<int>(core::BodyJoint).
using BodyPointArray = std::array<Eigen::Vector3d, core::kNumBodyJoints>;

/// Evaluates `spec.extra` for the human whose body points are `points` (world frame, at the
/// end of the episode) in `scene` (the catalog built from spec.scene; spec.object_id is looked
/// up there). kNone passes. A missing object fails the check (metric value NaN). Pure.
ExtraResult EvaluateExtra(const EpisodeSpec& spec, const core::SceneCatalog& scene,
                          const BodyPointArray& points);

}  // namespace simhuman::eval
