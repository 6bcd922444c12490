#include "simhuman/world/objects.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace simhuman::world {
namespace {

using ::testing::HasSubstr;

constexpr double kTol = 1e-9;

ObjectSpec Spec(const std::string& type) {
  ObjectSpec s;
  s.id = type + "000";
  s.type = type;
  return s;
}

core::CatalogObject Build(const ObjectSpec& spec) {
  core::StatusOr<core::CatalogObject> obj = BuildObject(spec);
  EXPECT_TRUE(obj.ok()) << obj.status();
  return obj.ok() ? *obj : core::CatalogObject{};
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> PartBounds(const core::CatalogObject& o,
                                                       const std::string& part) {
  const core::CatalogPart* p = o.FindPart(part);
  EXPECT_NE(p, nullptr) << part;
  return p ? core::ShapesBounds(p->shapes)
           : std::make_pair(Eigen::Vector3d::Zero().eval(), Eigen::Vector3d::Zero().eval());
}

bool SameShape(const core::Shape& a, const core::Shape& b) {
  return a.kind == b.kind && (a.size - b.size).norm() < kTol &&
         (a.pose.pos - b.pose.pos).norm() < kTol && a.pose.quat.isApprox(b.pose.quat, kTol);
}

double Volume(const core::Shape& s) {
  return 8.0 * s.size.x() * s.size.y() * s.size.z();  // boxes only
}

TEST(ObjectsTest, EveryTypeBuildsWithItsParts) {
  const std::map<std::string, std::vector<std::string>> expected = {
      {"chair", {"seat surface", "back surface"}},
      {"armchair", {"seat surface", "back surface", "left arm", "right arm"}},
      {"sofa", {"seat surface", "back surface", "left arm", "right arm"}},
      {"stool", {"seat surface"}},
      {"high_stool", {"seat surface"}},
      {"bed", {"mattress", "pillow"}},
      {"table", {"board"}},
      {"laptop", {"keyboard", "screen"}},
      {"box", {"top", "left side", "right side", "front side", "back side", "body"}},
      {"long_box", {"top", "left side", "right side", "front side", "back side", "body"}},
      {"cylinder", {"top", "body"}},
      {"sphere", {"body"}},
      {"cone", {"body"}},
      {"hourglass", {"top", "body"}}};
  ASSERT_EQ(ObjectTypes().size(), expected.size() + 2);  // + marker and mesh, tested below
  for (const std::string& type : ObjectTypes()) {
    if (type == "marker" || type == "mesh") continue;
    SCOPED_TRACE(type);
    core::CatalogObject o = Build(Spec(type));
    EXPECT_EQ(o.type, type);
    EXPECT_EQ(o.id, type + "000");
    std::vector<std::string> names = o.PartNames();
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()),
              std::set<std::string>(expected.at(type).begin(), expected.at(type).end()));
    EXPECT_GT(o.shapes.size(), 0u);
    for (const core::CatalogPart& p : o.parts) {
      ASSERT_FALSE(p.shapes.empty()) << p.name;
      for (const core::Shape& ps : p.shapes) {
        bool found = false;
        for (const core::Shape& s : o.shapes) found |= SameShape(ps, s);
        EXPECT_TRUE(found) << p.name << " has a shape that is not in shapes";
      }
    }
    for (const core::Shape& s : o.shapes) {
      EXPECT_TRUE(s.size.allFinite());
      EXPECT_GT(s.size.x(), 0.0);
      if (s.kind != core::ShapeKind::kSphere) {
        EXPECT_GT(s.size.y(), 0.0);
      }
    }
    // standing on the floor
    auto [lo, hi] = o.LocalBounds();
    EXPECT_NEAR(lo.z(), 0.0, 1e-3);
    EXPECT_GT(hi.z(), 0.05);
    EXPECT_FALSE(o.color.empty());
    EXPECT_EQ(o.movable, AlwaysMovable(type));
  }
}

TEST(ObjectsTest, ZeroShotShapesAreFrustums) {
  ObjectSpec cone = Spec("cone");
  cone.size = {{"radius", 0.05}, {"height", 0.16}};
  cone.scale = 3;  // heavier than the 0.1 kg floor of the mass by volume
  core::CatalogObject c = Build(cone);
  ASSERT_EQ(c.shapes.size(), 1u);
  EXPECT_EQ(c.shapes[0].kind, core::ShapeKind::kFrustum);
  EXPECT_NEAR(c.mass_kg, 100.0 * 27 * M_PI * 0.05 * 0.05 * 0.16 / 3, 1e-9);  // a cone's volume
  auto [lo, hi] = c.LocalBounds();
  EXPECT_NEAR(lo.z(), 0.0, 1e-12);
  EXPECT_NEAR(hi.z(), 0.48, 1e-12);
  // the hourglass: two frustums meeting at the waist
  ObjectSpec glass = Spec("hourglass");
  core::CatalogObject g = Build(glass);
  ASSERT_EQ(g.shapes.size(), 2u);
  const core::Shape* top = &g.FindPart("top")->shapes[0];
  EXPECT_NEAR(top->size.x(), 0.025, 1e-12);  // its bottom is the waist
  EXPECT_NEAR(top->size.z(), 0.045, 1e-12);
  glass.size = {{"waist_radius", 0.05}};
  EXPECT_NE(BuildObject(glass).status().ToString().find("waist_radius must be below radius"),
            std::string::npos);
}

TEST(ObjectsTest, MeshObjectsComeFromTheirObjFile) {
  ObjectSpec spec = Spec("mesh");
  spec.mesh = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/meshes/vase.obj";
  spec.scale = 0.5;
  core::CatalogObject o = Build(spec);
  ASSERT_EQ(o.shapes.size(), 1u);
  EXPECT_EQ(o.shapes[0].kind, core::ShapeKind::kMesh);
  EXPECT_TRUE(o.movable);
  auto [lo, hi] = o.LocalBounds();
  EXPECT_NEAR(lo.z(), 0.0, 1e-9);           // resting on its lowest vertex
  EXPECT_NEAR(hi.z(), 0.08, 1e-6);          // scaled
  EXPECT_NEAR(lo.x() + hi.x(), 0.0, 1e-9);  // centred in plan
  EXPECT_NEAR(lo.y() + hi.y(), 0.0, 1e-9);
  // errors name the object and what would be valid
  spec.mesh.clear();
  EXPECT_NE(BuildObject(spec).status().ToString().find("needs \"mesh\""), std::string::npos);
  spec.mesh = "/nonexistent/vase.obj";
  EXPECT_NE(BuildObject(spec).status().ToString().find("/nonexistent/vase.obj"), std::string::npos);
  ObjectSpec box = Spec("box");
  box.mesh = "x.obj";
  EXPECT_NE(BuildObject(box).status().ToString().find("only for objects of type mesh"),
            std::string::npos);
}

TEST(ObjectsTest, MarkerIsASmallNonCollidingPoint) {
  ObjectSpec spec = Spec("marker");
  spec.pos = Eigen::Vector3d(0.3, -0.2, 1.1);
  core::CatalogObject m = Build(spec);
  ASSERT_NE(m.FindPart("point"), nullptr);
  EXPECT_FALSE(m.collides);
  EXPECT_FALSE(m.movable);
  Eigen::Vector3d np = core::NearestPointOnShapes(m.FindPart("point")->shapes, m.pose,
                                                  Eigen::Vector3d(0.3, -0.2, 2.0));
  EXPECT_NEAR(np.z(), 1.1 + 0.015, 1e-9);
}

TEST(ObjectsTest, PartNamesAndAliasesResolve) {
  core::CatalogObject chair = Build(Spec("chair"));
  const core::CatalogPart* seat = chair.FindPart("seat surface");
  ASSERT_NE(seat, nullptr);
  EXPECT_EQ(chair.FindPart("seat soft surface42"), seat);
  EXPECT_EQ(chair.FindPart("seat_hard_surface10"), seat);
  EXPECT_EQ(chair.FindPart("Seat"), seat);
  EXPECT_EQ(chair.FindPart("back soft surface47"), chair.FindPart("back surface"));
  EXPECT_EQ(chair.FindPart("backrest"), chair.FindPart("back surface"));
  EXPECT_EQ(chair.FindPart("left arm"), nullptr);  // a plain chair has no arms
  EXPECT_EQ(chair.FindPart("arm sofa style44"), nullptr);

  core::CatalogObject armchair = Build(Spec("armchair"));
  EXPECT_EQ(armchair.FindPart("left armrest hard surface")->name, "left arm");
  EXPECT_EQ(armchair.FindPart("right_armrest")->name, "right arm");
  ASSERT_NE(armchair.FindPart("arm sofa style44"), nullptr);  // ambiguous: the left arm first
  EXPECT_EQ(armchair.FindPart("arm sofa style44")->name, "left arm");
  EXPECT_EQ(armchair.FindPart("armrest_hard_surface26")->name, "left arm");

  core::CatalogObject bed = Build(Spec("bed"));
  EXPECT_EQ(bed.FindPart("mattress25")->name, "mattress");
  EXPECT_EQ(bed.FindPart("mattress16")->name, "mattress");
  EXPECT_EQ(bed.FindPart("blanket3")->name, "mattress");
  EXPECT_EQ(bed.FindPart("pillow17")->name, "pillow");

  EXPECT_EQ(Build(Spec("table")).FindPart("table top")->name, "board");
  EXPECT_EQ(Build(Spec("table")).FindPart("tabletop")->name, "board");
  EXPECT_EQ(Build(Spec("laptop")).FindPart("keyboard15")->name, "keyboard");
  EXPECT_EQ(Build(Spec("laptop")).FindPart("screen")->name, "screen");
  EXPECT_EQ(Build(Spec("high stool")).FindPart("seat")->name, "seat surface");
  EXPECT_EQ(Build(Spec("box")).FindPart("container")->name, "body");
}

TEST(ObjectsTest, ChairSeatHeightAndFrontEdgeMatchTheSpec) {
  core::CatalogObject chair = Build(Spec("chair"));
  auto [lo, hi] = PartBounds(chair, "seat surface");
  EXPECT_NEAR(hi.z(), 0.45, kTol);
  EXPECT_NEAR(hi.x(), 0.225, kTol);  // front edge at +x
  EXPECT_NEAR(lo.x(), -0.225, kTol);
  EXPECT_NEAR(hi.y() - lo.y(), 0.45, kTol);
  auto [blo, bhi] = PartBounds(chair, "back surface");
  EXPECT_NEAR(bhi.z(), 0.90, kTol);
  EXPECT_LE(bhi.x(), lo.x() + kTol);  // the back is behind the seat

  ObjectSpec spec = Spec("chair");
  spec.size = {{"seat_height", 0.5}, {"seat_depth", 0.48}};
  chair = Build(spec);
  std::tie(lo, hi) = PartBounds(chair, "seat surface");
  EXPECT_NEAR(hi.z(), 0.5, kTol);
  EXPECT_NEAR(hi.x(), 0.24, kTol);

  spec.scale = 1.2;
  chair = Build(spec);
  std::tie(lo, hi) = PartBounds(chair, "seat surface");
  EXPECT_NEAR(hi.z(), 0.6, kTol);
  EXPECT_NEAR(hi.x(), 0.288, kTol);
}

TEST(ObjectsTest, ArmsAreOnTheSeatedPersonsSides) {
  for (const std::string type : {"armchair", "sofa"}) {
    SCOPED_TRACE(type);
    core::CatalogObject o = Build(Spec(type));
    auto [llo, lhi] = PartBounds(o, "left arm");
    auto [rlo, rhi] = PartBounds(o, "right arm");
    auto [slo, shi] = PartBounds(o, "seat surface");
    EXPECT_GE(llo.y(), shi.y() - kTol);  // left = +y
    EXPECT_LE(rhi.y(), slo.y() + kTol);
    EXPECT_GT(lhi.z(), shi.z() + 0.1);  // arm rests above the seat
    EXPECT_NEAR(lhi.z(), DefaultSizes(type).at("arm_height"), kTol);
    EXPECT_NEAR(shi.x(), DefaultSizes(type).at("seat_depth") / 2, kTol);  // front edge
  }
  core::CatalogObject sofa = Build(Spec("sofa"));
  auto [lo, hi] = sofa.LocalBounds();
  EXPECT_GE(hi.y() - lo.y(), 1.8);
  EXPECT_LE(hi.y() - lo.y(), 2.0);
  EXPECT_NEAR(PartBounds(sofa, "seat surface").second.z(), 0.42, kTol);
  EXPECT_NEAR(PartBounds(Build(Spec("armchair")), "left arm").second.z(), 0.63, kTol);
}

TEST(ObjectsTest, StoolsBedsTablesLaptops) {
  EXPECT_NEAR(PartBounds(Build(Spec("stool")), "seat surface").second.z(), 0.45, kTol);
  EXPECT_NEAR(PartBounds(Build(Spec("high_stool")), "seat surface").second.z(), 0.75, kTol);

  core::CatalogObject bed = Build(Spec("bed"));
  auto [mlo, mhi] = PartBounds(bed, "mattress");
  EXPECT_NEAR(mhi.z(), 0.5, kTol);
  EXPECT_NEAR(mhi.y() - mlo.y(), 2.0, kTol);  // long along y
  EXPECT_NEAR(mhi.x() - mlo.x(), 1.5, kTol);
  auto [plo, phi] = PartBounds(bed, "pillow");
  EXPECT_NEAR(plo.z(), mhi.z(), kTol);  // resting on the mattress
  EXPECT_GT(plo.y(), 0.4);              // at the +y (head) end
  EXPECT_LE(phi.y(), mhi.y());

  core::CatalogObject table = Build(Spec("table"));
  auto [tlo, thi] = PartBounds(table, "board");
  EXPECT_NEAR(thi.z(), 0.75, kTol);
  EXPECT_NEAR(thi.y() - tlo.y(), 1.2, kTol);

  core::CatalogObject laptop = Build(Spec("laptop"));
  auto [klo, khi] = PartBounds(laptop, "keyboard");
  auto [slo, shi] = PartBounds(laptop, "screen");
  EXPECT_NEAR(klo.z(), 0.0, kTol);
  EXPECT_GT(shi.z(), 0.2);             // the screen stands up
  EXPECT_LE(shi.x(), klo.x() + 1e-3);  // behind the keyboard (the user is at +x)
  EXPECT_NEAR(khi.y() - klo.y(), 0.34, kTol);
}

TEST(ObjectsTest, BoxPartsTileTheBoxAndBoxesAreMovable) {
  ObjectSpec spec = Spec("box");
  spec.size = {{"depth", 0.5}, {"width", 0.4}, {"height", 0.3}};
  core::CatalogObject box = Build(spec);
  EXPECT_TRUE(box.movable);
  EXPECT_GE(box.mass_kg, 2.0);
  EXPECT_LE(box.mass_kg, 10.0);
  double volume = 0;
  for (const core::Shape& s : box.shapes) volume += Volume(s);
  EXPECT_NEAR(volume, 0.5 * 0.4 * 0.3, 1e-9);
  auto [lo, hi] = box.LocalBounds();
  EXPECT_NEAR(hi.x(), 0.25, kTol);
  EXPECT_NEAR(hi.z(), 0.3, kTol);
  EXPECT_NEAR(PartBounds(box, "top").first.z(), 0.3 - 0.02, kTol);
  EXPECT_NEAR(PartBounds(box, "left side").second.y(), 0.2, kTol);
  EXPECT_NEAR(PartBounds(box, "right side").first.y(), -0.2, kTol);
  EXPECT_NEAR(PartBounds(box, "front side").second.x(), 0.25, kTol);
  EXPECT_NEAR(PartBounds(box, "back side").first.x(), -0.25, kTol);
  EXPECT_EQ(box.FindPart("body")->shapes.size(), box.shapes.size());

  spec.mass_kg = 7.5;
  EXPECT_DOUBLE_EQ(Build(spec).mass_kg, 7.5);
  // a mass makes any object movable
  ObjectSpec chair = Spec("chair");
  chair.mass_kg = 6.0;
  EXPECT_TRUE(Build(chair).movable);
}

TEST(ObjectsTest, PoseComesFromPositionAndYaw) {
  ObjectSpec spec = Spec("chair");
  spec.pos = Eigen::Vector3d(1, 2, 0);
  spec.yaw_rad = M_PI / 2;
  core::CatalogObject o = Build(spec);
  EXPECT_TRUE(o.pose.pos.isApprox(Eigen::Vector3d(1, 2, 0)));
  // the front (+x) now faces world +y
  EXPECT_TRUE((o.pose.quat * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST(ObjectsTest, ErrorsNameTheCulpritAndListValidChoices) {
  ObjectSpec spec = Spec("chiar");
  auto r = BuildObject(spec);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("'chiar'"));
  EXPECT_THAT(std::string(r.status().message()),
              HasSubstr("chair, armchair, sofa, stool, high_stool, bed"));

  spec = Spec("bed");
  spec.size = {{"seat_height", 0.5}};
  r = BuildObject(spec);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("'seat_height'"));
  EXPECT_THAT(std::string(r.status().message()),
              HasSubstr("length, width, mattress_height, headboard_height"));
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("bed000"));

  for (double bad : {-0.1, 0.0, std::nan(""), static_cast<double>(INFINITY)}) {
    spec = Spec("table");
    spec.size = {{"height", bad}};
    EXPECT_FALSE(BuildObject(spec).ok()) << bad;
    spec = Spec("table");
    spec.scale = bad;
    EXPECT_FALSE(BuildObject(spec).ok()) << bad;
    spec = Spec("box");
    spec.mass_kg = bad;
    EXPECT_FALSE(BuildObject(spec).ok()) << bad;
  }
  spec = Spec("table");
  spec.size = {{"height", 5.0}};
  r = BuildObject(spec);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("valid range"));

  spec = Spec("chair");
  spec.size = {{"back_height", 0.5}};
  r = BuildObject(spec);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("back_height"));

  spec = Spec("chair");
  spec.color = "mauve";
  r = BuildObject(spec);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(std::string(r.status().message()), HasSubstr("red, green, blue"));

  spec = Spec("chair");
  spec.pos.x() = std::nan("");
  EXPECT_FALSE(BuildObject(spec).ok());
  spec = Spec("chair");
  spec.yaw_rad = INFINITY;
  EXPECT_FALSE(BuildObject(spec).ok());
  spec = Spec("chair");
  spec.id.clear();
  EXPECT_FALSE(BuildObject(spec).ok());
}

TEST(ObjectsTest, RandomSpecsStayInRangeAndAreDeterministic) {
  for (const std::string& type : ObjectTypes()) {
    if (type == "mesh") continue;  // its shape is a file (MeshObjectsComeFromTheirObjFile)
    SCOPED_TRACE(type);
    core::Rng rng(17);
    auto ranges = SizeRanges(type);
    ASSERT_FALSE(ranges.empty());
    for (int i = 0; i < 100; ++i) {
      ObjectSpec spec = RandomObjectSpec(type, rng);
      ASSERT_EQ(spec.size.size(), ranges.size());
      for (const auto& [key, value] : spec.size) {
        EXPECT_GE(value, ranges.at(key).first) << key;
        EXPECT_LE(value, ranges.at(key).second) << key;
      }
      if (type == "box") {
        ASSERT_TRUE(spec.mass_kg.has_value());
        EXPECT_GE(*spec.mass_kg, 2.0);
        EXPECT_LE(*spec.mass_kg, 10.0);
      }
      ASSERT_TRUE(BuildObject(spec).ok()) << BuildObject(spec).status();
    }
    core::Rng a(5), b(5);
    EXPECT_EQ(RandomObjectSpec(type, a).size, RandomObjectSpec(type, b).size);
  }
  // defaults lie inside the random ranges, which lie inside the valid ranges
  for (const std::string& type : ObjectTypes()) {
    for (const SizeParam& p : SizeParams(type)) {
      EXPECT_LE(p.random_lo_m, p.default_m) << type << " " << p.name;
      EXPECT_GE(p.random_hi_m, p.default_m) << type << " " << p.name;
      EXPECT_LE(p.valid_lo_m, p.random_lo_m) << type << " " << p.name;
      EXPECT_GE(p.valid_hi_m, p.random_hi_m) << type << " " << p.name;
    }
  }
}

TEST(ObjectsTest, TypesAndColours) {
  EXPECT_EQ(CanonicalObjectType("High stool"), "high_stool");
  EXPECT_EQ(CanonicalObjectType("high-stool"), "high_stool");
  EXPECT_EQ(CanonicalObjectType("CHAIR"), "chair");
  EXPECT_FALSE(CanonicalObjectType("throne").has_value());
  EXPECT_TRUE(SizeParams("throne").empty());

  auto red = ColorRgba("red");
  ASSERT_TRUE(red.has_value());
  EXPECT_GT((*red)[0], 0.5f);
  EXPECT_EQ(ColorRgba("Gray"), ColorRgba("grey"));
  EXPECT_FALSE(ColorRgba("mauve").has_value());
  EXPECT_EQ(ColorNames().size(), 10u);
  EXPECT_EQ(DefaultColor("chair"), "brown");
  EXPECT_EQ(DefaultColor("throne"), "grey");
  for (const std::string& type : ObjectTypes()) EXPECT_TRUE(ColorRgba(DefaultColor(type)));

  ObjectSpec spec = Spec("box");
  spec.color = "Gray";
  EXPECT_EQ(Build(spec).color, "grey");
}

}  // namespace
}  // namespace simhuman::world
