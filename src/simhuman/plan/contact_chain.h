#pragma once
/// Chain of Contacts (UniHSI, ICLR 2024, section 3): a plan is a sequence of steps, each step a
/// set of {object, part, joint, contact type, direction} pairs that must hold at the same time.
///
/// This header holds the plain types and their JSON forms. Parsing checks structure only (types,
/// keys, arity, enum spellings, body joint names); names of objects and parts are checked against
/// a scene by ValidateAndGround() in validate.h. The accepted file forms are documented in
/// docs/FORMATS.md ("Plan files"). No MuJoCo here.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/carry.h"

namespace simhuman::plan {

/// What a pair asks of its joint (Eq. 7-8 of UniHSI).
enum class ContactType {
  kContact,     // "contact": the joint touches the part, from the given direction
  kNotContact,  // "not contact": the joint stays more than 0.1 m away from the part
  kNotCare,     // "not care": no requirement (always satisfied)
};

/// Where the joint lies relative to its contact point on the part. kUp/kDown are world +z/-z;
/// the four sides are the object's +x/-x/+y/-y axes turned by the object's yaw (see
/// DirectionVector() in metrics.h). For get-close pairs the side of the object to stand at.
enum class Direction { kUp, kDown, kFront, kBack, kLeft, kRight, kNone };

/// "contact", "not contact", "not care".
std::string_view ContactTypeName(ContactType type);
/// Case-insensitive, '_' accepted for ' '. nullopt if unknown.
std::optional<ContactType> ParseContactType(std::string_view name);
/// All names in enum order, for error messages.
std::vector<std::string> ContactTypeNames();

/// "up", "down", "front", "back", "left", "right", "none".
std::string_view DirectionName(Direction direction);
/// Case-insensitive. nullopt if unknown.
std::optional<Direction> ParseDirection(std::string_view name);
/// All names in enum order, for error messages.
std::vector<std::string> DirectionNames();
/// True for kFront, kBack, kLeft, kRight: the only directions a get-close pair may have.
bool IsSideDirection(Direction direction);

/// The name used for "nothing" in part, joint and contact of a get-close pair.
inline constexpr std::string_view kNoneName = "none";

/// One contact requirement between a body joint of one agent and one part of an object, or a
/// get-close requirement (part "none", no joint) that asks the agent to stand at one side of the
/// object. Distances are in metres in the world frame.
struct ContactPair {
  std::string object;  // scene object id, e.g. "chair000"
  std::string part;    // part name (canonical after grounding), or "none"
  /// The body point: a standard joint's id as soon as it is parsed, another point's (a palm)
  /// once grounded against the agent's body-point catalog. nullopt for get-close pairs.
  std::optional<core::BodyJoint> joint;
  /// The body point's name as given (canonical form), set by the parser and by grounding; empty
  /// for get-close pairs and for pairs built in code with `joint` only.
  std::string joint_name;
  ContactType type = ContactType::kContact;  // ignored for get-close pairs
  Direction direction = Direction::kNone;
  int agent = 0;  // index of the simulated human, 0-based
  /// Set by ValidateAndGround() when `part` names a body joint of the same agent instead of an
  /// object part, e.g. "left knee" in "right foot on left knee" or "pelvis" in "hand on stomach".
  std::optional<core::BodyJoint> part_joint;
  /// JSON pointer of this pair in its source ("/steps/1/pairs/0" or "/0/1"); empty when the pair
  /// was built in code. Used to name the culprit in validation errors.
  std::string where;
  /// Object-object pairs (tabletop goals, "the red box on top of the blue cylinder"): the id of
  /// a movable object whose part `subject_part` must touch `part` of `object` from `direction`,
  /// in place of a body joint (`joint` is then nullopt). Only in the simhuman JSON form.
  std::optional<std::string> subject_object;
  std::string subject_part;  // part of subject_object (canonical after grounding)

  /// True for "get close to the object" pairs: part is "none", no joint and no subject.
  bool IsGetClose() const;
  /// True when the pair names a body point (by id or by a name still to be grounded).
  bool HasJoint() const { return joint.has_value() || !joint_name.empty(); }
  /// The body point's name: joint_name, else the standard name of `joint`, else "none".
  std::string JointName() const;
  /// True for object-object pairs (subject_object set).
  bool IsObjectPair() const { return subject_object.has_value(); }
};

/// One step: all pairs must be satisfied at the same time for the step to complete. A carry
/// step (`carry` set, carry.h) has no pairs of its own in a file: grounding fills `pairs` with
/// its carriers' hand contacts on the object's held parts.
struct ContactStep {
  std::vector<ContactPair> pairs;
  std::optional<CarryStep> carry;  ///< set: one or more humans carry an object (carry.h)
  std::string label;               // optional free text, e.g. "sit on the chair"
  std::string where;  // JSON pointer of the step in its source; empty when built in code
};

/// Which JSON form a chain was read from (decides how field locations are spelt in errors).
enum class ChainForm {
  kSimhuman,  // {"steps": [{"pairs": [{"object": ...}]}]}; also chains built in code
  kTuple,     // UniHSI tuples: [[["chair000", "seat surface", "pelvis", "contact", "up"]]]
};

/// A whole plan: steps executed in order.
struct ContactChain {
  std::vector<ContactStep> steps;
  std::string source;                     // file name or "<string>"; empty when built in code
  ChainForm form = ChainForm::kSimhuman;  // form of the source
};

/// JSON pointer of one field of a pair, for error messages: "<where>/part" in the simhuman
/// form, "<where>/1" in the tuple form. `field` is one of "object", "part", "joint", "contact",
/// "direction", "agent", "subject_object", "subject_part". Falls back to
/// "/steps/<step>/pairs/<pair>/<field>" when the pair has no `where`. A tuple pair has no agent
/// field: its own pointer is returned.
std::string FieldPointer(const ContactChain& chain, int step, int pair, std::string_view field);

/// Structural checks of one pair that need no scene: a get-close pair has part "none", no
/// joint, and a side direction; any other pair has a part that is not "none", a joint, and a
/// part that is not the joint itself; an object-object pair has no joint, a subject part, a part
/// that is not "none" and a subject other than its object; agent >= 0. Errors are prefixed with the
/// field's pointer.
absl::Status CheckPairShape(const ContactChain& chain, int step, int pair);

/// Parses a chain from JSON in either accepted form (simhuman object form, or UniHSI tuples as
/// a bare list of steps or under the key "chain of contacts", where a sibling "obj" key is
/// ignored). Checks structure, enum spellings and body joint names, but not object or part
/// names. Joint names are checked against the agent's body points when grounding (validate.h).
/// Every error starts with "<source>: <JSON pointer>: " and lists valid alternatives.
absl::StatusOr<ContactChain> ParseContactChainJson(const nlohmann::json& j,
                                                   std::string_view source);

/// Parses JSON text; syntax errors name "<source>:<line>:<column>".
absl::StatusOr<ContactChain> ParseContactChain(std::string_view text, std::string_view source);

/// Reads and parses a plan file; the file name is the source in error messages.
absl::StatusOr<ContactChain> LoadContactChainFile(const std::string& path);

/// Writes the simhuman object form. "label" is written only when non-empty and "agent" only
/// when non-zero; a carry step is written as its "carry" (without the grounded hand pairs);
/// get-close pairs are written without "contact"; object-object pairs with "subject_object" and
/// "subject_part" instead of "joint". Parsing the result gives back the same steps and pairs (the
/// `where`, `source` and `part_joint` fields are not written: part_joint is recomputed by grounding
/// from `part`).
nlohmann::json ContactChainToJson(const ContactChain& chain);

}  // namespace simhuman::plan
