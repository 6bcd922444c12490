#include "simhuman/perceive/heightmap.h"

#include <gtest/gtest.h>

namespace simhuman::perceive {
namespace {

TEST(HeightmapTest, SeesATableInFrontAndTheFloorBehind) {
  core::SceneCatalog scene;
  core::CatalogObject table;
  table.id = "table000";
  core::Shape board;
  board.kind = core::ShapeKind::kBox;
  board.size = Eigen::Vector3d(0.4, 0.6, 0.02);
  board.pose.pos = Eigen::Vector3d(0, 0, 0.73);
  table.shapes = {board};
  table.pose = core::Pose::FromYaw(Eigen::Vector3d(1.0, 0, 0), 0);
  scene.objects.push_back(table);
  std::vector<float> map;
  const int n = 16;
  const double cell = 0.1;
  // pelvis at the origin facing +x: the table is 0.6-1.4 m ahead
  BuildHeightmap(scene, Eigen::Vector3d(0, 0, 0.9), 0.0, n, cell, &map);
  ASSERT_EQ(map.size(), static_cast<size_t>(n * n));
  // row index = forward cell; the last rows (0.65-0.75 m ahead) are over the table
  EXPECT_NEAR(map[(n - 1) * n + n / 2], 0.75, 1e-6);
  EXPECT_NEAR(map[0 * n + n / 2], 0.0, 1e-6);
  // facing -x, the table is behind: the front rows see the floor
  BuildHeightmap(scene, Eigen::Vector3d(0, 0, 0.9), M_PI, n, cell, &map);
  EXPECT_NEAR(map[(n - 1) * n + n / 2], 0.0, 1e-6);
  EXPECT_NEAR(map[0 * n + n / 2], 0.75, 1e-6);
}

TEST(SensorRegistryTest, MakesTheHeightmapAndNamesBadInput) {
  core::StatusOr<std::unique_ptr<Sensor>> s = MakeSensor("heightmap", {{"size", 8}});
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ((*s)->name(), "heightmap");
  EXPECT_EQ((*s)->Config()["size"], 8);
  EXPECT_DOUBLE_EQ((*s)->Config()["cell_m"].get<double>(), 0.1);

  core::StatusOr<std::unique_ptr<Sensor>> unknown = MakeSensor("sonar", {});
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("valid sensors are: heightmap"), std::string::npos);

  core::StatusOr<std::unique_ptr<Sensor>> bad = MakeSensor("heightmap", {{"size", 0.5}});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("/sensors/heightmap/size"), std::string::npos);
  core::StatusOr<std::unique_ptr<Sensor>> extra = MakeSensor("heightmap", {{"fov", 1}});
  ASSERT_FALSE(extra.ok());
  EXPECT_NE(extra.status().message().find("'fov'"), std::string::npos);
}

}  // namespace
}  // namespace simhuman::perceive
