#include "simhuman/world/room.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/world/objects.h"

namespace simhuman::world {
namespace {

using ::testing::HasSubstr;

// smallest horizontal distance from points spread over a's footprint (a 5 x 5 grid of its
// local bounds, in the world) to b's solids, probed at b's mid height
double FootprintGap(const core::CatalogObject& a, const core::CatalogObject& b) {
  auto [alo, ahi] = a.LocalBounds();
  auto [blo, bhi] = b.LocalBounds();
  const double z = b.pose.pos.z() + 0.5 * (blo.z() + bhi.z());
  double best = 1e9;
  for (int i = 0; i <= 4; ++i) {
    for (int j = 0; j <= 4; ++j) {
      Eigen::Vector3d local(alo.x() + (ahi.x() - alo.x()) * i / 4.0,
                            alo.y() + (ahi.y() - alo.y()) * j / 4.0, 0);
      Eigen::Vector3d p = a.pose.Apply(local);
      p.z() = z;
      Eigen::Vector3d q = core::NearestPointOnShapes(b.shapes, b.pose, p);
      best = std::min(best, (q - p).head<2>().norm());
    }
  }
  return best;
}

TEST(RoomTest, FurnishesWithoutOverlapsAndKeepsDesksTogether) {
  RoomRequest req;
  req.items = {"desk", "bed", "sofa", "stool"};
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    core::Rng rng(seed);
    core::StatusOr<Room> room = GenerateRoom(req, rng);
    ASSERT_TRUE(room.ok()) << room.status();
    ASSERT_EQ(room->item_ids.size(), 4u);
    ASSERT_EQ(room->item_ids[0].size(), 3u);  // table, laptop, chair
    core::StatusOr<core::SceneCatalog> cat = BuildCatalog(room->scene);
    ASSERT_TRUE(cat.ok()) << cat.status();
    // groups apart; a desk's chair faces its table across a gap to stand in
    for (size_t i = 0; i < room->item_ids.size(); ++i) {
      for (size_t j = i + 1; j < room->item_ids.size(); ++j) {
        for (const std::string& a : room->item_ids[i]) {
          for (const std::string& b : room->item_ids[j]) {
            // footprints are 0.6 m apart (walkways)
            EXPECT_GT(FootprintGap(*cat->Find(a), *cat->Find(b)), 0.55) << a << " " << b;
          }
        }
      }
    }
    const core::CatalogObject& table = *cat->Find(room->item_ids[0][0]);
    const core::CatalogObject& chair = *cat->Find(room->item_ids[0][2]);
    const core::CatalogObject& laptop = *cat->Find(room->item_ids[0][1]);
    EXPECT_GT(laptop.pose.pos.z(), 0.5);  // on the board
    Eigen::Vector2d chair_front =
        (chair.pose.quat * Eigen::Vector3d::UnitX()).head<2>().normalized();
    Eigen::Vector2d to_table = (table.pose.pos - chair.pose.pos).head<2>();
    EXPECT_GT(chair_front.dot(to_table.normalized()), 0.95);
    for (const ObjectSpec& o : room->scene.objects) {
      EXPECT_LE(std::abs(o.pos.x()), 4.0 + 1e-9);
      EXPECT_LE(std::abs(o.pos.y()), 3.5 + 1e-9);
    }
  }
}

TEST(RoomTest, ARoomThatCannotBeFurnishedIsAnErrorNotAHang) {
  RoomRequest req;
  req.width_m = 3.0;
  req.depth_m = 3.0;
  req.items = {"bed", "sofa", "desk", "bed"};
  core::Rng rng(3);
  core::StatusOr<Room> room = GenerateRoom(req, rng);
  ASSERT_FALSE(room.ok());
  EXPECT_EQ(room.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(std::string(room.status().message()), HasSubstr("cannot furnish a 3.0 x 3.0 m"));
  req.items = {"piano"};
  room = GenerateRoom(req, rng);
  ASSERT_FALSE(room.ok());
  EXPECT_THAT(std::string(room.status().message()),
              HasSubstr("unknown item 'piano'; valid items are: desk, bed"));
}

TEST(RoomTest, StartsAreFreeAndAtTheAskedDistance) {
  RoomRequest req;
  req.items = {"desk", "bed", "armchair"};
  core::Rng rng(5);
  core::StatusOr<Room> room = GenerateRoom(req, rng);
  ASSERT_TRUE(room.ok()) << room.status();
  for (int i = 0; i < 50; ++i) {
    core::StatusOr<HumanSpec> h =
        RandomStart(room->scene, req, Eigen::Vector2d(0.5, 0.5), 1.0, 6.0, 0.45, rng);
    ASSERT_TRUE(h.ok()) << h.status();
    double r = (h->pos_xy - Eigen::Vector2d(0.5, 0.5)).norm();
    EXPECT_GE(r, 1.0);
    EXPECT_LE(r, 6.0);
  }
}

}  // namespace
}  // namespace simhuman::world
