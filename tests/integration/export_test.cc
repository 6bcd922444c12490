// `simhuman export`: BVH that round-trips through our own importer (learn/bvh.h) within a
// degree per joint, one BVH per human, an animated .glb, bad run folders refused with a clear
// message, and (when Debian's blender is installed) both files imported by Blender headless.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "simhuman/core/rng.h"
#include "simhuman/eval/episode.h"
#include "simhuman/learn/bvh.h"
#include "simhuman/render/bvh_export.h"
#include "simhuman/world/scene.h"

namespace {

namespace fs = std::filesystem;
using simhuman::control::Trajectory;
using simhuman::world::AgentIndex;
using simhuman::world::SimWorld;

const std::string kSource = SIMHUMAN_SOURCE_DIR;
// the target for the round trip, per joint and frame
constexpr double kRoundTripTolDeg = 1.0;
// root positions come back in metres (divided by the human's scale: the importer scales the
// skeleton to an adult's standing height)
constexpr double kRootTolM = 1e-4;
constexpr double kRadToDeg = 180.0 / M_PI;

std::string TempDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("simhuman_export_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Proc {
  int exit_code = -1;
  std::string out, err;
};

// runs a shell command line, its output into files
Proc Shell(const std::string& cmd) {
  static int n = 0;
  const std::string base = TempDir("proc" + std::to_string(n++)) + "/p";
  const int st = std::system((cmd + " >" + base + ".out 2>" + base + ".err").c_str());
  Proc p;
  p.exit_code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  p.out = Slurp(base + ".out");
  p.err = Slurp(base + ".err");
  return p;
}

// `seconds` of random poses at 30 Hz: every hinge of every human uniform within its range, the
// roots anywhere nearby in any orientation (fixed seed)
Trajectory RandomPoses(const SimWorld& world, double seconds, uint64_t seed) {
  simhuman::core::Rng rng(seed);
  const mjModel* m = world.model();
  Trajectory tr;
  tr.nq = m->nq;
  const int n = static_cast<int>(std::lround(seconds * 30)) + 1;
  for (int f = 0; f < n; ++f) {
    std::vector<double> q(m->qpos0, m->qpos0 + m->nq);
    for (int a = 0; a < world.num_agents(); ++a) {
      const AgentIndex& ag = world.agent(a);
      for (int k = 0; k < 3; ++k) q[ag.root_qpos + k] = rng.Uniform(-2, 2);
      const Eigen::Quaterniond r(
          Eigen::Vector4d(rng.Normal(), rng.Normal(), rng.Normal(), rng.Normal()).normalized());
      q[ag.root_qpos + 3] = r.w();
      q[ag.root_qpos + 4] = r.x();
      q[ag.root_qpos + 5] = r.y();
      q[ag.root_qpos + 6] = r.z();
      for (int adr : ag.hinge_qpos) {
        int jid = 0;
        while (m->jnt_qposadr[jid] != adr) ++jid;
        q[adr] = rng.Uniform(m->jnt_range[2 * jid], m->jnt_range[2 * jid + 1]);
      }
    }
    tr.time_s.push_back(f / 30.0);
    tr.step_index.push_back(0);
    tr.qpos.push_back(q);
  }
  return tr;
}

// the worst hinge error (degrees) of a BVH of agent `ag` read back by our importer, and checks
// the root
double RoundTripWorstDeg(const std::string& bvh_text, const AgentIndex& ag, const Trajectory& tr) {
  auto bvh = simhuman::learn::ParseBvh(bvh_text, "export.bvh");
  EXPECT_TRUE(bvh.ok()) << bvh.status();
  if (!bvh.ok()) return 1e9;
  auto clip = simhuman::learn::RetargetBvh(*bvh, "export.bvh");
  EXPECT_TRUE(clip.ok()) << clip.status();
  if (!clip.ok()) return 1e9;
  EXPECT_EQ(clip->frames.size(), tr.qpos.size());
  EXPECT_NEAR(clip->fps, 30, 1e-6);
  double worst = 0;
  const std::vector<double>& q0 = tr.qpos[0];
  const int r = ag.root_qpos;
  for (size_t f = 0; f < std::min(clip->frames.size(), tr.qpos.size()); ++f) {
    const auto& fr = clip->frames[f];
    const std::vector<double>& q = tr.qpos[f];
    for (int k = 0; k < simhuman::world::kHumanoidDofs; ++k) {
      const double e = std::abs(fr.q_rad[k] - q[ag.hinge_qpos[k]]) * kRadToDeg;
      worst = std::max(worst, e);
      EXPECT_LT(e, kRoundTripTolDeg) << "frame " << f << " hinge " << k;
    }
    // the importer moves the first frame's horizontal position to the origin
    for (int k = 0; k < 3; ++k) {
      const double expected = (q[r + k] - (k < 2 ? q0[r + k] : 0.0)) / ag.scale;
      EXPECT_NEAR(fr.root_pos_m[k], expected, kRootTolM) << "frame " << f << " axis " << k;
    }
    const Eigen::Quaterniond want(q[r + 3], q[r + 4], q[r + 5], q[r + 6]);
    const Eigen::Quaterniond got(fr.root_quat_wxyz[0], fr.root_quat_wxyz[1], fr.root_quat_wxyz[2],
                                 fr.root_quat_wxyz[3]);
    EXPECT_LT(want.angularDistance(got) * kRadToDeg, kRoundTripTolDeg) << "frame " << f;
  }
  return worst;
}

std::unique_ptr<SimWorld> WorldOf(const std::string& scene) {
  auto spec = simhuman::world::LoadScene(scene);
  EXPECT_TRUE(spec.ok()) << spec.status();
  auto catalog = simhuman::world::BuildCatalog(*spec);
  EXPECT_TRUE(catalog.ok()) << catalog.status();
  auto world = simhuman::eval::BuildWorld(*spec, *catalog);
  EXPECT_TRUE(world.ok()) << world.status();
  return std::move(world).value();
}

simhuman::render::QposFrames FramesOf(const Trajectory& tr) { return {tr.time_s, tr.qpos}; }

TEST(BvhExport, RoundTripsThroughOurImporterWithinADegree) {
  // an adult and a child (scale 0.7): every hinge over its whole range, any root orientation
  std::unique_ptr<SimWorld> world = WorldOf(kSource + "/assets/scenes/lounge_two_humans.json");
  ASSERT_EQ(world->num_agents(), 2);
  const Trajectory tr = RandomPoses(*world, 4.0, 18);
  for (int a = 0; a < 2; ++a) {
    auto text = simhuman::render::AgentBvh(world->model(), world->agent(a), FramesOf(tr), 30);
    ASSERT_TRUE(text.ok()) << text.status();
    const double worst = RoundTripWorstDeg(*text, world->agent(a), tr);
    std::cout << "human " << a << ": worst hinge error after the round trip " << worst << " deg"
              << std::endl;
  }
}

TEST(BvhExport, SkeletonAndBadInput) {
  std::unique_ptr<SimWorld> world = WorldOf("sit_demo");
  const Trajectory tr = RandomPoses(*world, 0.2, 1);
  auto text = simhuman::render::AgentBvh(world->model(), world->agent(0), FramesOf(tr), 30);
  ASSERT_TRUE(text.ok()) << text.status();
  for (const std::string& name : simhuman::render::BvhExportJointNames()) {
    EXPECT_NE(text->find(" " + name + "\n"), std::string::npos) << name;
  }
  EXPECT_NE(text->find("Frames: 7\nFrame Time: 0.0333333333"), std::string::npos);
  EXPECT_FALSE(simhuman::render::AgentBvh(world->model(), world->agent(0), FramesOf(tr), 0).ok());
  Trajectory short_row = tr;
  short_row.qpos[2].pop_back();
  auto st = simhuman::render::AgentBvh(world->model(), world->agent(0), FramesOf(short_row), 30);
  EXPECT_NE(st.status().message().find("frame 2"), std::string::npos) << st.status();
}

// a run folder as `simhuman run` writes it (scene.json, trajectory.csv), with random poses
std::string WriteRunFolder(const std::string& scene, const std::string& name, Trajectory* tr,
                           std::unique_ptr<SimWorld>* world_out) {
  const std::string dir = TempDir(name);
  auto spec = simhuman::world::LoadScene(scene);
  EXPECT_TRUE(spec.ok());
  std::unique_ptr<SimWorld> world = WorldOf(scene);
  *tr = RandomPoses(*world, 2.0, 7);
  std::ofstream(dir + "/scene.json") << simhuman::world::SceneToJson(*spec).dump(2);
  EXPECT_TRUE(
      simhuman::eval::WriteTrajectoryCsv(dir + "/trajectory.csv", world->model(), *tr).ok());
  *world_out = std::move(world);
  return dir;
}

TEST(ExportCommand, OneBvhPerHumanAndAGlb) {
  Trajectory tr;
  std::unique_ptr<SimWorld> world;
  const std::string dir =
      WriteRunFolder(kSource + "/assets/scenes/lounge_two_humans.json", "two", &tr, &world);
  const Proc p = Shell(std::string(SIMHUMAN_BIN) + " export " + dir + " --bvh " + dir +
                       "/out.bvh --gltf " + dir + "/out.glb");
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_NE(p.out.find("out_h1.bvh (human 1, 30 fps)"), std::string::npos) << p.out;
  // through the CSV (7 significant digits) and the file: still well within a degree
  for (int a = 0; a < 2; ++a) {
    const std::string text = Slurp(dir + "/out_h" + std::to_string(a) + ".bvh");
    RoundTripWorstDeg(text, world->agent(a), tr);
  }
  EXPECT_GT(fs::file_size(dir + "/out.glb"), 10000u);
  // --agent picks one human and keeps the name
  const Proc one = Shell(std::string(SIMHUMAN_BIN) + " export " + dir + " --agent 1 --bvh " + dir +
                         "/child.bvh");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(Slurp(dir + "/child.bvh"), Slurp(dir + "/out_h1.bvh"));
}

TEST(ExportCommand, BadRunFoldersAndFlagsAreRefused) {
  const std::string bin = SIMHUMAN_BIN;
  Proc p = Shell(bin + " export /nonexistent/run --bvh /tmp/x.bvh");
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("'/nonexistent/run' does not exist"), std::string::npos) << p.err;
  Trajectory tr;
  std::unique_ptr<SimWorld> world;
  const std::string dir = WriteRunFolder("sit_demo", "bad", &tr, &world);
  p = Shell(bin + " export " + dir);
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("--bvh"), std::string::npos) << p.err;
  p = Shell(bin + " export " + dir + " --agent 3 --bvh " + dir + "/a.bvh");
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("valid: 0..0"), std::string::npos) << p.err;
  // a trajectory recorded on another model: the first differing column is named
  std::string csv = Slurp(dir + "/trajectory.csv");
  csv.replace(csv.find("abdomen_x"), 9, "abdomen_q");
  std::ofstream(dir + "/trajectory.csv") << csv;
  p = Shell(bin + " export " + dir + " --gltf " + dir + "/a.glb");
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("trajectory.csv:1: column"), std::string::npos) << p.err;
  EXPECT_NE(p.err.find("'abdomen_q'"), std::string::npos) << p.err;
  fs::remove(dir + "/trajectory.csv");
  p = Shell(bin + " export " + dir + " --gltf " + dir + "/a.glb");
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("has no trajectory.csv"), std::string::npos) << p.err;
}

TEST(ExportCommand, BlenderImportsTheGlbAndTheBvh) {
  if (Shell("command -v blender").exit_code != 0) {
    GTEST_SKIP() << "blender is not installed (Debian package blender; scripts/install_deps.sh)";
  }
  Trajectory tr;
  std::unique_ptr<SimWorld> world;
  const std::string dir = WriteRunFolder("sit_demo", "blender", &tr, &world);
  const Proc ex = Shell(std::string(SIMHUMAN_BIN) + " export " + dir + " --bvh " + dir +
                        "/out.bvh --gltf " + dir + "/out.glb");
  ASSERT_EQ(ex.exit_code, 0) << ex.err;
  const Proc b =
      Shell("blender -b --python " + kSource + "/tests/integration/blender_check.py -- " + dir +
            "/out.glb " + dir + "/out.bvh");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  // sit_demo: the floor, the chair and the humanoid's 15 bodies, all 15 moving; 2 s at 30 Hz
  std::smatch g;
  ASSERT_TRUE(std::regex_search(b.out, g,
                                std::regex("GLB objects (\\d+) meshes (\\d+) actions (\\d+) frames "
                                           "(\\S+) (\\S+)")))
      << b.out << b.err;
  EXPECT_EQ(g[1], "17");
  EXPECT_EQ(g[2], "17");
  EXPECT_EQ(g[3], "15");
  EXPECT_EQ(g[4], "0");
  EXPECT_EQ(g[5], "60");
  ASSERT_TRUE(std::regex_search(
      b.out, g, std::regex("BVH armatures (\\d+) bones (\\d+) frames (\\S+) (\\S+)")))
      << b.out;
  EXPECT_EQ(g[1], "1");
  EXPECT_EQ(g[2], "15");
  EXPECT_EQ(g[3], "1");
  EXPECT_EQ(g[4], "61");
  // Blender turns glTF's y-up back into z-up: the pelvis is where MuJoCo had it at frame 0
  ASSERT_TRUE(std::regex_search(b.out, g, std::regex("GLB pelvis (\\S+) (\\S+) (\\S+)"))) << b.out;
  const int r = world->agent(0).root_qpos;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::stod(g[k + 1]), tr.qpos[0][r + k], 1e-3) << k;
}

}  // namespace

namespace {

TEST(ExportCommand, RendersTheContactSheetAgain) {
  Trajectory tr;
  std::unique_ptr<SimWorld> world;
  const std::string dir = WriteRunFolder("sit_demo", "sheet", &tr, &world);
  const std::string bin = SIMHUMAN_BIN;
  // without the run's plan there are no captions: refused, naming the file
  Proc p = Shell(bin + " export " + dir + " --sheet " + dir + "/sheet.png");
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("plan.json"), std::string::npos) << p.err;
  fs::copy_file(kSource + "/assets/plans/sit_then_stand.json", dir + "/plan.json");
  p = Shell(bin + " export " + dir + " --sheet " + dir + "/sheet.png");
  if (p.exit_code == 1 && p.err.find("EGL") != std::string::npos) {
    GTEST_SKIP() << "no EGL display: " << p.err;
  }
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_GT(fs::file_size(dir + "/sheet.png"), 10000u);
}

}  // namespace
