#include "simhuman/learn/bvh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "simhuman/core/testing_temp.h"

namespace simhuman::learn {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kAngleTol = 1e-6;  // rad: retargeting exact rotations is exact up to rounding

// hinge indices (world::HumanoidJointNames())
constexpr int kRShX = 6, kRShY = 7, kRShZ = 8, kRElbow = 9, kLShX = 10, kLShY = 11, kLShZ = 12,
              kLElbow = 13, kRKnee = 17, kLHipX = 21, kLHipY = 22, kLHipZ = 23, kLKnee = 24,
              kLAnkY = 26;

// A small CMU-style skeleton (Y up, facing +Z, T-pose, CMU-like units: hips 15.5 above the
// toes). `p` prefixes every joint name (e.g. "mixamorig:"); `six` gives LeftLeg 6 channels.
std::string Hierarchy(const std::string& p = "", bool six = false) {
  std::ostringstream o;
  auto rot3 = "CHANNELS 3 Zrotation Xrotation Yrotation\n";
  o << "HIERARCHY\nROOT " << p << "Hips\n{\n  OFFSET 0 0 0\n"
    << "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  for (int side : {1, -1}) {
    std::string s = side > 0 ? "Left" : "Right";
    o << "  JOINT " << p << s << "UpLeg\n  {\n    OFFSET " << 1.5 * side << " -0.5 0\n    " << rot3
      << "    JOINT " << p << s << "Leg\n    {\n      OFFSET 0 -7 0\n      "
      << (six && side > 0 ? "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation "
                            "Yrotation\n"
                          : rot3)
      << "      JOINT " << p << s << "Foot\n      {\n        OFFSET 0 -7 0\n        " << rot3
      << "        JOINT " << p << s << "ToeBase\n        {\n          OFFSET 0 -1 2\n          "
      << rot3 << "          End Site\n          {\n            OFFSET 0 0 1\n          }\n"
      << "        }\n      }\n    }\n  }\n";
  }
  o << "  JOINT " << p << "LowerBack\n  {\n    OFFSET 0 1 0\n    " << rot3;
  o << "    JOINT " << p << "Spine\n    {\n      OFFSET 0 3 0\n      " << rot3;
  o << "      JOINT " << p << "Spine1\n      {\n        OFFSET 0 3 0\n        " << rot3;
  o << "        JOINT " << p << "Neck\n        {\n          OFFSET 0 3 0\n          " << rot3
    << "          JOINT " << p << "Head\n          {\n            OFFSET 0 1.5 0\n            "
    << rot3 << "            End Site\n            {\n              OFFSET 0 2 0\n            }\n"
    << "          }\n        }\n";
  for (int side : {1, -1}) {
    std::string s = side > 0 ? "Left" : "Right";
    o << "        JOINT " << p << s << "Shoulder\n        {\n          OFFSET " << side
      << " 2 0\n          " << rot3 << "          JOINT " << p << s << "Arm\n          {\n"
      << "            OFFSET " << 2 * side << " 0 0\n            " << rot3 << "            JOINT "
      << p << s << "ForeArm\n            {\n              OFFSET " << 5 * side
      << " 0 0\n              " << rot3 << "              JOINT " << p << s
      << "Hand\n              {\n                OFFSET " << 4 * side << " 0 0\n"
      << "                " << rot3 << "                End Site\n                {\n"
      << "                  OFFSET " << side << " 0 0\n                }\n"
      << "              }\n            }\n          }\n        }\n";
  }
  o << "      }\n    }\n  }\n}\n";
  return o.str();
}

// channel order of Hierarchy(): Hips(6) LUpLeg LLeg LFoot LToe RUpLeg RLeg RFoot RToe
// LowerBack Spine Spine1 Neck Head LShoulder LArm LForeArm LHand RShoulder RArm RForeArm RHand
struct Pose {
  double root[6] = {0, 15.5, 0, 0, 0, 0};  // x y z, then Z X Y rotations
  double left_knee_x = 0, left_arm_z = 0, right_arm_z = 0;
  double left_hip_x = 0;  // LeftUpLeg Xrotation: negative swings the leg forward
};

std::string FrameLine(const Pose& p, bool six) {
  std::vector<double> v(p.root, p.root + 6);
  auto rot = [&](double z, double x, double y) { v.insert(v.end(), {z, x, y}); };
  rot(0, p.left_hip_x, 0);  // LeftUpLeg
  if (six) v.insert(v.end(), {0, -7, 0});
  rot(0, p.left_knee_x, 0);  // LeftLeg
  rot(0, 0, 0);
  rot(0, 0, 0);
  for (int k = 0; k < 4; ++k) rot(0, 0, 0);  // right leg
  for (int k = 0; k < 5; ++k) rot(0, 0, 0);  // spine, neck, head
  rot(0, 0, 0);                              // LeftShoulder
  rot(p.left_arm_z, 0, 0);                   // LeftArm
  rot(0, 0, 0);
  rot(0, 0, 0);
  rot(0, 0, 0);  // RightShoulder
  rot(p.right_arm_z, 0, 0);
  rot(0, 0, 0);
  rot(0, 0, 0);
  std::ostringstream o;
  for (size_t k = 0; k < v.size(); ++k) o << (k ? " " : "") << v[k];
  return o.str() + "\n";
}

// frame 0: T-pose; 1: left knee bent 30 deg; 2: arms down, moved 10 forward, turned 90 left
std::string ThreeFrames(const std::string& prefix = "", bool six = false) {
  Pose t_pose, knee, arms;
  knee.left_knee_x = 30;
  arms.left_arm_z = -90;
  arms.right_arm_z = 90;
  arms.root[2] = 10;
  arms.root[5] = 90;
  return Hierarchy(prefix, six) + "MOTION\nFrames: 3\nFrame Time: 0.0083333\n" +
         FrameLine(t_pose, six) + FrameLine(knee, six) + FrameLine(arms, six);
}

void ExpectRetargeted(const MotionClip& c) {
  ASSERT_EQ(c.frames.size(), 3u);
  EXPECT_NEAR(c.fps, 120, 0.01);
  const ClipFrame &t_pose = c.frames[0], &knee = c.frames[1], &arms = c.frames[2];
  // T-pose: both arms abducted 90 degrees, everything else straight
  EXPECT_NEAR(t_pose.q_rad[kLShX], 90 * kDeg, kAngleTol);
  EXPECT_NEAR(t_pose.q_rad[kRShX], 90 * kDeg, kAngleTol);
  for (int j : {kLShY, kLShZ, kRShY, kRShZ, kLElbow, kRElbow, kLKnee, kRKnee}) {
    EXPECT_NEAR(t_pose.q_rad[j], 0, kAngleTol) << j;
  }
  // root at our standing height, at the origin, upright
  EXPECT_NEAR(t_pose.root_pos_m[2], world::kPelvisStandHeight, 1e-9);
  EXPECT_NEAR(t_pose.root_pos_m[0], 0, 1e-9);
  EXPECT_NEAR(t_pose.root_quat_wxyz[0], 1, 1e-9);
  // knee bent 30 degrees on our left knee hinge only; the foot follows the shin
  EXPECT_NEAR(knee.q_rad[kLKnee], 30 * kDeg, kAngleTol);
  EXPECT_NEAR(knee.q_rad[kRKnee], 0, kAngleTol);
  EXPECT_NEAR(knee.q_rad[kLAnkY], 0, kAngleTol);
  // arms lowered to the sides: our rest pose
  for (int j : {kLShX, kLShY, kLShZ, kRShX, kRShY, kRShZ}) {
    EXPECT_NEAR(arms.q_rad[j], 0, kAngleTol) << j;
  }
  // 10 BVH units forward (+Z) = our +x, scaled by 0.96 / 15.5; turned 90 degrees left (yaw)
  EXPECT_NEAR(arms.root_pos_m[0], 10 * world::kPelvisStandHeight / 15.5, 1e-9);
  EXPECT_NEAR(arms.root_pos_m[1], 0, 1e-9);
  EXPECT_NEAR(arms.root_quat_wxyz[0], std::cos(M_PI / 4), 1e-9);
  EXPECT_NEAR(arms.root_quat_wxyz[3], std::sin(M_PI / 4), 1e-9);
}

TEST(Bvh, ParsesCmuStyleSkeleton) {
  auto bvh = ParseBvh(ThreeFrames(), "t.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.status();
  EXPECT_EQ(bvh->num_channels, 6 + 21 * 3);
  EXPECT_EQ(bvh->frames.size(), 3u);
  EXPECT_EQ(bvh->joints[0].name, "Hips");
  EXPECT_NEAR(bvh->frame_time_s, 0.0083333, 1e-12);
}

TEST(Bvh, RetargetsKneeShoulderAndRoot) {
  auto bvh = ParseBvh(ThreeFrames(), "t.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.status();
  auto clip = RetargetBvh(*bvh, "t.bvh");
  ASSERT_TRUE(clip.ok()) << clip.status();
  ExpectRetargeted(*clip);
}

TEST(Bvh, MixamoNamesAndSixChannelJoints) {
  auto bvh = ParseBvh(ThreeFrames("mixamorig:", true), "mixamo.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.status();
  auto clip = RetargetBvh(*bvh, "mixamo.bvh");
  ASSERT_TRUE(clip.ok()) << clip.status();
  ExpectRetargeted(*clip);
}

// hips below another root, with 6 channels (their positions move them)
TEST(Bvh, HipsBelowAReferenceRoot) {
  std::string t = ThreeFrames();
  t.replace(t.find("ROOT Hips"), 9,
            "ROOT Reference\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition "
            "Xrotation Yrotation Zrotation\n  JOINT Hips");
  t.replace(t.find("MOTION"), 6, "}\nMOTION");
  // every frame line gets the reference's six zeros in front
  std::istringstream in(t);
  std::string line, out;
  bool frames = false;
  while (std::getline(in, line)) {
    out += (frames ? "0 0 0 0 0 0 " : "") + line + "\n";
    frames = frames || line.rfind("Frame Time:", 0) == 0;
  }
  auto bvh = ParseBvh(out, "ref.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.status();
  auto clip = RetargetBvh(*bvh, "ref.bvh");
  ASSERT_TRUE(clip.ok()) << clip.status();
  ExpectRetargeted(*clip);
}

TEST(Bvh, LoadsFileAndRetargetsThroughLoadAnyClip) {
  std::string path = core::testing::UniqueTempPath("bvh_test.BVH");
  std::ofstream(path) << ThreeFrames();
  auto clip = LoadAnyClip(path);
  ASSERT_TRUE(clip.ok()) << clip.status();
  ExpectRetargeted(*clip);
  std::filesystem::remove(path);
}

// the line (1-based) of the first occurrence of `needle` in `text`
int LineOf(const std::string& text, const std::string& needle) {
  size_t pos = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + pos, '\n'));
}

void ExpectErrorAt(const std::string& text, int line, const std::string& what) {
  auto bvh = ParseBvh(text, "malformed.bvh");
  ASSERT_FALSE(bvh.ok());
  std::string msg(bvh.status().message());
  EXPECT_NE(msg.find("malformed.bvh:" + std::to_string(line) + ":"), std::string::npos) << msg;
  EXPECT_NE(msg.find(what), std::string::npos) << msg;
}

// a hip flexed beyond 90 degrees (sitting deep) has two Euler triples; the one inside the
// hinge ranges is taken (the other, 70 degrees with the thigh turned over, used to be clipped)
TEST(Bvh, HipFlexedBeyondNinetyDegreesComesBackAsIs) {
  Pose deep;
  deep.left_hip_x = -110;
  auto bvh =
      ParseBvh(Hierarchy() + "MOTION\nFrames: 1\nFrame Time: 0.0333333\n" + FrameLine(deep, false),
               "deep.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.status();
  auto clip = RetargetBvh(*bvh, "deep.bvh");
  ASSERT_TRUE(clip.ok()) << clip.status();
  const ClipFrame& f = clip->frames[0];
  EXPECT_NEAR(f.q_rad[kLHipY], 110 * kDeg, kAngleTol);
  EXPECT_NEAR(f.q_rad[kLHipX], 0, kAngleTol);
  EXPECT_NEAR(f.q_rad[kLHipZ], 0, kAngleTol);
}

TEST(Bvh, ParseErrorsNameTheLine) {
  std::string good = ThreeFrames();
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  std::string t = replace("CHANNELS 3 Zrotation Xrotation Yrotation\n    JOINT Left",
                          "CHANNELS 2 Zrotation Xrotation\n    JOINT Left");
  ExpectErrorAt(t, LineOf(t, "CHANNELS 2"), "2 channels");
  t = replace("Zrotation Xrotation Yrotation\n    JOINT LeftLeg",
              "Zrotation Xrotation Wrotation\n    JOINT LeftLeg");
  ExpectErrorAt(t, LineOf(t, "Wrotation"), "Wrotation");
  t = replace("OFFSET 0 -7 0", "OFFSET 0 seven 0");
  ExpectErrorAt(t, LineOf(t, "seven"), "seven");
  t = replace("Frames: 3", "Frames: 4");
  ExpectErrorAt(t, LineOf(t, "Frame Time") + 3, "Frames: announced 4");
  // a frame line with one value too few
  size_t last = good.rfind(' ', good.size() - 2);
  t = good.substr(0, last) + "\n";
  ExpectErrorAt(t, LineOf(t, "Frame Time") + 3, "channels");
  t = replace("End Site", "End Sight");
  ExpectErrorAt(t, LineOf(t, "End Sight"), "Site");
}

// found by tests/fuzz/bvh_fuzz: the message cast a huge channel count to int (undefined)
TEST(Bvh, MalformedChannelCountIsAnErrorNamingTheCount) {
  std::string t = ThreeFrames();
  t.replace(t.find("CHANNELS 6"), 10, "CHANNELS 888888888888888888");
  ExpectErrorAt(t, LineOf(t, "CHANNELS 888"), "has 8.88889e+17 channels; valid: 6");
}

// a hierarchy nested 20000 joints deep overflowed the stack of the recursive parse (ASan
// stack-overflow); now refused at the first joint below the limit
TEST(Bvh, MalformedDeepNestingIsAnErrorNotAStackOverflow) {
  std::string t =
      "HIERARCHY\nROOT a0\n{\nOFFSET 0 0 0\n"
      "CHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation Zrotation\n";
  for (int i = 1; i < 20000; ++i) {
    t += "JOINT a" + std::to_string(i) +
         "\n{\nOFFSET 0 0 0\nCHANNELS 3 Xrotation Yrotation "
         "Zrotation\n";
  }
  ExpectErrorAt(t, LineOf(t, "JOINT a256\n"), "joints nested deeper than 256 levels");
}

TEST(Bvh, MissingJointsAreListed) {
  std::string t = ThreeFrames();
  // rename LeftFoot: the retargeter must say which joint it needs
  t.replace(t.find("LeftFoot"), 8, "LeftPaw");
  auto bvh = ParseBvh(t, "paw.bvh");
  ASSERT_TRUE(bvh.ok()) << bvh.status();
  auto clip = RetargetBvh(*bvh, "paw.bvh");
  ASSERT_FALSE(clip.ok());
  std::string msg(clip.status().message());
  EXPECT_NE(msg.find("paw.bvh"), std::string::npos) << msg;
  EXPECT_NE(msg.find("leftfoot"), std::string::npos) << msg;
}

}  // namespace
}  // namespace simhuman::learn
