#pragma once
/// Our AMP-like humanoid, generated as MJCF: 15 bodies, 28 hinge DoF, PD position servos
/// (P in the actuator, D as implicit joint damping), human proportions (~1.70 m, ~60 kg at
/// scale 1). Facing +x, z up; the root is a free joint on the pelvis.

#include <array>
#include <string>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/world/hand.h"

namespace simhuman::world {

/// Parameters of one humanoid.
struct HumanoidSpec {
  double scale = 1.0;  ///< length scale (1 = adult 1.70 m; 0.7 = a child ~1.19 m); mass ~ s^3
  std::string prefix;  ///< prefix for every name, e.g. "h1/" for a second agent
  std::string rgba = "0.85 0.65 0.5 1";
  /// A dexterous hand on the right / left arm instead of the capsule hand (world/hand.h): the
  /// arm gains forearm rotation and two wrist hinges, the hand 22 hinges, kHandDofs in all,
  /// and the body points "<side> palm", "<side> fingertips", "<side> thumb tip".
  bool right_hand = false;
  bool left_hand = false;
  /// > 0: each capsule hand grips what it touches, as fingers curled over a box's edges would:
  /// an adhesion actuator (MuJoCo's bounded pull along the contact normals, acting only while
  /// the hand touches something; nothing is welded) of up to `grip_n` N x scale^3, named
  /// "<side>_grip", control 0-1, after every hinge actuator (HumanoidGripActuatorNames()).
  double grip_n = 0;
};

/// The grip actuators' names (without prefix) of a humanoid with HumanoidSpec::grip_n > 0, in
/// actuator order: right, then left.
const std::vector<std::string>& HumanoidGripActuatorNames();

/// One body point of a humanoid: what plans call it and the MJCF site (without prefix) that
/// marks it.
struct BodyPointSite {
  core::BodyPointInfo info;
  std::string site;
};

/// Hinge joints (and actuators) of the humanoid's body: every humanoid kind has these, first
/// and in HumanoidJointNames() order; hands add theirs after them (HumanoidJointNames(spec)).
inline constexpr int kHumanoidDofs = 28;
inline constexpr int kHumanoidBodies = 15;

/// The body's 28 hinge joint names in actuator order (without prefix).
const std::vector<std::string>& HumanoidJointNames();

/// All hinge joint (and actuator) names of the humanoid `spec` describes, without prefix: the
/// body's 28, then the right hand's, then the left hand's.
std::vector<std::string> HumanoidJointNames(const HumanoidSpec& spec);

/// All body points of the humanoid `spec` describes, in id order: the 15 standard points
/// (core::BodyJoint), then the hands' (right, then left).
std::vector<BodyPointSite> HumanoidBodyPoints(const HumanoidSpec& spec);

/// Body names in tree order (without prefix).
const std::vector<std::string>& HumanoidBodyNames();

/// Site name (without prefix) of a Chain-of-Contacts body point, e.g. "pt_left_hand".
std::string BodyPointSiteName(core::BodyJoint joint);

/// Standing height of the pelvis origin above the floor at scale 1 (feet flat, legs straight).
inline constexpr double kPelvisStandHeight = 0.96;
/// A pelvis origin below 3/4 of standing height (x scale) is seated or lying, not standing.
inline bool PelvisLowAsSeated(double pelvis_z, double scale) {
  return pelvis_z < 0.75 * kPelvisStandHeight * scale;
}

/// The `<body>` subtree of one humanoid (goes inside `<worldbody>`), placed standing at
/// (x, y) with heading yaw_rad.
/// `pelvis_z` > 0 places the pelvis origin at that height instead of standing height.
std::string HumanoidBodyXml(const HumanoidSpec& spec, double x, double y, double yaw_rad,
                            double pelvis_z = 0);

/// The `<contact>` children of one humanoid (pair exclusions of its dexterous hands; empty
/// without hands).
std::string HumanoidContactXml(const HumanoidSpec& spec);

/// The `<actuator>` children of one humanoid (position servos, one per hinge).
std::string HumanoidActuatorXml(const HumanoidSpec& spec);

/// Total mass (kg) the generator assigns at `scale`.
double HumanoidMassKg(double scale);

}  // namespace simhuman::world
