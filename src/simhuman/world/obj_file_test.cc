// OBJ files: what is read, and errors that name the file, the line and what is valid.
#include "simhuman/world/obj_file.h"

#include <gtest/gtest.h>

#include <string>

namespace simhuman::world {
namespace {

const char kCube[] = R"(# a 10 cm cube, quads, with normals and texture coordinates
o cube
v 0 0 0
v 0.1 0 0
v 0.1 0.1 0
v 0 0.1 0
v 0 0 0.1
v 0.1 0 0.1
v 0.1 0.1 0.1
v 0 0.1 0.1
vn 0 0 1
vt 0 0
f 1 4 3 2
f 5/1 6/1 7/1 8/1
f 1//1 2//1 6//1 5//1
f 2/1/1 3/1/1 7/1/1 6/1/1
f 3 4 8 7
f -4 -8 -5 -1
)";

TEST(ObjFileTest, QuadsBecomeTrianglesAndEveryCornerFormIsRead) {
  core::StatusOr<std::shared_ptr<const core::Mesh>> m = ParseObjMesh(kCube, "cube.obj");
  ASSERT_TRUE(m.ok()) << m.status();
  EXPECT_EQ((*m)->vertices.size(), 8u);
  EXPECT_EQ((*m)->faces.size(), 12u);
  EXPECT_TRUE((*m)->lo.isApprox(Eigen::Vector3d::Zero()));
  EXPECT_TRUE((*m)->hi.isApprox(Eigen::Vector3d::Constant(0.1)));
  // the negative indices of the last face count back from the eighth vertex
  EXPECT_EQ((*m)->faces.back()[0], 4);
  EXPECT_EQ((*m)->faces.back()[2], 7);
  core::Shape s;
  s.kind = core::ShapeKind::kMesh;
  s.mesh = *m;
  s.size = Eigen::Vector3d::Ones();
  EXPECT_NEAR(core::ShapeVolume(s), 0.001, 1e-12);
}

void ExpectError(const std::string& text, const std::string& part) {
  core::StatusOr<std::shared_ptr<const core::Mesh>> m = ParseObjMesh(text, "thing.obj");
  ASSERT_FALSE(m.ok()) << text;
  EXPECT_NE(std::string(m.status().message()).find("thing.obj"), std::string::npos) << m.status();
  EXPECT_NE(std::string(m.status().message()).find(part), std::string::npos) << m.status();
}

TEST(ObjFileTest, BadFilesAreErrorsNamingTheFileAndTheLine) {
  ExpectError("v 0 0 0\nv 1 x 0\n", "line 2: a vertex needs three finite numbers");
  ExpectError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "line 4: face corner 9");
  ExpectError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 a\n", "is not a vertex index");
  ExpectError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "at least three corners");
  ExpectError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "at least 4");
  ExpectError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n", "no faces");
  // a flat square and a 10 m slab are not objects
  ExpectError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n", "must be within");
  ExpectError("v 0 0 0\nv 10 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n", "must be within");
  core::StatusOr<std::shared_ptr<const core::Mesh>> missing = ReadObjMesh("/nonexistent/x.obj");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(std::string(missing.status().message()).find("/nonexistent/x.obj"), std::string::npos);
}

TEST(ObjFileTest, TheShippedVaseIsAClosedSolid) {
  core::StatusOr<std::shared_ptr<const core::Mesh>> m =
      ReadObjMesh(std::string(SIMHUMAN_SOURCE_DIR) + "/" + "assets/meshes/vase.obj");
  ASSERT_TRUE(m.ok()) << m.status();
  core::Shape s;
  s.kind = core::ShapeKind::kMesh;
  s.mesh = *m;
  s.size = Eigen::Vector3d::Ones();
  const Eigen::Vector3d ext = (*m)->hi - (*m)->lo;
  EXPECT_NEAR(ext.z(), 0.16, 1e-6);
  EXPECT_GT(ext.x(), 0.08);
  EXPECT_LT(ext.x(), 0.10);  // a hand's width, as DASH's objects (6-10 cm)
  // the faces enclose about the volume of its bounding cylinder's share (closed and outward)
  EXPECT_GT(core::ShapeVolume(s), 0.5 * ext.x() * ext.y() * ext.z());
  EXPECT_LT(core::ShapeVolume(s), ext.x() * ext.y() * ext.z());
}

}  // namespace
}  // namespace simhuman::world
