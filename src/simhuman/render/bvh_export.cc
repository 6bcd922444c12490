#include "simhuman/render/bvh_export.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "simhuman/world/humanoid.h"

namespace simhuman::render {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kRadToDeg = 180.0 / M_PI;

// one BVH joint: the body it follows (without prefix), its parent (index into kJoints) and,
// for a leaf, its End Site in our axes at scale 1 (metres)
struct JointDef {
  const char* name;
  const char* body;
  int parent;
  bool end_site;
  double ex, ey, ez;
};

// the end sites: straight up or down the bone (the importer takes rest bone directions from
// them): the top of the head, the hand's far end, the toe tip at standing floor level
// (their z is set in MakeSkeleton)
constexpr JointDef kJoints[] = {
    {"Hips", "pelvis", -1, false, 0, 0, 0},
    {"Spine", "torso", 0, false, 0, 0, 0},
    {"Head", "head", 1, true, 0, 0, 0.26},
    {"RightArm", "right_upper_arm", 1, false, 0, 0, 0},
    {"RightForeArm", "right_lower_arm", 3, false, 0, 0, 0},
    {"RightHand", "right_hand", 4, true, 0, 0, -0.10},
    {"LeftArm", "left_upper_arm", 1, false, 0, 0, 0},
    {"LeftForeArm", "left_lower_arm", 6, false, 0, 0, 0},
    {"LeftHand", "left_hand", 7, true, 0, 0, -0.10},
    {"RightUpLeg", "right_thigh", 0, false, 0, 0, 0},
    {"RightLeg", "right_shin", 9, false, 0, 0, 0},
    {"RightFoot", "right_foot", 10, true, 0.15, 0, 0},
    {"LeftUpLeg", "left_thigh", 0, false, 0, 0, 0},
    {"LeftLeg", "left_shin", 12, false, 0, 0, 0},
    {"LeftFoot", "left_foot", 13, true, 0.15, 0, 0},
};
constexpr int kNumJoints = sizeof(kJoints) / sizeof(kJoints[0]);

// our axes (x forward, y left, z up) -> BVH (Y up, facing +Z, +X to the left)
Vector3d ToBvh(const Vector3d& v) { return Vector3d(v.y(), v.z(), v.x()); }

// a hinge's place among its joint's three rotation channels: channel k (in "Zrotation
// Xrotation Yrotation" order) turns about our axis k (x, y, z), `sign` the axis direction
struct HingeSlot {
  int qpos_adr;
  int joint;  // BVH joint
  int axis;   // 0, 1, 2 = our x, y, z
  double sign;
};

struct Skeleton {
  std::vector<int> body;           // per BVH joint: the model's body id
  std::vector<Vector3d> offset;    // per BVH joint: offset from the parent (our axes)
  std::vector<Vector3d> end_site;  // per BVH joint (leaves): End Site offset (our axes)
  std::vector<HingeSlot> hinges;
};

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6f", v);
  // "-0.000000" reads badly
  return std::string(buf) == "-0.000000" ? "0.000000" : buf;
}

core::StatusOr<Skeleton> MakeSkeleton(const mjModel* m, const world::AgentIndex& agent) {
  Skeleton sk;
  const std::string prefix = [&] {
    const char* pelvis = mj_id2name(m, mjOBJ_BODY, agent.pelvis_body);
    std::string p = pelvis ? pelvis : "";
    return p.size() >= 6 ? p.substr(0, p.size() - 6) : std::string();  // strip "pelvis"
  }();
  for (int j = 0; j < kNumJoints; ++j) {
    const std::string name = prefix + kJoints[j].body;
    const int b = mj_name2id(m, mjOBJ_BODY, name.c_str());
    if (b < 0) return absl::InternalError("bvh export: the model has no body '" + name + "'");
    sk.body.push_back(b);
    sk.offset.push_back(j == 0 ? Vector3d::Zero() : Vector3d(m->body_pos + 3 * b));
    Vector3d e = agent.scale * Vector3d(kJoints[j].ex, kJoints[j].ey, kJoints[j].ez);
    sk.end_site.push_back(e);
  }
  // the toes sit at standing floor level: kPelvisStandHeight below the hips in the rest pose
  for (int j = 0; j < kNumJoints; ++j) {
    if (std::string(kJoints[j].body).find("foot") == std::string::npos) continue;
    double depth = 0;
    for (int k = j; k > 0; k = kJoints[k].parent) depth += sk.offset[k].z();
    sk.end_site[j].z() = -world::kPelvisStandHeight * agent.scale - depth;
  }
  // the body's hinges (actuator order), each along one body axis, in x, y, z order per body
  const int nh = std::min<int>(world::kHumanoidDofs, agent.num_actuators());
  std::vector<int> last_axis(kNumJoints, -1);
  for (int k = 0; k < nh; ++k) {
    const int jid = m->actuator_trnid[2 * agent.actuator[k]];
    const char* jname = mj_id2name(m, mjOBJ_JOINT, jid);
    const int j = static_cast<int>(std::find(sk.body.begin(), sk.body.end(), m->jnt_bodyid[jid]) -
                                   sk.body.begin());
    const Vector3d axis(m->jnt_axis + 3 * jid);
    int a = 0;
    axis.cwiseAbs().maxCoeff(&a);
    if (j == kNumJoints || std::abs(std::abs(axis[a]) - 1) > 1e-9 || a <= last_axis[j]) {
      return absl::InternalError(std::string("bvh export: hinge '") + (jname ? jname : "?") +
                                 "' is not on an exported body along a body axis in x, y, z order");
    }
    last_axis[j] = a;
    sk.hinges.push_back({m->jnt_qposadr[jid], j, a, axis[a]});
  }
  return sk;
}

void WriteHierarchy(const Skeleton& sk, std::ostream& o) {
  o << "HIERARCHY\n";
  // depth-first: children of j are the later joints naming j as parent (kJoints is ordered so)
  struct Writer {
    const Skeleton& sk;
    std::ostream& o;
    void Joint(int j, int depth) {
      const std::string pad(2 * depth, ' ');
      const Vector3d off = ToBvh(sk.offset[j]);
      o << pad << (j == 0 ? "ROOT " : "JOINT ") << kJoints[j].name << "\n" << pad << "{\n";
      o << pad << "  OFFSET " << Num(off.x()) << " " << Num(off.y()) << " " << Num(off.z()) << "\n";
      o << pad << "  CHANNELS "
        << (j == 0 ? "6 Xposition Yposition Zposition Yrotation Zrotation Xrotation"
                   : "3 Zrotation Xrotation Yrotation")
        << "\n";
      for (int c = j + 1; c < kNumJoints; ++c) {
        if (kJoints[c].parent == j) Joint(c, depth + 1);
      }
      if (kJoints[j].end_site) {
        const Vector3d e = ToBvh(sk.end_site[j]);
        o << pad << "  End Site\n" << pad << "  {\n";
        o << pad << "    OFFSET " << Num(e.x()) << " " << Num(e.y()) << " " << Num(e.z()) << "\n";
        o << pad << "  }\n";
      }
      o << pad << "}\n";
    }
  };
  Writer{sk, o}.Joint(0, 0);
}

// the root rotation as intrinsic angles about our z, x, y (BVH Y, Z, X): R = Rz(a) Rx(b) Ry(c);
// each angle is unwrapped to the nearest of `prev` + k 360 degrees, so curves do not jump
Vector3d RootAnglesDeg(const Matrix3d& R, const Vector3d& prev) {
  const double b = std::asin(std::clamp(R(2, 1), -1.0, 1.0));
  const double a = std::atan2(-R(0, 1), R(1, 1));
  const double c = std::atan2(-R(2, 0), R(2, 2));
  Vector3d deg = Vector3d(a, b, c) * kRadToDeg;
  for (int k : {0, 2}) deg[k] = prev[k] + std::remainder(deg[k] - prev[k], 360.0);
  return deg;
}

}  // namespace

std::vector<double> SampleQpos(const mjModel* m, const QposFrames& frames, double t_s) {
  const std::vector<double>& ts = frames.time_s;
  const size_t n = frames.qpos.size();
  size_t i = std::upper_bound(ts.begin(), ts.begin() + n, t_s) - ts.begin();
  if (i == 0) return frames.qpos.front();
  if (i >= n) return frames.qpos.back();
  // trajectory.csv keeps times to 0.1 ms: a sample that close to a row is that row
  constexpr double kSnapS = 1e-4;
  if (t_s - ts[i - 1] <= kSnapS) return frames.qpos[i - 1];
  if (ts[i] - t_s <= kSnapS) return frames.qpos[i];
  const double span = ts[i] - ts[i - 1];
  const double w = span > 0 ? (t_s - ts[i - 1]) / span : 1.0;
  const std::vector<double>& q0 = frames.qpos[i - 1];
  const std::vector<double>& q1 = frames.qpos[i];
  std::vector<double> q(q0.size());
  for (size_t k = 0; k < q.size(); ++k) q[k] = (1 - w) * q0[k] + w * q1[k];
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] != mjJNT_FREE && m->jnt_type[j] != mjJNT_BALL) continue;
    const int adr = m->jnt_qposadr[j] + (m->jnt_type[j] == mjJNT_FREE ? 3 : 0);
    // the shorter way round
    const double dot = q0[adr] * q1[adr] + q0[adr + 1] * q1[adr + 1] + q0[adr + 2] * q1[adr + 2] +
                       q0[adr + 3] * q1[adr + 3];
    const double s = dot < 0 ? -1 : 1;
    for (int k = 0; k < 4; ++k) q[adr + k] = (1 - w) * q0[adr + k] + w * s * q1[adr + k];
    mju_normalize4(q.data() + adr);
  }
  return q;
}

const std::vector<std::string>& BvhExportJointNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const JointDef& j : kJoints) n.push_back(j.name);
    return n;
  }();
  return names;
}

core::StatusOr<std::string> AgentBvh(const mjModel* m, const world::AgentIndex& agent,
                                     const QposFrames& frames, double fps) {
  if (!(fps > 0 && fps <= 1000)) {
    return absl::InvalidArgumentError("bvh export: fps " + Num(fps) + " is not in (0, 1000]");
  }
  if (frames.qpos.empty() || frames.time_s.size() != frames.qpos.size()) {
    return absl::InvalidArgumentError("bvh export: no frames (or times and rows differ in count)");
  }
  for (size_t f = 0; f < frames.qpos.size(); ++f) {
    if (static_cast<int>(frames.qpos[f].size()) != m->nq) {
      return absl::InvalidArgumentError("bvh export: frame " + std::to_string(f) + " has " +
                                        std::to_string(frames.qpos[f].size()) +
                                        " qpos values, the model " + std::to_string(m->nq));
    }
  }
  SH_ASSIGN_OR_RETURN(const Skeleton sk, MakeSkeleton(m, agent));
  std::ostringstream o;
  WriteHierarchy(sk, o);
  const double t0 = frames.time_s.front();
  const double duration = frames.time_s.back() - t0;
  // frames at t0 + k / fps up to the last recorded time (a hair of slack for rounded times)
  const int count = 1 + static_cast<int>(std::floor(duration * fps + 1e-6));
  char frame_time[32];
  std::snprintf(frame_time, sizeof(frame_time), "%.9g", 1.0 / fps);
  o << "MOTION\nFrames: " << count << "\nFrame Time: " << frame_time << "\n";
  Vector3d prev_angles = Vector3d::Zero();
  std::vector<double> ch(3 * kNumJoints + 3);
  for (int f = 0; f < count; ++f) {
    const std::vector<double> q = SampleQpos(m, frames, t0 + f / fps);
    const int r = agent.root_qpos;
    const Vector3d pos = ToBvh(Vector3d(q[r], q[r + 1], q[r + 2]));
    const Eigen::Quaterniond quat(q[r + 3], q[r + 4], q[r + 5], q[r + 6]);
    prev_angles = RootAnglesDeg(quat.normalized().toRotationMatrix(), prev_angles);
    std::fill(ch.begin(), ch.end(), 0.0);
    for (int k = 0; k < 3; ++k) ch[k] = pos[k];
    for (int k = 0; k < 3; ++k) ch[3 + k] = prev_angles[k];
    // joint j > 0 has channels at 3 + 3 j: our x, y, z hinges (BVH Z, X, Y rotations)
    for (const HingeSlot& h : sk.hinges) {
      ch[3 + 3 * h.joint + h.axis] = h.sign * q[h.qpos_adr] * kRadToDeg;
    }
    for (size_t k = 0; k < ch.size(); ++k) o << (k ? " " : "") << Num(ch[k]);
    o << "\n";
  }
  return o.str();
}

}  // namespace simhuman::render
