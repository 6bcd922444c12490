#pragma once
/// The offline planner: a small rule-based parser from everyday English commands to a grounded
/// Chain of Contacts. Deterministic, no network, no model files; typical commands plan in tens
/// of microseconds.
///
/// What it understands (docs/FORMATS.md, "Language commands", has the full list):
/// - the interaction vocabulary of UniHSI's ScenePlan (Tables 8 and 9): get close to X, stand
///   up, left/right/both hands reach X (or a part of X), sit on X with its variants (hands or
///   elbows on the arms, hands on the knees or stomach, a foot on the other knee, lean forward
///   or back) and lie on X with its variants (knees up, hands on the pillow, on the left or
///   right side, a foot on the other knee, head up);
/// - DASH-style tabletop commands: "put/place/stack/move the [colour] [shape] on/on top of/next
///   to/left of/right of/in front of/behind the [colour] [shape] [that is <relation> the
///   <colour> <shape>]", planned as a grasp step and an object-on-object goal step;
/// - clauses joined by "then", "and then", "after that", "afterwards", "and", commas and full
///   stops; object references by type, part, colour, size, spatial relation and pronoun;
/// - implied steps: a get-close step before interacting with an object more than
///   kNearEnoughM from the human's planned position, a stand-up step before leaving a seat.
///
/// A command the rules refuse as not understood is read again by the general fallback
/// (offline/fallback.h: actions, objects and body parts in the order they occur, planned by the
/// same rules); negations, unknown actions on objects and unknown objects stay refused.
///
/// It plans for the first human of the scene (agent 0; the others keep still), from
/// PlanContext::agents[0] (or a standing human at the origin facing +x when the list is empty).
/// "Left", "right", "in front of" and "behind" are seen from that human's start pose.
///
/// Status codes follow Planner (planner.h): kFailedPrecondition with a question ending in '?'
/// when a reference matches several objects; kInvalidArgument for unknown words, impossible
/// requests and objects the scene lacks (the message lists the scene's objects and parts).

#include <cstddef>
#include <string>
#include <string_view>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/language/planner.h"

namespace simhuman::language {

/// Commands longer than this (bytes) are refused with kInvalidArgument.
inline constexpr size_t kMaxCommandBytes = 4096;
/// Commands with more clauses than this are refused with kInvalidArgument.
inline constexpr int kMaxClauses = 40;
/// An object farther than this (metres, horizontally from the human's planned position to the
/// object's footprint) gets a get-close step before the human interacts with it.
inline constexpr double kNearEnoughM = 1.0;
/// A seated human handles table objects whose footprint lies within this distance of its
/// position (the pelvis) without standing up: the arm and a forward lean reach about this far.
inline constexpr double kSeatedReachM = 0.8;

/// The rule-based planner. Default-constructible and stateless between calls; Plan() is
/// thread-safe (it keeps no state in the instance).
class OfflinePlanner : public Planner {
 public:
  OfflinePlanner() = default;
  /// See the class comment and Planner::Plan(). `context.scene` must be set (InvalidArgument
  /// otherwise). The result's chain passed plan::ValidateAndGround() against the scene.
  core::StatusOr<PlanResult> Plan(std::string_view command, const PlanContext& context) override;
  /// "offline".
  std::string name() const override { return "offline"; }
};

/// One line per object: "chair000 (chair, brown): seat surface, back surface". For error
/// messages ("what the scene offers").
std::string DescribeSceneObjects(const core::SceneCatalog& scene);

}  // namespace simhuman::language
