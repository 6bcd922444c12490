#pragma once
/// The 15 named body joints (body points) of the Chain of Contacts, as UniHSI lists them.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace simhuman::core {

/// One of the 15 body points a contact pair may name. Order is fixed (used as an index).
enum class BodyJoint {
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

/// Canonical names: "pelvis", "torso", "head", "left shoulder", ..., "right foot".
std::string_view BodyJointName(BodyJoint joint);

/// Parses a canonical name (case-insensitive; '_' accepted for ' '). nullopt if unknown.
std::optional<BodyJoint> ParseBodyJoint(std::string_view name);

/// All canonical names in enum order (for error messages).
std::vector<std::string> BodyJointNames();

/// All joints in enum order.
std::array<BodyJoint, kNumBodyJoints> AllBodyJoints();

}  // namespace simhuman::core
