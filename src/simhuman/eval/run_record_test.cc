#include "simhuman/eval/run_record.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "simhuman/core/json_io.h"
#include "simhuman/eval/episode.h"

namespace simhuman::eval {
namespace {

using ::testing::HasSubstr;

constexpr double kQposTol = 1e-6;  // the CSV keeps 7 significant digits
constexpr double kFpsTol = 0.05;   // and 4 decimals of time

std::filesystem::path TempDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("simhuman_run_record_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

struct Sit {
  world::SceneSpec spec = *world::LoadScene("sit_demo");
  core::SceneCatalog catalog = *world::BuildCatalog(spec);
  std::unique_ptr<world::SimWorld> world = *BuildWorld(spec, catalog);
};

control::Trajectory ThreeFrames(const mjModel* m, const mjData* d) {
  control::Trajectory t;
  t.nq = m->nq;
  for (int f = 0; f < 3; ++f) {
    t.time_s.push_back(f / 30.0);
    t.step_index.push_back(f == 2 ? 1 : 0);
    t.qpos.emplace_back(d->qpos, d->qpos + m->nq);
    t.qpos.back()[0] += 0.1 * f;
  }
  return t;
}

TEST(RunRecordTest, TrajectoryCsvReadsBackWhatWasWritten) {
  Sit s;
  const auto dir = TempDir("roundtrip");
  const std::string path = (dir / "trajectory.csv").string();
  control::Trajectory t = ThreeFrames(s.world->model(), s.world->data());
  ASSERT_TRUE(WriteTrajectoryCsv(path, s.world->model(), t).ok());
  auto back = ReadTrajectoryCsv(path, s.world->model());
  ASSERT_TRUE(back.ok()) << back.status();
  ASSERT_EQ(back->qpos.size(), 3u);
  EXPECT_EQ(back->step_index, t.step_index);
  EXPECT_NEAR(back->fps, 30.0, kFpsTol);
  EXPECT_NEAR(back->qpos[2][0], t.qpos[2][0], kQposTol);
}

TEST(RunRecordTest, MalformedTrajectoriesNameLineAndColumn) {
  Sit s;
  const auto dir = TempDir("malformed");
  const std::string path = (dir / "malformed_trajectory.csv").string();
  ASSERT_TRUE(
      WriteTrajectoryCsv(path, s.world->model(), ThreeFrames(s.world->model(), s.world->data()))
          .ok());
  std::string text = *core::ReadFile(path);
  std::string bad_cell = text;
  bad_cell.insert(bad_cell.rfind('\n', bad_cell.size() - 2) + 1, "x");
  std::ofstream(path) << bad_cell;
  EXPECT_THAT(ReadTrajectoryCsv(path, s.world->model()).status().message(),
              HasSubstr(":4: column 'time_s' holds 'x0.0667'"));
  std::ofstream(path) << "time_s,step,nothing\n0,0,1\n";
  EXPECT_THAT(ReadTrajectoryCsv(path, s.world->model()).status().message(),
              HasSubstr(":1: column 3 is 'nothing'"));
  EXPECT_TRUE(absl::IsNotFound(LoadRunRecord((dir / "none").string()).status()));
  EXPECT_THAT(LoadRunRecord(dir.string()).status().message(), HasSubstr("has no scene.json"));
}

}  // namespace
}  // namespace simhuman::eval
