#include "simhuman/world/objects.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <sstream>

#include "simhuman/world/carry.h"
#include "simhuman/world/obj_file.h"

namespace simhuman::world {
namespace {

using Eigen::Vector3d;
using Sizes = std::map<std::string, double>;

// fixed construction constants (metres before scale)
constexpr double kChairSeatThickness = 0.05;
constexpr double kChairBackThickness = 0.04;
constexpr double kChairLegRadius = 0.02;
constexpr double kUpholsteredLegHeight = 0.10;
constexpr double kUpholsteredLegRadius = 0.025;
constexpr double kArmchairBackThickness = 0.15;
constexpr double kSofaBackThickness = 0.20;
constexpr double kStoolSeatThickness = 0.04;
constexpr double kStoolLegRadius = 0.015;
constexpr double kHighStoolFootrestHeight = 0.28;
constexpr double kBedLegHeight = 0.10;
constexpr double kBedMattressThickness = 0.22;
constexpr double kBedHeadboardThickness = 0.06;
constexpr double kPillowLength = 0.40;  // along the bed (y)
constexpr double kPillowHeight = 0.12;
constexpr double kTableBoardThickness = 0.04;
constexpr double kTableLegHalfWidth = 0.025;
constexpr double kLaptopBaseThickness = 0.018;
constexpr double kLaptopScreenThickness = 0.006;
constexpr double kLaptopScreenTiltRad = 15.0 * M_PI / 180.0;  // back from vertical
constexpr double kBoxFaceThickness = 0.02;
constexpr double kBoxDensityKgM3 = 100.0;  // a cardboard box with some contents
constexpr double kBoxMinMassKg = 0.1;
constexpr double kBoxMaxMassKg = 10.0;
constexpr double kLongBoxMassKg = 25.0;  // CooHOI's nominal two-agent box
constexpr double kLongBoxRandomMassLoKg = 15.0;
constexpr double kLongBoxRandomMassHiKg = 40.0;
constexpr double kMaxMassKg = 1000.0;
constexpr double kMinScale = 0.1;
constexpr double kMaxScale = 10.0;
constexpr double kMaxAbsPosM = 1000.0;

// aliases; the generic arm names are ambiguous between the two arms and are listed on both (the
// left arm first), so the plan grounder can pick the side by the body joint
const std::vector<std::string> kSeatAliases = {
    "seat",         "seat soft surface", "seat hard surface", "chair seat",
    "seat cushion", "cushion",           "seat frame",        "sofa seat"};
const std::vector<std::string> kBackAliases = {"back",
                                               "back soft surface",
                                               "back hard surface",
                                               "backrest",
                                               "back cushion",
                                               "back frame",
                                               "back complex decoration",
                                               "back frame horizontal bar",
                                               "back surface horizontal bar",
                                               "back surface vertical bar"};
const std::vector<std::string> kGenericArmAliases = {"arm",
                                                     "armrest",
                                                     "arm sofa style",
                                                     "armrest hard surface",
                                                     "armrest soft surface",
                                                     "arm holistic frame",
                                                     "arm horizontal bar"};

std::vector<std::string> ArmAliases(const std::string& side) {
  std::vector<std::string> out = {side + " armrest", side + " armrest hard surface",
                                  side + " armrest soft surface", side + " arm sofa style"};
  out.insert(out.end(), kGenericArmAliases.begin(), kGenericArmAliases.end());
  return out;
}

// an axis-aligned box from its bounds
core::Shape Box(const Vector3d& lo, const Vector3d& hi) {
  core::Shape s;
  s.kind = core::ShapeKind::kBox;
  s.pose.pos = 0.5 * (lo + hi);
  s.size = 0.5 * (hi - lo);
  return s;
}

// a vertical cylinder standing on z = z_lo
core::Shape Cylinder(double x, double y, double z_lo, double z_hi, double radius) {
  core::Shape s;
  s.kind = core::ShapeKind::kCylinder;
  s.pose.pos = Vector3d(x, y, 0.5 * (z_lo + z_hi));
  s.size = Vector3d(radius, 0.5 * (z_hi - z_lo), 0.0);
  return s;
}

// collects parts and solids; every part shape is also a solid
struct Assembly {
  void Part(const std::string& name, std::vector<std::string> aliases,
            std::vector<core::Shape> part_shapes) {
    for (const core::Shape& s : part_shapes) shapes.push_back(s);
    parts.push_back({name, std::move(aliases), std::move(part_shapes)});
  }
  // a part made of solids that are already in `shapes` (the box's "body")
  void PartOfExisting(const std::string& name, std::vector<std::string> aliases,
                      std::vector<core::Shape> part_shapes) {
    parts.push_back({name, std::move(aliases), std::move(part_shapes)});
  }
  void Solid(const core::Shape& s) { shapes.push_back(s); }

  std::vector<core::CatalogPart> parts;
  std::vector<core::Shape> shapes;
};

// four vertical legs at (+-x, +-y)
void AddLegs(Assembly& a, double x_front, double x_back, double y_half, double z_hi, double r) {
  for (double x : {x_front, x_back}) {
    for (double y : {y_half, -y_half}) a.Solid(Cylinder(x, y, 0.0, z_hi, r));
  }
}

void BuildChair(const Sizes& s, Assembly& a) {
  double h = s.at("seat_height"), w = s.at("seat_width"), d = s.at("seat_depth");
  double bh = s.at("back_height");
  double z_seat_lo = h - kChairSeatThickness;
  a.Part("seat surface", kSeatAliases,
         {Box(Vector3d(-d / 2, -w / 2, z_seat_lo), Vector3d(d / 2, w / 2, h))});
  a.Part("back surface", kBackAliases,
         {Box(Vector3d(-d / 2 - kChairBackThickness, -w / 2, z_seat_lo),
              Vector3d(-d / 2, w / 2, bh))});
  double inset = kChairLegRadius + 0.01;
  AddLegs(a, d / 2 - inset, -d / 2 + inset, w / 2 - inset, z_seat_lo, kChairLegRadius);
}

// armchair and sofa: an upholstered seat block on short legs, arms flush with the seat front,
// a full-width back behind the seat
void BuildUpholstered(const Sizes& s, double back_thickness, Assembly& a) {
  double h = s.at("seat_height"), w = s.at("seat_width"), d = s.at("seat_depth");
  double bh = s.at("back_height"), ah = s.at("arm_height"), aw = s.at("arm_width");
  double z0 = kUpholsteredLegHeight;
  a.Part("seat surface", kSeatAliases,
         {Box(Vector3d(-d / 2, -w / 2, z0), Vector3d(d / 2, w / 2, h))});
  a.Part(
      "back surface", kBackAliases,
      {Box(Vector3d(-d / 2 - back_thickness, -w / 2 - aw, z0), Vector3d(-d / 2, w / 2 + aw, bh))});
  a.Part("left arm", ArmAliases("left"),
         {Box(Vector3d(-d / 2, w / 2, z0), Vector3d(d / 2, w / 2 + aw, ah))});
  a.Part("right arm", ArmAliases("right"),
         {Box(Vector3d(-d / 2, -w / 2 - aw, z0), Vector3d(d / 2, -w / 2, ah))});
  double inset = kUpholsteredLegRadius + 0.015;
  AddLegs(a, d / 2 - inset, -d / 2 - back_thickness + inset, w / 2 + aw - inset, z0,
          kUpholsteredLegRadius);
}

void BuildStool(const Sizes& s, bool high, Assembly& a) {
  double h = s.at("seat_height"), r = s.at("seat_radius");
  double z_seat_lo = h - kStoolSeatThickness;
  core::Shape seat = Cylinder(0, 0, z_seat_lo, h, r);
  a.Part("seat surface", kSeatAliases, {seat});
  double c = 0.75 * r / std::sqrt(2.0);
  AddLegs(a, c, -c, c, z_seat_lo, kStoolLegRadius);
  if (high) {
    // a square footrest between the legs
    double z = kHighStoolFootrestHeight, t = kStoolLegRadius;
    for (double sgn : {1.0, -1.0}) {
      a.Solid(Box(Vector3d(-c, sgn * c - t, z - t), Vector3d(c, sgn * c + t, z + t)));
      a.Solid(Box(Vector3d(sgn * c - t, -c, z - t), Vector3d(sgn * c + t, c, z + t)));
    }
  }
}

void BuildBed(const Sizes& s, Assembly& a) {
  double len = s.at("length"), w = s.at("width"), mh = s.at("mattress_height");
  double hb = s.at("headboard_height");
  double z_mat_lo = mh - kBedMattressThickness;
  a.Part("mattress",
         {"mattress surface", "bed surface", "blanket", "hammock pad", "sleep area", "bed"},
         {Box(Vector3d(-w / 2, -len / 2, z_mat_lo), Vector3d(w / 2, len / 2, mh))});
  double pw = std::min(0.6, w - 0.2);
  double y_hi = len / 2 - 0.05;
  a.Part("pillow", {"pillows", "cushion", "head rest"},
         {Box(Vector3d(-pw / 2, y_hi - kPillowLength, mh),
              Vector3d(pw / 2, y_hi, mh + kPillowHeight))});
  // frame under the mattress, headboard at the head end (+y), legs
  a.Solid(Box(Vector3d(-w / 2, -len / 2, kBedLegHeight), Vector3d(w / 2, len / 2, z_mat_lo)));
  a.Solid(
      Box(Vector3d(-w / 2, len / 2, 0.0), Vector3d(w / 2, len / 2 + kBedHeadboardThickness, hb)));
  double inset = 0.06;
  AddLegs(a, w / 2 - inset, -w / 2 + inset, len / 2 - inset, kBedLegHeight, 0.03);
}

void BuildTable(const Sizes& s, Assembly& a) {
  double h = s.at("height"), w = s.at("width"), d = s.at("depth");
  double z_lo = h - kTableBoardThickness;
  a.Part("board",
         {"table top", "tabletop", "top", "desk top", "desktop", "table surface", "surface"},
         {Box(Vector3d(-d / 2, -w / 2, z_lo), Vector3d(d / 2, w / 2, h))});
  double lw = kTableLegHalfWidth, inset = lw + 0.03;
  for (double x : {d / 2 - inset, -d / 2 + inset}) {
    for (double y : {w / 2 - inset, -w / 2 + inset}) {
      a.Solid(Box(Vector3d(x - lw, y - lw, 0.0), Vector3d(x + lw, y + lw, z_lo)));
    }
  }
}

void BuildLaptop(const Sizes& s, Assembly& a) {
  double w = s.at("width"), d = s.at("depth"), sh = s.at("screen_height");
  a.Part("keyboard", {"keys", "keyboard surface", "base", "touchpad"},
         {Box(Vector3d(-d / 2, -w / 2, 0.0), Vector3d(d / 2, w / 2, kLaptopBaseThickness))});
  // the screen rises from the hinge at the back edge, tilted back (towards -x) by the tilt
  core::Shape screen;
  screen.kind = core::ShapeKind::kBox;
  screen.pose.quat =
      Eigen::Quaterniond(Eigen::AngleAxisd(-kLaptopScreenTiltRad, Vector3d::UnitY()));
  Vector3d up = screen.pose.quat * Vector3d::UnitZ();
  Vector3d normal = screen.pose.quat * Vector3d::UnitX();  // faces the user
  Vector3d hinge(-d / 2, 0.0, kLaptopBaseThickness);
  screen.pose.pos = hinge + up * (sh / 2) - normal * (kLaptopScreenThickness / 2);
  screen.size = Vector3d(kLaptopScreenThickness / 2, w / 2, sh / 2);
  a.Part("screen", {"display", "monitor", "lid"}, {screen});
}

void BuildBox(const Sizes& s, Assembly& a) {
  double d = s.at("depth"), w = s.at("width"), h = s.at("height");
  double t = std::min(kBoxFaceThickness, 0.25 * std::min({d, w, h}));
  // seven solids tile the box exactly: top and bottom slabs, front/back slabs between them,
  // left/right slabs between those, and the core
  core::Shape top = Box(Vector3d(-d / 2, -w / 2, h - t), Vector3d(d / 2, w / 2, h));
  core::Shape bottom = Box(Vector3d(-d / 2, -w / 2, 0.0), Vector3d(d / 2, w / 2, t));
  core::Shape front = Box(Vector3d(d / 2 - t, -w / 2, t), Vector3d(d / 2, w / 2, h - t));
  core::Shape back = Box(Vector3d(-d / 2, -w / 2, t), Vector3d(-d / 2 + t, w / 2, h - t));
  core::Shape left = Box(Vector3d(-d / 2 + t, w / 2 - t, t), Vector3d(d / 2 - t, w / 2, h - t));
  core::Shape right = Box(Vector3d(-d / 2 + t, -w / 2, t), Vector3d(d / 2 - t, -w / 2 + t, h - t));
  core::Shape core_solid =
      Box(Vector3d(-d / 2 + t, -w / 2 + t, t), Vector3d(d / 2 - t, w / 2 - t, h - t));
  a.Part("top", {"top side", "top surface", "lid"}, {top});
  a.Part("left side", {"left", "left surface"}, {left});
  a.Part("right side", {"right", "right surface"}, {right});
  a.Part("front side", {"front", "front surface"}, {front});
  a.Part("back side", {"back", "back surface"}, {back});
  a.Solid(bottom);
  a.Solid(core_solid);
  a.PartOfExisting("body", {"box", "whole", "container", "base frame"},
                   {top, bottom, front, back, left, right, core_solid});
}

// a vertical cylinder: a top slab (the surface things are stacked on) over the rest
void BuildCylinder(const Sizes& s, Assembly& a) {
  double r = s.at("radius"), h = s.at("height");
  double t = std::min(kBoxFaceThickness, 0.25 * h);
  core::Shape top = Cylinder(0, 0, h - t, h, r);
  core::Shape lower = Cylinder(0, 0, 0.0, h - t, r);
  a.Part("top", {"top side", "top surface", "lid"}, {top});
  a.Solid(lower);
  a.PartOfExisting("body", {"cylinder", "whole", "surface", "side"}, {top, lower});
}

// a frustum about +z from z_lo (radius r_lo) to z_hi (radius r_hi)
core::Shape Frustum(double z_lo, double r_lo, double z_hi, double r_hi) {
  core::Shape s;
  s.kind = core::ShapeKind::kFrustum;
  s.pose.pos = Vector3d(0, 0, 0.5 * (z_lo + z_hi));
  s.size = Vector3d(r_lo, 0.5 * (z_hi - z_lo), r_hi);
  return s;
}

// shapes not in DASH's training set (its zero-shot tests: a cone, an hourglass, a mesh)
void BuildCone(const Sizes& s, Assembly& a) {
  a.Part("body", {"cone", "whole", "surface", "side"},
         {Frustum(0.0, s.at("radius"), s.at("height"), 0.0)});
}

void BuildHourglass(const Sizes& s, Assembly& a) {
  const double r = s.at("radius"), w = s.at("waist_radius"), h = s.at("height");
  core::Shape lower = Frustum(0.0, r, h / 2, w);
  core::Shape upper = Frustum(h / 2, w, h, r);
  a.Part("top", {"top side", "top surface", "lid", "upper bulb"}, {upper});
  a.Solid(lower);
  a.PartOfExisting("body", {"hourglass", "whole", "surface", "side"}, {lower, upper});
}

// the mesh resting on its lowest vertex, its bounding box centred on the origin in x and y
void BuildMesh(const std::shared_ptr<const core::Mesh>& mesh, Assembly& a) {
  core::Shape s;
  s.kind = core::ShapeKind::kMesh;
  s.mesh = mesh;
  s.size = Vector3d::Ones();
  s.pose.pos = Vector3d(-0.5 * (mesh->lo.x() + mesh->hi.x()), -0.5 * (mesh->lo.y() + mesh->hi.y()),
                        -mesh->lo.z());
  a.Part("body", {"mesh", "object", "whole", "surface", "side"}, {s});
}

void BuildSphere(const Sizes& s, Assembly& a) {
  core::Shape ball;
  ball.kind = core::ShapeKind::kSphere;
  ball.size = Vector3d(s.at("radius"), 0, 0);
  ball.pose.pos = Vector3d(0, 0, s.at("radius"));
  a.Part("body", {"sphere", "ball", "whole", "surface", "top"}, {ball});
}

struct TypeInfo {
  std::string name;
  std::string default_color;
  std::vector<SizeParam> params;
  std::function<void(const Sizes&, Assembly&)> build;
  // cross-parameter constraints: {description, predicate}
  std::vector<std::pair<std::string, std::function<bool(const Sizes&)>>> constraints;
};

const std::vector<TypeInfo>& Types() {
  static const std::vector<TypeInfo>* types = [] {
    auto* t = new std::vector<TypeInfo>;
    auto back_above_seat =
        std::make_pair(std::string("back_height must exceed seat_height by at least 0.15"),
                       std::function<bool(const Sizes&)>([](const Sizes& s) {
                         return s.at("back_height") >= s.at("seat_height") + 0.15;
                       }));
    auto arm_above_seat =
        std::make_pair(std::string("arm_height must exceed seat_height by at least 0.05"),
                       std::function<bool(const Sizes&)>([](const Sizes& s) {
                         return s.at("arm_height") >= s.at("seat_height") + 0.05;
                       }));
    auto seat_above_legs =
        std::make_pair(std::string("seat_height must exceed the 0.10 legs by at least 0.05"),
                       std::function<bool(const Sizes&)>([](const Sizes& s) {
                         return s.at("seat_height") >= kUpholsteredLegHeight + 0.05;
                       }));
    t->push_back({"chair",
                  "brown",
                  {{"seat_height", 0.45, 0.42, 0.50, 0.25, 1.0, "top of the seat above the floor"},
                   {"seat_width", 0.45, 0.40, 0.52, 0.25, 1.0, "seat size along y"},
                   {"seat_depth", 0.45, 0.40, 0.50, 0.25, 1.0, "seat size along x"},
                   {"back_height", 0.90, 0.80, 1.00, 0.45, 2.0, "top of the back above the floor"}},
                  BuildChair,
                  {back_above_seat}});
    t->push_back(
        {"armchair",
         "red",
         {{"seat_height", 0.42, 0.38, 0.46, 0.20, 1.0, "top of the seat cushion above the floor"},
          {"seat_width", 0.55, 0.50, 0.65, 0.30, 1.5, "seat size along y, between the arms"},
          {"seat_depth", 0.52, 0.48, 0.58, 0.30, 1.0, "seat size along x, front edge to back"},
          {"back_height", 0.85, 0.75, 0.95, 0.40, 2.0, "top of the back above the floor"},
          {"arm_height", 0.63, 0.58, 0.68, 0.25, 1.5, "top of the arm rests above the floor"},
          {"arm_width", 0.12, 0.08, 0.16, 0.03, 0.5, "width of each arm rest along y"}},
         [](const Sizes& s, Assembly& a) { BuildUpholstered(s, kArmchairBackThickness, a); },
         {back_above_seat, arm_above_seat, seat_above_legs}});
    t->push_back(
        {"sofa",
         "grey",
         {{"seat_height", 0.42, 0.38, 0.46, 0.20, 1.0, "top of the seat cushion above the floor"},
          {"seat_width", 1.60, 1.40, 1.80, 0.80, 4.0, "seat size along y, between the arms"},
          {"seat_depth", 0.58, 0.52, 0.65, 0.30, 1.2, "seat size along x, front edge to back"},
          {"back_height", 0.85, 0.75, 0.95, 0.40, 2.0, "top of the back above the floor"},
          {"arm_height", 0.62, 0.55, 0.68, 0.25, 1.5, "top of the arms above the floor"},
          {"arm_width", 0.18, 0.12, 0.22, 0.03, 0.6, "width of each arm along y"}},
         [](const Sizes& s, Assembly& a) { BuildUpholstered(s, kSofaBackThickness, a); },
         {back_above_seat, arm_above_seat, seat_above_legs}});
    t->push_back({"stool",
                  "brown",
                  {{"seat_height", 0.45, 0.42, 0.50, 0.15, 1.2, "top of the seat above the floor"},
                   {"seat_radius", 0.17, 0.15, 0.20, 0.08, 0.5, "radius of the round seat"}},
                  [](const Sizes& s, Assembly& a) { BuildStool(s, false, a); },
                  {}});
    t->push_back({"high_stool",
                  "black",
                  {{"seat_height", 0.75, 0.65, 0.80, 0.40, 1.2, "top of the seat above the floor"},
                   {"seat_radius", 0.18, 0.15, 0.20, 0.08, 0.5, "radius of the round seat"}},
                  [](const Sizes& s, Assembly& a) { BuildStool(s, true, a); },
                  {}});
    t->push_back(
        {"bed",
         "white",
         {{"length", 2.00, 1.90, 2.20, 1.50, 3.0, "mattress size along y (head end at +y)"},
          {"width", 1.50, 1.20, 1.80, 0.70, 3.0, "mattress size along x"},
          {"mattress_height", 0.50, 0.45, 0.60, 0.35, 1.2, "top of the mattress above the floor"},
          {"headboard_height", 0.90, 0.80, 1.10, 0.40, 2.0,
           "top of the headboard above the floor"}},
         BuildBed,
         {{"headboard_height must not be below mattress_height",
           [](const Sizes& s) { return s.at("headboard_height") >= s.at("mattress_height"); }}}});
    t->push_back({"table",
                  "brown",
                  {{"height", 0.75, 0.70, 0.78, 0.30, 1.30, "top of the board above the floor"},
                   {"width", 1.20, 1.00, 1.60, 0.30, 4.0, "board size along y"},
                   {"depth", 0.75, 0.60, 0.90, 0.30, 2.0, "board size along x"}},
                  BuildTable,
                  {}});
    t->push_back({"laptop",
                  "grey",
                  {{"width", 0.34, 0.30, 0.38, 0.20, 0.50, "base and screen size along y"},
                   {"depth", 0.24, 0.21, 0.27, 0.15, 0.35, "base size along x"},
                   {"screen_height", 0.22, 0.19, 0.25, 0.12, 0.35, "screen size from the hinge"}},
                  BuildLaptop,
                  {}});
    t->push_back({"marker",
                  "red",
                  {{"radius", 0.015, 0.01, 0.02, 0.005, 0.2, "radius of the marker sphere"}},
                  [](const Sizes& sz, Assembly& a) {
                    core::Shape ball;
                    ball.kind = core::ShapeKind::kSphere;
                    ball.size = Vector3d(sz.at("radius"), 0, 0);
                    a.Part("point", {"target", "marker"}, {ball});
                  },
                  {}});
    t->push_back({"box",
                  "orange",
                  {{"depth", 0.40, 0.30, 0.60, 0.03, 1.5, "size along x"},
                   {"width", 0.40, 0.30, 0.60, 0.03, 1.5, "size along y"},
                   {"height", 0.30, 0.25, 0.50, 0.03, 1.5, "size along z"}},
                  BuildBox,
                  {}});
    t->push_back(
        {"long_box",
         "yellow",
         {{"length", 2.00, 1.60, 2.40, 1.0, 4.0, "size along x (the long axis)"},
          {"width", 0.50, 0.40, 0.60, 0.1, 1.5, "size along y"},
          {"height", 0.50, 0.40, 0.60, 0.1, 1.5, "size along z"}},
         [](const Sizes& s, Assembly& a) {
           BuildBox(
               {{"depth", s.at("length")}, {"width", s.at("width")}, {"height", s.at("height")}},
               a);
         },
         {}});
    t->push_back({"cylinder",
                  "blue",
                  {{"radius", 0.04, 0.03, 0.06, 0.01, 1.0, "radius"},
                   {"height", 0.10, 0.06, 0.15, 0.02, 2.0, "size along z"}},
                  BuildCylinder,
                  {}});
    t->push_back(
        {"sphere", "green", {{"radius", 0.04, 0.03, 0.06, 0.01, 1.0, "radius"}}, BuildSphere, {}});
    t->push_back({"cone",
                  "red",
                  {{"radius", 0.04, 0.03, 0.05, 0.01, 1.0, "radius of the base"},
                   {"height", 0.15, 0.13, 0.18, 0.02, 2.0, "base to apex"}},
                  BuildCone,
                  {}});
    t->push_back({"hourglass",
                  "yellow",
                  {{"radius", 0.045, 0.035, 0.05, 0.01, 1.0, "radius of the base and the top"},
                   {"waist_radius", 0.025, 0.02, 0.03, 0.005, 1.0, "radius at half height"},
                   {"height", 0.15, 0.13, 0.18, 0.02, 2.0, "size along z"}},
                  BuildHourglass,
                  {{"waist_radius must be below radius",
                    [](const Sizes& s) { return s.at("waist_radius") < s.at("radius"); }}}});
    // the shape comes from ObjectSpec::mesh, scaled by ObjectSpec::scale
    t->push_back({"mesh", "grey", {}, nullptr, {}});
    return t;
  }();
  return *types;
}

const TypeInfo* FindType(std::string_view type) {
  std::optional<std::string> canon = CanonicalObjectType(type);
  if (!canon) return nullptr;
  for (const TypeInfo& t : Types()) {
    if (t.name == *canon) return &t;
  }
  return nullptr;
}

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

core::Status Invalid(const ObjectSpec& spec, const std::string& msg) {
  std::string who = spec.id.empty() ? std::string("object") : "object '" + spec.id + "'";
  return absl::InvalidArgumentError(who + ": " + msg);
}

struct PaletteColor {
  const char* name;
  std::array<float, 4> rgba;
};

constexpr PaletteColor kPalette[] = {
    {"red", {0.80f, 0.15f, 0.15f, 1.0f}},    {"green", {0.20f, 0.62f, 0.25f, 1.0f}},
    {"blue", {0.20f, 0.35f, 0.80f, 1.0f}},   {"yellow", {0.95f, 0.85f, 0.20f, 1.0f}},
    {"white", {0.92f, 0.92f, 0.90f, 1.0f}},  {"black", {0.12f, 0.12f, 0.12f, 1.0f}},
    {"brown", {0.55f, 0.36f, 0.20f, 1.0f}},  {"grey", {0.50f, 0.50f, 0.52f, 1.0f}},
    {"orange", {0.95f, 0.55f, 0.15f, 1.0f}}, {"purple", {0.55f, 0.30f, 0.70f, 1.0f}},
};

// the palette name for `name` (case-insensitive, "gray" = "grey"), nullopt if none
std::optional<std::string> CanonicalColor(std::string_view name) {
  std::string s;
  for (char c : name) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s == "gray") s = "grey";
  for (const PaletteColor& c : kPalette) {
    if (s == c.name) return s;
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> ColorNames() {
  std::vector<std::string> out;
  for (const PaletteColor& c : kPalette) out.push_back(c.name);
  return out;
}

std::optional<std::array<float, 4>> ColorRgba(std::string_view name) {
  std::optional<std::string> canon = CanonicalColor(name);
  if (!canon) return std::nullopt;
  for (const PaletteColor& c : kPalette) {
    if (*canon == c.name) return c.rgba;
  }
  return std::nullopt;
}

std::string DefaultColor(std::string_view type) {
  const TypeInfo* t = FindType(type);
  return t ? t->default_color : std::string("grey");
}

std::vector<std::string> ObjectTypes() {
  std::vector<std::string> out;
  for (const TypeInfo& t : Types()) out.push_back(t.name);
  return out;
}

std::optional<std::string> CanonicalObjectType(std::string_view name) {
  std::string s;
  for (char c : name) {
    if (c == ' ' || c == '-') {
      s += '_';
    } else {
      s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  for (const TypeInfo& t : Types()) {
    if (t.name == s) return s;
  }
  return std::nullopt;
}

std::vector<SizeParam> SizeParams(std::string_view type) {
  const TypeInfo* t = FindType(type);
  return t ? t->params : std::vector<SizeParam>{};
}

std::map<std::string, double> DefaultSizes(std::string_view type) {
  std::map<std::string, double> out;
  for (const SizeParam& p : SizeParams(type)) out[p.name] = p.default_m;
  return out;
}

std::map<std::string, std::pair<double, double>> SizeRanges(std::string_view type) {
  std::map<std::string, std::pair<double, double>> out;
  for (const SizeParam& p : SizeParams(type)) out[p.name] = {p.random_lo_m, p.random_hi_m};
  return out;
}

ObjectSpec RandomObjectSpec(std::string_view type, core::Rng& rng) {
  ObjectSpec spec;
  spec.type = CanonicalObjectType(type).value_or(std::string(type));
  spec.id = spec.type + "000";
  for (const SizeParam& p : SizeParams(type)) {
    spec.size[p.name] = rng.Uniform(p.random_lo_m, p.random_hi_m);
  }
  std::vector<std::string> colors = ColorNames();
  spec.color = colors[static_cast<size_t>(rng.UniformInt(0, static_cast<int>(colors.size()) - 1))];
  if (spec.type == "box") spec.mass_kg = rng.Uniform(2.0, 10.0);
  if (spec.type == "long_box") {
    spec.mass_kg = rng.Uniform(kLongBoxRandomMassLoKg, kLongBoxRandomMassHiKg);
  }
  if (spec.type == "cylinder" || spec.type == "sphere" || spec.type == "cone" ||
      spec.type == "hourglass") {
    spec.mass_kg = rng.Uniform(0.1, 1.0);
  }
  return spec;
}

bool AlwaysMovable(std::string_view type) {
  for (const char* t : {"box", "long_box", "cylinder", "sphere", "cone", "hourglass", "mesh"}) {
    if (type == t) return true;
  }
  return false;
}

core::StatusOr<core::CatalogObject> BuildObject(const ObjectSpec& spec) {
  const TypeInfo* type = FindType(spec.type);
  if (type == nullptr) {
    return Invalid(spec, "unknown object type '" + spec.type +
                             "'; valid types are: " + core::JoinNames(ObjectTypes()));
  }
  if (spec.id.empty()) return Invalid(spec, "empty object id");
  if (!spec.pos.allFinite() || spec.pos.cwiseAbs().maxCoeff() > kMaxAbsPosM) {
    return Invalid(spec, "position must be finite and within " + Num(kMaxAbsPosM) + " m");
  }
  if (!std::isfinite(spec.yaw_rad)) return Invalid(spec, "yaw is not finite");
  if (!std::isfinite(spec.scale) || spec.scale < kMinScale || spec.scale > kMaxScale) {
    return Invalid(spec, "scale " + Num(spec.scale) + " is outside [" + Num(kMinScale) + ", " +
                             Num(kMaxScale) + "]");
  }
  if (spec.mass_kg &&
      (!std::isfinite(*spec.mass_kg) || *spec.mass_kg <= 0 || *spec.mass_kg > kMaxMassKg)) {
    return Invalid(spec,
                   "mass_kg " + Num(*spec.mass_kg) + " is outside (0, " + Num(kMaxMassKg) + "]");
  }
  if (spec.friction && (!std::isfinite(*spec.friction) || *spec.friction < kMinFriction ||
                        *spec.friction > kMaxFriction)) {
    return Invalid(spec, "friction " + Num(*spec.friction) + " is outside the valid range [" +
                             Num(kMinFriction) + ", " + Num(kMaxFriction) + "]");
  }
  std::string color = spec.color.empty() ? type->default_color : spec.color;
  if (!ColorRgba(color)) {
    return Invalid(spec, "unknown colour '" + spec.color +
                             "'; valid colours are: " + core::JoinNames(ColorNames()));
  }
  // resolve and check the sizes
  Sizes sizes;
  std::vector<std::string> keys;
  for (const SizeParam& p : type->params) {
    sizes[p.name] = p.default_m;
    keys.push_back(p.name);
  }
  for (const auto& [key, value] : spec.size) {
    // clang before 16 cannot capture a structured binding
    const std::string& wanted = key;
    auto it = std::find_if(type->params.begin(), type->params.end(),
                           [&](const SizeParam& p) { return p.name == wanted; });
    if (it == type->params.end()) {
      return Invalid(spec, "unknown size key '" + key + "' for type " + type->name +
                               "; valid keys are: " + core::JoinNames(keys));
    }
    if (!std::isfinite(value) || value <= 0) {
      return Invalid(spec,
                     "size '" + key + "' must be a positive finite number, got " + Num(value));
    }
    if (value < it->valid_lo_m || value > it->valid_hi_m) {
      return Invalid(spec, "size '" + key + "' = " + Num(value) +
                               " m is outside the valid range [" + Num(it->valid_lo_m) + ", " +
                               Num(it->valid_hi_m) + "] for type " + type->name);
    }
    sizes[key] = value;
  }
  for (const auto& [what, ok] : type->constraints) {
    if (!ok(sizes)) return Invalid(spec, "inconsistent sizes: " + what);
  }

  Assembly a;
  if (type->name == "mesh") {
    if (spec.mesh.empty()) {
      return Invalid(spec, "type mesh needs \"mesh\": the path of an OBJ file");
    }
    core::StatusOr<std::shared_ptr<const core::Mesh>> mesh = ReadObjMesh(spec.mesh);
    if (!mesh.ok()) return Invalid(spec, std::string(mesh.status().message()));
    BuildMesh(*mesh, a);
  } else if (!spec.mesh.empty()) {
    return Invalid(spec, "\"mesh\" is only for objects of type mesh, not " + type->name);
  } else {
    type->build(sizes, a);
  }

  core::CatalogObject obj;
  obj.id = spec.id;
  obj.type = type->name;
  obj.color = *CanonicalColor(color);
  obj.pose = core::Pose::FromYaw(spec.pos, spec.yaw_rad);
  obj.parts = std::move(a.parts);
  obj.shapes = std::move(a.shapes);
  // uniform scale of every length
  auto scale_shape = [&](core::Shape& s) {
    s.pose.pos *= spec.scale;
    s.size *= spec.scale;
  };
  for (core::Shape& s : obj.shapes) scale_shape(s);
  for (core::CatalogPart& p : obj.parts) {
    for (core::Shape& s : p.shapes) scale_shape(s);
  }
  obj.collides = type->name != "marker";
  obj.friction = spec.friction;
  if (spec.mass_kg) {
    obj.movable = true;
    obj.mass_kg = *spec.mass_kg;
  } else if (AlwaysMovable(type->name) && type->name != "long_box") {
    double volume = 0.0;  // the solids tile the object (scaled above)
    for (const core::Shape& s : obj.shapes) volume += core::ShapeVolume(s);
    obj.movable = true;
    obj.mass_kg = std::clamp(kBoxDensityKgM3 * volume, kBoxMinMassKg, kBoxMaxMassKg);
  } else if (type->name == "long_box") {
    obj.movable = true;
    obj.mass_kg = kLongBoxMassKg;
  }
  obj.carry = MakeCarryInfo(obj);
  return obj;
}

}  // namespace simhuman::world
