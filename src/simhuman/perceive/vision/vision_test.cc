#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <random>

#include "simhuman/core/testing_temp.h"
#include "simhuman/perceive/vision/associate.h"
#include "simhuman/perceive/vision/detect.h"
#include "simhuman/perceive/vision/head_camera.h"
#include "simhuman/perceive/vision/vision_model.h"

namespace simhuman::perceive {
namespace {

TEST(PinholeCameraTest, RaysAndProjectionsInvertEachOther) {
  const PinholeCamera c = LookAt({0.3, 0.1, 1.25}, {0.9, -0.1, 0.75}, 60, 160, 120);
  EXPECT_NEAR(c.forward.norm(), 1, 1e-12);
  EXPECT_NEAR(c.right.z(), 0, 1e-12);  // no roll
  EXPECT_NEAR(c.forward.dot(c.up), 0, 1e-12);
  EXPECT_LT(c.Pitch(), 0);  // looking down
  for (double u : {0.0, 17.5, 80.0, 159.0}) {
    for (double v : {0.0, 60.0, 119.5}) {
      double pu, pv;
      ASSERT_TRUE(c.Project(c.eye + 0.7 * c.Ray(u, v), &pu, &pv));
      EXPECT_NEAR(pu, u, 1e-9);
      EXPECT_NEAR(pv, v, 1e-9);
    }
  }
  // the gaze point is the image centre; a point to the camera's right is right of it
  double u, v;
  ASSERT_TRUE(c.Project({0.9, -0.1, 0.75}, &u, &v));
  EXPECT_NEAR(u, 80, 1e-9);
  EXPECT_NEAR(v, 60, 1e-9);
  ASSERT_TRUE(c.Project(Eigen::Vector3d(0.9, -0.1, 0.75) + 0.1 * c.right, &u, &v));
  EXPECT_GT(u, 80);
  EXPECT_FALSE(c.Project(c.eye - c.forward, &u, &v));
  // level frame: forward along the ground is +x, left +y, up +z; and back
  const Eigen::Vector3d w(0.2, -0.3, 0.4);
  EXPECT_TRUE(c.FromLevel(c.ToLevel(w)).isApprox(w, 1e-12));
  EXPECT_NEAR(c.ToLevel(c.forward).y(), 0, 1e-12);
  EXPECT_GT(c.ToLevel(c.forward).x(), 0);
}

// a frame of `w` x `h` background with filled rectangles of given colours
std::vector<uint8_t> Frame(int w, int h, const std::vector<std::array<int, 7>>& rects) {
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3, 0);
  for (size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = 140;
    rgb[i + 1] = 90;
    rgb[i + 2] = 50;  // a brown table
  }
  for (const auto& r : rects) {  // x0 y0 x1 y1 (exclusive) r g b
    for (int y = r[1]; y < r[3]; ++y) {
      for (int x = r[0]; x < r[2]; ++x) {
        uint8_t* p = &rgb[3 * (static_cast<size_t>(y) * w + x)];
        p[0] = static_cast<uint8_t>(r[4]);
        p[1] = static_cast<uint8_t>(r[5]);
        p[2] = static_cast<uint8_t>(r[6]);
      }
    }
  }
  return rgb;
}

ColourTable RedBlueTable() {
  ColourTable t;
  const uint8_t brown[3] = {140, 90, 50}, red[3] = {200, 30, 30}, blue[3] = {40, 80, 200};
  for (int i = 0; i < 10; ++i) {
    t.Add(brown, 0);
    t.Add(red, 1);
    t.Add(blue, 4);
  }
  t.Add(red, 0);  // one stray label does not outvote ten
  t.Finish();
  return t;
}

TEST(DetectTest, ColourTableLearnsTheMajorityAndRejectsBadLabels) {
  const ColourTable t = RedBlueTable();
  const uint8_t red[3] = {200, 30, 30}, blue[3] = {40, 80, 200}, unseen[3] = {0, 255, 0};
  EXPECT_EQ(t.Classify(red), 1);
  EXPECT_EQ(t.Classify(blue), 4);
  EXPECT_EQ(t.Classify(unseen), 0);
  ColourTable u;
  EXPECT_FALSE(u.SetLabels(std::vector<uint8_t>(10, 0)).ok());
  std::vector<uint8_t> labels(ColourTable::kCells, 0);
  labels[5] = 7;
  const core::Status s = u.SetLabels(labels);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(std::string(s.message()).find("7"), std::string::npos);
}

TEST(DetectTest, BlobsAreConnectedRegionsOfOneColourLargestFirst) {
  // two red squares apart, a blue one touching the second red one, a tiny red speck
  const std::vector<uint8_t> rgb = Frame(40, 30,
                                         {{{2, 2, 8, 8, 200, 30, 30},
                                           {20, 10, 30, 20, 200, 30, 30},
                                           {30, 10, 36, 20, 40, 80, 200},
                                           {0, 28, 1, 29, 200, 30, 30}}});
  const std::vector<Blob> blobs = FindBlobs(rgb, 40, 30, RedBlueTable(), 4);
  ASSERT_EQ(blobs.size(), 3u);
  EXPECT_EQ(blobs[0].pixels, 100);
  EXPECT_EQ(blobs[0].colour, 0);
  EXPECT_EQ(blobs[0].x0, 20);
  EXPECT_EQ(blobs[0].x1, 29);
  EXPECT_NEAR(blobs[0].cu, 25.0, 1e-9);
  EXPECT_NEAR(blobs[0].cv, 15.0, 1e-9);
  EXPECT_EQ(blobs[1].colour, 3);  // blue
  EXPECT_EQ(blobs[1].pixels, 60);
  EXPECT_EQ(blobs[2].pixels, 36);
}

TEST(AssociateTest, HungarianMatchesBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const int rows = 1 + trial % 5, cols = 1 + (trial / 5) % 5;
    std::vector<std::vector<double>> c(rows, std::vector<double>(cols));
    for (auto& r : c) {
      for (double& x : r) x = uni(rng);
    }
    const std::vector<int> a = HungarianAssign(c);
    ASSERT_EQ(static_cast<int>(a.size()), rows);
    double got = 0;
    std::vector<int> used;
    for (int r = 0; r < rows; ++r) {
      if (a[r] < 0) continue;
      got += c[r][a[r]];
      used.push_back(a[r]);
    }
    std::sort(used.begin(), used.end());
    EXPECT_EQ(std::unique(used.begin(), used.end()), used.end());
    EXPECT_EQ(static_cast<int>(used.size()), std::min(rows, cols));
    // brute force over column permutations
    std::vector<int> perm(std::max(rows, cols));
    std::iota(perm.begin(), perm.end(), 0);
    double best = 1e9;
    do {
      double s = 0;
      for (int r = 0; r < rows; ++r) {
        if (perm[r] < cols) s += c[r][perm[r]];
      }
      best = std::min(best, s);
    } while (std::next_permutation(perm.begin(), perm.end()));
    EXPECT_NEAR(got, best, 1e-9) << rows << "x" << cols;
  }
}

TEST(AssociateTest, TrackerKeepsIdentitiesAndRefusesFarMatches) {
  ObjectEstimate a, b;
  a.centre = {0.8, 0.0, 0.8};
  a.colour = 0;
  b.centre = {0.9, 0.2, 0.8};
  b.colour = 3;
  ObjectTracker t;
  t.Reset({a, b});
  // the next frame lists them the other way round, the red one moved 4 cm (lifted)
  ObjectEstimate a2 = a, far = b;
  a2.centre.z() += 0.04;
  far.centre = {2.0, 2.0, 0.8};
  t.Update({b, a2});
  EXPECT_NEAR(t.objects()[0].centre.z(), 0.84, 1e-12);
  EXPECT_EQ(t.objects()[1].colour, 3);
  // a blue estimate far away is not the blue object: it keeps its last estimate, unseen
  t.Update({a2, far});
  EXPECT_NEAR(t.objects()[1].centre.x(), 0.9, 1e-12);
  EXPECT_EQ(t.unseen_frames()[1], 1);
  EXPECT_EQ(t.unseen_frames()[0], 0);
}

TEST(VisionModelTest, SavesLoadsAndNamesBadFiles) {
  auto m = VisionModel::Create(5);
  m->colours() = RedBlueTable();
  m->width = 40;
  m->height = 30;
  m->fovy_deg = 50;
  const std::string path = core::testing::UniqueTempPath("vision.pt");
  ASSERT_TRUE(m->Save(path).ok());
  auto back = VisionModel::Load(path);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ((*back)->width, 40);
  EXPECT_DOUBLE_EQ((*back)->fovy_deg, 50);
  // the same estimates from both
  const std::vector<uint8_t> rgb = Frame(40, 30, {{{10, 10, 20, 20, 200, 30, 30}}});
  const PinholeCamera cam = LookAt({0, 0, 1.25}, {0.6, 0, 0.75}, 50, 40, 30);
  const auto e1 = m->Estimate(rgb, cam), e2 = (*back)->Estimate(rgb, cam);
  ASSERT_EQ(e1.size(), e2.size());
  for (size_t i = 0; i < e1.size(); ++i) EXPECT_TRUE(e1[i].centre.isApprox(e2[i].centre, 1e-6));

  std::remove(path.c_str());
  auto missing = VisionModel::Load(core::testing::UniqueTempPath("none.pt"));
  EXPECT_TRUE(absl::IsNotFound(missing.status()));
  const std::string junk = core::testing::UniqueTempPath("junk.pt");
  std::ofstream(junk) << "not a model";
  auto bad = VisionModel::Load(junk);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(std::string(bad.status().message()).find(junk), std::string::npos);
  std::remove(junk.c_str());
}

TEST(VisionModelTest, TrainingLowersThePositionErrorIntegration) {
  // blobs of a red square at varying places; the answer is a function of the ray: the network
  // must learn it (a smoke test of the losses, the decoding and the optimiser)
  const PinholeCamera cam = LookAt({0, 0, 1.25}, {0.6, 0, 0.75}, 50, 40, 30);
  std::vector<BlobSample> samples;
  std::mt19937 rng(1);
  for (int i = 0; i < 250; ++i) {
    const int x = static_cast<int>(rng() % 30), y = static_cast<int>(rng() % 20);
    const std::vector<uint8_t> rgb = Frame(40, 30, {{{x, y, x + 8, y + 8, 200, 30, 30}}});
    const std::vector<Blob> blobs = FindBlobs(rgb, 40, 30, RedBlueTable(), 4);
    ASSERT_EQ(blobs.size(), 1u);
    BlobSample s = MakeBlobSample(rgb, cam, blobs[0]);
    s.shape = 0;
    s.rel = 0.9 * s.ray;  // 0.9 m along its ray
    s.up = Eigen::Vector3d::UnitZ();
    s.height_m = 0.15;
    s.width_m = 0.08;
    samples.push_back(s);
  }
  auto m = VisionModel::Create(2);
  const VisionLosses before = m->Evaluate(samples);
  for (int e = 0; e < 12; ++e) m->TrainEpoch(samples, 64, 2e-3, e);
  const VisionLosses after = m->Evaluate(samples);
  EXPECT_LT(after.position_cm, 0.3 * before.position_cm);
  EXPECT_LT(after.position_cm, 3.0);
  EXPECT_LT(after.shape, 0.5 * before.shape);
}

}  // namespace
}  // namespace simhuman::perceive
