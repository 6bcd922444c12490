#include "simhuman/render/offscreen.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "simhuman/core/testing_temp.h"
#include "simhuman/render/image_io.h"
#include "simhuman/render/test_scene.h"

namespace simhuman::render {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;

struct Pixel {
  int r, g, b;
};

Pixel At(const std::vector<uint8_t>& rgb, int w, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * w + x) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

// looks at the red box from the -y side, slightly from above: +x is to the right
CameraSpec BoxCamera() {
  CameraSpec cam;
  cam.lookat = Eigen::Vector3d(0, 0, 0.25);
  cam.distance_m = 2.5;
  cam.azimuth_deg = 90;
  cam.elevation_deg = -15;
  return cam;
}

class OffscreenTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    m_ = testing::LoadTestScene(::testing::TempDir(), &error);
    ASSERT_NE(m_, nullptr) << error;
    d_ = mj_makeData(m_);
    mj_forward(m_, d_);
  }
  void TearDown() override {
    // no MuJoCo warning may come out of rendering
    for (int i = 0; i < mjNWARNING; ++i) {
      EXPECT_EQ(d_->warning[i].number, 0) << "MuJoCo warning " << i;
    }
    mj_deleteData(d_);
    mj_deleteModel(m_);
  }

  // creates a renderer, or skips the test when this machine has no usable EGL
  std::unique_ptr<OffscreenRenderer> MakeRenderer(int w, int h,
                                                  const RendererOptions& options = {}) {
    auto r = OffscreenRenderer::Create(m_, w, h, options);
    if (absl::IsUnavailable(r.status())) {
      skip_reason_ = std::string(r.status().message());
      return nullptr;
    }
    EXPECT_TRUE(r.ok()) << r.status();
    return r.ok() ? std::move(r).value() : nullptr;
  }

  mjModel* m_ = nullptr;
  mjData* d_ = nullptr;
  std::string skip_reason_;
};

#define MAKE_RENDERER_OR_SKIP(var, ...)                                  \
  auto var = MakeRenderer(__VA_ARGS__);                                  \
  if (!skip_reason_.empty()) GTEST_SKIP() << "no EGL: " << skip_reason_; \
  ASSERT_NE(var, nullptr)

TEST_F(OffscreenTest, RendersBoxFloorAndBackground) {
  MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight);
  std::vector<uint8_t> rgb;
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &rgb).ok());
  ASSERT_EQ(rgb.size(), static_cast<size_t>(kWidth * kHeight * 3));

  // not uniform
  bool varied = false;
  for (size_t i = 3; i < rgb.size() && !varied; ++i) varied = rgb[i] != rgb[i % 3];
  EXPECT_TRUE(varied);

  // the box fills the centre: reddish
  const Pixel c = At(rgb, kWidth, kWidth / 2, kHeight / 2);
  EXPECT_GT(c.r, 100);
  EXPECT_GT(c.r, 2 * c.g);
  EXPECT_GT(c.r, 2 * c.b);

  // top row first: background (black, no skybox) at the top, lit floor at the bottom
  const Pixel top = At(rgb, kWidth, 2, 0);
  const Pixel bottom = At(rgb, kWidth, 2, kHeight - 1);
  EXPECT_LT(top.r + top.g + top.b, 30);
  EXPECT_GT(bottom.r + bottom.g + bottom.b, 100);

  // the blue ball is on +x, which is to the right when looking along +y
  int blue_left = 0, blue_right = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const Pixel p = At(rgb, kWidth, x, y);
      if (p.b > 80 && p.b > 2 * p.r && p.b > 2 * p.g) (x < kWidth / 2 ? blue_left : blue_right)++;
    }
  }
  EXPECT_EQ(blue_left, 0);
  EXPECT_GT(blue_right, 5);
}

TEST_F(OffscreenTest, SkyPaintsTheBackgroundOnlyAndKeepsTheCaption) {
  RendererOptions with_sky;
  with_sky.sky = true;
  MAKE_RENDERER_OR_SKIP(plain, kWidth, kHeight);
  MAKE_RENDERER_OR_SKIP(sky, kWidth, kHeight, with_sky);
  std::vector<uint8_t> a, b, c;
  ASSERT_TRUE(plain->Render(d_, BoxCamera(), &a).ok());
  ASSERT_TRUE(sky->Render(d_, BoxCamera(), &b).ok());
  // the background at the top is a light blue sky, no longer black
  const Pixel top = At(b, kWidth, 2, 0);
  EXPECT_GT(top.b, 150);
  EXPECT_GT(top.b, top.r);
  // the box and the floor are drawn as before
  const Pixel box_a = At(a, kWidth, kWidth / 2, kHeight / 2),
              box_b = At(b, kWidth, kWidth / 2, kHeight / 2);
  EXPECT_EQ(box_a.r, box_b.r);
  EXPECT_EQ(box_a.g, box_b.g);
  const Pixel floor_a = At(a, kWidth, 2, kHeight - 1), floor_b = At(b, kWidth, 2, kHeight - 1);
  EXPECT_NEAR(floor_a.r, floor_b.r, 2);
  // a caption goes over the sky: the top-left corner differs from the sky without one
  ASSERT_TRUE(sky->Render(d_, BoxCamera(), &c, "step 1/2").ok());
  int changed = 0;
  for (size_t i = 0; i < b.size(); ++i) changed += b[i] != c[i];
  EXPECT_GT(changed, 20);
}

TEST_F(OffscreenTest, CreateDestroyCreateAgain) {
  std::vector<uint8_t> first, second;
  {
    MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight);
    ASSERT_TRUE(r->Render(d_, BoxCamera(), &first).ok());
  }
  {
    MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight);
    ASSERT_TRUE(r->Render(d_, BoxCamera(), &second).ok());
  }
  EXPECT_EQ(first, second);
}

TEST_F(OffscreenTest, TwoRenderersAtOnce) {
  MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight);
  std::vector<uint8_t> before, after, small;
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &before).ok());
  {
    // another renderer of another size, alive at the same time and destroyed first
    MAKE_RENDERER_OR_SKIP(r2, 32, 32);
    ASSERT_TRUE(r2->Render(d_, BoxCamera(), &small).ok());
    EXPECT_EQ(small.size(), 32u * 32u * 3u);
    ASSERT_TRUE(r->Render(d_, BoxCamera(), &after).ok());
    EXPECT_EQ(before, after);
  }
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &after).ok());
  EXPECT_EQ(before, after);
}

TEST_F(OffscreenTest, OddWidthRowsArePacked) {
  MAKE_RENDERER_OR_SKIP(r, 33, 17);
  std::vector<uint8_t> rgb;
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &rgb).ok());
  ASSERT_EQ(rgb.size(), 33u * 17u * 3u);
  const Pixel c = At(rgb, 33, 16, 8);
  EXPECT_GT(c.r, 2 * c.g);
  // each row starts with the same background/floor structure: no row drift from padding
  const Pixel top_left = At(rgb, 33, 0, 0);
  const Pixel top_right = At(rgb, 33, 32, 0);
  EXPECT_EQ(top_left.r + top_left.g + top_left.b, top_right.r + top_right.g + top_right.b);
}

TEST_F(OffscreenTest, CaptionChangesTopRowsOnly) {
  MAKE_RENDERER_OR_SKIP(r, 160, 120);
  std::vector<uint8_t> plain, captioned;
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &plain).ok());
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &captioned, "step 2/3 sit  t=4.2 s").ok());
  int changed_top_band = 0, changed_below = 0;
  for (int y = 0; y < 120; ++y) {
    for (int x = 0; x < 160; ++x) {
      const size_t i = (static_cast<size_t>(y) * 160 + x) * 3;
      if (plain[i] != captioned[i]) (y < 30 ? changed_top_band : changed_below)++;
    }
  }
  EXPECT_GT(changed_top_band, 20);
  EXPECT_EQ(changed_below, 0);
  if (HasFailure()) {
    ASSERT_TRUE(
        WritePng(core::testing::UniqueTempPath("caption_test.png"), captioned, 160, 120).ok());
  }
}

TEST_F(OffscreenTest, RenderFromAnotherThreadIsAnError) {
  MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight);
  absl::Status status;
  std::vector<uint8_t> rgb;
  std::thread t([&] { status = r->Render(d_, BoxCamera(), &rgb); });
  t.join();
  EXPECT_EQ(status.code(), absl::StatusCode::kFailedPrecondition) << status;
  // still usable on its own thread
  EXPECT_TRUE(r->Render(d_, BoxCamera(), &rgb).ok());
}

TEST_F(OffscreenTest, RejectsBadArguments) {
  EXPECT_EQ(OffscreenRenderer::Create(m_, 0, 10).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(OffscreenRenderer::Create(nullptr, 10, 10).status().code(),
            absl::StatusCode::kInvalidArgument);
  RendererOptions options;
  options.font_scale = 75;
  const auto r = OffscreenRenderer::Create(m_, 10, 10, options);
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(r.status().message().find("font_scale"), std::string::npos) << r.status();
}

TEST_F(OffscreenTest, SceneOverflowIsAnError) {
  RendererOptions options;
  options.max_geoms = 2;
  MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight, options);
  std::vector<uint8_t> rgb;
  // MuJoCo's default handler would print the expected warning to stdout and MUJOCO_LOG.TXT
  void (*saved)(const char*) = mju_user_warning;
  mju_user_warning = [](const char*) {};
  const absl::Status s = r->Render(d_, BoxCamera(), &rgb);
  mju_user_warning = saved;
  EXPECT_EQ(s.code(), absl::StatusCode::kResourceExhausted) << s;
  // MuJoCo counted it too; this test expects that warning
  EXPECT_GT(d_->warning[mjWARN_VGEOMFULL].number, 0);
  d_->warning[mjWARN_VGEOMFULL].number = 0;
}

}  // namespace
}  // namespace simhuman::render

namespace simhuman::render {
namespace {

TEST_F(OffscreenTest, BodyIdsMatchTheColourImage) {
  RendererOptions o;
  o.msaa_samples = 0;
  MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight, o);
  std::vector<uint8_t> rgb;
  std::vector<int> ids;
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &rgb).ok());
  ASSERT_TRUE(r->RenderBodyIds(d_, BoxCamera(), &ids).ok());
  ASSERT_EQ(ids.size(), static_cast<size_t>(kWidth * kHeight));
  const int box = mj_name2id(m_, mjOBJ_BODY, "box");
  const int ball = mj_name2id(m_, mjOBJ_BODY, "ball");
  // the centre shows the box; the floor is the world body (0); the sky nothing (-1)
  EXPECT_EQ(ids[(kHeight / 2) * kWidth + kWidth / 2], box);
  EXPECT_EQ(ids[(kHeight - 1) * kWidth + 2], 0);
  EXPECT_EQ(ids[2], -1);
  // every pixel called the ball is blue in the colour image, and there are some
  int ball_px = 0;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] != ball) continue;
    ++ball_px;
    EXPECT_GT(rgb[3 * i + 2], rgb[3 * i]) << "pixel " << i;
  }
  EXPECT_GT(ball_px, 5);
  // the colour render after a segmentation render is lit as before
  std::vector<uint8_t> again;
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &again).ok());
  EXPECT_EQ(again, rgb);
}

TEST_F(OffscreenTest, SetModelSwitchesTheSceneAndFieldOfView) {
  RendererOptions o;
  o.fovy_deg = 90;
  MAKE_RENDERER_OR_SKIP(r, kWidth, kHeight, o);
  EXPECT_FLOAT_EQ(r->model()->vis.global.fovy, 90.0f);
  mjModel* other = mj_copyModel(nullptr, m_);
  other->geom_rgba[4 * mj_name2id(other, mjOBJ_GEOM, "box") + 1] = 0.9f;  // the box turns yellow
  ASSERT_TRUE(r->SetModel(other).ok());
  EXPECT_FLOAT_EQ(r->model()->vis.global.fovy, 90.0f);
  std::vector<uint8_t> rgb;
  ASSERT_TRUE(r->Render(d_, BoxCamera(), &rgb).ok());
  const Pixel c = At(rgb, kWidth, kWidth / 2, kHeight / 2);
  EXPECT_GT(c.g, 100);
  mj_deleteModel(other);
  RendererOptions bad;
  bad.fovy_deg = 200;
  EXPECT_TRUE(absl::IsInvalidArgument(bad.Validate()));
}

}  // namespace
}  // namespace simhuman::render
