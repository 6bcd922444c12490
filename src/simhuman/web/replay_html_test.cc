#include "simhuman/web/replay_html.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>

#include "absl/strings/escaping.h"
#include "simhuman/eval/episode.h"
#include "simhuman/plan/validate.h"
#include "simhuman/web/clarify.h"
#include "simhuman/web/scene_view.h"
#include "simhuman/web/viewer_page.h"
#include "simhuman/world/scene.h"

namespace simhuman::web {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr double kPosTolM = 1e-5;

struct World {
  world::SceneSpec spec;
  core::SceneCatalog catalog;
  std::unique_ptr<world::SimWorld> world;
  plan::ContactChain chain;
};

World SitDemo() {
  World w;
  w.spec = *world::LoadScene("sit_demo");
  w.catalog = *world::BuildCatalog(w.spec);
  auto sim = eval::BuildWorld(w.spec, w.catalog);
  EXPECT_TRUE(sim.ok()) << sim.status();
  w.world = std::move(sim).value();
  auto chain =
      plan::ParseAndGround(R"([[["chair000", "seat surface", "pelvis", "contact", "up"]]])",
                           "<test>", w.world->catalog());
  EXPECT_TRUE(chain.ok()) << chain.status();
  w.chain = *chain;
  return w;
}

// `n` frames at `fps`, the first free joint (the human's root) sliding along x by `dx_m` each
control::Trajectory Sliding(const world::SimWorld& w, int n, double fps, double dx_m) {
  control::Trajectory t;
  t.fps = fps;
  t.nq = w.model()->nq;
  std::vector<double> q(w.data()->qpos, w.data()->qpos + w.model()->nq);
  for (int f = 0; f < n; ++f) {
    t.time_s.push_back(f / fps);
    t.step_index.push_back(0);
    t.qpos.push_back(q);
    q[0] += dx_m;
  }
  return t;
}

std::vector<float> Floats(const std::string& b64) {
  std::string bytes;
  EXPECT_TRUE(absl::Base64Unescape(b64, &bytes));
  std::vector<float> out(bytes.size() / sizeof(float));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
  return out;
}

TEST(ReplayHtmlTest, FramesArePosesOfTheMovingBodiesDecimatedToMaxFps) {
  World w = SitDemo();
  control::Trajectory t = Sliding(*w.world, 60, 60.0, 0.01);
  auto data = ReplayData(*w.world, w.chain, t, nullptr, {});
  ASSERT_TRUE(data.ok()) << data.status();
  const nlohmann::json& r = (*data)["replay"];
  EXPECT_DOUBLE_EQ(r["fps"].get<double>(), 30.0);  // every second frame of 60 Hz
  ASSERT_EQ(r["times"].size(), 30u);
  int moving = 0;
  for (const auto& b : (*data)["scene"]["bodies"]) moving += b["moving"].get<bool>();
  EXPECT_GT(moving, 10);  // the humanoid's bodies (the chair is static)
  std::vector<float> poses = Floats(r["poses"]);
  ASSERT_EQ(poses.size(), 30u * moving * kPoseFloats);
  // the root body slides 2 cm per kept frame
  EXPECT_NEAR(poses[moving * kPoseFloats] - poses[0], 0.02, kPosTolM);
  // one contact target per frame (pelvis on the seat), its point near the seat's height
  EXPECT_EQ(r["target_offsets"].back().get<int>(), 30);
  std::vector<float> targets = Floats(r["targets"]);
  ASSERT_EQ(targets.size(), 30u * kTargetFloats);
  EXPECT_GT(targets[5], 0.3);
  EXPECT_LT(targets[5], 0.6);
  EXPECT_EQ((*data)["steps"][0], "pelvis on chair000 seat surface");
}

TEST(ReplayHtmlTest, SeveralHumansAreAllDrawn) {
  auto spec =
      world::LoadScene(std::string(SIMHUMAN_SOURCE_DIR) + "/assets/scenes/lounge_two_humans.json");
  ASSERT_TRUE(spec.ok()) << spec.status();
  auto catalog = world::BuildCatalog(*spec);
  ASSERT_TRUE(catalog.ok()) << catalog.status();
  auto sim = eval::BuildWorld(*spec, *catalog);
  ASSERT_TRUE(sim.ok()) << sim.status();
  auto chain = plan::ParseAndGround(R"([[["sofa000", "seat surface", "pelvis", "contact", "up"]]])",
                                    "<test>", (*sim)->catalog());
  ASSERT_TRUE(chain.ok()) << chain.status();
  auto data = ReplayData(**sim, *chain, Sliding(**sim, 4, 30.0, 0.0), nullptr);
  ASSERT_TRUE(data.ok()) << data.status();
  int per_agent[2] = {0, 0};
  for (const auto& b : (*data)["scene"]["bodies"]) {
    const int a = b["agent"];
    if (a >= 0 && a < 2) ++per_agent[a];
  }
  EXPECT_GT(per_agent[0], 10);
  EXPECT_EQ(per_agent[0], per_agent[1]);
}

// a cone and an OBJ mesh reach the page as their triangles, not as boxes
TEST(ReplayHtmlTest, MeshObjectsAreSentAsTheirTriangles) {
  world::SceneSpec spec = *world::LoadScene("sit_demo");
  world::ObjectSpec cone;
  cone.id = "cone100";
  cone.type = "cone";
  cone.pos = Eigen::Vector3d(2, 2, 0);
  world::ObjectSpec vase = cone;
  vase.id = "mesh101";
  vase.type = "mesh";
  vase.pos.x() = 3;
  vase.mesh = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/meshes/vase.obj";
  spec.objects.push_back(cone);
  spec.objects.push_back(vase);
  auto catalog = world::BuildCatalog(spec);
  ASSERT_TRUE(catalog.ok()) << catalog.status();
  auto sim = eval::BuildWorld(spec, *catalog);
  ASSERT_TRUE(sim.ok()) << sim.status();
  const SceneView view = DescribeScene(**sim, (*sim)->data());
  int meshes = 0;
  for (const auto& b : view.json["bodies"]) {
    for (const auto& g : b["geoms"]) {
      if (g["type"] != "mesh") continue;
      ++meshes;
      const size_t nv = g["vertices"].size() / 3;
      ASSERT_GE(nv, 4u);
      ASSERT_GE(g["faces"].size(), 12u);
      EXPECT_EQ(g["faces"].size() % 3, 0u);
      for (const auto& f : g["faces"]) EXPECT_LT(f.get<size_t>(), nv);
    }
  }
  EXPECT_EQ(meshes, 2);
}

TEST(ReplayHtmlTest, BadTrajectoriesAreRefused) {
  World w = SitDemo();
  control::Trajectory empty;
  EXPECT_THAT(ReplayData(*w.world, w.chain, empty, nullptr).status().message(),
              HasSubstr("no frames"));
  control::Trajectory t = Sliding(*w.world, 3, 30.0, 0.0);
  t.qpos[1].pop_back();
  EXPECT_THAT(ReplayData(*w.world, w.chain, t, nullptr).status().message(),
              HasSubstr("frame 1 has"));
}

TEST(ReplayHtmlTest, PageInlinesThreeJsAndTheDataSafely) {
  const std::string page =
      ViewerPageHtml({{"mode", "replay"}, {"title", "</script><b>x"}, {"n", 1}});
  EXPECT_THAT(page, HasSubstr("THREE.OrbitControls"));  // Debian's r111, linked in
  EXPECT_THAT(page, HasSubstr("REVISION=\"111\""));
  EXPECT_THAT(page, HasSubstr("<\\/script><b>x"));
  EXPECT_THAT(page, Not(HasSubstr("</script><b>x")));
  EXPECT_THAT(page, Not(HasSubstr("/*SIMHUMAN_DATA*/")));
  // nothing is fetched: no script or style from elsewhere
  EXPECT_THAT(page, Not(HasSubstr("<script src")));
  EXPECT_THAT(page, Not(HasSubstr("<link")));
}

TEST(ClarifyTest, AnswerNamesTheChosenObject) {
  auto spec = world::LoadScene("tabletop_demo");
  ASSERT_TRUE(spec.ok());
  auto catalog = world::BuildCatalog(*spec);
  ASSERT_TRUE(catalog.ok());
  const std::string q =
      "Which box: the one on the brown table (box001), the one at (0.85, 0.00) (box002), the "
      "one in front of the green sphere (box003) or the one at (1.10, 0.15) (box004)?";
  EXPECT_EQ(*AnswerQuestion("touch the box", q, "box003", *catalog), "touch box003");
  EXPECT_EQ(*AnswerQuestion("touch the box", q, "2", *catalog), "touch box002");
  EXPECT_EQ(*AnswerQuestion("Touch the box now", q, "on the brown table", *catalog),
            "Touch box001 now");
  EXPECT_EQ(*AnswerQuestion("touch the box", q, "the one in front of the green sphere", *catalog),
            "touch box003");
  auto none = AnswerQuestion("touch the box", q, "the purple one", *catalog);
  EXPECT_THAT(none.status().message(), HasSubstr("matches none"));
  EXPECT_THAT(none.status().message(), HasSubstr("1 = box001 (the one on the brown table)"));
  EXPECT_THAT(AnswerQuestion("touch the box", q, "the one at", *catalog).status().message(),
              HasSubstr("matches several"));
  EXPECT_FALSE(AnswerQuestion("touch the box", "Which one?", "1", *catalog).ok());
}

}  // namespace
}  // namespace simhuman::web
