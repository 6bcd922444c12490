#include "simhuman/world/humanoid.h"

#include <cmath>
#include <sstream>

#include "simhuman/world/hand.h"

namespace simhuman::world {
namespace {

// servo gains per joint group at scale 1 (see shared notes: gains that behaved well)
struct Gains {
  double kp, damping, force;
};
constexpr Gains kSpine{500, 40, 250};
constexpr Gains kNeck{60, 5, 50};
constexpr Gains kShoulder{200, 15, 100};
constexpr Gains kElbow{150, 10, 80};
constexpr Gains kHip{500, 40, 300};
constexpr Gains kKnee{450, 35, 300};
constexpr Gains kAnkle{300, 20, 150};

struct JointDef {
  const char* name;
  const char* axis;
  double lo_deg, hi_deg;
  Gains gains;
};

// segment masses (kg) at scale 1; after Winter's segment fractions for a 60 kg adult
constexpr double kPelvisMass = 8.5, kTorsoMass = 21.0, kHeadMass = 4.9;
constexpr double kUpperArmMass = 1.7, kLowerArmMass = 0.96, kHandMass = 0.36;
constexpr double kThighMass = 6.0, kShinMass = 2.8, kFootMass = 0.87;

std::string F(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string V(double x, double y, double z) { return F(x) + " " + F(y) + " " + F(z); }

class Writer {
 public:
  Writer(const HumanoidSpec& spec) : s_(spec.scale), p_(spec.prefix), rgba_(spec.rgba) {}

  std::string Pos(double x, double y, double z) const { return V(s_ * x, s_ * y, s_ * z); }
  double L(double v) const { return s_ * v; }
  double M(double v) const { return s_ * s_ * s_ * v; }
  const std::string& p() const { return p_; }

  void Joint(std::ostringstream& o, const JointDef& j) const {
    // dynamic similarity (Froude scaling: times x sqrt(s)): torques ~ s^4, so damping (torque
    // per rad/s) ~ s^4.5 and armature (an inertia, mass x length^2) ~ s^5
    const double damping = j.gains.damping * std::pow(s_, 4.5), armature = 0.02 * std::pow(s_, 5);
    o << "<joint name=\"" << p_ << j.name << "\" type=\"hinge\" axis=\"" << j.axis << "\" range=\""
      << j.lo_deg << " " << j.hi_deg << "\" damping=\"" << F(damping) << "\" armature=\""
      << F(armature) << "\"/>\n";
  }
  void Capsule(std::ostringstream& o, const std::string& name, double x0, double y0, double z0,
               double x1, double y1, double z1, double r, double mass) const {
    o << "<geom name=\"" << p_ << name << "\" type=\"capsule\" fromto=\"" << Pos(x0, y0, z0) << " "
      << Pos(x1, y1, z1) << "\" size=\"" << F(L(r)) << "\" mass=\"" << F(M(mass)) << "\" rgba=\""
      << rgba_ << "\"/>\n";
  }
  void Sphere(std::ostringstream& o, const std::string& name, double x, double y, double z,
              double r, double mass, const std::string& extra = "") const {
    o << "<geom name=\"" << p_ << name << "\" type=\"sphere\" pos=\"" << Pos(x, y, z)
      << "\" size=\"" << F(L(r)) << "\" mass=\"" << F(M(mass)) << "\" rgba=\"" << rgba_ << "\""
      << extra << "/>\n";
  }
  void Site(std::ostringstream& o, core::BodyJoint j, double x, double y, double z) const {
    NamedSite(o, BodyPointSiteName(j), x, y, z);
  }
  void NamedSite(std::ostringstream& o, const std::string& site, double x, double y,
                 double z) const {
    o << "<site name=\"" << p_ << site << "\" pos=\"" << Pos(x, y, z) << "\" size=\"" << F(L(0.02))
      << "\" rgba=\"0.2 0.8 0.2 0\"/>\n";
  }

 private:
  double s_;
  std::string p_;
  std::string rgba_;
};

const std::vector<JointDef>& JointDefs() {
  // axes are chosen so that positive angles are flexion / abduction where that makes sense:
  // hip_y and shoulder_y positive = forward flexion, knee and elbow positive = flexion.
  static const std::vector<JointDef> defs = {
      {"abdomen_x", "1 0 0", -35, 35, kSpine},
      {"abdomen_y", "0 1 0", -40, 70, kSpine},
      {"abdomen_z", "0 0 1", -45, 45, kSpine},
      {"neck_x", "1 0 0", -40, 40, kNeck},
      {"neck_y", "0 1 0", -50, 60, kNeck},
      {"neck_z", "0 0 1", -70, 70, kNeck},
      {"right_shoulder_x", "-1 0 0", -30, 150, kShoulder},
      {"right_shoulder_y", "0 -1 0", -60, 170, kShoulder},
      {"right_shoulder_z", "0 0 1", -90, 90, kShoulder},
      {"right_elbow", "0 -1 0", 0, 150, kElbow},
      {"left_shoulder_x", "1 0 0", -30, 150, kShoulder},
      {"left_shoulder_y", "0 -1 0", -60, 170, kShoulder},
      {"left_shoulder_z", "0 0 1", -90, 90, kShoulder},
      {"left_elbow", "0 -1 0", 0, 150, kElbow},
      {"right_hip_x", "-1 0 0", -30, 60, kHip},
      {"right_hip_y", "0 -1 0", -30, 125, kHip},
      {"right_hip_z", "0 0 1", -45, 45, kHip},
      {"right_knee", "0 1 0", 0, 150, kKnee},
      {"right_ankle_x", "1 0 0", -30, 30, kAnkle},
      {"right_ankle_y", "0 1 0", -45, 45, kAnkle},
      {"right_ankle_z", "0 0 1", -30, 30, kAnkle},
      {"left_hip_x", "1 0 0", -30, 60, kHip},
      {"left_hip_y", "0 -1 0", -30, 125, kHip},
      {"left_hip_z", "0 0 1", -45, 45, kHip},
      {"left_knee", "0 1 0", 0, 150, kKnee},
      {"left_ankle_x", "1 0 0", -30, 30, kAnkle},
      {"left_ankle_y", "0 1 0", -45, 45, kAnkle},
      {"left_ankle_z", "0 0 1", -30, 30, kAnkle},
  };
  return defs;
}

// the dexterous hand's body points (per side, after "right " / "left "); their sites are
// written by HandBodyXml()
constexpr const char* kHandPoints[] = {"palm", "fingertips", "thumb tip"};

std::string SiteName(std::string name) {
  for (char& c : name) {
    if (c == ' ') c = '_';
  }
  return "pt_" + name;
}

const JointDef& Def(const std::string& name) {
  for (const auto& d : JointDefs()) {
    if (name == d.name) return d;
  }
  static JointDef none{"", "", 0, 0, kSpine};
  return none;
}

}  // namespace

const std::vector<std::string>& HumanoidJointNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& d : JointDefs()) n.push_back(d.name);
    return n;
  }();
  return names;
}

const std::vector<std::string>& HumanoidBodyNames() {
  static const std::vector<std::string> names = {
      "pelvis",     "torso",          "head",           "right_upper_arm", "right_lower_arm",
      "right_hand", "left_upper_arm", "left_lower_arm", "left_hand",       "right_thigh",
      "right_shin", "right_foot",     "left_thigh",     "left_shin",       "left_foot"};
  return names;
}

std::string BodyPointSiteName(core::BodyJoint joint) {
  return SiteName(std::string(core::BodyJointName(joint)));
}

std::vector<std::string> HumanoidJointNames(const HumanoidSpec& spec) {
  std::vector<std::string> names = HumanoidJointNames();
  for (const char* side : {"right_", "left_"}) {
    if (!(side[0] == 'r' ? spec.right_hand : spec.left_hand)) continue;
    for (const HandJoint& d : HandJoints()) names.push_back(std::string(side) + d.name);
  }
  return names;
}

std::vector<BodyPointSite> HumanoidBodyPoints(const HumanoidSpec& spec) {
  std::vector<BodyPointSite> out;
  for (core::BodyJoint j : core::AllBodyJoints()) {
    out.push_back({{std::string(core::BodyJointName(j)), {}}, BodyPointSiteName(j)});
  }
  for (const char* side : {"right", "left"}) {
    if (!(side[0] == 'r' ? spec.right_hand : spec.left_hand)) continue;
    for (const char* hp : kHandPoints) {
      std::string name = std::string(side) + " " + hp;
      out.push_back({{name, {}}, SiteName(name)});
    }
  }
  return out;
}

double HumanoidMassKg(double scale) {
  return scale * scale * scale *
         (kPelvisMass + kTorsoMass + kHeadMass +
          2 * (kUpperArmMass + kLowerArmMass + kHandMass + kThighMass + kShinMass + kFootMass));
}

std::string HumanoidBodyXml(const HumanoidSpec& spec, double x, double y, double yaw_rad,
                            double pelvis_z) {
  using core::BodyJoint;
  Writer w(spec);
  const std::string& p = w.p();
  std::ostringstream o;
  o << "<body name=\"" << p << "pelvis\" pos=\""
    << V(x, y, pelvis_z > 0 ? pelvis_z : w.L(kPelvisStandHeight)) << "\" quat=\""
    << V(std::cos(yaw_rad / 2), 0, 0) << " " << F(std::sin(yaw_rad / 2)) << "\">\n";
  o << "<freejoint name=\"" << p << "root\"/>\n";
  w.Capsule(o, "pelvis_geom", 0, -0.065, -0.03, 0, 0.065, -0.03, 0.09, kPelvisMass);
  w.Site(o, BodyJoint::kPelvis, 0, 0, -0.09);

  // torso: lumbar joint 0.10 above the pelvis origin; shoulders at +0.33
  o << "<body name=\"" << p << "torso\" pos=\"" << w.Pos(0, 0, 0.10) << "\">\n";
  for (const char* j : {"abdomen_x", "abdomen_y", "abdomen_z"}) w.Joint(o, Def(j));
  w.Capsule(o, "waist_geom", 0, 0, 0.02, 0, 0, 0.14, 0.085, 0.35 * kTorsoMass);
  w.Capsule(o, "chest_geom", -0.01, -0.075, 0.26, -0.01, 0.075, 0.26, 0.11, 0.65 * kTorsoMass);
  // the torso point on the thoracic spine, which lies toward the back of a real trunk (6 cm
  // behind the chest capsule's axis, 5 cm inside the back): a back against a backrest puts it
  // about 6 cm from it
  w.Site(o, BodyJoint::kTorso, -0.06, 0, 0.22);

  o << "<body name=\"" << p << "head\" pos=\"" << w.Pos(0, 0, 0.38) << "\">\n";
  for (const char* j : {"neck_x", "neck_y", "neck_z"}) w.Joint(o, Def(j));
  w.Capsule(o, "neck_geom", 0, 0, 0.0, 0, 0, 0.06, 0.05, 0.2 * kHeadMass);
  w.Sphere(o, "head_geom", 0.01, 0, 0.16, 0.1, 0.8 * kHeadMass);
  w.Site(o, BodyJoint::kHead, 0.01, 0, 0.16);
  o << "</body>\n";

  // arms: side = +1 left, -1 right
  for (int side : {-1, 1}) {
    std::string s = side < 0 ? "right_" : "left_";
    BodyJoint sh = side < 0 ? BodyJoint::kRightShoulder : BodyJoint::kLeftShoulder;
    BodyJoint el = side < 0 ? BodyJoint::kRightElbow : BodyJoint::kLeftElbow;
    BodyJoint ha = side < 0 ? BodyJoint::kRightHand : BodyJoint::kLeftHand;
    o << "<body name=\"" << p << s << "upper_arm\" pos=\"" << w.Pos(0, side * 0.185, 0.31)
      << "\">\n";
    for (const char* j : {"shoulder_x", "shoulder_y", "shoulder_z"}) w.Joint(o, Def(s + j));
    w.Capsule(o, s + "upper_arm_geom", 0, 0, -0.04, 0, 0, -0.26, 0.045, kUpperArmMass);
    w.Site(o, sh, 0, 0, 0);
    o << "<body name=\"" << p << s << "lower_arm\" pos=\"" << w.Pos(0, 0, -0.30) << "\">\n";
    w.Joint(o, Def(s + "elbow"));
    w.Capsule(o, s + "lower_arm_geom", 0, 0, -0.03, 0, 0, -0.21, 0.038, kLowerArmMass);
    w.Site(o, el, 0, 0, 0);
    o << "<body name=\"" << p << s << "hand\" pos=\"" << w.Pos(0, 0, -0.25) << "\">\n";
    if (side < 0 ? spec.right_hand : spec.left_hand) {
      HandBodyXml(p, side < 0, spec.scale, spec.rgba, o);
    } else {
      // a gripping hand's contacts are found 1 cm early (margin) but act only on touch (gap):
      // adhesion pulls only along contacts the collision pass has found
      w.Sphere(o, s + "hand_geom", 0, 0, -0.055, 0.045, kHandMass,
               spec.grip_n > 0 ? " margin=\"0.01\" gap=\"0.01\"" : "");
    }
    w.Site(o, ha, 0, 0, -0.055);
    o << "</body>\n</body>\n</body>\n";
  }
  o << "</body>\n";  // torso

  // legs: hip joints 0.05 below and 0.085 beside the pelvis origin
  for (int side : {-1, 1}) {
    std::string s = side < 0 ? "right_" : "left_";
    BodyJoint hip = side < 0 ? BodyJoint::kRightHip : BodyJoint::kLeftHip;
    BodyJoint knee = side < 0 ? BodyJoint::kRightKnee : BodyJoint::kLeftKnee;
    BodyJoint foot = side < 0 ? BodyJoint::kRightFoot : BodyJoint::kLeftFoot;
    o << "<body name=\"" << p << s << "thigh\" pos=\"" << w.Pos(0, side * 0.085, -0.05) << "\">\n";
    for (const char* j : {"hip_x", "hip_y", "hip_z"}) w.Joint(o, Def(s + j));
    w.Capsule(o, s + "thigh_geom", 0, 0, -0.03, 0, 0, -0.37, 0.065, kThighMass);
    w.Site(o, hip, 0, 0, 0);
    o << "<body name=\"" << p << s << "shin\" pos=\"" << w.Pos(0, 0, -0.42) << "\">\n";
    w.Joint(o, Def(s + "knee"));
    w.Capsule(o, s + "shin_geom", 0, 0, -0.03, 0, 0, -0.36, 0.05, kShinMass);
    w.Site(o, knee, 0, 0, 0);
    o << "<body name=\"" << p << s << "foot\" pos=\"" << w.Pos(0, 0, -0.42) << "\">\n";
    for (const char* j : {"ankle_x", "ankle_y", "ankle_z"}) w.Joint(o, Def(s + j));
    o << "<geom name=\"" << p << s << "foot_geom\" type=\"box\" pos=\"" << w.Pos(0.045, 0, -0.0375)
      << "\" size=\"" << V(w.L(0.105), w.L(0.045), w.L(0.0275)) << "\" mass=\"" << F(w.M(kFootMass))
      << "\" friction=\"1.0 0.02 0.01\" rgba=\"" << spec.rgba << "\"/>\n";
    w.Site(o, foot, 0.045, 0, -0.0375);
    o << "</body>\n</body>\n</body>\n";
  }
  o << "</body>\n";  // pelvis
  return o.str();
}

const std::vector<std::string>& HumanoidGripActuatorNames() {
  static const std::vector<std::string> names = {"right_grip", "left_grip"};
  return names;
}

std::string HumanoidContactXml(const HumanoidSpec& spec) {
  std::string out;
  if (spec.right_hand) out += HandContactExcludesXml(spec.prefix, true);
  if (spec.left_hand) out += HandContactExcludesXml(spec.prefix, false);
  return out;
}

std::string HumanoidActuatorXml(const HumanoidSpec& spec) {
  std::ostringstream o;
  double g = std::pow(spec.scale, 4);
  auto servo = [&](const std::string& name, const JointDef& d) {
    constexpr double kDeg = M_PI / 180.0;
    o << "<position name=\"" << spec.prefix << name << "\" joint=\"" << spec.prefix << name
      << "\" kp=\"" << F(d.gains.kp * g) << "\" ctrllimited=\"true\" ctrlrange=\""
      << F(d.lo_deg * kDeg) << " " << F(d.hi_deg * kDeg) << "\" forcelimited=\"true\" forcerange=\""
      << F(-d.gains.force * g) << " " << F(d.gains.force * g) << "\"/>\n";
  };
  for (const auto& d : JointDefs()) servo(d.name, d);
  for (const char* side : {"right_", "left_"}) {
    if (!(side[0] == 'r' ? spec.right_hand : spec.left_hand)) continue;
    for (const HandJoint& h : HandJoints()) {
      JointDef d{h.name, "", h.lo_deg, h.hi_deg, {h.kp, h.damping, h.force}};
      servo(std::string(side) + h.name, d);
    }
  }
  if (spec.grip_n > 0) {
    for (const std::string& name : HumanoidGripActuatorNames()) {
      const std::string side = name.substr(0, name.find('_') + 1);
      if (side == "right_" ? spec.right_hand : spec.left_hand) continue;  // fingers grip there
      o << "<adhesion name=\"" << spec.prefix << name << "\" body=\"" << spec.prefix << side
        << "hand\" ctrlrange=\"0 1\" gain=\"" << F(spec.grip_n * std::pow(spec.scale, 3))
        << "\"/>\n";
    }
  }
  return o.str();
}

}  // namespace simhuman::world
