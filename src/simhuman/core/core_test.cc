#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <string>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/geometry.h"
#include "simhuman/core/json_io.h"
#include "simhuman/core/rng.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/testing_temp.h"
#include "simhuman/core/version.h"

namespace simhuman::core {
namespace {

constexpr double kTol = 1e-9;

Shape MakeBox(const Eigen::Vector3d& half, const Eigen::Vector3d& pos) {
  Shape s;
  s.kind = ShapeKind::kBox;
  s.size = half;
  s.pose.pos = pos;
  return s;
}

TEST(GeometryTest, NearestPointOnABoxAtAYawedPose) {
  Shape box = MakeBox({0.5, 0.2, 0.1}, {0, 0, 0.4});
  Pose obj = Pose::FromYaw({1, 2, 0}, M_PI / 2);  // object x axis along world +y
  // a point 0.3 m above the top face centre
  Eigen::Vector3d np = NearestPointOnShape(box, obj, {1, 2, 0.8});
  EXPECT_NEAR((np - Eigen::Vector3d(1, 2, 0.5)).norm(), 0.0, kTol);
  // beyond the long end (object +x = world +y): clamped to the end face
  np = NearestPointOnShape(box, obj, {1, 3, 0.4});
  EXPECT_NEAR((np - Eigen::Vector3d(1, 2.5, 0.4)).norm(), 0.0, kTol);
  // inside: the point itself
  np = NearestPointOnShape(box, obj, {1.05, 2.1, 0.42});
  EXPECT_NEAR((np - Eigen::Vector3d(1.05, 2.1, 0.42)).norm(), 0.0, kTol);
}

TEST(GeometryTest, NearestPointOnSphereCapsuleCylinder) {
  Shape sphere;
  sphere.kind = ShapeKind::kSphere;
  sphere.size = {0.1, 0, 0};
  EXPECT_NEAR(NearestPointOnShape(sphere, Pose(), {0, 0, 1}).z(), 0.1, kTol);
  Shape capsule;
  capsule.kind = ShapeKind::kCapsule;
  capsule.size = {0.05, 0.2, 0};
  EXPECT_NEAR(NearestPointOnShape(capsule, Pose(), {0, 0, 1}).z(), 0.25, kTol);
  EXPECT_NEAR(NearestPointOnShape(capsule, Pose(), {1, 0, 0.1}).x(), 0.05, kTol);
  Shape cyl;
  cyl.kind = ShapeKind::kCylinder;
  cyl.size = {0.17, 0.02, 0};
  Eigen::Vector3d np = NearestPointOnShape(cyl, Pose(), {1, 0, 1});
  EXPECT_NEAR(np.x(), 0.17, kTol);
  EXPECT_NEAR(np.z(), 0.02, kTol);
}

TEST(GeometryTest, UnionTakesTheClosestShape) {
  std::vector<Shape> shapes = {MakeBox({0.1, 0.1, 0.1}, {0, 0, 0}),
                               MakeBox({0.1, 0.1, 0.1}, {1, 0, 0})};
  Eigen::Vector3d np = NearestPointOnShapes(shapes, Pose(), {0.8, 0, 0});
  EXPECT_NEAR(np.x(), 0.9, kTol);
}

TEST(GeometryTest, SurfaceSamplesLieOnTheSurfaceAndCoverIt) {
  Shape box = MakeBox({0.3, 0.2, 0.05}, {0, 0, 0.5});
  std::vector<Eigen::Vector3d> pts = SampleShapeSurface(box, 0.02);
  ASSERT_GT(pts.size(), 100u);
  double max_top = -1;
  for (const auto& p : pts) {
    Eigen::Vector3d l = p - box.pose.pos;
    // on at least one face
    bool on_face = std::abs(std::abs(l.x()) - 0.3) < 1e-9 ||
                   std::abs(std::abs(l.y()) - 0.2) < 1e-9 ||
                   std::abs(std::abs(l.z()) - 0.05) < 1e-9;
    EXPECT_TRUE(on_face);
    max_top = std::max(max_top, p.z());
  }
  EXPECT_NEAR(max_top, 0.55, kTol);
  // deterministic
  EXPECT_EQ(SampleShapeSurface(box, 0.02).size(), pts.size());
}

TEST(GeometryTest, BoundsOfRotatedShapes) {
  Shape box = MakeBox({0.5, 0.1, 0.1}, {0, 0, 0});
  box.pose.quat = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  auto [lo, hi] = ShapesBounds({box});
  EXPECT_NEAR(hi.y(), 0.5, kTol);
  EXPECT_NEAR(hi.x(), 0.1, kTol);
}

TEST(RngTest, DerivedSeedsAreDeterministicAndDistinct) {
  EXPECT_EQ(DeriveSeed(1, 2, 3), DeriveSeed(1, 2, 3));
  EXPECT_NE(DeriveSeed(1, 2, 3), DeriveSeed(1, 3, 2));
  EXPECT_NE(DeriveSeed(1, 0), DeriveSeed(2, 0));
  Rng a(7), b(7);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(a.Uniform(), b.Uniform());
}

TEST(BodyJointTest, NamesRoundTrip) {
  for (BodyJoint j : AllBodyJoints()) {
    EXPECT_EQ(ParseBodyJoint(BodyJointName(j)), j);
  }
  EXPECT_EQ(ParseBodyJoint("Left_Hand"), BodyJoint::kLeftHand);
  EXPECT_FALSE(ParseBodyJoint("left paw").has_value());
  EXPECT_EQ(BodyJointNames().size(), static_cast<size_t>(kNumBodyJoints));
}

TEST(SceneCatalogTest, NormalizeNameStripsScenePlanDigits) {
  EXPECT_EQ(NormalizeName("Seat_Soft_Surface42"), "seat soft surface");
  EXPECT_EQ(NormalizeName("mattress25"), "mattress");
  EXPECT_EQ(NormalizeName("  pillow "), "pillow");
}

TEST(JsonIoTest, SyntaxErrorsNameLineAndColumn) {
  auto r = ParseJson("{\n  \"a\": 1,\n  \"b\": ]\n}", "plan.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("plan.json:3:"), std::string::npos) << r.status();
}

TEST(JsonIoTest, HugeNumbersAreAnErrorNotACrash) {
  auto r = ParseJson("{\"a\": 1e999}", "x.json");
  EXPECT_FALSE(r.ok());
}

TEST(JsonIoTest, MissingFileAndStrictKeys) {
  auto r = ReadJsonFile("/nonexistent/simhuman.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("/nonexistent/simhuman.json"), std::string::npos);
  nlohmann::json j = {{"a", 1}, {"zz", 2}};
  absl::Status st = CheckKeys(j, {"a", "b"}, "/cfg");
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("zz"), std::string::npos);
  EXPECT_NE(st.message().find("a, b"), std::string::npos);
  EXPECT_FALSE(GetNumber(nlohmann::json{{"x", "1"}}, "x", "/cfg").ok());
  EXPECT_TRUE(GetNumber(nlohmann::json{{"x", 1.5}}, "x", "/cfg").ok());
}

TEST(JsonIoTest, AtomicWriteReplacesTheFile) {
  std::string path = core::testing::UniqueTempPath("simhuman_atomic.txt");
  ASSERT_TRUE(WriteFileAtomic(path, "one").ok());
  ASSERT_TRUE(WriteFileAtomic(path, "two").ok());
  auto r = ReadFile(path);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(*r, "two");
  std::remove(path.c_str());
}

TEST(VersionTest, GitRevisionIsAnAbbreviatedHashOrUnknown) {
  const std::string rev(GitRevision());
  EXPECT_TRUE(std::regex_match(rev, std::regex("[0-9a-f]{7,40}(-dirty)?|unknown"))) << rev;
}

}  // namespace
}  // namespace simhuman::core
