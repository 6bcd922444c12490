#include "simhuman/learn/bvh.h"

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "simhuman/core/json_io.h"
#include "simhuman/core/json_reader.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::learn {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kDeg = M_PI / 180.0;
// deepest joint nesting accepted (human skeletons with fingers are about 30 deep); deeper
// files are refused before the recursive parse runs out of stack
constexpr int kMaxJointDepth = 256;

// ---------------------------------------------------------------------------------------------
// parsing

struct Token {
  std::string text;
  int line;
};

class Lexer {
 public:
  Lexer(const std::string& text, const std::string& where) : where_(where) {
    std::istringstream in(text);
    std::string line;
    int n = 0;
    bool header = true;  // the frame values after "Frame Time:" are read from lines_
    while (std::getline(in, line)) {
      ++n;
      lines_.push_back(line);
      if (!header) continue;
      const size_t before = toks_.size();
      std::string cur;
      auto flush = [&] {
        if (!cur.empty()) toks_.push_back({cur, n});
        cur.clear();
      };
      for (char c : line) {
        if (std::isspace(static_cast<unsigned char>(c))) {
          flush();
        } else if (c == '{' || c == '}') {
          flush();
          toks_.push_back({std::string(1, c), n});
        } else {
          cur += c;
        }
      }
      flush();
      if (toks_.size() >= before + 2 && toks_[before].text == "Frame" &&
          toks_[before + 1].text == "Time:") {
        header = false;
      }
    }
    last_line_ = n;
  }

  bool done() const { return pos_ >= toks_.size(); }
  const Token& Peek() const { return toks_[pos_]; }
  int line() const { return done() ? last_line_ : toks_[pos_].line; }
  absl::Status Error(int line, const std::string& what) const {
    return absl::InvalidArgumentError(where_ + ":" + std::to_string(line) + ": " + what);
  }
  core::StatusOr<Token> Next(const std::string& what) {
    if (done()) return Error(last_line_, "unexpected end of file, expected " + what);
    return toks_[pos_++];
  }
  absl::Status Expect(const std::string& word) {
    SH_ASSIGN_OR_RETURN(Token t, Next("'" + word + "'"));
    if (t.text != word) return Error(t.line, "expected '" + word + "', found '" + t.text + "'");
    return absl::OkStatus();
  }
  core::StatusOr<double> Number(const std::string& what) {
    SH_ASSIGN_OR_RETURN(Token t, Next(what));
    char* end = nullptr;
    double v = std::strtod(t.text.c_str(), &end);
    if (end != t.text.c_str() + t.text.size() || !std::isfinite(v)) {
      return Error(t.line, "expected " + what + " (a number), found '" + t.text + "'");
    }
    return v;
  }
  // the raw lines after the token position (the MOTION block is read line by line)
  size_t pos() const { return pos_; }
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  std::string where_;
  std::vector<Token> toks_;
  std::vector<std::string> lines_;
  size_t pos_ = 0;
  int last_line_ = 0;
};

core::StatusOr<BvhChannel> ChannelOf(const std::string& s) {
  static const std::map<std::string, BvhChannel> names = {
      {"Xposition", BvhChannel::kXpos}, {"Yposition", BvhChannel::kYpos},
      {"Zposition", BvhChannel::kZpos}, {"Xrotation", BvhChannel::kXrot},
      {"Yrotation", BvhChannel::kYrot}, {"Zrotation", BvhChannel::kZrot}};
  auto it = names.find(s);
  if (it == names.end()) {
    return absl::InvalidArgumentError(
        "unknown channel '" + s +
        "'; valid: Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation");
  }
  return it->second;
}

absl::Status ParseJoint(Lexer& lx, BvhMotion* bvh, int parent, int depth) {
  const bool root = depth == 0;
  SH_ASSIGN_OR_RETURN(Token name, lx.Next("a joint name"));
  if (depth >= kMaxJointDepth) {
    return lx.Error(name.line,
                    "joints nested deeper than " + std::to_string(kMaxJointDepth) + " levels");
  }
  BvhJoint j;
  j.name = name.text;
  j.parent = parent;
  j.first_channel = bvh->num_channels;
  for (const BvhJoint& o : bvh->joints) {
    if (!o.end_site && o.name == j.name) {
      return lx.Error(name.line, "joint '" + j.name + "' appears twice");
    }
  }
  SH_RETURN_IF_ERROR(lx.Expect("{"));
  SH_RETURN_IF_ERROR(lx.Expect("OFFSET"));
  for (int k = 0; k < 3; ++k) {
    SH_ASSIGN_OR_RETURN(j.offset[k], lx.Number("an OFFSET value"));
  }
  SH_RETURN_IF_ERROR(lx.Expect("CHANNELS"));
  int ch_line = lx.line();
  SH_ASSIGN_OR_RETURN(double n, lx.Number("the channel count"));
  if (!(n == 3 || n == 6)) {
    return lx.Error(ch_line, "joint '" + j.name + "' has " + core::FormatNumber(n) +
                                 " channels; valid: 6 (root or positions + rotations) or 3");
  }
  int rot = 0;
  for (int k = 0; k < static_cast<int>(n); ++k) {
    SH_ASSIGN_OR_RETURN(Token c, lx.Next("a channel name"));
    auto ch = ChannelOf(c.text);
    if (!ch.ok()) return lx.Error(c.line, std::string(ch.status().message()));
    for (BvhChannel prev : j.channels) {
      if (prev == *ch) return lx.Error(c.line, "channel '" + c.text + "' is listed twice");
    }
    rot += *ch == BvhChannel::kXrot || *ch == BvhChannel::kYrot || *ch == BvhChannel::kZrot;
    j.channels.push_back(*ch);
  }
  if (rot != 3) {
    return lx.Error(ch_line, "joint '" + j.name + "' must have all three rotation channels");
  }
  if (root && n != 6) {
    return lx.Error(ch_line, "the root '" + j.name + "' must have 6 channels (3 positions first)");
  }
  bvh->num_channels += static_cast<int>(n);
  const int self = static_cast<int>(bvh->joints.size());
  bvh->joints.push_back(j);
  for (;;) {
    SH_ASSIGN_OR_RETURN(Token t, lx.Next("JOINT, End Site or '}'"));
    if (t.text == "}") return absl::OkStatus();
    if (t.text == "JOINT") {
      SH_RETURN_IF_ERROR(ParseJoint(lx, bvh, self, depth + 1));
    } else if (t.text == "End") {
      SH_RETURN_IF_ERROR(lx.Expect("Site"));
      SH_RETURN_IF_ERROR(lx.Expect("{"));
      SH_RETURN_IF_ERROR(lx.Expect("OFFSET"));
      BvhJoint e;
      e.name = bvh->joints[self].name + "/End Site";
      e.parent = self;
      e.end_site = true;
      e.first_channel = bvh->num_channels;
      for (int k = 0; k < 3; ++k) {
        SH_ASSIGN_OR_RETURN(e.offset[k], lx.Number("an OFFSET value"));
      }
      SH_RETURN_IF_ERROR(lx.Expect("}"));
      bvh->joints.push_back(e);
    } else {
      return lx.Error(t.line, "expected JOINT, End Site or '}', found '" + t.text + "'");
    }
  }
}

// ---------------------------------------------------------------------------------------------
// retargeting

Matrix3d AxisRot(int axis, double rad) {
  return Eigen::AngleAxisd(rad, Vector3d::Unit(axis)).toRotationMatrix();
}

// our segments and the BVH names (normalized: lower case, no prefix before ':', no '_' or
// spaces) that drive them
enum Seg {
  kPelvis,
  kTorso,
  kHead,
  kRUpperArm,
  kRLowerArm,
  kLUpperArm,
  kLLowerArm,
  kRThigh,
  kRShin,
  kRFoot,
  kLThigh,
  kLShin,
  kLFoot,
  kNumSegs
};

const char* const kSegNames[kNumSegs] = {
    "pelvis",         "torso",          "head",        "right_upper_arm", "right_lower_arm",
    "left_upper_arm", "left_lower_arm", "right_thigh", "right_shin",      "right_foot",
    "left_thigh",     "left_shin",      "left_foot"};

std::string Normalize(const std::string& name) {
  std::string s =
      name.substr(name.find_last_of(':') == std::string::npos ? 0 : name.find_last_of(':') + 1);
  std::string out;
  for (char c : s) {
    if (c == '_' || c == ' ' || c == '-') continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

const std::vector<std::string>& Aliases(const std::string& key) {
  static const std::map<std::string, std::vector<std::string>> a = {
      {"hips", {"hips", "pelvis", "hip"}},
      {"neck", {"neck", "neck1"}},
      {"head", {"head"}},
      {"leftarm", {"leftarm", "leftupperarm", "leftuparm", "lshoulder"}},
      {"leftforearm", {"leftforearm", "leftlowerarm", "lelbow"}},
      {"lefthand", {"lefthand", "leftwrist", "lwrist"}},
      {"rightarm", {"rightarm", "rightupperarm", "rightuparm", "rshoulder"}},
      {"rightforearm", {"rightforearm", "rightlowerarm", "relbow"}},
      {"righthand", {"righthand", "rightwrist", "rwrist"}},
      {"leftupleg", {"leftupleg", "leftthigh", "leftupperleg", "lhip"}},
      {"leftleg", {"leftleg", "leftshin", "leftlowerleg", "leftknee", "lknee"}},
      {"leftfoot", {"leftfoot", "leftankle", "lankle"}},
      {"lefttoe", {"lefttoebase", "lefttoe", "lefttoes", "lefttoe0"}},
      {"rightupleg", {"rightupleg", "rightthigh", "rightupperleg", "rhip"}},
      {"rightleg", {"rightleg", "rightshin", "rightlowerleg", "rightknee", "rknee"}},
      {"rightfoot", {"rightfoot", "rightankle", "rankle"}},
      {"righttoe", {"righttoebase", "righttoe", "righttoes", "righttoe0"}},
  };
  return a.at(key);
}

int FindJoint(const BvhMotion& bvh, const std::string& key) {
  const auto& names = Aliases(key);
  // earlier aliases win (e.g. "neck" before "neck1")
  for (const std::string& n : names) {
    for (size_t i = 0; i < bvh.joints.size(); ++i) {
      if (!bvh.joints[i].end_site && Normalize(bvh.joints[i].name) == n) return static_cast<int>(i);
    }
  }
  return -1;
}

// first child joint (or end site) of joint j
int FirstChild(const BvhMotion& bvh, int j) {
  for (size_t i = 0; i < bvh.joints.size(); ++i) {
    if (bvh.joints[i].parent == j) return static_cast<int>(i);
  }
  return -1;
}

bool IsAncestor(const BvhMotion& bvh, int anc, int j) {
  for (int p = bvh.joints[j].parent; p >= 0; p = bvh.joints[p].parent) {
    if (p == anc) return true;
  }
  return false;
}

// minimal rotation taking unit vector a to unit vector b
Matrix3d RotBetween(const Vector3d& a, const Vector3d& b) {
  return Eigen::Quaterniond::FromTwoVectors(a, b).toRotationMatrix();
}

// R = Rx(a) Ry(b) Rz(c)
Vector3d EulerXYZ(const Matrix3d& R) {
  double b = std::asin(std::clamp(R(0, 2), -1.0, 1.0));
  double a = std::atan2(-R(1, 2), R(2, 2));
  double c = std::atan2(-R(0, 1), R(0, 0));
  return Vector3d(a, b, c);
}

// rotation angle of R's twist about the unit axis
double TwistAngle(const Matrix3d& R, const Vector3d& axis) {
  Eigen::Quaterniond q(R);
  double t = 2.0 * std::atan2(q.vec().dot(axis), q.w());
  return std::remainder(t, 2.0 * M_PI);
}

}  // namespace

core::StatusOr<BvhMotion> ParseBvh(const std::string& text, const std::string& where) {
  Lexer lx(text, where);
  BvhMotion bvh;
  SH_RETURN_IF_ERROR(lx.Expect("HIERARCHY"));
  SH_RETURN_IF_ERROR(lx.Expect("ROOT"));
  SH_RETURN_IF_ERROR(ParseJoint(lx, &bvh, -1, 0));
  if (!lx.done() && lx.Peek().text == "ROOT") {
    return lx.Error(lx.line(), "a second ROOT is not supported (one skeleton per file)");
  }
  SH_RETURN_IF_ERROR(lx.Expect("MOTION"));
  SH_RETURN_IF_ERROR(lx.Expect("Frames:"));
  int frames_line = lx.line();
  SH_ASSIGN_OR_RETURN(double nf, lx.Number("the frame count"));
  if (nf < 1 || nf != std::floor(nf) || nf > 1e7) {
    return lx.Error(frames_line, "Frames: must be a positive integer");
  }
  SH_RETURN_IF_ERROR(lx.Expect("Frame"));
  SH_RETURN_IF_ERROR(lx.Expect("Time:"));
  int ft_line = lx.line();
  SH_ASSIGN_OR_RETURN(bvh.frame_time_s, lx.Number("the frame time"));
  if (!(bvh.frame_time_s > 0 && bvh.frame_time_s < 10)) {
    return lx.Error(ft_line, "Frame Time: must be in (0, 10) seconds");
  }
  // frame values: one line per frame, from the line after "Frame Time:"
  const auto& lines = lx.lines();
  const int n_frames = static_cast<int>(nf);
  // as many as announced, but no more than there are lines (Frames: 10000000 in a short file)
  bvh.frames.reserve(std::min<size_t>(n_frames, lines.size() - static_cast<size_t>(ft_line)));
  for (size_t li = static_cast<size_t>(ft_line); li < lines.size(); ++li) {
    std::istringstream in(lines[li]);
    std::vector<double> row;
    std::string tok;
    while (in >> tok) {
      char* end = nullptr;
      double v = std::strtod(tok.c_str(), &end);
      if (end != tok.c_str() + tok.size() || !std::isfinite(v)) {
        return lx.Error(static_cast<int>(li) + 1, "'" + tok + "' is not a number");
      }
      row.push_back(v);
    }
    if (row.empty()) continue;
    if (static_cast<int>(bvh.frames.size()) == n_frames) {
      return lx.Error(static_cast<int>(li) + 1,
                      "more frame lines than Frames: " + std::to_string(n_frames));
    }
    if (static_cast<int>(row.size()) != bvh.num_channels) {
      return lx.Error(static_cast<int>(li) + 1, "frame " + std::to_string(bvh.frames.size()) +
                                                    " has " + std::to_string(row.size()) +
                                                    " values; the hierarchy has " +
                                                    std::to_string(bvh.num_channels) + " channels");
    }
    bvh.frames.push_back(std::move(row));
  }
  if (static_cast<int>(bvh.frames.size()) != n_frames) {
    return lx.Error(static_cast<int>(lines.size()),
                    "the file ends after " + std::to_string(bvh.frames.size()) +
                        " frame lines; Frames: announced " + std::to_string(n_frames));
  }
  return bvh;
}

core::StatusOr<BvhMotion> LoadBvh(const std::string& path) {
  SH_ASSIGN_OR_RETURN(std::string text, core::ReadFile(path));
  return ParseBvh(text, path);
}

namespace {

// the BVH joints that drive our segments (indices into BvhMotion::joints; -1: none)
struct DrivingJoints {
  std::map<std::string, int> by_key;  // Aliases() key -> joint
  int hips = -1, head = -1, neck = -1, chest = -1;
};

// the rest pose (all channels zero) and how it maps onto ours
struct RestFrame {
  std::vector<Vector3d> rest;  // global joint positions (file units)
  Matrix3d A;                  // BVH axes -> ours (rows: forward, left, up)
  double scale = 1;            // file units -> m, from the standing hip height
};

// one of our segments: driving joint, child marker (rest direction), our rest direction, parent
struct SegDef {
  int joint;
  int child;  // -1: no rest correction
  Vector3d ours;
  int parent;
  bool flatten;
};

// our hinges, from the compiled humanoid (actuator order)
struct HingeTable {
  std::array<Vector3d, world::kHumanoidDofs> axis;
  std::array<double, world::kHumanoidDofs> lo, hi;  // range (rad)
  std::array<int, world::kHumanoidDofs> seg_of;     // the segment the hinge turns
};

// finds the joints that drive our segments by their aliases; errors name the missing ones
core::StatusOr<DrivingJoints> FindDrivingJoints(const BvhMotion& bvh, const std::string& where) {
  DrivingJoints dj;
  std::map<std::string, int>& jt = dj.by_key;
  std::vector<std::string> missing;
  for (const char* key :
       {"hips", "head", "leftarm", "leftforearm", "rightarm", "rightforearm", "leftupleg",
        "leftleg", "leftfoot", "rightupleg", "rightleg", "rightfoot"}) {
    jt[key] = FindJoint(bvh, key);
    if (jt[key] < 0)
      missing.push_back(key + std::string(" (") + core::JoinNames(Aliases(key)) + ")");
  }
  for (const char* key : {"neck", "lefthand", "righthand", "lefttoe", "righttoe"}) {
    jt[key] = FindJoint(bvh, key);
  }
  if (!missing.empty()) {
    return absl::InvalidArgumentError(
        where + ": cannot retarget: no joint for " + core::JoinNames(missing) +
        " (names compare without case, '_', '-', spaces and a 'prefix:')");
  }
  dj.hips = jt["hips"];
  dj.head = jt["head"];
  dj.neck = jt["neck"] >= 0 && IsAncestor(bvh, jt["neck"], dj.head) ? jt["neck"] : dj.head;
  dj.chest = bvh.joints[dj.neck].parent;
  if (dj.chest <= 0) {
    return absl::InvalidArgumentError(where + ": no spine joint between the hips and '" +
                                      bvh.joints[dj.neck].name + "'");
  }
  return dj;
}

// the rest pose's joint positions, our axes in BVH terms and the scale to our standing height
core::StatusOr<RestFrame> MakeRestFrame(const BvhMotion& bvh, const DrivingJoints& dj,
                                        const std::string& where) {
  RestFrame rf;
  const size_t nj = bvh.joints.size();
  std::vector<Vector3d>& rest = rf.rest;
  rest.resize(nj);
  for (size_t i = 0; i < nj; ++i) {
    int p = bvh.joints[i].parent;
    rest[i] = (p < 0 ? Vector3d::Zero() : rest[p]) + bvh.joints[i].offset;
  }
  const int hips = dj.hips, neck = dj.neck;
  // BVH axes -> ours: up from the hips to the neck, left from the right to the left thigh
  Vector3d up = (rest[neck] - rest[hips]).normalized();
  Vector3d left = rest[dj.by_key.at("leftupleg")] - rest[dj.by_key.at("rightupleg")];
  left = (left - left.dot(up) * up);
  if (left.norm() < 1e-9 || (rest[neck] - rest[hips]).norm() < 1e-9) {
    return absl::InvalidArgumentError(where +
                                      ": degenerate rest skeleton (cannot tell up or "
                                      "left from the hips, neck and thighs)");
  }
  left.normalize();
  Vector3d fwd = left.cross(up);
  rf.A.row(0) = fwd.transpose();
  rf.A.row(1) = left.transpose();
  rf.A.row(2) = up.transpose();
  // standing height: hips above the lowest rest point
  double lowest = 0;
  for (size_t i = 0; i < nj; ++i) lowest = std::min(lowest, (rest[i] - rest[hips]).dot(up));
  if (lowest > -1e-9) return absl::InvalidArgumentError(where + ": the legs have no length");
  rf.scale = world::kPelvisStandHeight / -lowest;
  return rf;
}

// our segments (kSegNames order) in terms of the driving joints
std::array<SegDef, kNumSegs> SegmentDefs(const BvhMotion& bvh, const DrivingJoints& dj) {
  auto jt = [&](const char* key) { return dj.by_key.at(key); };
  auto child_or = [&](int j, int preferred) {
    return preferred >= 0 ? preferred : FirstChild(bvh, j);
  };
  const int hips = dj.hips, head = dj.head, neck = dj.neck, chest = dj.chest;
  const Vector3d kUp(0, 0, 1), kDown(0, 0, -1), kFwd(1, 0, 0);
  return {{
      {hips, -1, kUp, -1, false},
      {chest, neck, kUp, kPelvis, false},
      {head, FirstChild(bvh, head), kUp, kTorso, false},
      {jt("rightarm"), jt("rightforearm"), kDown, kTorso, false},
      {jt("rightforearm"), child_or(jt("rightforearm"), jt("righthand")), kDown, kRUpperArm, false},
      {jt("leftarm"), jt("leftforearm"), kDown, kTorso, false},
      {jt("leftforearm"), child_or(jt("leftforearm"), jt("lefthand")), kDown, kLUpperArm, false},
      {jt("rightupleg"), jt("rightleg"), kDown, kPelvis, false},
      {jt("rightleg"), jt("rightfoot"), kDown, kRThigh, false},
      {jt("rightfoot"), child_or(jt("rightfoot"), jt("righttoe")), kFwd, kRShin, true},
      {jt("leftupleg"), jt("leftleg"), kDown, kPelvis, false},
      {jt("leftleg"), jt("leftfoot"), kDown, kLThigh, false},
      {jt("leftfoot"), child_or(jt("leftfoot"), jt("lefttoe")), kFwd, kLShin, true},
  }};
}

// per segment, the rotation from our rest direction to the BVH rest bone (in our axes)
std::array<Matrix3d, kNumSegs> RestCorrections(const std::array<SegDef, kNumSegs>& segs,
                                               const RestFrame& rf) {
  const std::vector<Vector3d>& rest = rf.rest;
  std::array<Matrix3d, kNumSegs> C;
  for (int s = 0; s < kNumSegs; ++s) {
    C[s] = Matrix3d::Identity();
    if (segs[s].child < 0) continue;
    Vector3d d = rf.A * (rest[segs[s].child] - rest[segs[s].joint]);
    if (segs[s].flatten) d.z() = 0;
    if (d.norm() < 1e-9) continue;  // a zero-length bone: no correction
    C[s] = RotBetween(segs[s].ours, d.normalized());
  }
  return C;
}

// our hinge axes, ranges and segments, from the compiled humanoid
core::StatusOr<HingeTable> LoadHingeTable() {
  SH_ASSIGN_OR_RETURN(std::unique_ptr<world::SimWorld> sim,
                      world::SimWorld::Create(core::SceneCatalog(), {world::AgentSpec()}, {}));
  const mjModel* m = sim->model();
  const world::AgentIndex& ag = sim->agent(0);
  const auto& jnames = world::HumanoidJointNames();
  HingeTable ht;
  for (int k = 0; k < world::kHumanoidDofs; ++k) {
    int jid = m->actuator_trnid[2 * ag.actuator[k]];
    ht.axis[k] = Vector3d(m->jnt_axis[3 * jid], m->jnt_axis[3 * jid + 1], m->jnt_axis[3 * jid + 2]);
    ht.lo[k] = m->jnt_range[2 * jid];
    ht.hi[k] = m->jnt_range[2 * jid + 1];
    const char* body = mj_id2name(m, mjOBJ_BODY, m->jnt_bodyid[jid]);
    ht.seg_of[k] = -1;
    for (int s = 0; s < kNumSegs; ++s) {
      if (std::string(body) == kSegNames[s]) ht.seg_of[k] = s;
    }
    if (ht.seg_of[k] < 0)
      return absl::InternalError("retarget: hinge '" + jnames[k] + "' has no segment");
  }
  return ht;
}

// forward kinematics of one frame row: global joint rotations G and positions P (file units)
void GlobalPose(const BvhMotion& bvh, const std::vector<double>& row, std::vector<Matrix3d>* g,
                std::vector<Vector3d>* p) {
  std::vector<Matrix3d>& G = *g;
  std::vector<Vector3d>& P = *p;
  for (size_t i = 0; i < bvh.joints.size(); ++i) {
    const BvhJoint& j = bvh.joints[i];
    Matrix3d L = Matrix3d::Identity();
    // position channels replace the OFFSET (the root's are its position)
    Vector3d local = j.offset;
    for (size_t c = 0; c < j.channels.size(); ++c) {
      double v = row[j.first_channel + c];
      switch (j.channels[c]) {
        case BvhChannel::kXrot:
          L = L * AxisRot(0, v * kDeg);
          break;
        case BvhChannel::kYrot:
          L = L * AxisRot(1, v * kDeg);
          break;
        case BvhChannel::kZrot:
          L = L * AxisRot(2, v * kDeg);
          break;
        case BvhChannel::kXpos:
          local.x() = v;
          break;
        case BvhChannel::kYpos:
          local.y() = v;
          break;
        case BvhChannel::kZpos:
          local.z() = v;
          break;
      }
    }
    G[i] = j.parent < 0 ? L : G[j.parent] * L;
    P[i] = j.parent < 0 ? local : P[j.parent] + G[j.parent] * local;
  }
}

// our hinge angles from the segments' rotations R (our axes): segments with three hinges are
// intrinsic x-y-z Euler angles, one hinge a twist; clamped to the hinge ranges
absl::Status SegmentHinges(const std::array<Matrix3d, kNumSegs>& R,
                           const std::array<SegDef, kNumSegs>& segs, const HingeTable& ht,
                           ClipFrame* fr) {
  const auto& jnames = world::HumanoidJointNames();
  for (int k = 0; k < world::kHumanoidDofs;) {
    int s = ht.seg_of[k];
    Matrix3d rel = R[segs[s].parent].transpose() * R[s];
    int n = 1;
    while (k + n < world::kHumanoidDofs && ht.seg_of[k + n] == s) ++n;
    if (n == 3) {
      // two Euler triples give the same rotation; take the one nearer the hinge ranges (a hip
      // flexed beyond 90 degrees is the second)
      const Vector3d e = EulerXYZ(rel);
      const Vector3d alt(std::remainder(e[0] + M_PI, 2 * M_PI),
                         std::remainder(M_PI - e[1], 2 * M_PI),
                         std::remainder(e[2] + M_PI, 2 * M_PI));
      double outside[2] = {0, 0};
      for (int a = 0; a < 3; ++a) {
        double sign = ht.axis[k + a][a];
        if (std::abs(std::abs(sign) - 1) > 1e-9) {
          return absl::InternalError("retarget: hinge '" + jnames[k + a] +
                                     "' is not along a body axis in x, y, z order");
        }
        for (int c = 0; c < 2; ++c) {
          const double q = (c == 0 ? e[a] : alt[a]) * sign;
          outside[c] += std::max({0.0, ht.lo[k + a] - q, q - ht.hi[k + a]});
        }
      }
      const Vector3d& best = outside[1] < outside[0] - 1e-9 ? alt : e;
      for (int a = 0; a < 3; ++a) fr->q_rad[k + a] = best[a] * ht.axis[k + a][a];
    } else if (n == 1) {
      fr->q_rad[k] = TwistAngle(rel, ht.axis[k]);
    } else {
      return absl::InternalError("retarget: segment with " + std::to_string(n) + " hinges");
    }
    for (int a = 0; a < n; ++a)
      fr->q_rad[k + a] = std::clamp(fr->q_rad[k + a], ht.lo[k + a], ht.hi[k + a]);
    k += n;
  }
  return absl::OkStatus();
}

}  // namespace

core::StatusOr<MotionClip> RetargetBvh(const BvhMotion& bvh, const std::string& where) {
  if (bvh.joints.empty() || bvh.frames.empty()) {
    return absl::InvalidArgumentError(where + ": no skeleton or no frames");
  }
  SH_ASSIGN_OR_RETURN(const DrivingJoints dj, FindDrivingJoints(bvh, where));
  SH_ASSIGN_OR_RETURN(const RestFrame rf, MakeRestFrame(bvh, dj, where));
  const Matrix3d& A = rf.A;
  const std::array<SegDef, kNumSegs> segs = SegmentDefs(bvh, dj);
  const std::array<Matrix3d, kNumSegs> C = RestCorrections(segs, rf);
  SH_ASSIGN_OR_RETURN(const HingeTable ht, LoadHingeTable());

  // ---- frames
  const size_t nj = bvh.joints.size();
  MotionClip clip;
  clip.fps = 1.0 / bvh.frame_time_s;
  clip.source = where;
  clip.frames.resize(bvh.frames.size());
  std::vector<Matrix3d> G(nj);
  std::vector<Vector3d> P(nj);  // global joint positions (file units)
  Vector3d origin_xy = Vector3d::Zero();
  for (size_t f = 0; f < bvh.frames.size(); ++f) {
    GlobalPose(bvh, bvh.frames[f], &G, &P);
    std::array<Matrix3d, kNumSegs> R;
    for (int s = 0; s < kNumSegs; ++s) R[s] = A * G[segs[s].joint] * A.transpose() * C[s];
    ClipFrame& fr = clip.frames[f];
    Vector3d p = rf.scale * (A * P[dj.hips]);
    if (f == 0) origin_xy = Vector3d(p.x(), p.y(), 0);
    p -= origin_xy;
    for (int k = 0; k < 3; ++k) fr.root_pos_m[k] = p[k];
    Eigen::Quaterniond q(R[kPelvis]);
    q.normalize();
    fr.root_quat_wxyz = {q.w(), q.x(), q.y(), q.z()};
    SH_RETURN_IF_ERROR(SegmentHinges(R, segs, ht, &fr));
  }
  SH_RETURN_IF_ERROR(core::Annotate(clip.Validate(), where));
  return clip;
}

core::StatusOr<MotionClip> LoadBvhAsClip(const std::string& path) {
  SH_ASSIGN_OR_RETURN(BvhMotion bvh, LoadBvh(path));
  return RetargetBvh(bvh, path);
}

core::StatusOr<MotionClip> LoadAnyClip(const std::string& path) {
  std::string lower = path;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".bvh") == 0) {
    return LoadBvhAsClip(path);
  }
  return LoadMotionClip(path);
}

}  // namespace simhuman::learn
