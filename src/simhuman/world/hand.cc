#include "simhuman/world/hand.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace simhuman::world {
namespace {

// finger servo gains and limits (a finger must not inherit the arm's damping or it never
// closes; light armature keeps the small phalanges stable at a 5 ms step)
constexpr double kFingerDamping = 0.08, kFingerArmature = 0.002;
constexpr double kWristDamping = 1.0, kWristArmature = 0.01;

// segment masses (kg, scale 1): palm halves, then proximal/middle/distal phalanges; the thumb's
// metacarpal, proximal and distal
constexpr double kPalmRadialMass = 0.14, kPalmUlnarMass = 0.08;
constexpr double kPhalanxMass[3] = {0.012, 0.007, 0.005};
constexpr double kThumbMass[3] = {0.025, 0.012, 0.007};

struct Finger {
  const char* name;
  bool on_ulnar_palm;   // ring and little ride on the palm-arch hinge
  double mcp_x, mcp_z;  // MCP position in the hand frame (y = 0)
  double length[3];     // proximal, middle, distal (m)
  double radius[3];
};
constexpr Finger kFingers[] = {
    {"index", false, 0.032, -0.100, {0.042, 0.025, 0.020}, {0.0095, 0.0085, 0.0075}},
    {"middle", false, 0.011, -0.104, {0.044, 0.027, 0.021}, {0.0098, 0.0088, 0.0078}},
    {"ring", true, -0.010, -0.100, {0.042, 0.026, 0.020}, {0.0092, 0.0082, 0.0072}},
    {"little", true, -0.030, -0.092, {0.033, 0.020, 0.018}, {0.0080, 0.0072, 0.0065}},
};
constexpr const char* kSegment[3] = {"proximal", "middle", "distal"};
constexpr double kPalmArchX = -0.005;  // the palm-arch hinge line (along the palm, x = const)

// the thumb: CMC in the hand frame, its rest direction (distal), and its segments
constexpr double kThumbCmc[3] = {0.028, 0.012, -0.022};
constexpr double kThumbDir[3] = {0.25, 0.45, -0.86};
constexpr double kThumbFlexToward[3] = {
    -0.35, 0.75, -0.55};  // palmar, ulnar, distal  // palmar and ulnar: opposition
constexpr double kThumbLength[3] = {0.046, 0.032, 0.025};
constexpr double kThumbRadius[3] = {0.011, 0.0100, 0.0088};

std::string F(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// writes hand-frame geometry for one side: lengths scaled, the left side mirrored
class HandWriter {
 public:
  HandWriter(const std::string& prefix, bool right, double scale, const std::string& rgba)
      : p_(prefix + (right ? "right_" : "left_")), m_(right ? 1.0 : -1.0), s_(scale), rgba_(rgba) {}

  // a hand-frame position, mirrored for the left hand
  std::string Pos(double x, double y, double z) const {
    return F(s_ * x) + " " + F(s_ * m_ * y) + " " + F(s_ * z);
  }
  // a hinge axis given for the right hand (a pseudovector: mirrors as (-x, y, -z))
  std::string Axis(double x, double y, double z) const {
    return m_ > 0 ? F(x) + " " + F(y) + " " + F(z) : F(-x) + " " + F(y) + " " + F(-z);
  }
  void Joint(std::ostringstream& o, const HandJoint& j, const std::string& axis) const {
    const double g = std::pow(s_, 4);
    o << "<joint name=\"" << p_ << j.name << "\" type=\"hinge\" axis=\"" << axis << "\" range=\""
      << j.lo_deg << " " << j.hi_deg << "\" damping=\"" << F(j.damping * g) << "\" armature=\""
      << F(j.armature * g) << "\"/>\n";
  }
  void Capsule(std::ostringstream& o, const std::string& part, double length, double r,
               double mass) const {
    // along -z from the joint, ending a radius short of the segment's end
    o << "<geom name=\"" << p_ << part << "_geom\" type=\"capsule\" fromto=\"0 0 "
      << F(-s_ * r * 0.5) << " 0 0 " << F(-s_ * (length - r)) << "\" size=\"" << F(s_ * r)
      << "\" mass=\"" << F(s_ * s_ * s_ * mass) << "\"" << Skin() << "/>\n";
  }
  void Box(std::ostringstream& o, const std::string& part, double cx, double cy, double cz,
           double hx, double hy, double hz, double mass) const {
    o << "<geom name=\"" << p_ << part << "_geom\" type=\"box\" pos=\"" << Pos(cx, cy, cz)
      << "\" size=\"" << F(s_ * hx) << " " << F(s_ * hy) << " " << F(s_ * hz) << "\" mass=\""
      << F(s_ * s_ * s_ * mass) << "\"" << Skin() << "/>\n";
  }
  void Site(std::ostringstream& o, const std::string& name, const std::string& pos) const {
    o << "<site name=\"" << p_ << name << "\" pos=\"" << pos << "\" size=\"" << F(s_ * 0.006)
      << "\" rgba=\"0.2 0.8 0.2 0\"/>\n";
  }
  // a body point site ("pt_right_palm"): the agent prefix, then pt_<side>_<name>
  void PointSite(std::ostringstream& o, const std::string& name, const std::string& pos) const {
    const std::string side = m_ > 0 ? "right_" : "left_";
    const std::string agent = p_.substr(0, p_.size() - side.size());
    o << "<site name=\"" << agent << "pt_" << side << name << "\" pos=\"" << pos << "\" size=\""
      << F(s_ * 0.01) << "\" rgba=\"0.2 0.8 0.2 0\"/>\n";
  }
  const std::string& p() const { return p_; }
  double mirror() const { return m_; }
  double s() const { return s_; }

 private:
  std::string Skin() const {
    // skin grips: torsional friction for a pad, not a point; hand-hand contacts filtered
    return " rgba=\"" + rgba_ + "\" contype=\"2\" conaffinity=\"1\" condim=\"4\" " +
           "friction=\"1 0.01 0.0002\"";
  }
  std::string p_;
  double m_, s_;
  std::string rgba_;
};

const HandJoint& J(const char* name) {
  for (const HandJoint& j : HandJoints()) {
    if (std::string(j.name) == name) return j;
  }
  static const HandJoint none{"", 0, 0, 0, 0, 0, 0};
  return none;
}

// one finger: three nested phalanx bodies from the MCP
void FingerXml(const HandWriter& w, const Finger& f, std::ostringstream& o) {
  const std::string n = f.name;
  const double x0 = f.on_ulnar_palm ? f.mcp_x - kPalmArchX : f.mcp_x;
  const char* joints[3][2] = {{"_abd", "_mcp"}, {"_pip", nullptr}, {"_dip", nullptr}};
  for (int k = 0; k < 3; ++k) {
    const std::string pos = k == 0 ? w.Pos(x0, 0, f.mcp_z) : w.Pos(0, 0, -f.length[k - 1]);
    o << "<body name=\"" << w.p() << n << "_" << kSegment[k] << "\" pos=\"" << pos << "\">\n";
    for (const char* suffix : joints[k]) {
      if (!suffix) continue;
      const bool abd = std::string(suffix) == "_abd";
      w.Joint(o, J(("" + n + suffix).c_str()), abd ? w.Axis(0, 1, 0) : w.Axis(1, 0, 0));
    }
    w.Capsule(o, n + "_" + kSegment[k], f.length[k], f.radius[k], kPhalanxMass[k]);
  }
  w.Site(o, n + "_tip", w.Pos(0, f.radius[2] * 0.3, -f.length[2]));
  if (n == "middle") w.PointSite(o, "fingertips", w.Pos(0, 0, -f.length[2]));
  o << "</body>\n</body>\n</body>\n";
}

// the thumb: a metacarpal body turned to the thumb's rest direction, then two phalanges; hinge
// axes in that local frame (flexion about local x brings the tip toward local +y: opposition)
void ThumbXml(const HandWriter& w, std::ostringstream& o) {
  const Eigen::Vector3d d = Eigen::Vector3d(kThumbDir[0], kThumbDir[1], kThumbDir[2]).normalized();
  const Eigen::Vector3d z = -d;
  Eigen::Vector3d v(kThumbFlexToward[0], kThumbFlexToward[1], kThumbFlexToward[2]);
  Eigen::Vector3d y = (v - v.dot(z) * z).normalized();
  Eigen::Vector3d x = y.cross(z);
  if (w.mirror() < 0) {  // the mirrored frame, kept right-handed: x -> -Mx, y -> My
    x = Eigen::Vector3d(-x.x(), x.y(), -x.z());
    y = Eigen::Vector3d(y.x(), -y.y(), y.z());
  }
  const std::string flex = "1 0 0", abd = w.mirror() > 0 ? "0 1 0" : "0 -1 0";
  const std::string xy =
      F(x.x()) + " " + F(x.y()) + " " + F(x.z()) + " " + F(y.x()) + " " + F(y.y()) + " " + F(y.z());
  o << "<body name=\"" << w.p() << "thumb_metacarpal\" pos=\""
    << w.Pos(kThumbCmc[0], kThumbCmc[1], kThumbCmc[2]) << "\" xyaxes=\"" << xy << "\">\n";
  w.Joint(o, J("thumb_cmc_flex"), flex);
  w.Joint(o, J("thumb_cmc_abd"), abd);
  w.Capsule(o, "thumb_metacarpal", kThumbLength[0], kThumbRadius[0], kThumbMass[0]);
  o << "<body name=\"" << w.p() << "thumb_proximal\" pos=\"0 0 " << F(-w.s() * kThumbLength[0])
    << "\">\n";
  w.Joint(o, J("thumb_mcp_flex"), flex);
  w.Joint(o, J("thumb_mcp_abd"), abd);
  w.Capsule(o, "thumb_proximal", kThumbLength[1], kThumbRadius[1], kThumbMass[1]);
  o << "<body name=\"" << w.p() << "thumb_distal\" pos=\"0 0 " << F(-w.s() * kThumbLength[1])
    << "\">\n";
  w.Joint(o, J("thumb_ip"), flex);
  w.Capsule(o, "thumb_distal", kThumbLength[2], kThumbRadius[2], kThumbMass[2]);
  const std::string tip =
      "0 " + F(w.s() * kThumbRadius[2] * 0.3) + " " + F(-w.s() * kThumbLength[2]);
  w.Site(o, "thumb_tip", tip);
  w.PointSite(o, "thumb_tip", tip);
  o << "</body>\n</body>\n</body>\n";
}

}  // namespace

const std::vector<HandJoint>& HandJoints() {
  // ranges after published active ranges of motion; torque limits after hand-strength data
  // (a finger's MCP flexes with a few N m, the wrist with ~10)
  static const std::vector<HandJoint> all = [] {
    std::vector<HandJoint> j = {
        {"forearm_rot", -85, 85, 40, kWristDamping, 8, kWristArmature},
        {"wrist_flex", -70, 80, 40, kWristDamping, 12, kWristArmature},
        {"wrist_dev", -20, 35, 40, kWristDamping, 10, kWristArmature},
        {"palm_arch", 0, 25, 8, kFingerDamping, 2, kFingerArmature},
    };
    static const char* kNames[4][4] = {{"index_abd", "index_mcp", "index_pip", "index_dip"},
                                       {"middle_abd", "middle_mcp", "middle_pip", "middle_dip"},
                                       {"ring_abd", "ring_mcp", "ring_pip", "ring_dip"},
                                       {"little_abd", "little_mcp", "little_pip", "little_dip"}};
    for (auto& f : kNames) {
      j.push_back({f[0], -20, 20, 6, kFingerDamping, 2, kFingerArmature});
      j.push_back({f[1], -20, 90, 10, kFingerDamping, 3, kFingerArmature});
      j.push_back({f[2], 0, 110, 6, kFingerDamping, 2, kFingerArmature});
      j.push_back({f[3], 0, 80, 4, kFingerDamping, 1.2, kFingerArmature});
    }
    j.push_back({"thumb_cmc_flex", -35, 55, 12, kFingerDamping, 4, kFingerArmature});
    j.push_back({"thumb_cmc_abd", -20, 45, 12, kFingerDamping, 4, kFingerArmature});
    j.push_back({"thumb_mcp_flex", 0, 60, 8, kFingerDamping, 2.5, kFingerArmature});
    j.push_back({"thumb_mcp_abd", -10, 10, 6, kFingerDamping, 2, kFingerArmature});
    j.push_back({"thumb_ip", -10, 80, 5, kFingerDamping, 1.5, kFingerArmature});
    return j;
  }();
  return all;
}

const std::vector<std::string>& HandTouchParts() {
  static const std::vector<std::string> parts = [] {
    std::vector<std::string> p = {"palm_radial", "palm_ulnar"};
    for (const Finger& f : kFingers) {
      for (const char* s : kSegment) p.push_back(std::string(f.name) + "_" + s);
    }
    for (const char* s : {"metacarpal", "proximal", "distal"})
      p.push_back(std::string("thumb_") + s);
    return p;
  }();
  return parts;
}

const std::vector<std::string>& HandTipSites() {
  static const std::vector<std::string> tips = {"thumb_tip", "index_tip", "middle_tip", "ring_tip",
                                                "little_tip"};
  return tips;
}

void HandBodyXml(const std::string& prefix, bool right, double scale, const std::string& rgba,
                 std::ostringstream& o) {
  HandWriter w(prefix, right, scale, rgba);
  // the arm's extra hinges, in order from the elbow: forearm rotation, wrist flexion
  // (fingers toward the palm), wrist deviation (positive toward the little finger)
  w.Joint(o, J("forearm_rot"), w.Axis(0, 0, 1));
  w.Joint(o, J("wrist_flex"), w.Axis(1, 0, 0));
  w.Joint(o, J("wrist_dev"), w.Axis(0, 1, 0));
  // the palm: index-and-middle half fixed to the hand, ring-and-little half on the arch hinge
  const double palm_z = -0.052, palm_hz = 0.048, palm_hy = 0.014;
  w.Box(o, "palm_radial", (kPalmArchX + 0.043) / 2, 0, palm_z, (0.043 - kPalmArchX) / 2, palm_hy,
        palm_hz, kPalmRadialMass);
  w.PointSite(o, "palm", w.Pos(0.0, palm_hy + 0.002, -0.06));
  w.Site(o, "palm_centre", w.Pos(0.0, palm_hy, -0.06));
  for (const Finger& f : kFingers) {
    if (!f.on_ulnar_palm) FingerXml(w, f, o);
  }
  ThumbXml(w, o);
  o << "<body name=\"" << w.p() << "palm_ulnar\" pos=\"" << w.Pos(kPalmArchX, 0, 0) << "\">\n";
  w.Joint(o, J("palm_arch"), w.Axis(0, 0, -1));
  w.Box(o, "palm_ulnar", (-0.043 - kPalmArchX) / 2, 0, palm_z + 0.003, (0.043 + kPalmArchX) / 2,
        palm_hy - 0.001, palm_hz - 0.003, kPalmUlnarMass);
  for (const Finger& f : kFingers) {
    if (f.on_ulnar_palm) FingerXml(w, f, o);
  }
  o << "</body>\n";
}

std::string HandContactExcludesXml(const std::string& prefix, bool right) {
  const std::string p = prefix + (right ? "right_" : "left_");
  std::string out;
  for (const char* b : {"palm_ulnar", "thumb_metacarpal", "thumb_proximal"}) {
    out += "<exclude body1=\"" + p + "lower_arm\" body2=\"" + p + b + "\"/>\n";
  }
  return out;
}

double HandMassKg(double scale) {
  double m = kPalmRadialMass + kPalmUlnarMass;
  for (int k = 0; k < 3; ++k) m += 4 * kPhalanxMass[k] + kThumbMass[k];
  return scale * scale * scale * m;
}

}  // namespace simhuman::world
