#pragma once
/// Body points: the points of a simulated human a plan may name. Every humanoid has the 15
/// body joints of the Chain of Contacts (UniHSI's list), with fixed ids 0..14; an agent kind
/// may add more (a palm, fingertips), with ids from 15 on, listed in its BodyPointCatalog,
/// which world/ exports with the scene catalog. plan/ grounds joint names against that catalog.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace simhuman::core {

/// The id of a body point of one agent: an index into its BodyPointCatalog. The named values are
/// the 15 standard points every humanoid has, in fixed order; ids >= kNumBodyJoints are extra
/// points of an agent kind (BodyPointCatalog::points[id]).
enum class BodyJoint : int {
  kPelvis,
  kTorso,
  kHead,
  kLeftShoulder,
  kLeftElbow,
  kLeftHand,
  kRightShoulder,
  kRightElbow,
  kRightHand,
  kLeftHip,
  kLeftKnee,
  kLeftFoot,
  kRightHip,
  kRightKnee,
  kRightFoot,
};

inline constexpr int kNumBodyJoints = 15;

/// Canonical names: "pelvis", "torso", "head", "left shoulder", ..., "right foot"; "extra point"
/// for an id past the standard 15 (an agent's BodyPointCatalog names those).
std::string_view BodyJointName(BodyJoint joint);

/// Parses a canonical name (case-insensitive; '_' accepted for ' '). nullopt if unknown.
std::optional<BodyJoint> ParseBodyJoint(std::string_view name);

/// All canonical names in enum order (for error messages).
std::vector<std::string> BodyJointNames();

/// All joints in enum order.
std::array<BodyJoint, kNumBodyJoints> AllBodyJoints();

/// One body point a plan may name.
struct BodyPointInfo {
  std::string name;                  ///< canonical, lower case with spaces: "right palm"
  std::vector<std::string> aliases;  ///< other accepted names
};

/// The body points of one agent kind, indexed by BodyJoint id: the 15 standard points first.
/// Plain data, exported by world/ for every agent of a scene (SceneCatalog::agents).
struct BodyPointCatalog {
  std::vector<BodyPointInfo> points;

  int size() const { return static_cast<int>(points.size()); }
  /// The id whose name or alias matches `name` (case-insensitive, '_' for ' '); nullopt if none.
  std::optional<BodyJoint> Find(std::string_view name) const;
  /// The canonical name of `id`; "point <id>" when it is out of range.
  std::string Name(BodyJoint id) const;
  /// Canonical names in id order (for error messages).
  std::vector<std::string> Names() const;
  /// True when `id` is a point of this catalog.
  bool Contains(BodyJoint id) const {
    return static_cast<int>(id) >= 0 && static_cast<int>(id) < size();
  }
};

/// The catalog of the plain humanoid: the 15 standard points.
BodyPointCatalog StandardBodyPointCatalog();

}  // namespace simhuman::core
