#include "simhuman/eval/replay.h"

#include <gtest/gtest.h>

#include "simhuman/core/testing_temp.h"
#include "simhuman/eval/episode.h"
#include "simhuman/render/image_io.h"
#include "simhuman/world/scene.h"

namespace simhuman::eval {
namespace {

// mean brightness (0..255) of the bottom rows of a contact sheet's first frame: the floor in
// front of the human
double FloorBrightness(const std::string& png, int frame_w, int frame_h) {
  std::vector<uint8_t> rgb;
  int w = 0, h = 0;
  EXPECT_TRUE(render::ReadPng(png, &rgb, &w, &h).ok());
  double sum = 0;
  int n = 0;
  for (int y = frame_h - 10; y < frame_h; ++y) {
    for (int x = 0; x < frame_w; ++x, ++n) {
      for (int k = 0; k < 3; ++k) sum += rgb[(static_cast<size_t>(y) * w + x) * 3 + k] / 3.0;
    }
  }
  return sum / n;
}

// the sun lights the floor in replays: the replay poses the model with mj_camlight too (it
// used to call mj_kinematics only, which leaves a directional light without a direction, and
// the floor came out grey and shadowless)
TEST(ReplayTest, TheSunLightsTheFloorIntegration) {
  auto spec = world::LoadScene("empty");
  ASSERT_TRUE(spec.ok());
  auto catalog = world::BuildCatalog(*spec);
  ASSERT_TRUE(catalog.ok());
  auto world = BuildWorld(*spec, *catalog);
  ASSERT_TRUE(world.ok()) << world.status();
  const mjModel* m = (*world)->model();
  control::Trajectory tr;
  tr.nq = m->nq;
  for (int f = 0; f < 3; ++f) {
    tr.time_s.push_back(f / 30.0);
    tr.step_index.push_back(0);
    tr.qpos.emplace_back(m->qpos0, m->qpos0 + m->nq);
  }
  plan::ContactChain chain;
  chain.steps.resize(1);
  chain.steps[0].label = "stand";
  ReplayOptions o;
  o.width = 160;
  o.height = 120;
  o.sheet_frames = 1;  // (one frame: a sheet of one used to come out empty)
  o.sheet_cols = 1;
  o.sheet_downscale = 1;
  o.sheet_path = core::testing::UniqueTempPath("replay_light.png");
  const absl::Status st = RenderReplay(**world, chain, tr, o);
  if (absl::IsUnavailable(st)) GTEST_SKIP() << "no EGL: " << st;
  ASSERT_TRUE(st.ok()) << st;
  // measured: 106 lit by the headlight alone, 194 with the sun
  EXPECT_GT(FloorBrightness(o.sheet_path, o.width, o.height), 150.0);
}

}  // namespace
}  // namespace simhuman::eval
