#include "simhuman/control/controller.h"

#include <gtest/gtest.h>

namespace simhuman::control {
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

}  // namespace
}  // namespace simhuman::control
