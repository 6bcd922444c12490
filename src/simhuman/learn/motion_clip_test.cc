#include "simhuman/learn/motion_clip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "simhuman/core/rng.h"
#include "simhuman/core/testing_temp.h"

namespace simhuman::learn {
namespace {

namespace fs = std::filesystem;

std::string TempPath(const std::string& name) {
  return core::testing::UniqueTempPath("clip_test_" + name);
}

MotionClip RandomClip(int frames, uint64_t seed) {
  core::Rng rng(seed);
  MotionClip c;
  c.fps = 30;
  c.source = "test";
  for (int f = 0; f < frames; ++f) {
    ClipFrame fr;
    for (double& v : fr.root_pos_m) v = rng.Uniform(-2, 2);
    double n = 0;
    for (double& v : fr.root_quat_wxyz) {
      v = rng.Normal();
      n += v * v;
    }
    for (double& v : fr.root_quat_wxyz) v /= std::sqrt(n);
    for (double& v : fr.q_rad) v = rng.Uniform(-1, 1) / 3.0;
    c.frames.push_back(fr);
  }
  return c;
}

// a valid clip file with one field replaced (or removed when `value` is null)
std::string ClipText(const std::string& key, const nlohmann::json& value) {
  nlohmann::json j = nlohmann::json::parse(MotionClipToJson(RandomClip(2, 1)));
  if (value.is_null()) {
    j.erase(key);
  } else {
    j[key] = value;
  }
  return j.dump();
}

TEST(MotionClip, RoundTripIsExact) {
  MotionClip c = RandomClip(5, 7);
  std::string path = TempPath("rt.clip.json");
  ASSERT_TRUE(SaveMotionClip(c, path).ok());
  auto back = LoadMotionClip(path);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->fps, c.fps);
  EXPECT_EQ(back->source, c.source);
  ASSERT_EQ(back->frames.size(), c.frames.size());
  for (size_t f = 0; f < c.frames.size(); ++f) {
    EXPECT_EQ(back->frames[f].root_pos_m, c.frames[f].root_pos_m);
    EXPECT_EQ(back->frames[f].root_quat_wxyz, c.frames[f].root_quat_wxyz);
    EXPECT_EQ(back->frames[f].q_rad, c.frames[f].q_rad);
  }
  fs::remove(path);
}

TEST(MotionClip, StrictErrorsNameFileAndField) {
  auto err = [](const std::string& text) {
    auto c = ParseMotionClip(text, "malformed_x.clip.json");
    EXPECT_FALSE(c.ok());
    std::string msg(c.status().message());
    EXPECT_NE(msg.find("malformed_x.clip.json"), std::string::npos) << msg;
    return msg;
  };
  EXPECT_NE(err(ClipText("speed", 3)).find("speed"), std::string::npos);
  EXPECT_NE(err(ClipText("fps", nullptr)).find("/fps"), std::string::npos);
  EXPECT_NE(err(ClipText("fps", -1)).find("/fps"), std::string::npos);
  EXPECT_NE(err(ClipText("format", "clip-v0")).find("/format"), std::string::npos);
  nlohmann::json names = world::HumanoidJointNames();
  names[5] = "neck_q";
  EXPECT_NE(err(ClipText("joints", names)).find("/joints/5"), std::string::npos);
  nlohmann::json frames = nlohmann::json::parse(ClipText("fps", 30))["frames"];
  nlohmann::json short_row = frames;
  short_row[1].erase(short_row[1].begin());
  EXPECT_NE(err(ClipText("frames", short_row)).find("/frames/1"), std::string::npos);
  nlohmann::json bad_quat = frames;
  bad_quat[0][3] = 2.0;
  EXPECT_NE(err(ClipText("frames", bad_quat)).find("/frames/0"), std::string::npos);
  nlohmann::json text_value = frames;
  text_value[1][9] = "x";
  EXPECT_NE(err(ClipText("frames", text_value)).find("/frames/1/9"), std::string::npos);
  EXPECT_NE(err("{\"fps\": ").find("malformed_x"), std::string::npos);
  EXPECT_EQ(LoadMotionClip(TempPath("missing.clip.json")).status().code(),
            absl::StatusCode::kNotFound);
}

TEST(MotionClip, ResampleInterpolates) {
  constexpr double kTol = 1e-12;
  MotionClip c;
  c.fps = 10;
  ClipFrame a, b;
  a.root_pos_m = {0, 0, 1};
  b.root_pos_m = {1, 2, 1};
  a.q_rad[3] = 0.2;
  b.q_rad[3] = 0.6;
  b.root_quat_wxyz = {std::cos(0.5), 0, 0, std::sin(0.5)};  // yaw 1 rad
  c.frames = {a, b};
  auto r = ResampleClip(c, 40);
  ASSERT_TRUE(r.ok()) << r.status();
  ASSERT_EQ(r->frames.size(), 5u);  // 0.1 s at 40 fps
  EXPECT_NEAR(r->duration_s(), c.duration_s(), kTol);
  const ClipFrame& mid = r->frames[2];
  EXPECT_NEAR(mid.root_pos_m[0], 0.5, kTol);
  EXPECT_NEAR(mid.root_pos_m[1], 1.0, kTol);
  EXPECT_NEAR(mid.q_rad[3], 0.4, kTol);
  EXPECT_NEAR(mid.root_quat_wxyz[0], std::cos(0.25), 1e-9);  // half the yaw
  EXPECT_NEAR(mid.root_quat_wxyz[3], std::sin(0.25), 1e-9);
  EXPECT_FALSE(ResampleClip(c, 0).ok());
}

// malformed_tiny_fps: a valid clip at fps 1e-300 lasts 1e300 s; resampling it cast 3e301 to
// size_t (undefined), and at fps 1e-6 it asked for 17 GB (found with tests/fuzz/motion_clip_fuzz)
TEST(MotionClip, MalformedTinyFpsIsAnErrorWhenResampled) {
  for (double fps : {1e-300, 1e-6}) {
    auto c = ParseMotionClip(ClipText("fps", fps), "malformed_tiny_fps.clip.json");
    ASSERT_TRUE(c.ok()) << c.status();  // the file itself is valid
    auto r = ResampleClip(*c, 30);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.status().message().find("more than 1000000"), std::string::npos) << r.status();
  }
}

}  // namespace
}  // namespace simhuman::learn
