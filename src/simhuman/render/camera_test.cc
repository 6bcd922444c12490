#include "simhuman/render/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "simhuman/render/test_scene.h"

namespace simhuman::render {
namespace {

constexpr double kTol = 1e-9;

class CameraTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    m_ = testing::LoadTestScene(::testing::TempDir(), &error);
    ASSERT_NE(m_, nullptr) << error;
    d_ = mj_makeData(m_);
    mj_forward(m_, d_);
  }
  void TearDown() override {
    mj_deleteData(d_);
    mj_deleteModel(m_);
  }
  mjModel* m_ = nullptr;
  mjData* d_ = nullptr;
};

TEST_F(CameraTest, FrameOneBodyLooksAtItsCentre) {
  const int box = mj_name2id(m_, mjOBJ_BODY, "box");
  const CameraSpec cam = FrameBodies(m_, d_, {box}, 30, -20, 1.0);
  EXPECT_NEAR(cam.lookat.x(), 0, kTol);
  EXPECT_NEAR(cam.lookat.y(), 0, kTol);
  EXPECT_NEAR(cam.lookat.z(), 0.25, kTol);
  EXPECT_EQ(cam.azimuth_deg, 30);
  EXPECT_EQ(cam.elevation_deg, -20);
  // the box's bounding sphere (radius sqrt(3)*0.25) fills the vertical field of view
  const double r = m_->geom_rbound[mj_name2id(m_, mjOBJ_GEOM, "box")];
  const double half_fovy = 0.5 * m_->vis.global.fovy * M_PI / 180;
  // the bounding box of the sphere has half-diagonal sqrt(3) * r
  EXPECT_NEAR(cam.distance_m, std::sqrt(3.0) * r / std::sin(half_fovy), 1e-6);
}

TEST_F(CameraTest, MarginAndAspectScaleDistance) {
  const int box = mj_name2id(m_, mjOBJ_BODY, "box");
  const CameraSpec tight = FrameBodies(m_, d_, {box}, 0, -20, 1.0);
  const CameraSpec loose = FrameBodies(m_, d_, {box}, 0, -20, 1.5);
  EXPECT_NEAR(loose.distance_m, 1.5 * tight.distance_m, 1e-9);
  // a portrait image has a narrower horizontal view: the camera steps back
  const CameraSpec portrait = FrameBodies(m_, d_, {box}, 0, -20, 1.0, 0.5);
  EXPECT_GT(portrait.distance_m, tight.distance_m);
}

TEST_F(CameraTest, FrameTwoBodiesCoversBoth) {
  const int box = mj_name2id(m_, mjOBJ_BODY, "box");
  const int ball = mj_name2id(m_, mjOBJ_BODY, "ball");
  const CameraSpec both = FrameBodies(m_, d_, {box, ball}, 90, -20, 1.0);
  // box spans x in [-0.43, 0.43] (bounding sphere), ball x in [0.7, 1.1]
  EXPECT_GT(both.lookat.x(), 0.2);
  EXPECT_LT(both.lookat.x(), 0.5);
  // empty list: every body but the world, the floor plane ignored
  const CameraSpec all = FrameBodies(m_, d_, {}, 90, -20, 1.0);
  EXPECT_NEAR((all.lookat - both.lookat).norm(), 0, kTol);
  EXPECT_NEAR(all.distance_m, both.distance_m, kTol);
}

TEST(CameraSmootherTest, SnapsThenFollowsExponentially) {
  CameraSmoother smoother(0.5);
  CameraSpec a;
  a.lookat = Eigen::Vector3d(0, 0, 1);
  a.distance_m = 2;
  EXPECT_EQ(smoother.Update(a, 0.1).lookat, a.lookat);

  CameraSpec b = a;
  b.lookat = Eigen::Vector3d(1, 0, 1);
  b.distance_m = 4;
  const CameraSpec s = smoother.Update(b, 0.5);  // one time constant: 1 - 1/e of the way
  const double frac = 1 - std::exp(-1.0);
  EXPECT_NEAR(s.lookat.x(), frac, 1e-12);
  EXPECT_NEAR(s.distance_m, 2 + 2 * frac, 1e-12);

  // converges
  CameraSpec last;
  for (int i = 0; i < 200; ++i) last = smoother.Update(b, 1.0 / 30);
  EXPECT_NEAR(last.lookat.x(), 1, 1e-6);

  smoother.Reset();
  EXPECT_EQ(smoother.Update(a, 0.1).distance_m, 2);
}

TEST(CameraSmootherTest, AzimuthTakesTheShortWayRound) {
  CameraSmoother smoother(1.0);
  CameraSpec a;
  a.azimuth_deg = 179;
  smoother.Update(a, 0.1);
  CameraSpec b;
  b.azimuth_deg = -179;
  const double az = smoother.Update(b, 1e6).azimuth_deg;  // fully converged
  EXPECT_NEAR(std::remainder(az - (-179), 360.0), 0, 1e-6);
  const double mid = CameraSmoother(1.0).Update(a, 0.1).azimuth_deg;
  EXPECT_EQ(mid, 179);
  CameraSmoother s2(1.0);
  s2.Update(a, 0.1);
  const double step = s2.Update(b, 1.0).azimuth_deg;
  EXPECT_GT(step, 179);  // went up through 180, not down through 0
  EXPECT_LT(step, 181);
}

TEST(CameraSmootherTest, ZeroTimeConstantDoesNotSmooth) {
  CameraSmoother smoother(0);
  CameraSpec a, b;
  b.distance_m = 9;
  smoother.Update(a, 0.1);
  EXPECT_EQ(smoother.Update(b, 0.01).distance_m, 9);
}

}  // namespace
}  // namespace simhuman::render
