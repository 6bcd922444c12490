#include "simhuman/world/scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "simhuman/core/geometry.h"
#include "simhuman/core/json_io.h"
#include "simhuman/core/json_reader.h"
#include "simhuman/world/carry.h"
#include "simhuman/world/embodiment.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::world {
namespace {

using nlohmann::json;

constexpr double kDegToRad = M_PI / 180.0;
// (0.3, 1.5), exclusive as the model builder checks
const core::NumberRange kHumanScaleRange = {0.3, 1.5, true, true};
constexpr double kHumanRadiusM = 0.25;  // standing footprint of an adult (scaled)
constexpr double kHumanHeightM = 1.8;   // objects higher than this (scaled) do not block
constexpr double kDefaultHumanClearanceM = 0.35;
constexpr double kScenePlanRotTolerance = 1e-6;

const std::vector<std::string> kSceneKeys = {"name", "objects", "humans"};
const std::vector<std::string> kObjectKeys = {"id",      "type",     "pos",   "yaw_deg",
                                              "scale",   "size",     "color", "mass_kg",
                                              "movable", "friction", "mesh"};
const core::NumberRange kFrictionRange = core::NumberRange::Closed(kMinFriction, kMaxFriction);
const std::vector<std::string> kHumanKeys = {"pos", "yaw_deg", "scale", "posture", "kind"};
const std::vector<std::string> kPlanKeys = {"obj", "chain of contacts", "contact_pairs"};
const std::vector<std::string> kPlanObjectKeys = {"id",       "name",        "rotate", "scale",
                                                  "transfer", "stand_point", "part_id"};

// ScenePlan object names and our types
const std::vector<std::pair<std::string, std::string>> kPlanNames = {
    {"chair", "chair"},          {"armchair", "armchair"}, {"sofa", "sofa"},
    {"couch", "sofa"},           {"stool", "stool"},       {"high stool", "high_stool"},
    {"bar stool", "high_stool"}, {"bed", "bed"},           {"table", "table"},
    {"desk", "table"},           {"laptop", "laptop"},     {"box", "box"}};

std::string SourceStem(std::string_view source) {
  std::string s(source);
  size_t slash = s.find_last_of('/');
  if (slash != std::string::npos) s = s.substr(slash + 1);
  size_t dot = s.find_last_of('.');
  if (dot != std::string::npos && dot > 0) s = s.substr(0, dot);
  if (s.empty() || s.front() == '<') return "scene";
  return s;
}

// "movable": true gives furniture its default mass (world/carry.h) unless "mass_kg" sets one;
// boxes, long boxes and small objects (AlwaysMovable) are movable anyway
core::Status ApplyMovable(const json& v, const std::string& where, ObjectSpec& o) {
  SH_ASSIGN_OR_RETURN(bool movable, core::ReadBool(v, where));
  const bool always = AlwaysMovable(o.type);
  if (!movable) {
    if (always) return core::JsonError(where, "a " + o.type + " is always movable");
    if (o.mass_kg) {
      return core::JsonError(where,
                             "\"movable\": false contradicts \"mass_kg\" (which makes the "
                             "object movable); remove one of them");
    }
    return absl::OkStatus();
  }
  if (o.mass_kg || always) return absl::OkStatus();
  std::optional<double> kg = DefaultMovableMassKg(o.type);
  if (!kg) {
    std::vector<std::string> types;
    for (const std::string& t : ObjectTypes()) {
      if (DefaultMovableMassKg(t)) types.push_back(t);
    }
    return core::JsonError(where, "a " + o.type +
                                      " has no default mass to make it movable; give \"mass_kg\" "
                                      "or use a type with one: " +
                                      core::JoinNames(types));
  }
  o.mass_kg = kg;
  return absl::OkStatus();
}

core::StatusOr<ObjectSpec> ParseObject(const json& j, const std::string& where, size_t index) {
  SH_RETURN_IF_ERROR(core::CheckKeys(j, kObjectKeys, where));
  SH_RETURN_IF_ERROR(core::RequireKey(j, "type", where));
  SH_RETURN_IF_ERROR(core::RequireKey(j, "pos", where));
  ObjectSpec o;
  SH_ASSIGN_OR_RETURN(std::string type,
                      core::ReadString(j.at("type"), core::JsonPointer(where, "type")));
  std::optional<std::string> canon = CanonicalObjectType(type);
  if (!canon) {
    return core::JsonError(
        core::JsonPointer(where, "type"),
        "unknown object type '" + type + "'; valid types are: " + core::JoinNames(ObjectTypes()));
  }
  o.type = *canon;
  if (j.contains("id")) {
    SH_ASSIGN_OR_RETURN(o.id, core::ReadString(j.at("id"), core::JsonPointer(where, "id")));
    if (o.id.empty()) return core::JsonError(core::JsonPointer(where, "id"), "empty object id");
  } else {
    char buf[16];
    std::snprintf(buf, sizeof(buf), "%03zu", index);
    o.id = o.type + buf;
  }
  SH_ASSIGN_OR_RETURN(std::vector<double> pos,
                      core::ReadNumbers(j.at("pos"), core::JsonPointer(where, "pos"), 2, 3));
  o.pos = Eigen::Vector3d(pos[0], pos[1], pos.size() > 2 ? pos[2] : 0.0);
  SH_ASSIGN_OR_RETURN(std::optional<double> yaw_deg, core::ReadOptionalNumber(j, "yaw_deg", where));
  o.yaw_rad = yaw_deg.value_or(0.0) * kDegToRad;
  SH_ASSIGN_OR_RETURN(std::optional<double> scale, core::ReadOptionalNumber(j, "scale", where));
  o.scale = scale.value_or(1.0);
  SH_ASSIGN_OR_RETURN(o.mass_kg, core::ReadOptionalNumber(j, "mass_kg", where));
  SH_ASSIGN_OR_RETURN(o.friction, core::ReadOptionalNumber(j, "friction", where, kFrictionRange));
  if (j.contains("movable")) {
    SH_RETURN_IF_ERROR(ApplyMovable(j.at("movable"), core::JsonPointer(where, "movable"), o));
  }
  if (j.contains("color")) {
    SH_ASSIGN_OR_RETURN(o.color,
                        core::ReadString(j.at("color"), core::JsonPointer(where, "color")));
    if (!ColorRgba(o.color)) {
      return core::JsonError(
          core::JsonPointer(where, "color"),
          "unknown colour '" + o.color + "'; valid colours are: " + core::JoinNames(ColorNames()));
    }
  }
  if (j.contains("mesh")) {
    SH_ASSIGN_OR_RETURN(o.mesh, core::ReadString(j.at("mesh"), core::JsonPointer(where, "mesh")));
    if (o.type != "mesh" || o.mesh.empty()) {
      return core::JsonError(core::JsonPointer(where, "mesh"),
                             o.mesh.empty() ? std::string("empty mesh file name")
                                            : "\"mesh\" names an OBJ file for objects of type "
                                              "mesh, not " +
                                                  o.type);
    }
  } else if (o.type == "mesh") {
    return core::JsonError(where, "an object of type mesh needs \"mesh\": an OBJ file's path");
  }
  if (j.contains("size")) {
    const json& size = j.at("size");
    std::string sw = core::JsonPointer(where, "size");
    if (!size.is_object()) return core::JsonError(sw, "expected an object of size parameters");
    std::vector<std::string> keys;
    for (const SizeParam& p : SizeParams(o.type)) keys.push_back(p.name);
    for (auto it = size.begin(); it != size.end(); ++it) {
      if (std::find(keys.begin(), keys.end(), it.key()) == keys.end()) {
        return core::JsonError(
            core::JsonPointer(sw, it.key()),
            "unknown size key for type " + o.type + "; valid keys are: " + core::JoinNames(keys));
      }
      SH_ASSIGN_OR_RETURN(double v, core::ReadNumber(it.value(), core::JsonPointer(sw, it.key())));
      o.size[it.key()] = v;
    }
  }
  return o;
}

core::StatusOr<HumanSpec> ParseHuman(const json& j, const std::string& where) {
  SH_RETURN_IF_ERROR(core::CheckKeys(j, kHumanKeys, where));
  SH_RETURN_IF_ERROR(core::RequireKey(j, "pos", where));
  HumanSpec h;
  SH_ASSIGN_OR_RETURN(std::vector<double> pos,
                      core::ReadNumbers(j.at("pos"), core::JsonPointer(where, "pos"), 2, 2));
  h.pos_xy = Eigen::Vector2d(pos[0], pos[1]);
  SH_ASSIGN_OR_RETURN(std::optional<double> yaw_deg, core::ReadOptionalNumber(j, "yaw_deg", where));
  h.yaw_rad = yaw_deg.value_or(0.0) * kDegToRad;
  SH_ASSIGN_OR_RETURN(std::optional<double> scale,
                      core::ReadOptionalNumber(j, "scale", where, kHumanScaleRange));
  h.scale = scale.value_or(1.0);
  if (j.contains("posture")) {
    SH_ASSIGN_OR_RETURN(h.posture,
                        core::ReadName(j.at("posture"), core::JsonPointer(where, "posture"),
                                       HumanPostures(), "posture"));
  }
  if (j.contains("kind")) {
    SH_ASSIGN_OR_RETURN(h.kind, core::ReadName(j.at("kind"), core::JsonPointer(where, "kind"),
                                               EmbodimentNames(), "agent kind"));
  }
  return h;
}

core::StatusOr<SceneSpec> ParseOurForm(const json& j, std::string_view source) {
  SH_RETURN_IF_ERROR(core::CheckKeys(j, kSceneKeys, "/"));
  SceneSpec spec;
  spec.name = SourceStem(source);
  if (j.contains("name")) {
    SH_ASSIGN_OR_RETURN(spec.name, core::ReadString(j.at("name"), "/name"));
  }
  SH_RETURN_IF_ERROR(core::RequireKey(j, "objects", "/"));
  const json& objects = j.at("objects");
  if (!objects.is_array()) {
    return core::JsonError("/objects",
                           "expected an array of objects, got " + std::string(objects.type_name()));
  }
  for (size_t i = 0; i < objects.size(); ++i) {
    SH_ASSIGN_OR_RETURN(ObjectSpec o, ParseObject(objects[i], core::JsonPointer("/objects", i), i));
    spec.objects.push_back(std::move(o));
  }
  if (j.contains("humans")) {
    const json& humans = j.at("humans");
    if (!humans.is_array() || humans.empty()) {
      return core::JsonError(
          "/humans", "expected a non-empty array of humans (omit the key for one default human)");
    }
    for (size_t i = 0; i < humans.size(); ++i) {
      SH_ASSIGN_OR_RETURN(HumanSpec h, ParseHuman(humans[i], core::JsonPointer("/humans", i)));
      spec.humans.push_back(std::move(h));
    }
  }
  return spec;
}

std::vector<std::string> PlanNames() {
  std::vector<std::string> out;
  for (const auto& [name, type] : kPlanNames) out.push_back(name);
  return out;
}

// the ScenePlan "rotate" list: [[pi/2, 0, 0] (Y-up to Z-up), then rotations about z only];
// returns the summed z angle
core::StatusOr<double> PlanRotationZ(const json& rotate, const std::string& where) {
  if (!rotate.is_array() || rotate.empty()) {
    return core::JsonError(where, "expected a non-empty array of [x, y, z] rotations");
  }
  double z = 0.0;
  for (size_t i = 0; i < rotate.size(); ++i) {
    std::string w = core::JsonPointer(where, i);
    SH_ASSIGN_OR_RETURN(std::vector<double> r, core::ReadNumbers(rotate[i], w, 3, 3));
    if (i == 0) {
      if (std::abs(r[0] - M_PI / 2) > kScenePlanRotTolerance ||
          std::abs(r[1]) > kScenePlanRotTolerance || std::abs(r[2]) > kScenePlanRotTolerance) {
        return core::JsonError(
            w, "the first rotation must be the Y-up to Z-up fix [1.5707963267948966, 0, 0]");
      }
    } else {
      if (std::abs(r[0]) > kScenePlanRotTolerance || std::abs(r[1]) > kScenePlanRotTolerance) {
        return core::JsonError(
            w, "only rotations about z ([0, 0, angle]) are supported after the first");
      }
      z += r[2];
    }
  }
  return z;
}

// our yaw for a ScenePlan object from the summed z rotation. After UniHSI's fixed first
// rotation a PartNet mesh's front (a chair's seat front, a bed's foot end) points along -y, so a
// z rotation of -90 degrees turns it to +x: our yaw is z + 90 degrees. Our bed's front is its
// long side, a quarter turn from its foot end: z + 180 degrees. Checked against the stand points
// in UniHSI's sceneplan files (docs/FORMATS.md).
double PlanYawOffset(const std::string& type) { return type == "bed" ? M_PI : M_PI / 2; }

// true when the entry's contact pairs name an arm part ("arm sofa style44", "left armrest") of
// object `id`
bool ChainNamesArmOf(const json& entry, const std::string& id) {
  for (const char* key : {"chain of contacts", "contact_pairs"}) {
    if (!entry.contains(key) || !entry.at(key).is_array()) continue;
    for (const json& step : entry.at(key)) {
      if (!step.is_array()) continue;
      for (const json& pair : step) {
        if (!pair.is_array() || pair.size() < 2 || !pair[0].is_string() || !pair[1].is_string())
          continue;
        if (pair[0].get<std::string>() != id) continue;
        std::string part = core::NormalizeName(pair[1].get<std::string>());
        if (part.find("arm") != std::string::npos) return true;
      }
    }
  }
  return false;
}

core::StatusOr<SceneSpec> ParsePlanForm(const json& j, const std::string& where,
                                        const std::string& name, std::vector<std::string>* ptrs) {
  SH_RETURN_IF_ERROR(core::CheckKeys(j, kPlanKeys, where));
  SH_RETURN_IF_ERROR(core::RequireKey(j, "obj", where));
  std::string ow = core::JsonPointer(where, "obj");
  const json& objs = j.at("obj");
  if (!objs.is_object()) {
    return core::JsonError(ow, "expected an object of objects keyed \"000\", \"001\", ...");
  }
  SceneSpec spec;
  spec.name = name;
  for (auto it = objs.begin(); it != objs.end(); ++it) {
    std::string w = core::JsonPointer(ow, it.key());
    const json& o = it.value();
    SH_RETURN_IF_ERROR(core::CheckKeys(o, kPlanObjectKeys, w));
    SH_RETURN_IF_ERROR(core::RequireKey(o, "name", w));
    SH_RETURN_IF_ERROR(core::RequireKey(o, "transfer", w));
    SH_RETURN_IF_ERROR(core::RequireKey(o, "rotate", w));
    SH_ASSIGN_OR_RETURN(std::string plan_name,
                        core::ReadString(o.at("name"), core::JsonPointer(w, "name")));
    std::string norm;
    for (char c : plan_name) {
      norm += c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    auto match = std::find_if(kPlanNames.begin(), kPlanNames.end(),
                              [&](const auto& p) { return p.first == norm; });
    if (match == kPlanNames.end()) {
      return core::JsonError(core::JsonPointer(w, "name"),
                             "unknown ScenePlan object name '" + plan_name +
                                 "'; valid names are: " + core::JoinNames(PlanNames()));
    }
    ObjectSpec spec_o;
    spec_o.type = match->second;
    spec_o.id = plan_name + it.key();
    // PartNet's chairs include armchairs: a chair whose arms the plan touches is one
    if (spec_o.type == "chair" && ChainNamesArmOf(j, spec_o.id)) spec_o.type = "armchair";
    SH_ASSIGN_OR_RETURN(
        std::vector<double> t,
        core::ReadNumbers(o.at("transfer"), core::JsonPointer(w, "transfer"), 3, 3));
    spec_o.pos = Eigen::Vector3d(t[0], t[1], t[2]);
    SH_ASSIGN_OR_RETURN(double z, PlanRotationZ(o.at("rotate"), core::JsonPointer(w, "rotate")));
    spec_o.yaw_rad = core::WrapAngle(z + PlanYawOffset(spec_o.type));
    // "scale" scales PartNet's unit-size meshes; our objects are metric, so it is only checked
    if (o.contains("scale")) {
      SH_RETURN_IF_ERROR(core::ReadNumber(o.at("scale"), core::JsonPointer(w, "scale"),
                                          core::NumberRange::Above(0))
                             .status());
    }
    spec.objects.push_back(std::move(spec_o));
    ptrs->push_back(w);
  }
  return spec;
}

// world xy bounds distance: 0 inside
double DistanceXy(const std::pair<Eigen::Vector3d, Eigen::Vector3d>& b, const Eigen::Vector2d& p) {
  double dx = std::max({b.first.x() - p.x(), 0.0, p.x() - b.second.x()});
  double dy = std::max({b.first.y() - p.y(), 0.0, p.y() - b.second.y()});
  return std::hypot(dx, dy);
}

// laptops and boxes of a ScenePlan standing inside a table's board footprint rest on the board
void RestOnTables(const std::vector<core::CatalogObject>& built, SceneSpec& spec) {
  for (size_t i = 0; i < spec.objects.size(); ++i) {
    ObjectSpec& o = spec.objects[i];
    if (o.type != "laptop" && o.type != "box") continue;
    for (const core::CatalogObject& t : built) {
      if (t.type != "table") continue;
      const core::CatalogPart* board = t.FindPart("board");
      core::CatalogObject board_only = t;
      board_only.shapes = board->shapes;
      auto b = WorldBounds(board_only);
      if (DistanceXy(b, o.pos.head<2>()) == 0.0) {
        o.pos.z() = b.second.z();
        break;
      }
    }
  }
}

// checks ids, builds every object (errors name the object's pointer in `ptrs`), places or
// checks the humans
core::Status Finish(SceneSpec& spec, const std::vector<std::string>& ptrs, bool plan_form) {
  std::map<std::string, std::string> seen;
  std::vector<core::CatalogObject> built;
  for (size_t i = 0; i < spec.objects.size(); ++i) {
    const ObjectSpec& o = spec.objects[i];
    const std::string& w = ptrs[i];
    auto [it, fresh] = seen.emplace(o.id, w);
    if (!fresh) {
      return core::JsonError(
          w, "duplicate object id '" + o.id + "' (also used by " + it->second + ")");
    }
    core::StatusOr<core::CatalogObject> obj = BuildObject(o);
    if (!obj.ok()) return core::Annotate(obj.status(), w);
    built.push_back(*std::move(obj));
  }
  if (plan_form) {
    RestOnTables(built, spec);
    for (size_t i = 0; i < spec.objects.size(); ++i) {
      built[i].pose = core::Pose::FromYaw(spec.objects[i].pos, spec.objects[i].yaw_rad);
    }
  }
  if (spec.humans.empty()) {
    spec.humans.push_back(DefaultHuman(built));
    return absl::OkStatus();
  }
  for (size_t h = 0; h < spec.humans.size(); ++h) {
    const HumanSpec& human = spec.humans[h];
    if (human.posture != "stand") continue;
    for (const core::CatalogObject& o : built) {
      if (!o.collides) continue;  // markers are not in the way
      // in the object's own frame, so a rotated object is not inflated by world-axis bounds
      auto b = o.LocalBounds();
      if (o.pose.pos.z() + b.first.z() > kHumanHeightM * human.scale) continue;
      Eigen::Vector3d local =
          o.pose.ApplyInverse(Eigen::Vector3d(human.pos_xy.x(), human.pos_xy.y(), o.pose.pos.z()));
      if (DistanceXy(b, local.head<2>()) < kHumanRadiusM * human.scale) {
        return core::JsonError(core::JsonPointer("/humans", h),
                               "a standing human at (" + core::FormatNumber(human.pos_xy.x()) +
                                   ", " + core::FormatNumber(human.pos_xy.y()) +
                                   ") overlaps object '" + o.id + "'");
      }
    }
  }
  return absl::OkStatus();
}

ObjectSpec Obj(const std::string& id, const std::string& type, double x, double y, double yaw_deg,
               double z = 0.0) {
  ObjectSpec o;
  o.id = id;
  o.type = type;
  o.pos = Eigen::Vector3d(x, y, z);
  o.yaw_rad = yaw_deg * kDegToRad;
  return o;
}

HumanSpec Human(double x, double y, double yaw_deg) {
  HumanSpec h;
  h.pos_xy = Eigen::Vector2d(x, y);
  h.yaw_rad = yaw_deg * kDegToRad;
  return h;
}

// built-in scenes (docs/FORMATS.md lists them); gaps follow from the default sizes, e.g. 0.65 m
// between living_room's chair and the table (pulled out: room to stand in front of the seat
// and sit down, then reach the laptop)
SceneSpec LivingRoom() {
  double table_h = DefaultSizes("table").at("height");
  double table_d = DefaultSizes("table").at("depth");
  double seat_d = DefaultSizes("chair").at("seat_depth");
  double laptop_d = DefaultSizes("laptop").at("depth");
  double table_x = 2.2, table_edge = table_x - table_d / 2;
  SceneSpec s;
  s.name = "living_room";
  // same ids as the paper's Table 7 plan for the first four
  s.objects.push_back(Obj("chair000", "chair", table_edge - 0.65 - seat_d / 2, 0.0, 0));
  s.objects.push_back(Obj("table001", "table", table_x, 0.0, 180));
  s.objects.push_back(
      Obj("laptop002", "laptop", table_edge + 0.02 + laptop_d / 2, 0.0, 180, table_h));
  s.objects.push_back(Obj("bed003", "bed", 4.2, -2.5, 90));
  s.objects.push_back(Obj("armchair004", "armchair", 0.0, 2.5, -90));
  s.objects.push_back(Obj("sofa005", "sofa", -2.5, 0.0, 0));
  s.objects.push_back(Obj("stool006", "stool", -0.5, -2.5, 0));
  // beside the bed, back to it, where sitting and lying back puts the head on the pillow (plans
  // that start on the bed need no walk); other objects are reached by walking
  s.humans.push_back(Human(4.0, -1.35, 90));
  return s;
}

SceneSpec Bedroom() {
  SceneSpec s;
  s.name = "bedroom";
  s.objects.push_back(Obj("bed000", "bed", 2.5, 0.0, 180));
  s.objects.push_back(Obj("stool001", "stool", 2.9, 1.5, 0));
  s.objects.push_back(Obj("chair002", "chair", 0.0, 2.2, -90));
  s.objects.push_back(Obj("box003", "box", -1.2, -1.5, 0));
  s.humans.push_back(Human(0.0, 0.0, 0));
  return s;
}

SceneSpec Office() {
  double table_h = DefaultSizes("table").at("height");
  double table_d = DefaultSizes("table").at("depth");
  double seat_d = DefaultSizes("chair").at("seat_depth");
  double laptop_d = DefaultSizes("laptop").at("depth");
  double table_x = 1.8, table_edge = table_x - table_d / 2;
  SceneSpec s;
  s.name = "office";
  s.objects.push_back(Obj("table000", "table", table_x, 0.0, 180));
  s.objects.push_back(
      Obj("laptop001", "laptop", table_edge + 0.02 + laptop_d / 2, 0.0, 180, table_h));
  s.objects.push_back(Obj("chair002", "chair", table_edge - 0.40 - seat_d / 2, 0.0, 0));
  s.objects.push_back(Obj("high_stool003", "high_stool", 1.0, 1.8, 0));
  s.objects.push_back(Obj("box004", "box", 2.0, -1.6, 0));
  s.humans.push_back(Human(0.0, -1.0, 0));
  return s;
}

// DASH-sized objects (world/tabletop.h): boxes 13-18 cm tall, square sides 0.8 x a 6-10 cm
// width, a 9 cm wide cylinder (a stacking base), a sphere 0.75 x 16 cm across, 1-5 kg, friction
// 0.8-1.2, centroids >= 0.25 m apart; the yellow box stays flat (commands call it "the flat box")
SceneSpec TabletopDemo() {
  double table_h = DefaultSizes("table").at("height");
  // seated at the table with a dexterous right hand, as DASH (TabletopBaseScene()), so that
  // `simhuman run` carries its commands out with the tabletop pipeline; its chair comes last
  SceneSpec base = TabletopBaseScene("tabletop_demo");
  SceneSpec s;
  s.name = base.name;
  s.objects.push_back(base.objects[0]);
  struct Item {
    const char* color;
    double x, y, d, w, h, mass_kg, friction;
  };
  // two rows within the seated right arm's reach (the generator's region, world/tabletop.h)
  const Item items[] = {{"red", 0.72, 0.28, 0.072, 0.072, 0.16, 2.5, 1.0},
                        {"green", 0.72, 0.0, 0.064, 0.064, 0.18, 1.5, 0.9},
                        {"blue", 0.72, -0.28, 0.072, 0.072, 0.15, 3.0, 1.1},
                        {"yellow", 0.97, 0.14, 0.08, 0.08, 0.05, 1.0, 1.0}};
  int n = 1;
  for (const Item& it : items) {
    char id[16];
    std::snprintf(id, sizeof(id), "box%03d", n++);
    ObjectSpec o = Obj(id, "box", it.x, it.y, 0, table_h);
    o.color = it.color;
    o.size = {{"depth", it.d}, {"width", it.w}, {"height", it.h}};
    o.mass_kg = it.mass_kg;
    o.friction = it.friction;
    s.objects.push_back(o);
  }
  // a blue cylinder left of a green sphere (as the human, facing +x, sees them)
  ObjectSpec cylinder = Obj("cylinder005", "cylinder", 0.97, -0.14, 0, table_h);
  cylinder.color = "blue";
  cylinder.size = {{"radius", 0.045}, {"height", 0.15}};
  cylinder.mass_kg = 2.0;
  cylinder.friction = 0.9;
  s.objects.push_back(cylinder);
  ObjectSpec sphere = Obj("sphere006", "sphere", 0.97, -0.40, 0, table_h);
  sphere.color = "green";
  sphere.size = {{"radius", 0.06}};
  sphere.mass_kg = 1.2;
  sphere.friction = 1.1;
  s.objects.push_back(sphere);
  ObjectSpec chair = base.objects[1];
  chair.id = "chair007";
  s.objects.push_back(chair);
  s.humans = base.humans;
  return s;
}

SceneSpec SitDemo() {
  double seat_d = DefaultSizes("chair").at("seat_depth");
  SceneSpec s;
  s.name = "sit_demo";
  s.objects.push_back(Obj("chair000", "chair", 0.0, 0.0, 0));
  // standing 0.4 m in front of the seat's front edge, back to the seat
  s.humans.push_back(Human(seat_d / 2 + 0.4, 0.0, 0));
  return s;
}

// carrying, one human: a 0.5 m box on the floor (8 kg), a bed and a sofa to carry it to, and a
// movable armchair (12 kg) for "move the armchair next to the sofa"
SceneSpec CarryDemo() {
  SceneSpec s;
  s.name = "carry_demo";
  ObjectSpec box = Obj("box000", "box", 2.0, 0.0, 0);
  box.size = {{"depth", 0.5}, {"width", 0.5}, {"height", 0.5}};
  box.mass_kg = 8.0;
  s.objects.push_back(box);
  s.objects.push_back(Obj("bed001", "bed", 5.5, 2.5, 180));
  s.objects.push_back(Obj("sofa002", "sofa", -2.5, 2.5, -90));
  ObjectSpec armchair = Obj("armchair003", "armchair", 1.0, -3.0, 90);
  armchair.mass_kg = DefaultMovableMassKg("armchair");
  s.objects.push_back(armchair);
  s.humans.push_back(Human(0.0, 0.0, 0));
  return s;
}

// carrying together, two humans: a 2 m long box (25 kg) and a movable sofa (35 kg), a bed as a
// destination
SceneSpec CarryTeamDemo() {
  SceneSpec s;
  s.name = "carry_team_demo";
  s.objects.push_back(Obj("long_box000", "long_box", 2.5, 0.0, 0));
  ObjectSpec sofa = Obj("sofa001", "sofa", 2.5, -3.0, 90);
  sofa.mass_kg = DefaultMovableMassKg("sofa");
  s.objects.push_back(sofa);
  s.objects.push_back(Obj("bed002", "bed", -3.0, 3.0, 0));
  s.humans.push_back(Human(0.0, 0.6, 0));
  s.humans.push_back(Human(0.0, -0.6, 0));
  return s;
}

SceneSpec Empty() {
  SceneSpec s;
  s.name = "empty";
  s.humans.push_back(Human(0.0, 0.0, 0));
  return s;
}

const std::vector<std::pair<std::string, SceneSpec (*)()>>& Builtins() {
  static const std::vector<std::pair<std::string, SceneSpec (*)()>> kBuiltins = {
      {"living_room", LivingRoom},
      {"bedroom", Bedroom},
      {"office", Office},
      {"tabletop_demo", TabletopDemo},
      {"sit_demo", SitDemo},
      {"empty", Empty},
      {"carry_demo", CarryDemo},
      {"carry_team_demo", CarryTeamDemo},
      {"tabletop_dash", TabletopDashScene},
      {"tabletop_zero_shot", TabletopZeroShotScene}};
  return kBuiltins;
}

}  // namespace

const std::vector<std::string>& HumanPostures() {
  static const std::vector<std::string> kPostures = {"stand", "sit", "lie"};
  return kPostures;
}

core::StatusOr<SceneSpec> ParseSceneJson(const nlohmann::json& j, std::string_view source) {
  auto parse = [&]() -> core::StatusOr<SceneSpec> {
    if (!j.is_object())
      return core::JsonError("/", "expected a JSON object, got " + std::string(j.type_name()));
    std::vector<std::string> ptrs;
    if (j.contains("obj")) {
      SH_ASSIGN_OR_RETURN(SceneSpec spec, ParsePlanForm(j, "/", SourceStem(source), &ptrs));
      SH_RETURN_IF_ERROR(Finish(spec, ptrs, true));
      return spec;
    }
    if (!j.contains("objects")) {
      // a ScenePlan wrapped in a key such as "0000"
      std::vector<std::string> plans;
      for (auto it = j.begin(); it != j.end(); ++it) {
        if (it.value().is_object() && it.value().contains("obj")) plans.push_back(it.key());
      }
      if (plans.size() == 1 && j.size() == 1) {
        std::string w = core::JsonPointer("/", plans[0]);
        SH_ASSIGN_OR_RETURN(SceneSpec spec, ParsePlanForm(j.at(plans[0]), w, plans[0], &ptrs));
        SH_RETURN_IF_ERROR(Finish(spec, ptrs, true));
        return spec;
      }
      if (plans.size() > 1) {
        return core::JsonError("/", "holds " + std::to_string(plans.size()) +
                                        " ScenePlan entries (" + core::JoinNames(plans) +
                                        "); pass one of them");
      }
    }
    SH_ASSIGN_OR_RETURN(SceneSpec spec, ParseOurForm(j, source));
    for (size_t i = 0; i < spec.objects.size(); ++i)
      ptrs.push_back(core::JsonPointer("/objects", i));
    SH_RETURN_IF_ERROR(Finish(spec, ptrs, false));
    return spec;
  };
  core::StatusOr<SceneSpec> out = absl::InternalError("unreachable");
  try {
    out = parse();
  } catch (const json::exception& e) {
    out = absl::InvalidArgumentError(std::string("unexpected JSON error: ") + e.what());
  }
  if (!out.ok()) return core::Annotate(out.status(), source);
  return out;
}

std::vector<std::string> BuiltinSceneNames() {
  std::vector<std::string> out;
  for (const auto& [name, fn] : Builtins()) out.push_back(name);
  return out;
}

core::StatusOr<SceneSpec> BuiltinScene(std::string_view name) {
  for (const auto& [n, fn] : Builtins()) {
    if (n != name) continue;
    // the same checks as a scene file (a failure here is a bug in the layout)
    SceneSpec spec = fn();
    std::vector<std::string> ptrs;
    for (size_t i = 0; i < spec.objects.size(); ++i)
      ptrs.push_back(core::JsonPointer("/objects", i));
    core::Status st = Finish(spec, ptrs, false);
    if (!st.ok()) return core::Annotate(st, "built-in scene " + n);
    return spec;
  }
  return absl::NotFoundError("unknown built-in scene '" + std::string(name) +
                             "'; built-in scenes are: " + core::JoinNames(BuiltinSceneNames()));
}

core::StatusOr<SceneSpec> LoadScene(const std::string& name_or_path) {
  core::StatusOr<SceneSpec> builtin = BuiltinScene(name_or_path);
  if (builtin.ok()) return builtin;
  core::StatusOr<std::string> text = core::ReadFile(name_or_path);
  if (!text.ok()) {
    if (absl::IsNotFound(text.status())) {
      return absl::NotFoundError("unknown scene '" + name_or_path + "': not a built-in scene (" +
                                 core::JoinNames(BuiltinSceneNames()) + ") and no such file");
    }
    return text.status();
  }
  json j;
  try {
    SH_ASSIGN_OR_RETURN(j, core::ParseJson(*text, name_or_path));
  } catch (const json::exception& e) {
    // core::ParseJson catches syntax errors only; e.g. 1e999 overflows with out_of_range
    return absl::InvalidArgumentError(name_or_path + ": invalid JSON: " + e.what());
  }
  return ParseSceneJson(j, name_or_path);
}

core::StatusOr<core::SceneCatalog> BuildCatalog(const SceneSpec& spec) {
  core::SceneCatalog catalog;
  std::set<std::string> ids;
  for (const ObjectSpec& o : spec.objects) {
    if (!ids.insert(o.id).second) {
      return absl::InvalidArgumentError("scene '" + spec.name + "': duplicate object id '" + o.id +
                                        "'");
    }
    core::StatusOr<core::CatalogObject> obj = BuildObject(o);
    if (!obj.ok()) return core::Annotate(obj.status(), "scene '" + spec.name + "'");
    catalog.objects.push_back(*std::move(obj));
  }
  catalog.agents.clear();
  for (const HumanSpec& h : spec.humans) {
    SH_ASSIGN_OR_RETURN(const Embodiment* kind, FindEmbodiment(h.kind));
    catalog.agents.push_back(MakeCatalogAgent(*kind, h.scale));
  }
  return catalog;
}

nlohmann::json SceneToJson(const SceneSpec& spec) {
  json j;
  j["name"] = spec.name;
  j["objects"] = json::array();
  for (const ObjectSpec& o : spec.objects) {
    json jo;
    jo["id"] = o.id;
    jo["type"] = o.type;
    jo["pos"] = {o.pos.x(), o.pos.y(), o.pos.z()};
    jo["yaw_deg"] = o.yaw_rad / kDegToRad;
    jo["scale"] = o.scale;
    if (!o.size.empty()) jo["size"] = o.size;
    if (!o.color.empty()) jo["color"] = o.color;
    if (o.mass_kg) jo["mass_kg"] = *o.mass_kg;
    if (o.friction) jo["friction"] = *o.friction;
    if (!o.mesh.empty()) jo["mesh"] = o.mesh;
    j["objects"].push_back(jo);
  }
  j["humans"] = json::array();
  for (const HumanSpec& h : spec.humans) {
    json jh = {{"pos", {h.pos_xy.x(), h.pos_xy.y()}},
               {"yaw_deg", h.yaw_rad / kDegToRad},
               {"scale", h.scale},
               {"posture", h.posture}};
    if (h.kind != kDefaultAgentKind) jh["kind"] = h.kind;  // written only when not the default
    j["humans"].push_back(std::move(jh));
  }
  return j;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> WorldBounds(const core::CatalogObject& object) {
  std::vector<core::Shape> world;
  world.reserve(object.shapes.size());
  for (const core::Shape& s : object.shapes) {
    core::Shape w = s;
    w.pose = object.pose.Compose(s.pose);
    world.push_back(w);
  }
  return core::ShapesBounds(world);
}

std::vector<std::pair<std::string, std::string>> OverlappingObjects(const core::SceneCatalog& scene,
                                                                    double tolerance_m) {
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> bounds;
  for (const core::CatalogObject& o : scene.objects) bounds.push_back(WorldBounds(o));
  std::vector<std::pair<std::string, std::string>> out;
  for (size_t a = 0; a < bounds.size(); ++a) {
    for (size_t b = a + 1; b < bounds.size(); ++b) {
      Eigen::Vector3d lo = bounds[a].first.cwiseMax(bounds[b].first);
      Eigen::Vector3d hi = bounds[a].second.cwiseMin(bounds[b].second);
      if (((hi - lo).array() > tolerance_m).all()) {
        out.emplace_back(scene.objects[a].id, scene.objects[b].id);
      }
    }
  }
  return out;
}

HumanSpec DefaultHuman(const std::vector<core::CatalogObject>& objects) {
  HumanSpec h;
  if (objects.empty()) return h;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> blocking;
  for (const core::CatalogObject& o : objects) {
    auto b = WorldBounds(o);
    if (b.first.z() < kHumanHeightM) blocking.push_back(b);
  }
  const core::Pose& first = objects.front().pose;
  Eigen::Vector3d front = first.quat * Eigen::Vector3d::UnitX();
  double front_yaw = std::atan2(front.y(), front.x());
  Eigen::Vector2d center = first.pos.head<2>();
  std::optional<Eigen::Vector2d> chosen;
  for (double dist : {2.0, 3.0}) {
    for (int k = 0; k <= 6 && !chosen; ++k) {
      for (int sign : {1, -1}) {
        if (chosen || ((k == 0 || k == 6) && sign < 0)) continue;
        double a = front_yaw + sign * k * 30.0 * kDegToRad;
        Eigen::Vector2d p = center + dist * Eigen::Vector2d(std::cos(a), std::sin(a));
        bool clear = true;
        for (const auto& b : blocking) clear &= DistanceXy(b, p) >= kDefaultHumanClearanceM;
        if (clear) chosen = p;
      }
    }
    if (chosen) break;
  }
  h.pos_xy =
      chosen.value_or(center + 2.0 * Eigen::Vector2d(std::cos(front_yaw), std::sin(front_yaw)));
  Eigen::Vector2d to_object = center - h.pos_xy;
  h.yaw_rad = std::atan2(to_object.y(), to_object.x());
  return h;
}

}  // namespace simhuman::world
