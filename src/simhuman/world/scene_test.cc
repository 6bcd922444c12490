#include "simhuman/world/scene.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "simhuman/core/json_io.h"
#include "simhuman/world/model_builder.h"

namespace simhuman::world {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr double kTol = 1e-9;
constexpr double kAngleTol = 1e-9;

std::string DataPath(const std::string& name) {
  return std::string(SIMHUMAN_SOURCE_DIR) + "/tests/data/world/" + name;
}

// loads tests/data/world/<name> and returns the error message (empty when it loaded)
std::string LoadError(const std::string& name) {
  core::StatusOr<SceneSpec> s = LoadScene(DataPath(name));
  return s.ok() ? std::string() : std::string(s.status().message());
}

double AngleDiff(double a, double b) { return std::remainder(a - b, 2 * M_PI); }

SceneSpec Parse(const std::string& text) {
  core::StatusOr<nlohmann::json> j = core::ParseJson(text, "<string>");
  EXPECT_TRUE(j.ok()) << j.status();
  core::StatusOr<SceneSpec> s = ParseSceneJson(*j, "<string>");
  EXPECT_TRUE(s.ok()) << s.status();
  return s.ok() ? *s : SceneSpec{};
}

std::string ParseError(const nlohmann::json& j) {
  core::StatusOr<SceneSpec> s = ParseSceneJson(j, "test.json");
  return s.ok() ? std::string() : std::string(s.status().message());
}

TEST(SceneTest, MalformedFilesNameTheCulprit) {
  std::string e = LoadError("malformed_syntax.json");
  EXPECT_THAT(e, HasSubstr("malformed_syntax.json:5:"));
  EXPECT_THAT(e, HasSubstr("invalid JSON"));

  e = LoadError("malformed_unknown_key.json");
  EXPECT_THAT(e, HasSubstr("/objects/0: unknown key 'colour'"));
  EXPECT_THAT(e, HasSubstr("color"));

  e = LoadError("malformed_unknown_type.json");
  EXPECT_THAT(e, HasSubstr("/objects/1/type: unknown object type 'throne'"));
  EXPECT_THAT(
      e, HasSubstr("chair, armchair, sofa, stool, high_stool, bed, table, laptop, marker, box"));

  e = LoadError("malformed_missing_pos.json");
  EXPECT_THAT(e, HasSubstr("/objects/0/pos: missing required key"));

  e = LoadError("malformed_nan.json");
  EXPECT_THAT(e, HasSubstr("malformed_nan.json:4:"));
  EXPECT_THAT(e, HasSubstr("invalid JSON"));

  e = LoadError("malformed_overflow.json");
  EXPECT_THAT(e, HasSubstr("malformed_overflow.json: invalid JSON"));
  EXPECT_THAT(e, HasSubstr("1e999"));

  e = LoadError("malformed_non_numeric.json");
  EXPECT_THAT(e, HasSubstr("/objects/0/pos/1: expected a number, got string"));

  e = LoadError("malformed_duplicate_id.json");
  EXPECT_THAT(e, HasSubstr("/objects/1: duplicate object id 'chair000'"));
  EXPECT_THAT(e, HasSubstr("/objects/0"));

  e = LoadError("malformed_size_key.json");
  EXPECT_THAT(e, HasSubstr("/objects/0/size/seat_height: unknown size key for type bed"));
  EXPECT_THAT(e, HasSubstr("length, width, mattress_height, headboard_height"));

  e = LoadError("malformed_plan_name.json");
  EXPECT_THAT(e, HasSubstr("/0000/obj/000/name: unknown ScenePlan object name 'toilet'"));
  EXPECT_THAT(e, HasSubstr("chair, armchair, sofa, couch"));

  e = LoadError("malformed_human_overlap.json");
  EXPECT_THAT(e, HasSubstr("/humans/0"));
  EXPECT_THAT(e, HasSubstr("table000"));
}

TEST(SceneTest, NonFiniteAndWrongTypesInMemoryJson) {
  nlohmann::json j = {{"objects", {{{"type", "chair"}, {"pos", {0.0, NAN}}}}}};
  EXPECT_THAT(ParseError(j), HasSubstr("test.json: /objects/0/pos/1: number is not finite"));
  j = {{"objects", {{{"type", "chair"}, {"pos", {0, 0}}, {"scale", "big"}}}}};
  EXPECT_THAT(ParseError(j), HasSubstr("/objects/0/scale: expected a number"));
  j = {{"objects", {{{"type", "chair"}, {"pos", {0, 0, 0, 0}}}}}};
  EXPECT_THAT(ParseError(j), HasSubstr("/objects/0/pos: expected an array of 2 or 3 numbers"));
  j = {{"objects", {{{"type", "chair"}, {"pos", {0, 0}}, {"size", {{"seat_height", 3.0}}}}}}};
  EXPECT_THAT(ParseError(j), HasSubstr("/objects/0: object 'chair000': size 'seat_height'"));
  j = {{"objects", nlohmann::json::array()}, {"humans", {{{"pos", {0, 0}}, {"posture", "fly"}}}}};
  EXPECT_THAT(ParseError(j), HasSubstr("/humans/0/posture: unknown posture 'fly'"));
  j = {{"objects", nlohmann::json::array()}, {"humans", {{{"pos", {0, 0}}, {"scale", 3}}}}};
  EXPECT_THAT(ParseError(j), HasSubstr("/humans/0/scale"));
  j = {{"objects", nlohmann::json::array()}, {"humans", nlohmann::json::array()}};
  EXPECT_THAT(ParseError(j), HasSubstr("/humans: expected a non-empty array"));
  j = {{"objects", nlohmann::json::array()}, {"humans", {{{"pos", {0, 0}}, {"kind", "robot"}}}}};
  EXPECT_THAT(ParseError(j), HasSubstr("/humans/0/kind: unknown agent kind 'robot'; valid agent "
                                       "kinds are: humanoid, humanoid_right_hand"));
  j = {{"name", "x"}};
  EXPECT_THAT(ParseError(j), HasSubstr("/objects: missing required key"));
  EXPECT_THAT(ParseError(nlohmann::json::array()), HasSubstr("expected a JSON object"));
}

TEST(SceneTest, HumansOfAKindAndTheirBodyPointsReachTheCatalog) {
  nlohmann::json j = {
      {"objects", nlohmann::json::array()},
      {"humans",
       {{{"pos", {0, 0}}}, {{"pos", {2, 0}}, {"kind", "humanoid_right_hand"}, {"scale", 0.8}}}}};
  core::StatusOr<SceneSpec> spec = ParseSceneJson(j, "kinds.json");
  ASSERT_TRUE(spec.ok()) << spec.status();
  EXPECT_EQ(spec->humans[0].kind, "humanoid");
  EXPECT_EQ(spec->humans[1].kind, "humanoid_right_hand");
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*spec);
  ASSERT_TRUE(cat.ok()) << cat.status();
  ASSERT_EQ(cat->num_agents(), 2);
  EXPECT_EQ(cat->agents[0].body_points.size(), core::kNumBodyJoints);
  EXPECT_TRUE(cat->agents[1].body_points.Find("right fingertips").has_value());
  EXPECT_DOUBLE_EQ(cat->agents[1].scale, 0.8);
  // the kind round-trips; the default kind is not written
  nlohmann::json out = SceneToJson(*spec);
  EXPECT_FALSE(out["humans"][0].contains("kind"));
  EXPECT_EQ(out["humans"][1]["kind"], "humanoid_right_hand");
  core::StatusOr<SceneSpec> again = ParseSceneJson(out, "again.json");
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->humans[1].kind, "humanoid_right_hand");
}

TEST(SceneTest, OurFormWithDefaults) {
  SceneSpec s = Parse(R"({
    "name": "demo",
    "objects": [
      {"type": "chair", "pos": [0, 0], "yaw_deg": 90, "color": "red"},
      {"id": "t", "type": "Table", "pos": [2, 0, 0], "size": {"height": 0.7}, "scale": 1.1},
      {"type": "box", "pos": [0, -2], "mass_kg": 3}
    ],
    "humans": [{"pos": [1, 1], "yaw_deg": 180, "scale": 0.7}]
  })");
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.objects[0].id, "chair000");
  EXPECT_NEAR(s.objects[0].yaw_rad, M_PI / 2, kAngleTol);
  EXPECT_EQ(s.objects[0].color, "red");
  EXPECT_EQ(s.objects[1].id, "t");
  EXPECT_EQ(s.objects[1].type, "table");
  EXPECT_DOUBLE_EQ(s.objects[1].size.at("height"), 0.7);
  EXPECT_DOUBLE_EQ(s.objects[1].scale, 1.1);
  EXPECT_EQ(s.objects[2].id, "box002");
  EXPECT_DOUBLE_EQ(*s.objects[2].mass_kg, 3.0);
  ASSERT_EQ(s.humans.size(), 1u);
  EXPECT_NEAR(s.humans[0].yaw_rad, M_PI, kAngleTol);
  EXPECT_DOUBLE_EQ(s.humans[0].scale, 0.7);
  EXPECT_EQ(s.humans[0].posture, "stand");

  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(s);
  ASSERT_TRUE(cat.ok()) << cat.status();
  EXPECT_EQ(cat->num_agents(), 1);
  EXPECT_NEAR(WorldBounds(*cat->Find("t")).second.z(), 0.77, 1e-9);
  EXPECT_TRUE(cat->Find("box002")->movable);
}

TEST(SceneTest, DefaultHumanStandsInFrontOfTheFirstObjectFacingIt) {
  SceneSpec s = Parse(R"({"objects": [{"type": "chair", "pos": [1, 1], "yaw_deg": 90}]})");
  ASSERT_EQ(s.humans.size(), 1u);
  EXPECT_TRUE(s.humans[0].pos_xy.isApprox(Eigen::Vector2d(1, 3), 1e-9));
  EXPECT_NEAR(AngleDiff(s.humans[0].yaw_rad, -M_PI / 2), 0.0, kAngleTol);
  EXPECT_EQ(s.name, "scene");

  // the spot in front is taken by a sofa: the human goes elsewhere, still clear of everything
  s = Parse(R"({"objects": [{"type": "chair", "pos": [0, 0]},
                            {"type": "sofa", "pos": [2, 0]}]})");
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(s);
  ASSERT_TRUE(cat.ok());
  Eigen::Vector2d p = s.humans[0].pos_xy;
  EXPECT_NEAR(p.norm(), 2.0, 1e-9);
  EXPECT_FALSE(p.isApprox(Eigen::Vector2d(2, 0), 1e-6));
  for (const core::CatalogObject& o : cat->objects) {
    auto [lo, hi] = WorldBounds(o);
    bool inside = p.x() > lo.x() - 0.35 && p.x() < hi.x() + 0.35 && p.y() > lo.y() - 0.35 &&
                  p.y() < hi.y() + 0.35;
    EXPECT_FALSE(inside) << o.id;
  }
  EXPECT_NEAR(AngleDiff(s.humans[0].yaw_rad, std::atan2(-p.y(), -p.x())), 0.0, kAngleTol);
}

TEST(SceneTest, ScenePlanTable7) {
  core::StatusOr<SceneSpec> s = LoadScene(DataPath("scene_plan_table7.json"));
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(s->name, "0000");
  ASSERT_EQ(s->objects.size(), 4u);
  const char* ids[] = {"chair000", "table001", "laptop002", "bed003"};
  const char* types[] = {"chair", "table", "laptop", "bed"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(s->objects[i].id, ids[i]);
    EXPECT_EQ(s->objects[i].type, types[i]);
    EXPECT_DOUBLE_EQ(s->objects[i].scale, 1.0);  // their mesh scale is not applied
    EXPECT_TRUE(s->objects[i].size.empty());
  }
  EXPECT_TRUE(s->objects[0].pos.isApprox(Eigen::Vector3d(0, -2, 0)));
  EXPECT_NEAR(AngleDiff(s->objects[0].yaw_rad, 0.0), 0.0, kAngleTol);   // z -90 + 90
  EXPECT_NEAR(AngleDiff(s->objects[1].yaw_rad, M_PI), 0.0, kAngleTol);  // z +90 + 90
  EXPECT_NEAR(AngleDiff(s->objects[2].yaw_rad, M_PI), 0.0, kAngleTol);
  EXPECT_NEAR(AngleDiff(s->objects[3].yaw_rad, M_PI / 2), 0.0, kAngleTol);  // bed: z + 180

  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*s);
  ASSERT_TRUE(cat.ok()) << cat.status();
  const core::CatalogObject& chair = *cat->Find("chair000");
  const core::CatalogObject& table = *cat->Find("table001");
  const core::CatalogObject& laptop = *cat->Find("laptop002");
  // the chair faces the table, the laptop faces the chair and rests on the table top
  EXPECT_GT(chair.pose.ApplyInverse(table.pose.pos).x(), 0.5);
  EXPECT_GT(laptop.pose.ApplyInverse(chair.pose.pos).x(), 0.5);
  EXPECT_NEAR(laptop.pose.pos.z(), WorldBounds(table).second.z(), 1e-9);
  EXPECT_NEAR(laptop.pose.pos.z(), 0.75, 1e-9);
  EXPECT_TRUE(OverlappingObjects(*cat).empty());
  // plan part names ground
  EXPECT_NE(chair.FindPart("seat soft surface58"), nullptr);
  EXPECT_NE(laptop.FindPart("keyboard15"), nullptr);
  EXPECT_NE(cat->Find("bed003")->FindPart("mattress16"), nullptr);
  EXPECT_NE(cat->Find("bed003")->FindPart("pillow17"), nullptr);
  // a default human, clear of the objects
  ASSERT_EQ(s->humans.size(), 1u);
  EXPECT_EQ(cat->num_agents(), 1);
}

TEST(SceneTest, ScenePlanUnwrappedAndMultiPlan) {
  nlohmann::json plan = {{"obj",
                          {{"000",
                            {{"id", "1"},
                             {"name", "Bed"},
                             {"rotate", {{M_PI / 2, 0, 0}, {0, 0, -M_PI / 2}}},
                             {"scale", 3},
                             {"transfer", {1, 2, 0}},
                             {"stand_point", {{1, 3, 0.86}}}}}}},
                         {"contact_pairs", nlohmann::json::array()}};
  core::StatusOr<SceneSpec> s = ParseSceneJson(plan, "plans/p.json");
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(s->name, "p");
  EXPECT_EQ(s->objects[0].id, "Bed000");
  EXPECT_EQ(s->objects[0].type, "bed");

  nlohmann::json two = {{"0000", plan}, {"0001", plan}};
  EXPECT_THAT(ParseError(two), HasSubstr("2 ScenePlan entries (0000, 0001)"));

  nlohmann::json bad = plan;
  bad["obj"]["000"]["rotate"] = {{0, 0, 0}};
  EXPECT_THAT(ParseError(bad), HasSubstr("/obj/000/rotate/0: the first rotation"));
  bad = plan;
  bad["obj"]["000"]["rotate"] = {{M_PI / 2, 0, 0}, {0.3, 0, 0}};
  EXPECT_THAT(ParseError(bad), HasSubstr("/obj/000/rotate/1: only rotations about z"));
  bad = plan;
  bad["obj"]["000"]["colour"] = "red";
  EXPECT_THAT(ParseError(bad), HasSubstr("/obj/000: unknown key 'colour'"));
  bad = plan;
  bad["obj"]["000"].erase("transfer");
  EXPECT_THAT(ParseError(bad), HasSubstr("/obj/000/transfer: missing required key"));
  bad = plan;
  bad["instruction"] = "sleep";
  EXPECT_THAT(ParseError(bad), HasSubstr("unknown key 'instruction'"));
}

TEST(SceneTest, BuiltinScenesLoadAndDoNotOverlap) {
  ASSERT_EQ(BuiltinSceneNames().size(), 10u);
  for (const std::string& name : BuiltinSceneNames()) {
    SCOPED_TRACE(name);
    core::StatusOr<SceneSpec> s = LoadScene(name);
    ASSERT_TRUE(s.ok()) << s.status();
    EXPECT_EQ(s->name, name);
    ASSERT_FALSE(s->humans.empty());
    core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*s);
    ASSERT_TRUE(cat.ok()) << cat.status();
    EXPECT_EQ(cat->num_agents(), static_cast<int>(s->humans.size()));
    auto overlaps = OverlappingObjects(*cat);
    for (const auto& [a, b] : overlaps) ADD_FAILURE() << a << " overlaps " << b;
    // round trip through our JSON form
    core::StatusOr<SceneSpec> again = ParseSceneJson(SceneToJson(*s), "<roundtrip>");
    ASSERT_TRUE(again.ok()) << again.status();
    EXPECT_EQ(SceneToJson(*again).dump(), SceneToJson(*s).dump());
  }
  core::StatusOr<SceneSpec> living = LoadScene("living_room");
  std::set<std::string> types;
  for (const ObjectSpec& o : living->objects) types.insert(o.type);
  for (const char* t : {"chair", "armchair", "sofa", "table", "laptop", "bed", "stool"}) {
    EXPECT_TRUE(types.count(t)) << t;
  }
}

TEST(SceneTest, LivingRoomLeavesRoomToWalkAndSit) {
  core::StatusOr<SceneSpec> s = LoadScene("living_room");
  ASSERT_TRUE(s.ok());
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*s);
  ASSERT_TRUE(cat.ok());
  // floor-standing objects are at least 0.4 m apart (0.65 m between the chair and the table)
  for (size_t a = 0; a < cat->objects.size(); ++a) {
    for (size_t b = a + 1; b < cat->objects.size(); ++b) {
      const auto& oa = cat->objects[a];
      const auto& ob = cat->objects[b];
      if (oa.type == "laptop" || ob.type == "laptop") continue;
      auto [alo, ahi] = WorldBounds(oa);
      auto [blo, bhi] = WorldBounds(ob);
      double gap =
          std::max({blo.x() - ahi.x(), alo.x() - bhi.x(), blo.y() - ahi.y(), alo.y() - bhi.y()});
      EXPECT_GE(gap, 0.4 - 1e-9) << oa.id << " " << ob.id;
    }
  }
  // the laptop rests on the table, facing the chair
  const core::CatalogObject& laptop = *cat->Find("laptop002");
  const core::CatalogObject& chair = *cat->Find("chair000");
  EXPECT_NEAR(laptop.pose.pos.z(), 0.75, 1e-9);
  EXPECT_GT(laptop.pose.ApplyInverse(chair.pose.pos).x(), 0.0);
  EXPECT_GT(chair.pose.ApplyInverse(laptop.pose.pos).x(), 0.0);
}

TEST(SceneTest, SitDemoHumanHasHisBackToTheSeat) {
  core::StatusOr<SceneSpec> s = LoadScene("sit_demo");
  ASSERT_TRUE(s.ok());
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*s);
  ASSERT_TRUE(cat.ok());
  const core::CatalogObject& chair = cat->objects.at(0);
  double front_edge = core::ShapesBounds(chair.FindPart("seat surface")->shapes).second.x();
  Eigen::Vector3d human(s->humans[0].pos_xy.x(), s->humans[0].pos_xy.y(), 0);
  Eigen::Vector3d local = chair.pose.ApplyInverse(human);
  EXPECT_NEAR(local.x() - front_edge, 0.4, kTol);
  EXPECT_NEAR(local.y(), 0.0, kTol);
  // facing away from the chair, the way the chair faces
  EXPECT_NEAR(AngleDiff(s->humans[0].yaw_rad, 0.0), 0.0, kAngleTol);
}

TEST(SceneTest, UnknownSceneListsBuiltins) {
  core::StatusOr<SceneSpec> s = LoadScene("kitchen");
  ASSERT_FALSE(s.ok());
  EXPECT_TRUE(absl::IsNotFound(s.status()));
  EXPECT_THAT(s.status().message(),
              HasSubstr("living_room, bedroom, office, tabletop_demo, sit_demo, empty"));
}

TEST(SceneTest, AssetSceneFilesLoad) {
  for (const char* f : {"unihsi_table7_plan.json", "lounge_two_humans.json"}) {
    core::StatusOr<SceneSpec> s =
        LoadScene(std::string(SIMHUMAN_SOURCE_DIR) + "/assets/scenes/" + f);
    ASSERT_TRUE(s.ok()) << f << ": " << s.status();
    core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*s);
    ASSERT_TRUE(cat.ok()) << cat.status();
    EXPECT_TRUE(OverlappingObjects(*cat).empty()) << f;
  }
}

TEST(SceneTest, OverlapsAreDetected) {
  SceneSpec s;
  ObjectSpec a;
  a.id = "a";
  a.type = "table";
  ObjectSpec b = a;
  b.id = "b";
  b.pos.x() = 0.5;
  s.objects = {a, b};
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(s);
  ASSERT_TRUE(cat.ok());
  ASSERT_EQ(OverlappingObjects(*cat).size(), 1u);
  EXPECT_EQ(cat->num_agents(), 0);
  s.objects[1].id = "a";
  EXPECT_THAT(std::string(BuildCatalog(s).status().message()), HasSubstr("duplicate object id"));
}

TEST(SceneTest, FrictionIsReadCheckedWrittenAndReachesTheModel) {
  SceneSpec s = Parse(R"({"objects": [{"type": "box", "pos": [0, 0], "friction": 1.1},
                                      {"type": "table", "pos": [2, 0], "friction": 0.5},
                                      {"type": "cylinder", "pos": [0, 1]}]})");
  ASSERT_EQ(s.objects.size(), 3u);
  ASSERT_TRUE(s.objects[0].friction.has_value());
  EXPECT_NEAR(*s.objects[0].friction, 1.1, kTol);
  EXPECT_FALSE(s.objects[2].friction.has_value());
  nlohmann::json j = SceneToJson(s);
  EXPECT_NEAR(j["objects"][1]["friction"].get<double>(), 0.5, kTol);
  EXPECT_FALSE(j["objects"][2].contains("friction"));
  core::StatusOr<SceneSpec> again = ParseSceneJson(j, "<again>");
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->objects[1].friction, s.objects[1].friction);

  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(s);
  ASSERT_TRUE(cat.ok()) << cat.status();
  EXPECT_EQ(cat->objects[0].friction, s.objects[0].friction);
  core::StatusOr<std::string> xml = BuildModelXml(*cat, {}, ModelOptions{});
  ASSERT_TRUE(xml.ok()) << xml.status();
  // movable: the given sliding friction, torsional 0.05; static: torsional 0.02; both priority 1
  EXPECT_THAT(*xml, HasSubstr("condim=\"4\" friction=\"1.1 0.05 0.01\" priority=\"1\""));
  EXPECT_THAT(*xml, HasSubstr("friction=\"0.5 0.02 0.01\" priority=\"1\""));
  EXPECT_THAT(*xml, HasSubstr("condim=\"4\" friction=\"0.9 0.05 0.01\"/>"));

  nlohmann::json bad = {{"objects", {{{"type", "box"}, {"pos", {0, 0}}, {"friction", 2.5}}}}};
  std::string e = ParseError(bad);
  EXPECT_THAT(e, HasSubstr("/objects/0/friction"));
  EXPECT_THAT(e, HasSubstr("[0.1, 2]"));
  bad["objects"][0]["friction"] = "slippery";
  EXPECT_THAT(ParseError(bad), HasSubstr("/objects/0/friction: expected a number"));
  ObjectSpec o = s.objects[0];
  o.friction = 0.01;
  core::StatusOr<core::CatalogObject> built = BuildObject(o);
  ASSERT_FALSE(built.ok());
  EXPECT_THAT(std::string(built.status().message()),
              HasSubstr("object 'box000': friction 0.01 is outside the valid range [0.1, 2]"));
}

// "mesh" names an OBJ file for objects of type mesh; it round-trips and the model gets a mesh
// asset (MuJoCo takes its convex hull) with feet to stand on
TEST(SceneParse, MeshObjectsNameTheirObjFile) {
  const std::string vase = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/meshes/vase.obj";
  nlohmann::json j = {
      {"objects",
       {{{"type", "mesh"}, {"pos", {1, 0}}, {"mesh", vase}}, {{"type", "cone"}, {"pos", {2, 0}}}}}};
  core::StatusOr<SceneSpec> s = ParseSceneJson(j, "<test>");
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(s->objects[0].mesh, vase);
  core::StatusOr<SceneSpec> again = ParseSceneJson(SceneToJson(*s), "<again>");
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->objects[0].mesh, vase);
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*s);
  ASSERT_TRUE(cat.ok()) << cat.status();
  core::StatusOr<std::string> xml = BuildModelXml(*cat, {}, ModelOptions{});
  ASSERT_TRUE(xml.ok()) << xml.status();
  EXPECT_THAT(*xml, HasSubstr("<mesh name=\"obj/mesh000/0\" vertex=\""));
  EXPECT_THAT(*xml, HasSubstr("type=\"mesh\" mesh=\"obj/cone001/0\""));
  EXPECT_THAT(*xml, HasSubstr("obj/mesh000/rim0"));  // feet under the mesh
  EXPECT_THAT(*xml, HasSubstr("obj/cone001/rim7"));  // a ring under the cone's base only
  EXPECT_THAT(*xml, Not(HasSubstr("obj/cone001/rim8")));

  nlohmann::json bad = {{"objects", {{{"type", "mesh"}, {"pos", {0, 0}}}}}};
  EXPECT_THAT(ParseError(bad), HasSubstr("/objects/0: an object of type mesh needs \"mesh\""));
  bad = {{"objects", {{{"type", "box"}, {"pos", {0, 0}}, {"mesh", "x.obj"}}}}};
  EXPECT_THAT(ParseError(bad), HasSubstr("/objects/0/mesh: \"mesh\" names an OBJ file for "
                                         "objects of type mesh, not box"));
  bad = {{"objects", {{{"type", "mesh"}, {"pos", {0, 0}}, {"mesh", "/nonexistent/a.obj"}}}}};
  EXPECT_THAT(ParseError(bad),
              HasSubstr("/objects/0: object 'mesh000': mesh file '/nonexistent/a.obj' cannot be "
                        "read"));
}

// MuJoCo's buffer sizes come from ModelOptions (the tabletop's are small: every mjData clears
// them when made); sizes below the minimum are refused by name
TEST(ModelBuilder, BufferSizesComeFromTheOptionsAndAreChecked) {
  SceneSpec s;
  s.name = "sizes";
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(s);
  ASSERT_TRUE(cat.ok()) << cat.status();
  ModelOptions o;
  o.nconmax = 250;
  o.njmax = 1000;
  o.nstack = 800000;
  core::StatusOr<std::string> xml = BuildModelXml(*cat, {}, o);
  ASSERT_TRUE(xml.ok()) << xml.status();
  EXPECT_THAT(*xml, HasSubstr("<size nconmax=\"250\" njmax=\"1000\" nstack=\"800000\"/>"));
  o.njmax = 0;
  xml = BuildModelXml(*cat, {}, o);
  ASSERT_FALSE(xml.ok());
  EXPECT_THAT(std::string(xml.status().message()), HasSubstr("njmax 0 must be at least 1"));
}

}  // namespace
}  // namespace simhuman::world
