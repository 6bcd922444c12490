#include "simhuman/world/tabletop.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "simhuman/core/json_reader.h"
#include "simhuman/core/rng.h"

namespace simhuman::world {
namespace {

// the layout (tabletop.h): the table's centre, the chair's gap to the table's edge, and where the
// table frame's origin lies (in from the board's near edge; right of the right shoulder; world y)
constexpr double kTableX = 1.0;
constexpr double kChairGapM = 0.02;
constexpr double kFrameInFromEdgeM = 0.17;
constexpr double kFrameRightOfShoulderM = 0.25;
constexpr double kFrameOriginY = -0.20;

const std::array<const char*, 3> kShapes = {"box", "cylinder", "sphere"};
const std::array<const char*, 4> kColors = {"red", "yellow", "green", "blue"};

double TableHeight() { return DefaultSizes("table").at("height"); }
double TableNearEdgeX() { return kTableX - DefaultSizes("table").at("depth") / 2; }
double ChairX() {
  return TableNearEdgeX() - kChairGapM - DefaultSizes("chair").at("seat_depth") / 2;
}
double HumanY() { return kFrameOriginY + kFrameRightOfShoulderM + kTabletopShoulderRightM; }
Eigen::Vector3d FrameOrigin() {
  return Eigen::Vector3d(TableNearEdgeX() + kFrameInFromEdgeM, kFrameOriginY, TableHeight());
}

core::Status OptionError(const std::string& name, double value, const std::string& valid) {
  return absl::InvalidArgumentError("tabletop option " + name + " = " + core::FormatNumber(value) +
                                    " is invalid; valid: " + valid);
}

core::Status CheckIn(const std::string& name, double value, double lo, double hi) {
  if (std::isfinite(value) && value >= lo && value <= hi) return absl::OkStatus();
  return OptionError(name, value,
                     "[" + core::FormatNumber(lo) + ", " + core::FormatNumber(hi) + "]");
}

// one object as drawn: its shape, colour and nominal sizes (DASH's width and height)
struct Draw {
  std::string shape, color;
  double width_m = 0, height_m = 0, mass_kg = 0, friction = 0;
  Eigen::Vector2d xy_table = Eigen::Vector2d::Zero();
};

bool SameLook(const Draw& a, const Draw& b) { return a.shape == b.shape && a.color == b.color; }

// the largest half width in plan any drawn object can have
double MaxHalfWidth(const TabletopOptions& o) {
  return std::max(
             {o.box_width_scale * o.width_hi_m, o.width_hi_m, o.sphere_scale * o.height_hi_m}) /
         2;
}

std::string PickColor(core::Rng& rng) {
  return kColors[static_cast<size_t>(rng.UniformInt(0, static_cast<int>(kColors.size()) - 1))];
}

Draw DrawLook(core::Rng& rng, const TabletopOptions& o, bool bottom) {
  Draw d;
  // a stack's bottom is never a sphere and is drawn at least stack_bottom_min_width_m wide
  d.shape = kShapes[static_cast<size_t>(rng.UniformInt(0, bottom ? 1 : 2))];
  d.color = PickColor(rng);
  d.width_m = rng.Uniform(bottom ? o.stack_bottom_min_width_m : o.width_lo_m, o.width_hi_m);
  d.height_m = rng.Uniform(o.height_lo_m, o.height_hi_m);
  d.mass_kg = rng.Uniform(o.mass_lo_kg, o.mass_hi_kg);
  d.friction = rng.Uniform(o.friction_lo, o.friction_hi);
  return d;
}

// a point in the region at least min_separation_m from every point of `taken` (and, when
// given, at least place_min_move_m from `start`); nullopt after 1 + max_resamples draws
std::optional<Eigen::Vector2d> DrawPosition(core::Rng& rng, const TabletopOptions& o,
                                            const std::vector<Eigen::Vector2d>& taken,
                                            const std::optional<Eigen::Vector2d>& start = {}) {
  for (int attempt = 0; attempt <= o.max_resamples; ++attempt) {
    Eigen::Vector2d p(rng.Uniform(o.region_x_lo_m, o.region_x_hi_m),
                      rng.Uniform(o.region_y_lo_m, o.region_y_hi_m));
    bool clear = !start || (p - *start).norm() >= o.place_min_move_m;
    for (const Eigen::Vector2d& t : taken) clear = clear && (p - t).norm() >= o.min_separation_m;
    if (clear) return p;
  }
  return std::nullopt;
}

// the height of the object's top above its base
double TopHeight(const Draw& d, const TabletopOptions& o) {
  return d.shape == "sphere" ? o.sphere_scale * d.height_m : d.height_m;
}

ObjectSpec ToSpec(const Draw& d, const TabletopOptions& o, int index) {
  ObjectSpec s;
  char buf[16];
  std::snprintf(buf, sizeof(buf), "%03d", index);
  s.id = d.shape + buf;
  s.type = d.shape;
  s.color = d.color;
  s.pos = TableToWorld(Eigen::Vector3d(d.xy_table.x(), d.xy_table.y(), 0.0));
  if (d.shape == "box") {
    const double side = o.box_width_scale * d.width_m;
    s.size = {{"depth", side}, {"width", side}, {"height", d.height_m}};
  } else if (d.shape == "cylinder") {
    s.size = {{"radius", d.width_m / 2}, {"height", d.height_m}};
  } else {
    s.size = {{"radius", o.sphere_scale * d.height_m / 2}};
  }
  s.mass_kg = d.mass_kg;
  s.friction = d.friction;
  return s;
}

// draws the other objects: a look unlike every task object's (redrawing the colour), a position
// clear of every centroid in `taken`; dropped when no position is found
void DrawOthers(core::Rng& rng, const TabletopOptions& o, int count, const std::vector<Draw>& task,
                std::vector<Eigen::Vector2d>& taken, std::vector<Draw>& out) {
  for (int i = 0; i < count; ++i) {
    Draw d = DrawLook(rng, o, false);
    auto clashes = [&](const Draw& x) {
      return std::any_of(task.begin(), task.end(), [&](const Draw& t) { return SameLook(t, x); });
    };
    while (clashes(d)) d.color = PickColor(rng);  // at most two task looks of four colours
    std::optional<Eigen::Vector2d> p = DrawPosition(rng, o, taken);
    if (!p) continue;
    d.xy_table = *p;
    taken.push_back(*p);
    out.push_back(d);
  }
}

// the place target: at least min_separation_m from the other objects' centroids and
// place_min_move_m from the task object's own (draws[0]); when none is found the last drawn other
// object is dropped and the search repeats (with the task object alone the region is open)
Eigen::Vector2d DrawPlaceTarget(core::Rng& rng, const TabletopOptions& o,
                                std::vector<Draw>& draws) {
  constexpr int kAloneRounds = 100;  // Validate() keeps place_min_move_m within half the region
  for (int alone = 0; alone < kAloneRounds;) {
    std::vector<Eigen::Vector2d> others;
    for (size_t i = 1; i < draws.size(); ++i) others.push_back(draws[i].xy_table);
    std::optional<Eigen::Vector2d> p = DrawPosition(rng, o, others, draws[0].xy_table);
    if (p) return *p;
    if (draws.size() > 1) {
      draws.pop_back();
    } else {
      ++alone;
    }
  }
  return draws[0].xy_table;
}

}  // namespace

core::Status TabletopOptions::Validate() const {
  SH_RETURN_IF_ERROR(CheckIn("min_objects", min_objects, 2, 20));
  SH_RETURN_IF_ERROR(CheckIn("max_objects", max_objects, min_objects, 20));
  SH_RETURN_IF_ERROR(CheckIn("max_resamples", max_resamples, 0, 10000));
  SH_RETURN_IF_ERROR(CheckIn("min_separation_m", min_separation_m, 0.01, 1.0));
  SH_RETURN_IF_ERROR(CheckIn("width_lo_m", width_lo_m, 0.02, 0.5));
  SH_RETURN_IF_ERROR(CheckIn("width_hi_m", width_hi_m, width_lo_m, 0.5));
  SH_RETURN_IF_ERROR(CheckIn("height_lo_m", height_lo_m, 0.03, 0.5));
  SH_RETURN_IF_ERROR(CheckIn("height_hi_m", height_hi_m, height_lo_m, 0.5));
  SH_RETURN_IF_ERROR(CheckIn("box_width_scale", box_width_scale, 0.5, 1.0));
  SH_RETURN_IF_ERROR(CheckIn("sphere_scale", sphere_scale, 0.5, 1.0));
  SH_RETURN_IF_ERROR(CheckIn("mass_lo_kg", mass_lo_kg, 0.01, 20.0));
  SH_RETURN_IF_ERROR(CheckIn("mass_hi_kg", mass_hi_kg, mass_lo_kg, 20.0));
  SH_RETURN_IF_ERROR(CheckIn("friction_lo", friction_lo, kMinFriction, kMaxFriction));
  SH_RETURN_IF_ERROR(CheckIn("friction_hi", friction_hi, friction_lo, kMaxFriction));
  SH_RETURN_IF_ERROR(
      CheckIn("stack_bottom_min_width_m", stack_bottom_min_width_m, width_lo_m, width_hi_m));
  // the region, widened by the largest half width, must lie on the board
  const double r = MaxHalfWidth(*this);
  const std::map<std::string, double> table = DefaultSizes("table");
  const Eigen::Vector3d lo =
      WorldToTable(Eigen::Vector3d(TableNearEdgeX(), -table.at("width") / 2, 0));
  const Eigen::Vector3d hi =
      WorldToTable(Eigen::Vector3d(TableNearEdgeX() + table.at("depth"), table.at("width") / 2, 0));
  SH_RETURN_IF_ERROR(CheckIn("region_x_lo_m", region_x_lo_m, lo.x() + r, hi.x() - r));
  SH_RETURN_IF_ERROR(CheckIn("region_x_hi_m", region_x_hi_m, region_x_lo_m, hi.x() - r));
  SH_RETURN_IF_ERROR(CheckIn("region_y_lo_m", region_y_lo_m, lo.y() + r, hi.y() - r));
  SH_RETURN_IF_ERROR(CheckIn("region_y_hi_m", region_y_hi_m, region_y_lo_m, hi.y() - r));
  const double half_region =
      std::min(region_x_hi_m - region_x_lo_m, region_y_hi_m - region_y_lo_m) / 2;
  SH_RETURN_IF_ERROR(CheckIn("place_min_move_m", place_min_move_m, 0.0, half_region));
  return absl::OkStatus();
}

const std::vector<std::string>& TabletopTaskKinds() {
  static const std::vector<std::string> kKinds = {"place", "stack", "any"};
  return kKinds;
}

Eigen::Vector3d TableToWorld(const Eigen::Vector3d& p_table) { return FrameOrigin() + p_table; }

Eigen::Vector3d WorldToTable(const Eigen::Vector3d& p_world) { return p_world - FrameOrigin(); }

Eigen::Vector3d TabletopRightShoulderWorld() {
  return Eigen::Vector3d(ChairX(), HumanY() - kTabletopShoulderRightM,
                         DefaultSizes("chair").at("seat_height") + kTabletopPelvisAboveSeatM +
                             kTabletopShoulderAbovePelvisM);
}

ModelOptions DexterousModelOptions() {
  ModelOptions o;
  o.timestep_s = 1.0 / 240;
  o.cone = "elliptic";
  o.impratio = 3;
  // one seated human, a hand and a table of 4-6 objects: 60-150 constraint rows measured;
  // MuJoCo clears every mjData's buffers when it makes one, and at the room-sized default the
  // tabletop pipeline spent about a third of its time doing so
  o.nconmax = 250;
  o.njmax = 1000;
  o.nstack = 800000;
  return o;
}

SceneSpec TabletopBaseScene(const std::string& name) {
  SceneSpec s;
  s.name = name;
  ObjectSpec table;
  table.id = "table000";
  table.type = "table";
  table.pos = Eigen::Vector3d(kTableX, 0, 0);
  table.yaw_rad = M_PI;  // its sitting side (+x) towards the human at world -x
  s.objects.push_back(table);
  ObjectSpec chair;
  chair.id = "chair001";
  chair.type = "chair";
  chair.pos = Eigen::Vector3d(ChairX(), HumanY(), 0);
  s.objects.push_back(chair);
  HumanSpec human;
  human.pos_xy = Eigen::Vector2d(ChairX(), HumanY());
  human.posture = "sit";
  human.kind = "humanoid_right_hand";
  s.humans.push_back(human);
  return s;
}

core::StatusOr<TabletopScene> GenerateTabletop(uint64_t seed, std::string_view kind,
                                               const TabletopOptions& options) {
  const std::vector<std::string>& kinds = TabletopTaskKinds();
  if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
    return absl::InvalidArgumentError("unknown tabletop task kind '" + std::string(kind) +
                                      "'; valid kinds are: " + core::JoinNames(kinds));
  }
  SH_RETURN_IF_ERROR(options.Validate());
  const TabletopOptions& o = options;
  core::Rng rng(seed);
  TabletopScene out;
  TabletopTask& task = out.task;
  task.kind = std::string(kind);
  if (kind == "any") task.kind = rng.Uniform() < 0.5 ? "place" : "stack";
  out.desired_objects = rng.UniformInt(o.min_objects, o.max_objects);
  const bool stack = task.kind == "stack";

  // the task objects first: stack draws the bottom, then the object put on it (unlike it)
  std::vector<Draw> task_draws;
  std::vector<Eigen::Vector2d> taken;
  for (int i = 0; i < (stack ? 2 : 1); ++i) {
    Draw d = DrawLook(rng, o, stack && i == 0);
    while (i == 1 && SameLook(d, task_draws[0])) d.color = PickColor(rng);
    std::optional<Eigen::Vector2d> p = DrawPosition(rng, o, taken);
    if (!p) {
      return absl::InternalError("tabletop seed " + std::to_string(seed) +
                                 ": no position for a task object in the region with "
                                 "min_separation_m " +
                                 core::FormatNumber(o.min_separation_m));
    }
    d.xy_table = *p;
    taken.push_back(*p);
    task_draws.push_back(d);
  }
  std::vector<Draw> draws = task_draws;
  DrawOthers(rng, o, out.desired_objects - static_cast<int>(task_draws.size()), task_draws, taken,
             draws);
  if (!stack) {
    const Eigen::Vector2d p = DrawPlaceTarget(rng, o, draws);
    task.target_table = Eigen::Vector3d(p.x(), p.y(), 0.0);
  }

  out.scene = TabletopBaseScene("tabletop_" + std::to_string(seed));
  const int first = static_cast<int>(out.scene.objects.size());
  for (size_t i = 0; i < draws.size(); ++i) {
    out.scene.objects.push_back(ToSpec(draws[i], o, first + static_cast<int>(i)));
  }
  const ObjectSpec& moved = out.scene.objects[first + (stack ? 1 : 0)];
  task.object_id = moved.id;
  if (stack) {
    const Draw& bottom = task_draws[0];
    task.target_id = out.scene.objects[first].id;
    task.target_table =
        Eigen::Vector3d(bottom.xy_table.x(), bottom.xy_table.y(), TopHeight(bottom, o));
    task.command = "put the " + moved.color + " " + moved.type + " on the " + bottom.color + " " +
                   bottom.shape;
  }
  task.target_world = TableToWorld(task.target_table);
  // every object is built once, so that a bad range shows here rather than in a model
  core::StatusOr<core::SceneCatalog> built = BuildCatalog(out.scene);
  if (!built.ok()) return core::Annotate(built.status(), "tabletop seed " + std::to_string(seed));
  return out;
}

const std::vector<std::string>& ZeroShotShapes() {
  static const std::vector<std::string> kShapes = {"cone", "hourglass", "mesh"};
  return kShapes;
}

core::Status MakeZeroShot(TabletopScene* ts, std::string_view shape, const std::string& mesh_file) {
  const std::vector<std::string>& shapes = ZeroShotShapes();
  if (std::find(shapes.begin(), shapes.end(), shape) == shapes.end()) {
    return absl::InvalidArgumentError("unknown zero-shot shape '" + std::string(shape) +
                                      "'; valid shapes are: " + core::JoinNames(shapes));
  }
  TabletopOptions defaults;
  for (ObjectSpec& o : ts->scene.objects) {
    if (o.id != ts->task.object_id) continue;
    // the drawn nominal width and height (ToSpec's sizes undone)
    double width = 0, height = 0;
    if (o.type == "box") {
      width = o.size.at("width") / defaults.box_width_scale;
      height = o.size.at("height");
    } else if (o.type == "cylinder") {
      width = 2 * o.size.at("radius");
      height = o.size.at("height");
    } else {
      height = 2 * o.size.at("radius") / defaults.sphere_scale;
      width = 0.5 * (defaults.width_lo_m + defaults.width_hi_m);
    }
    const std::string digits = o.id.substr(o.id.size() - 3);
    o.type = std::string(shape);
    o.id = o.type + digits;
    o.size.clear();
    o.mesh.clear();
    if (shape == "cone") {
      o.size = {{"radius", width / 2}, {"height", height}};
    } else if (shape == "hourglass") {
      o.size = {{"radius", width / 2}, {"waist_radius", 0.55 * width / 2}, {"height", height}};
    } else {
      o.mesh = mesh_file;
    }
    ts->task.object_id = o.id;
    if (!ts->task.command.empty()) {
      const size_t at = ts->task.command.find(" " + o.color + " ");
      const size_t end = ts->task.command.find(" on the ");
      if (at != std::string::npos && end != std::string::npos) {
        ts->task.command.replace(at + 2 + o.color.size(), end - (at + 2 + o.color.size()),
                                 shape == "mesh" ? "object" : o.type);
      }
    }
    core::StatusOr<core::SceneCatalog> built = BuildCatalog(ts->scene);
    if (!built.ok()) return core::Annotate(built.status(), "zero-shot " + std::string(shape));
    return absl::OkStatus();
  }
  return absl::InternalError("tabletop task object missing: " + ts->task.object_id);
}

// DASH's benchmark set-up, one generated stack scene: seated at a table, a dexterous right
// hand, "put the <colour> <shape> on the <colour> <shape>" (world/tabletop.h)
SceneSpec TabletopDashScene() {
  core::StatusOr<TabletopScene> ts = GenerateTabletop(3, "stack");
  SceneSpec s = ts.ok() ? ts->scene : TabletopBaseScene("tabletop_dash");
  s.name = "tabletop_dash";
  return s;
}

// tabletop_dash with shapes the grasp was not made for (DASH Section 5): its red box, the
// object to stack, becomes an hourglass, and its blue sphere a cone
SceneSpec TabletopZeroShotScene() {
  core::StatusOr<TabletopScene> ts = GenerateTabletop(3, "stack");
  if (!ts.ok() || !MakeZeroShot(&*ts, "hourglass").ok())
    return TabletopBaseScene("tabletop_zero_shot");
  SceneSpec s = ts->scene;
  s.name = "tabletop_zero_shot";
  for (ObjectSpec& o : s.objects) {
    if (o.type != "sphere") continue;
    const double r = o.size.at("radius");
    o.type = "cone";
    o.id = "cone" + o.id.substr(o.id.size() - 3);
    o.size = {{"radius", r * 0.8}, {"height", std::min(0.18, 3 * r)}};
  }
  return s;
}

}  // namespace simhuman::world
