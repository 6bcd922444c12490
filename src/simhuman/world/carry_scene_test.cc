// Scenes with carrying: the "movable" key and the built-in carry scenes.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/world/carry.h"
#include "simhuman/world/scene.h"

namespace simhuman::world {
namespace {

using ::testing::HasSubstr;

core::StatusOr<SceneSpec> ParseText(const std::string& text) {
  return ParseSceneJson(nlohmann::json::parse(text), "scene.json");
}

TEST(CarrySceneTest, MovableTrueGivesFurnitureItsDefaultMass) {
  core::StatusOr<SceneSpec> s = ParseText(
      R"({"objects": [{"type": "armchair", "pos": [0, 0], "movable": true},
                      {"type": "table", "pos": [3, 0], "movable": true, "mass_kg": 9},
                      {"type": "sofa", "pos": [-3, 0], "movable": false},
                      {"type": "box", "pos": [0, 3], "movable": true}]})");
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(s->objects[0].mass_kg, DefaultMovableMassKg("armchair"));
  EXPECT_EQ(s->objects[1].mass_kg, 9.0);
  EXPECT_FALSE(s->objects[2].mass_kg.has_value());
  EXPECT_FALSE(s->objects[3].mass_kg.has_value());
  core::StatusOr<core::SceneCatalog> c = BuildCatalog(*s);
  ASSERT_TRUE(c.ok()) << c.status();
  EXPECT_TRUE(c->objects[0].movable);
  EXPECT_TRUE(c->objects[0].carry.carryable());
  EXPECT_FALSE(c->objects[2].movable);
  EXPECT_TRUE(c->objects[3].carry.carryable());
}

TEST(CarrySceneTest, MalformedMovableKeysNameTheCulprit) {
  auto error = [](const std::string& text) {
    core::StatusOr<SceneSpec> s = ParseText(text);
    EXPECT_FALSE(s.ok());
    return s.ok() ? std::string() : std::string(s.status().message());
  };
  std::string e = error(R"({"objects": [{"type": "bed", "pos": [0, 0], "movable": true}]})");
  EXPECT_THAT(e, HasSubstr("/objects/0/movable"));
  EXPECT_THAT(e, HasSubstr("armchair"));
  EXPECT_THAT(e, HasSubstr("mass_kg"));
  e = error(R"({"objects": [{"type": "chair", "pos": [0, 0], "movable": false, "mass_kg": 3}]})");
  EXPECT_THAT(e, HasSubstr("contradicts"));
  e = error(R"({"objects": [{"type": "box", "pos": [0, 0], "movable": false}]})");
  EXPECT_THAT(e, HasSubstr("always movable"));
  e = error(R"({"objects": [{"type": "chair", "pos": [0, 0], "movable": "yes"}]})");
  EXPECT_THAT(e, HasSubstr("/objects/0/movable"));
}

TEST(CarrySceneTest, BuiltinCarryScenes) {
  core::StatusOr<SceneSpec> demo = BuiltinScene("carry_demo");
  ASSERT_TRUE(demo.ok()) << demo.status();
  core::StatusOr<core::SceneCatalog> c = BuildCatalog(*demo);
  ASSERT_TRUE(c.ok()) << c.status();
  EXPECT_EQ(c->num_agents(), 1);
  EXPECT_TRUE(OverlappingObjects(*c).empty());
  const core::CatalogObject* box = c->Find("box000");
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->carry.max_carriers(), 1);
  EXPECT_LE(box->mass_kg, core::TeamCapacityKg(1));
  EXPECT_TRUE(c->Find("armchair003")->carry.carryable());
  EXPECT_FALSE(c->Find("bed001")->movable);
  EXPECT_FALSE(c->Find("sofa002")->movable);

  core::StatusOr<SceneSpec> team = BuiltinScene("carry_team_demo");
  ASSERT_TRUE(team.ok()) << team.status();
  c = BuildCatalog(*team);
  ASSERT_TRUE(c.ok()) << c.status();
  EXPECT_EQ(c->num_agents(), 2);
  EXPECT_TRUE(OverlappingObjects(*c).empty());
  EXPECT_EQ(c->Find("long_box000")->carry.min_carriers(), 2);
  EXPECT_EQ(c->Find("sofa001")->carry.min_carriers(), 2);
}

TEST(CarrySceneTest, ExistingScenesKeepFurnitureStatic) {
  for (const char* name : {"living_room", "bedroom", "office", "sit_demo"}) {
    core::StatusOr<SceneSpec> s = BuiltinScene(name);
    ASSERT_TRUE(s.ok()) << s.status();
    core::StatusOr<core::SceneCatalog> c = BuildCatalog(*s);
    ASSERT_TRUE(c.ok()) << c.status();
    for (const core::CatalogObject& o : c->objects) {
      if (o.type != "box") {
        EXPECT_FALSE(o.movable) << name << " " << o.id;
      }
    }
  }
}

}  // namespace
}  // namespace simhuman::world
