#include "simhuman/render/auto_camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "simhuman/world/sim_world.h"

namespace simhuman::render {
namespace {

// a person-sized capsule at the origin with five points (head, hands, feet), and a wall 1.5 m
// away on the +x side, 4 m tall: every view from +x is blocked, every view from -x is clear
constexpr char kXml[] = R"(
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="10 10 0.1"/>
    <body name="person" pos="0 0 0">
      <geom type="capsule" fromto="0 0 0.2 0 0 1.5" size="0.2"/>
      <site name="head" pos="0 0 1.6"/>
      <site name="left_hand" pos="0 0.35 1.0"/>
      <site name="right_hand" pos="0 -0.35 1.0"/>
      <site name="left_foot" pos="0 0.1 0.05"/>
      <site name="right_foot" pos="0 -0.1 0.05"/>
    </body>
    <body name="wall" pos="1.5 0 2">
      <geom type="box" size="0.05 6 2"/>
    </body>
  </worldbody>
</mujoco>)";

class AutoCameraTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto m = world::SimWorld::CompileXml(kXml);
    ASSERT_TRUE(m.ok()) << m.status();
    m_ = *m;
    d_ = mj_makeData(m_);
    mj_kinematics(m_, d_);
    person_ = mj_name2id(m_, mjOBJ_BODY, "person");
    for (const char* s : {"head", "left_hand", "right_hand", "left_foot", "right_foot"}) {
      sites_.push_back(mj_name2id(m_, mjOBJ_SITE, s));
      points_.emplace_back(d_->site_xpos + 3 * sites_.back());
    }
    subject_.assign(m_->nbody, 0);
    subject_[person_] = 1;
  }
  void TearDown() override {
    mj_deleteData(d_);
    mj_deleteModel(m_);
  }
  mjModel* m_ = nullptr;
  mjData* d_ = nullptr;
  int person_ = -1;
  std::vector<int> sites_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<char> subject_;
};

TEST_F(AutoCameraTest, CameraPositionMatchesMujocosFreeCamera) {
  CameraSpec spec;
  spec.lookat = Eigen::Vector3d(1, 2, 1);
  spec.distance_m = 4;
  spec.azimuth_deg = 90;  // looks along +y: the camera is on -y
  spec.elevation_deg = -30;
  const Eigen::Vector3d eye = CameraPosition(spec);
  EXPECT_NEAR(eye.x(), 1, 1e-9);
  EXPECT_NEAR(eye.y(), 2 - 4 * std::cos(M_PI / 6), 1e-9);
  EXPECT_NEAR(eye.z(), 1 + 4 * std::sin(M_PI / 6), 1e-9);
  // MuJoCo agrees: mjv_updateScene puts its free camera there
  mjvCamera cam;
  ToMjvCamera(spec, &cam);
  mjvOption opt;
  mjv_defaultOption(&opt);
  mjvScene scn;
  mjv_defaultScene(&scn);
  mjv_makeScene(m_, &scn, 100);
  mjv_updateScene(m_, d_, &opt, nullptr, &cam, mjCAT_ALL, &scn);
  // (its two eyes sit half the inter-pupillary distance to either side)
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(0.5 * (scn.camera[0].pos[k] + scn.camera[1].pos[k]), eye[k], 1e-4) << k;
  }
  mjv_freeScene(&scn);
}

TEST_F(AutoCameraTest, VisibleFractionSeesTheWall) {
  CameraSpec from_minus_x;  // azimuth 0 looks along +x: the camera is on -x, the clear side
  from_minus_x.lookat = Eigen::Vector3d(0, 0, 0.9);
  from_minus_x.distance_m = 3.5;
  from_minus_x.azimuth_deg = 0;
  from_minus_x.elevation_deg = -15;
  EXPECT_DOUBLE_EQ(VisibleFraction(m_, d_, from_minus_x, points_, {}, subject_), 1.0);
  CameraSpec from_plus_x = from_minus_x;  // behind the wall
  from_plus_x.azimuth_deg = 180;
  EXPECT_DOUBLE_EQ(VisibleFraction(m_, d_, from_plus_x, points_, {}, subject_), 0.0);
  // the subject's own body never hides its points; the wall would if it were the subject
  std::vector<char> wall_is_subject(m_->nbody, 0);
  wall_is_subject[mj_name2id(m_, mjOBJ_BODY, "wall")] = 1;
  EXPECT_DOUBLE_EQ(VisibleFraction(m_, d_, from_plus_x, points_, {}, wall_is_subject), 1.0);
}

TEST_F(AutoCameraTest, AvoidsTheWallAndHoldsItsChoice) {
  AutoCameraOptions o;
  o.smooth_s = 0;  // the raw choice
  // the subject faces +x (0): its front is seen from +x, behind the wall
  AutoCamera camera(m_, {person_}, sites_, {}, o);
  const CameraSpec first = camera.Update(d_, 0.0, 1.0 / 30);
  EXPECT_DOUBLE_EQ(camera.last_score().visible, 1.0);
  EXPECT_DOUBLE_EQ(VisibleFraction(m_, d_, first, points_, {}, subject_), 1.0);
  EXPECT_LT(CameraPosition(first).x(), 1.5);
  // the same scene a few frames on: the same direction (no jumps without a reason)
  CameraSpec later = first;
  for (int f = 0; f < 20; ++f) later = camera.Update(d_, 0.0, 1.0 / 30);
  EXPECT_NEAR(later.azimuth_deg, first.azimuth_deg, 1e-9);
  EXPECT_NEAR(later.elevation_deg, first.elevation_deg, 1e-9);
}

TEST_F(AutoCameraTest, PrefersTheFrontWhenNothingIsInTheWay) {
  AutoCameraOptions o;
  o.smooth_s = 0;
  o.preferred_side_deg = 0;
  // facing -x (180): the preferred camera stands on -x, looking along +x (azimuth 0), clear
  AutoCamera camera(m_, {person_}, sites_, {}, o);
  const CameraSpec cam = camera.Update(d_, 180.0, 1.0 / 30);
  EXPECT_NEAR(std::remainder(cam.azimuth_deg, 360.0), 0.0, 1e-9);
  EXPECT_NEAR(cam.elevation_deg, o.preferred_elevation_deg, 3.0);
}

}  // namespace
}  // namespace simhuman::render
