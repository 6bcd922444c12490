#pragma once
/// The humanoid's dexterous hand option (DASH, Appendix A.2): with it, an arm has 7 DoF (the
/// body's shoulder 3 and elbow 1, plus forearm rotation and wrist flexion and deviation added
/// here) and the hand 22: four fingers of 4 hinges (MCP abduction and flexion, PIP, DIP), a
/// thumb of 5 (CMC flexion and abduction, MCP flexion and abduction, IP) and a palm-arch hinge
/// that cups the ring-and-little side of the palm. Adult proportions at scale 1: 19.4 cm from
/// the wrist to the middle fingertip, palm 8.6 cm wide, 0.36 kg; human joint ranges.
///
/// Hand frame (right hand, all hand joints at 0, arm hanging): origin at the wrist, -z toward
/// the fingertips, +y out of the palm (toward the body's midline), +x toward the thumb (the
/// front). The left hand is the mirror image through the body's sagittal plane: positions
/// (x, -y, z), hinge axes (-x, y, -z); the same joint angles give mirrored poses, so a
/// controller written for the right hand drives the left one unchanged.
///
/// Fingers do not collide with each other or with the palm (their geoms have contype 2,
/// conaffinity 1): they collide with objects, furniture and the rest of the body.

#include <sstream>
#include <string>
#include <vector>

namespace simhuman::world {

/// One hinge of the hand option, per side; the name goes after the side prefix "right_" or
/// "left_" (e.g. "right_index_pip"). Gains at scale 1 (kp N m/rad, damping N m s/rad, force
/// limit N m); the generator scales them by scale^4 as it does the body's.
struct HandJoint {
  const char* name;
  double lo_deg, hi_deg;
  double kp, damping, force, armature;
};

/// Hinges the option adds to each arm: 3 on the arm (forearm rotation, wrist flexion and
/// deviation), then 22 on the hand.
inline constexpr int kHandArmDofs = 3;
inline constexpr int kHandFingerDofs = 22;
inline constexpr int kHandDofs = kHandArmDofs + kHandFingerDofs;

/// The kHandDofs hinges of one side in actuator order: forearm_rot, wrist_flex, wrist_dev,
/// palm_arch, then index, middle, ring, little (abd, mcp, pip, dip each), then thumb (cmc_flex,
/// cmc_abd, mcp_flex, mcp_abd, ip).
const std::vector<HandJoint>& HandJoints();

/// Names (without side prefix) of the collision geoms that carry touch sensing, one per
/// phalanx and two for the palm: "palm_radial", "palm_ulnar", "index_proximal", ...,
/// "thumb_distal" (geom "<side>_<name>_geom"). 17 entries.
const std::vector<std::string>& HandTouchParts();

/// Fingertip site names (without side prefix), thumb first: "thumb_tip", "index_tip", ...,
/// "little_tip" (site "<side>_<name>").
const std::vector<std::string>& HandTipSites();

/// Writes the hand's bodies, geoms, joints and sites into an open hand body (`prefix` is the
/// agent's name prefix, `right` picks the side). `rgba` colours the skin. Also writes the
/// hand's Chain-of-Contacts sites pt_<side>_palm, pt_<side>_fingertips (middle fingertip) and
/// pt_<side>_thumb_tip.
void HandBodyXml(const std::string& prefix, bool right, double scale, const std::string& rgba,
                 std::ostringstream& o);

/// The `<exclude>` children of the model's `<contact>` section for one hand: the forearm and
/// the palm's and thumb's bodies beyond the wrist, which touch at the wrist (soft tissue in a
/// real arm) but are not parent and child.
std::string HandContactExcludesXml(const std::string& prefix, bool right);

/// The hand's mass (kg) at `scale`.
double HandMassKg(double scale);

}  // namespace simhuman::world
