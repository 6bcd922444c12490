#include "simhuman/render/gltf_export.h"

#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

#include "simhuman/render/geom_mesh.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::render {
namespace {

constexpr double kTol = 1e-5;  // float storage

// a box body at MuJoCo (1, 2, 3) that slides 1 m up along z, and a capsule that stays
constexpr char kXml[] = R"(
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 0.1"/>
    <body name="mover" pos="1 2 3">
      <joint name="lift" type="slide" axis="0 0 1"/>
      <geom type="box" size="0.1 0.2 0.3" rgba="1 0 0 1"/>
    </body>
    <body name="still" pos="-1 0 0.5">
      <geom type="capsule" size="0.05 0.2" rgba="0 1 0 1"/>
      <geom type="sphere" size="0.05" rgba="0 0 0 0"/>
    </body>
  </worldbody>
</mujoco>)";

struct Glb {
  nlohmann::json json;
  std::string bin;
};

uint32_t U32(const std::string& s, size_t at) {
  uint32_t v;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}

// splits a .glb into its JSON and BIN chunks, checking the container
Glb ParseGlb(const std::string& bytes) {
  Glb g;
  EXPECT_EQ(U32(bytes, 0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(U32(bytes, 4), 2u);
  EXPECT_EQ(U32(bytes, 8), bytes.size());
  const uint32_t json_len = U32(bytes, 12);
  EXPECT_EQ(U32(bytes, 16), 0x4E4F534Au);
  EXPECT_EQ(json_len % 4, 0u);
  g.json = nlohmann::json::parse(bytes.substr(20, json_len));
  const size_t bin_at = 20 + json_len;
  EXPECT_EQ(U32(bytes, bin_at + 4), 0x004E4942u);
  g.bin = bytes.substr(bin_at + 8, U32(bytes, bin_at));
  return g;
}

// floats of accessor `a`
std::vector<float> Floats(const Glb& g, int a) {
  const auto& acc = g.json["accessors"][a];
  const auto& view = g.json["bufferViews"][acc["bufferView"].get<int>()];
  const size_t n = view["byteLength"].get<size_t>() / 4;
  std::vector<float> out(n);
  std::memcpy(out.data(), g.bin.data() + view["byteOffset"].get<size_t>(), 4 * n);
  return out;
}

int NodeNamed(const Glb& g, const std::string& name) {
  for (size_t i = 0; i < g.json["nodes"].size(); ++i) {
    if (g.json["nodes"][i]["name"] == name) return static_cast<int>(i);
  }
  return -1;
}

class GltfExportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto m = world::SimWorld::CompileXml(kXml);
    ASSERT_TRUE(m.ok()) << m.status();
    m_ = *m;
    // 1 s at 10 Hz: the slider goes from 0 to 1 m
    for (int f = 0; f <= 10; ++f) {
      frames_.time_s.push_back(0.1 * f);
      frames_.qpos.push_back({0.1 * f});
    }
  }
  void TearDown() override { mj_deleteModel(m_); }
  mjModel* m_ = nullptr;
  QposFrames frames_;
};

TEST(GltfAxes, MujocoPointEndsAtXZMinusY) {
  const Eigen::Vector3d p = MujocoToGltf(Eigen::Vector3d(1, 2, 3));
  EXPECT_NEAR((p - Eigen::Vector3d(1, 3, -2)).norm(), 0, 1e-12);
  // the rotation agrees with the point map: rotating a vector then converting is converting
  // then rotating with the converted rotation
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()));
  const Eigen::Vector3d v(0.2, -1.1, 0.4);
  EXPECT_NEAR((MujocoToGltf(Eigen::Vector3d(q * v)) - MujocoToGltf(q) * MujocoToGltf(v)).norm(), 0,
              1e-12);
  // MuJoCo's up is glTF's up
  EXPECT_NEAR((MujocoToGltf(Eigen::Vector3d::UnitZ()) - Eigen::Vector3d::UnitY()).norm(), 0, 1e-12);
}

TEST_F(GltfExportTest, NodesSitAtYUpPositionsAndMoveUp) {
  GltfOptions options;
  options.fps = 10;
  auto bytes = SceneGlb(m_, frames_, options);
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  const Glb g = ParseGlb(*bytes);
  EXPECT_EQ(g.json["asset"]["version"], "2.0");
  const int mover = NodeNamed(g, "mover");
  ASSERT_GE(mover, 0);
  const auto& t = g.json["nodes"][mover]["translation"];
  EXPECT_NEAR(t[0].get<double>(), 1, kTol);  // MuJoCo (1, 2, 3) -> glTF (1, 3, -2)
  EXPECT_NEAR(t[1].get<double>(), 3, kTol);
  EXPECT_NEAR(t[2].get<double>(), -2, kTol);
  // the box's vertices in the node frame: half sizes (0.1, 0.2, 0.3) -> (0.1, 0.3, 0.2)
  const int mesh = g.json["nodes"][mover]["mesh"];
  const int pos = g.json["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"];
  const auto& acc = g.json["accessors"][pos];
  EXPECT_NEAR(acc["max"][0].get<double>(), 0.1, kTol);
  EXPECT_NEAR(acc["max"][1].get<double>(), 0.3, kTol);
  EXPECT_NEAR(acc["max"][2].get<double>(), 0.2, kTol);
  EXPECT_EQ(acc["count"], 24);
  // one animation: translation and rotation of the mover only (the rest is still)
  ASSERT_EQ(g.json["animations"].size(), 1u);
  const auto& anim = g.json["animations"][0];
  ASSERT_EQ(anim["channels"].size(), 2u);
  for (const auto& ch : anim["channels"]) EXPECT_EQ(ch["target"]["node"], mover);
  const auto& sampler = anim["samplers"][anim["channels"][0]["sampler"].get<int>()];
  const std::vector<float> times = Floats(g, sampler["input"]);
  ASSERT_EQ(times.size(), 11u);
  EXPECT_NEAR(times.back(), 1.0, kTol);
  const std::vector<float> out = Floats(g, sampler["output"]);
  ASSERT_EQ(out.size(), 33u);
  // the slide along MuJoCo +z is a rise along glTF +y: (1, 4, -2) at the end
  EXPECT_NEAR(out[30], 1, kTol);
  EXPECT_NEAR(out[31], 4, kTol);
  EXPECT_NEAR(out[32], -2, kTol);
}

TEST_F(GltfExportTest, HiddenGeomsAndColoursAndFloor) {
  auto bytes = SceneGlb(m_, frames_);
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  const Glb g = ParseGlb(*bytes);
  // world (floor), mover, still: the invisible sphere adds no primitive
  EXPECT_EQ(g.json["nodes"].size(), 3u);
  const int still = NodeNamed(g, "still");
  ASSERT_GE(still, 0);
  EXPECT_EQ(g.json["meshes"][g.json["nodes"][still]["mesh"].get<int>()]["primitives"].size(), 1u);
  // the infinite floor is cut to floor_half_m (10 m) and lies in glTF's x-z plane
  const int world_node = NodeNamed(g, "world");
  ASSERT_GE(world_node, 0);
  const int mesh = g.json["nodes"][world_node]["mesh"];
  const auto& acc =
      g.json["accessors"]
            [g.json["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"].get<int>()];
  EXPECT_NEAR(acc["max"][0].get<double>(), 10, kTol);
  EXPECT_NEAR(acc["max"][1].get<double>(), 0, kTol);
  EXPECT_NEAR(acc["max"][2].get<double>(), 10, kTol);
  EXPECT_EQ(g.json["materials"].size(), 3u);  // floor grey, red, green
}

TEST_F(GltfExportTest, BadInputIsAnError) {
  GltfOptions bad_fps;
  bad_fps.fps = 0;
  EXPECT_EQ(SceneGlb(m_, frames_, bad_fps).status().code(), absl::StatusCode::kInvalidArgument);
  QposFrames wrong = frames_;
  wrong.qpos[3].push_back(0);
  auto st = SceneGlb(m_, wrong).status();
  EXPECT_EQ(st.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(st.message().find("frame 3"), std::string::npos) << st;
  EXPECT_FALSE(SceneGlb(m_, QposFrames{}).ok());
}

TEST_F(GltfExportTest, GeomMeshesAreClosedAndOutward) {
  // every round shape: vertices on the surface, normals pointing away from the centre
  auto m = world::SimWorld::CompileXml(R"(<mujoco><worldbody>
      <geom type="sphere" size="0.5"/><geom type="capsule" size="0.2 0.4"/>
      <geom type="cylinder" size="0.3 0.1"/><geom type="ellipsoid" size="0.1 0.2 0.3"/>
      <geom type="box" size="0.1 0.2 0.3"/></worldbody></mujoco>)");
  ASSERT_TRUE(m.ok()) << m.status();
  for (int g = 0; g < (*m)->ngeom; ++g) {
    const TriMesh mesh = GeomMesh(*m, g, 16);
    ASSERT_FALSE(mesh.index.empty()) << "geom " << g;
    for (size_t t = 0; t < mesh.index.size(); t += 3) {
      // the triangle's winding normal agrees with its vertices' normals and faces outward
      Eigen::Vector3f p[3], n = Eigen::Vector3f::Zero();
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh.index[t + k];
        ASSERT_LT(v, static_cast<uint32_t>(mesh.num_vertices()));
        p[k] = Eigen::Vector3f(&mesh.position[3 * v]);
        n += Eigen::Vector3f(&mesh.normal[3 * v]);
      }
      const Eigen::Vector3f face = (p[1] - p[0]).cross(p[2] - p[0]);
      EXPECT_GT(face.dot(n), 0) << "geom " << g << " triangle " << t / 3;
      EXPECT_GT(face.dot(p[0] + p[1] + p[2]), 0) << "geom " << g << " triangle " << t / 3;
    }
  }
  mj_deleteModel(*m);
}

}  // namespace
}  // namespace simhuman::render
