#include "simhuman/eval/suites.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simhuman/core/geometry.h"
#include "simhuman/core/rng.h"
#include "simhuman/eval/plan_json.h"
#include "simhuman/eval/sceneplan_levels.h"
#include "simhuman/world/objects.h"

namespace simhuman::eval {
namespace {

using nlohmann::json;

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kTwoPi = 2.0 * M_PI;

// seat types of the sit suite (and the chair-type variant of sceneplan-simple)
const char* const kSeatTypes[] = {"chair", "armchair", "sofa", "stool", "high_stool"};
constexpr int kNumSeatTypes = 5;

// sit protocol
constexpr double kSitFrontLoM = 0.30, kSitFrontHiM = 0.50;
constexpr double kSitLateralM = 0.08;
constexpr double kSofaLateralM = 0.5;
constexpr double kYawJitterDeg = 15.0;
// lie protocol
constexpr double kLieFrontLoM = 0.30, kLieFrontHiM = 0.45;
constexpr double kLieLateralM = 0.10;
// where one sits on a bed's edge to lie down: the pelvis this far from the pillow's centre
constexpr double kLieFromPillowM = 0.65;
constexpr double kMidBedLateralM = 0.15;
// reach protocol (human frame: x forward, y left)
constexpr double kReachForwardLoM = 0.25, kReachForwardHiM = 0.55;
constexpr double kReachLateralInM = 0.10;   // across the body, towards the other hand
constexpr double kReachLateralOutM = 0.35;  // out to the reaching hand's side
constexpr double kReachHeightLoM = 0.7, kReachHeightHiM = 1.5;
// sceneplan-simple chair variant: a start facing the object, a little beyond its stand point
constexpr double kApproachLoM = 0.55, kApproachHiM = 0.85;
constexpr double kApproachLateralM = 0.25;
constexpr double kApproachYawJitterDeg = 20.0;
// stand-up: the seated pelvis this far behind the seat's front edge (at most half the seat's
// depth), sideways on a sofa or bed within these
constexpr double kStandUpDepthM = 0.22;
constexpr double kStandUpSofaLateralM = 0.4, kStandUpBedLateralM = 0.3;
constexpr double kStandUpYawJitterDeg = 5.0;
// sit-far: distance from the seat's front face and bearing off its front direction
constexpr double kSitFarLoM = 1.0, kSitFarHiM = 6.0, kSitFarBearingDeg = 60.0;

// world xy of a point given in the frame of an object at `pos` turned by `yaw`
Eigen::Vector2d LocalToWorld(const Eigen::Vector3d& pos, double yaw, double x, double y) {
  return pos.head<2>() + Eigen::Vector2d(std::cos(yaw) * x - std::sin(yaw) * y,
                                         std::sin(yaw) * x + std::cos(yaw) * y);
}

// a random object of `type` at the origin with a uniform yaw, built to read its bounds
core::Status RandomObject(const std::string& type, core::Rng& rng, world::ObjectSpec* spec,
                          core::CatalogObject* built) {
  *spec = world::RandomObjectSpec(type, rng);
  spec->pos = Eigen::Vector3d::Zero();
  spec->yaw_rad = core::WrapAngle(rng.Uniform(0.0, kTwoPi));
  core::StatusOr<core::CatalogObject> obj = world::BuildObject(*spec);
  if (!obj.ok()) {
    return absl::InternalError("eval suite: cannot build a random " + type + ": " +
                               std::string(obj.status().message()));
  }
  *built = *std::move(obj);
  return absl::OkStatus();
}

// the y centre of a part's bounds in the object frame
double PartCentreY(const core::CatalogObject& obj, const std::string& part) {
  const core::CatalogPart* p = obj.FindPart(part);
  if (p == nullptr) return 0.0;
  auto [lo, hi] = core::ShapesBounds(p->shapes);
  return 0.5 * (lo.y() + hi.y());
}

json SitStep(const std::string& id) {
  return PlanStep("sit on " + id, {PlanPair(id, "seat surface", "pelvis", "contact", "up")});
}

// sit: back to the seat, 0.30-0.50 m in front of its front face
core::Status MakeSit(core::Rng& rng, EpisodeSpec* out) {
  std::string type = kSeatTypes[rng.UniformInt(0, kNumSeatTypes - 1)];
  world::ObjectSpec o;
  core::CatalogObject built;
  SH_RETURN_IF_ERROR(RandomObject(type, rng, &o, &built));
  auto [lo, hi] = built.LocalBounds();
  double front = hi.x() + rng.Uniform(kSitFrontLoM, kSitFrontHiM);
  double lateral_m = type == "sofa" ? kSofaLateralM : kSitLateralM;
  double lateral = 0.5 * (lo.y() + hi.y()) + rng.Uniform(-lateral_m, lateral_m);
  double jitter = rng.Uniform(-kYawJitterDeg, kYawJitterDeg) * kDegToRad;
  world::HumanSpec h;
  h.pos_xy = LocalToWorld(o.pos, o.yaw_rad, front, lateral);
  h.yaw_rad = core::WrapAngle(o.yaw_rad + jitter);
  out->variant = type;
  out->object_id = o.id;
  out->scene.objects = {o};
  out->scene.humans = {h};
  out->plan = PlanOf({SitStep(o.id)});
  return absl::OkStatus();
}

void LieSteps(const std::string& id, std::vector<json>* steps) {
  steps->push_back(
      PlanStep("sit on the edge of " + id, {PlanPair(id, "mattress", "pelvis", "contact", "up"),
                                            PlanPair(id, "pillow", "head", "not contact", "up")}));
  steps->push_back(
      PlanStep("lie down on " + id, {PlanPair(id, "mattress", "pelvis", "contact", "up"),
                                     PlanPair(id, "pillow", "head", "contact", "up")}));
}

// lie: back to the bed's long side (its front), at the spot where sitting down and lying back
// puts the head on the pillow (as a person walking up to a bed to lie down would stand);
// `mid_bed` starts near the middle of the long side instead (sceneplan-simple)
core::Status MakeLie(core::Rng& rng, EpisodeSpec* out, bool mid_bed = false) {
  world::ObjectSpec o;
  core::CatalogObject built;
  SH_RETURN_IF_ERROR(RandomObject("bed", rng, &o, &built));
  auto [lo, hi] = built.LocalBounds();
  double front = hi.x() + rng.Uniform(kLieFrontLoM, kLieFrontHiM);
  double pillow = PartCentreY(built, "pillow"), mattress = PartCentreY(built, "mattress");
  double toward_foot = pillow > mattress ? -1.0 : 1.0;
  double lateral =
      pillow + toward_foot * kLieFromPillowM + rng.Uniform(-kLieLateralM, kLieLateralM);
  if (mid_bed) lateral = mattress + rng.Uniform(-kMidBedLateralM, kMidBedLateralM);
  double jitter = rng.Uniform(-kYawJitterDeg, kYawJitterDeg) * kDegToRad;
  world::HumanSpec h;
  h.pos_xy = LocalToWorld(o.pos, o.yaw_rad, front, lateral);
  h.yaw_rad = core::WrapAngle(o.yaw_rad + jitter);
  out->variant = "bed";
  out->object_id = o.id;
  out->scene.objects = {o};
  out->scene.humans = {h};
  std::vector<json> steps;
  LieSteps(o.id, &steps);
  out->plan = PlanOf(steps);
  return absl::OkStatus();
}

// reach: a marker point in front of a standing human, on the reaching hand's side
core::Status MakeReach(core::Rng& rng, EpisodeSpec* out) {
  world::HumanSpec h;
  h.yaw_rad = core::WrapAngle(rng.Uniform(0.0, kTwoPi));
  bool left = rng.Uniform() < 0.5;
  double side = left ? 1.0 : -1.0;  // the human's left is its +y
  double forward = rng.Uniform(kReachForwardLoM, kReachForwardHiM);
  double lateral = side * rng.Uniform(-kReachLateralInM, kReachLateralOutM);
  double height = rng.Uniform(kReachHeightLoM, kReachHeightHiM);
  world::ObjectSpec m;
  m.id = std::string(kMarkerType) + "000";
  m.type = kMarkerType;
  Eigen::Vector2d xy =
      LocalToWorld(Eigen::Vector3d(h.pos_xy.x(), h.pos_xy.y(), 0), h.yaw_rad, forward, lateral);
  m.pos = Eigen::Vector3d(xy.x(), xy.y(), height);
  std::string hand = left ? "left hand" : "right hand";
  out->variant = hand;
  out->object_id = m.id;
  out->joint = left ? core::BodyJoint::kLeftHand : core::BodyJoint::kRightHand;
  out->scene.objects = {m};
  out->scene.humans = {h};
  out->plan = PlanOf({PlanStep("touch " + m.id + " with the " + hand,
                               {PlanPair(m.id, kMarkerPart, hand, "contact", "none")})});
  return absl::OkStatus();
}

// sceneplan-simple: a chair-type object ([get close front], [sit]) or a bed ([sit on edge],
// [lie])
core::Status MakeScenePlanSimple(core::Rng& rng, EpisodeSpec* out) {
  if (rng.Uniform() < 0.5) {
    SH_RETURN_IF_ERROR(MakeLie(rng, out, /*mid_bed=*/true));
    out->variant = "bed: sit on edge, lie";
    return absl::OkStatus();
  }
  std::string type = kSeatTypes[rng.UniformInt(0, kNumSeatTypes - 1)];
  world::ObjectSpec o;
  core::CatalogObject built;
  SH_RETURN_IF_ERROR(RandomObject(type, rng, &o, &built));
  auto [lo, hi] = built.LocalBounds();
  double front = hi.x() + rng.Uniform(kApproachLoM, kApproachHiM);
  double lateral = 0.5 * (lo.y() + hi.y()) + rng.Uniform(-kApproachLateralM, kApproachLateralM);
  double jitter = rng.Uniform(-kApproachYawJitterDeg, kApproachYawJitterDeg) * kDegToRad;
  world::HumanSpec h;
  h.pos_xy = LocalToWorld(o.pos, o.yaw_rad, front, lateral);
  h.yaw_rad = core::WrapAngle(o.yaw_rad + M_PI + jitter);  // facing the object
  out->variant = type + ": get close, sit";
  out->object_id = o.id;
  out->scene.objects = {o};
  out->scene.humans = {h};
  out->plan =
      PlanOf({PlanStep("get close to " + o.id, {PlanGetClose(o.id, "front")}), SitStep(o.id)});
  return absl::OkStatus();
}

// a start 1-6 m from the point at the middle of `built`'s front face (object at `o`), within
// +-60 deg of its front direction, with any heading
world::HumanSpec FarStart(core::Rng& rng, const world::ObjectSpec& o,
                          const core::CatalogObject& built) {
  auto [lo, hi] = built.LocalBounds();
  double r = rng.Uniform(kSitFarLoM, kSitFarHiM);
  double bearing = rng.Uniform(-kSitFarBearingDeg, kSitFarBearingDeg) * kDegToRad;
  world::HumanSpec h;
  h.pos_xy = LocalToWorld(o.pos, o.yaw_rad, hi.x() + r * std::cos(bearing),
                          0.5 * (lo.y() + hi.y()) + r * std::sin(bearing));
  h.yaw_rad = core::WrapAngle(rng.Uniform(0.0, kTwoPi));
  return h;
}

// sit-far: 1-6 m from the seat's front, within +-60 deg of its front direction, any heading
core::Status MakeSitFar(core::Rng& rng, EpisodeSpec* out) {
  std::string type = kSeatTypes[rng.UniformInt(0, kNumSeatTypes - 1)];
  world::ObjectSpec o;
  core::CatalogObject built;
  SH_RETURN_IF_ERROR(RandomObject(type, rng, &o, &built));
  out->variant = type + ": walk, sit";
  out->object_id = o.id;
  out->scene.objects = {o};
  out->scene.humans = {FarStart(rng, o, built)};
  out->plan = PlanOf({PlanStep("walk to " + o.id, {PlanGetClose(o.id, "front")}), SitStep(o.id)});
  return absl::OkStatus();
}

// stand-up: the human starts seated (scene posture "sit") on a seat one sits on with the feet on
// the floor (the sit suite's types but the high stool, whose seated start would leave the feet
// hanging) or on a bed's front edge, facing out; the plan is UniHSI's "stand up", a get-close
// step to the object's front
core::Status MakeStandUp(core::Rng& rng, EpisodeSpec* out) {
  static const char* const kTypes[] = {"chair", "armchair", "sofa", "stool", "bed"};
  const std::string type = kTypes[rng.UniformInt(0, 4)];
  world::ObjectSpec o;
  core::CatalogObject built;
  SH_RETURN_IF_ERROR(RandomObject(type, rng, &o, &built));
  const core::CatalogPart* seat = built.FindPart(type == "bed" ? "mattress" : "seat surface");
  if (seat == nullptr) return absl::InternalError("eval suite stand-up: a " + type + " to sit on");
  auto [lo, hi] = core::ShapesBounds(seat->shapes);
  const double depth = std::min(kStandUpDepthM, 0.5 * (hi.x() - lo.x()));
  const double lateral_m =
      type == "bed" ? kStandUpBedLateralM : (type == "sofa" ? kStandUpSofaLateralM : 0.0);
  const double lateral = 0.5 * (lo.y() + hi.y()) + rng.Uniform(-lateral_m, lateral_m);
  world::HumanSpec h;
  h.pos_xy = LocalToWorld(o.pos, o.yaw_rad, hi.x() - depth, lateral);
  h.yaw_rad = core::WrapAngle(o.yaw_rad +
                              rng.Uniform(-kStandUpYawJitterDeg, kStandUpYawJitterDeg) * kDegToRad);
  h.posture = "sit";
  out->variant = type;
  out->object_id = o.id;
  out->scene.objects = {o};
  out->scene.humans = {h};
  out->plan = PlanOf({PlanStep("stand up from " + o.id, {PlanGetClose(o.id, "front")})});
  return absl::OkStatus();
}

// get-up: the lie suite's start and plan, then UniHSI's "stand up" from the bed (a get-close
// step to its front): getting up from lying, which the human does through sitting on the edge
core::Status MakeGetUp(core::Rng& rng, EpisodeSpec* out) {
  SH_RETURN_IF_ERROR(MakeLie(rng, out));
  std::vector<json> steps;
  LieSteps(out->object_id, &steps);
  steps.push_back(
      PlanStep("stand up from " + out->object_id, {PlanGetClose(out->object_id, "front")}));
  out->plan = PlanOf(steps);
  return absl::OkStatus();
}

// lie-far: as sit-far, for a bed: [get close (front)], [sit on the edge], [lie]
core::Status MakeLieFar(core::Rng& rng, EpisodeSpec* out) {
  world::ObjectSpec o;
  core::CatalogObject built;
  SH_RETURN_IF_ERROR(RandomObject("bed", rng, &o, &built));
  out->variant = "bed: walk, sit on edge, lie";
  out->object_id = o.id;
  out->scene.objects = {o};
  out->scene.humans = {FarStart(rng, o, built)};
  std::vector<json> steps = {PlanStep("walk to " + o.id, {PlanGetClose(o.id, "front")})};
  LieSteps(o.id, &steps);
  out->plan = PlanOf(steps);
  return absl::OkStatus();
}

// reach-far: a marker point at the reach suite's heights, the human 1-6 m from the point
// kReachFarStandM in front of it (the marker's yaw is random), any heading: [get close
// (front)], [touch it with one hand]
core::Status MakeReachFar(core::Rng& rng, EpisodeSpec* out) {
  world::ObjectSpec m;
  m.id = std::string(kMarkerType) + "000";
  m.type = kMarkerType;
  m.yaw_rad = core::WrapAngle(rng.Uniform(0.0, kTwoPi));
  m.pos = Eigen::Vector3d(0, 0, rng.Uniform(kReachHeightLoM, kReachHeightHiM));
  core::StatusOr<core::CatalogObject> built = world::BuildObject(m);
  if (!built.ok()) {
    return absl::InternalError("eval suite: cannot build a marker: " +
                               std::string(built.status().message()));
  }
  bool left = rng.Uniform() < 0.5;
  std::string hand = left ? "left hand" : "right hand";
  out->variant = hand;
  out->object_id = m.id;
  out->joint = left ? core::BodyJoint::kLeftHand : core::BodyJoint::kRightHand;
  out->scene.objects = {m};
  out->scene.humans = {FarStart(rng, m, *built)};
  out->plan = PlanOf({PlanStep("walk to " + m.id, {PlanGetClose(m.id, "front")}),
                      PlanStep("touch " + m.id + " with the " + hand,
                               {PlanPair(m.id, kMarkerPart, hand, "contact", "none")})});
  return absl::OkStatus();
}

}  // namespace

// the registry: a new suite is one line here (and its generator above)
const std::vector<SuiteDef>& Suites() {
  using C = SuiteController;
  using X = ExtraCheck;
  auto lie = [](core::Rng& rng, EpisodeSpec* out) { return MakeLie(rng, out); };
  static const std::vector<SuiteDef> suites = {
      {"sit", C::kMpc, X::kNone, MakeSit, "sit on a chair, armchair, sofa, stool or high stool"},
      {"lie", C::kMpc, X::kLieAlongBed, lie, "sit on a bed's edge, then lie along it"},
      {"reach", C::kMpc, X::kHandAtPoint, MakeReach, "touch a point with one hand"},
      {"sceneplan-simple", C::kMpc, X::kNone, MakeScenePlanSimple,
       "UniHSI's simple ScenePlan level (<= 3 steps, one object)"},
      {"sceneplan-mid", C::kMpc, X::kNone, MakeScenePlanMid,
       "UniHSI's medium ScenePlan level (> 3 steps, one object) in a furnished room"},
      {"sceneplan-hard", C::kMpc, X::kNone, MakeScenePlanHard,
       "UniHSI's hard ScenePlan level (> 3 steps, several objects) in a furnished room"},
      {"sit-far", C::kMpc, X::kNone, MakeSitFar, "walk 1-6 m to a seat, then sit"},
      {"lie-far", C::kMpc, X::kLieAlongBed, MakeLieFar, "walk 1-6 m to a bed, then lie"},
      {"reach-far", C::kMpc, X::kHandAtPoint, MakeReachFar, "walk 1-6 m, then touch a point"},
      {"stand-up", C::kMpc, X::kNone, MakeStandUp,
       "seated on a chair, armchair, sofa, stool or a bed's edge: stand up"},
      {"get-up", C::kMpc, X::kNone, MakeGetUp,
       "sit on a bed's edge, lie along it, then get up and stand in front of it"},
      {"walk", C::kWalkPolicy, X::kNone, nullptr, "the walking policy: walk to a goal"},
      {"walk-step", C::kWalkPolicy, X::kNone, nullptr,
       "the walking policy: short steps back and sideways"},
      {"carry", C::kCarryPolicy, X::kNone, nullptr,
       "the carrying policy: a 2-13 kg box carried 1-20 m (CooHOI Table 1)"},
      {"tabletop", C::kTabletop, X::kNone, nullptr,
       "DASH's benchmark: place or stack a table object, seated, one dexterous hand"},
      {"place", C::kTabletop, X::kNone, nullptr, "DASH's place tasks alone"},
      {"stack", C::kTabletop, X::kNone, nullptr, "DASH's stack tasks alone"},
      {"vision", C::kVision, X::kNone, nullptr,
       "egocentric vision: DASH Table 2's metrics at planning and while placing/stacking"},
      {"language", C::kPlanner, X::kNone, nullptr, "the command corpus through a planner"},
  };
  return suites;
}

std::vector<std::string> SuiteNames() {
  std::vector<std::string> out;
  for (const SuiteDef& s : Suites()) out.push_back(s.name);
  return out;
}

const SuiteDef* FindSuite(std::string_view name) {
  for (const SuiteDef& s : Suites()) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

core::StatusOr<EpisodeSpec> MakeEpisodeSpec(std::string_view suite, uint64_t seed) {
  const SuiteDef* def = FindSuite(suite);
  if (def == nullptr || def->make == nullptr) {
    std::vector<std::string> plan_suites;
    for (const SuiteDef& s : Suites()) {
      if (s.make) plan_suites.push_back(s.name);
    }
    return absl::InvalidArgumentError(
        "'" + std::string(suite) +
        "' is not a plan suite; valid are: " + core::JoinNames(plan_suites));
  }
  core::Rng rng(core::DeriveSeed(seed, kSceneStream));
  EpisodeSpec spec;
  spec.suite = def->name;
  spec.seed = seed;
  spec.scene.name = def->name + "_" + std::to_string(seed);
  spec.extra = def->extra;
  SH_RETURN_IF_ERROR(def->make(rng, &spec));
  return spec;
}

ExtraResult EvaluateExtra(const EpisodeSpec& spec, const core::SceneCatalog& scene,
                          const BodyPointArray& pts) {
  ExtraResult r;
  if (spec.extra == ExtraCheck::kNone) return r;
  const core::CatalogObject* obj = scene.Find(spec.object_id);
  const double scale = spec.agent < static_cast<int>(spec.scene.humans.size())
                           ? spec.scene.humans[spec.agent].scale
                           : 1.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (spec.extra) {
    case ExtraCheck::kNone:
      break;
    case ExtraCheck::kLieAlongBed: {
      r.metric = "lie_axis_error_deg";
      r.pass = false;
      r.value = nan;
      if (obj == nullptr) return r;
      Eigen::Vector3d axis = obj->pose.quat * Eigen::Vector3d::UnitY();
      Eigen::Vector2d a = axis.head<2>();
      Eigen::Vector3d span = pts[static_cast<int>(core::BodyJoint::kHead)] -
                             pts[static_cast<int>(core::BodyJoint::kPelvis)];
      Eigen::Vector2d s = span.head<2>();
      if (a.norm() < 1e-9 || s.norm() < 1e-9) {
        r.value = 180.0;
        return r;
      }
      double c = std::clamp(a.normalized().dot(s.normalized()), -1.0, 1.0);
      r.value = std::acos(c) / kDegToRad;
      r.pass = r.value <= kLieAxisTolDeg && s.norm() >= kLieMinSpanM * scale;
      break;
    }
    case ExtraCheck::kHandAtPoint: {
      r.metric = "hand_distance_m";
      r.pass = false;
      r.value = nan;
      if (obj == nullptr) return r;
      const core::CatalogPart* part = obj->FindPart(kMarkerPart);
      Eigen::Vector3d point = obj->pose.pos;
      if (part != nullptr && !part->shapes.empty()) {
        auto [lo, hi] = core::ShapesBounds(part->shapes);
        point = obj->pose.Apply(0.5 * (lo + hi));
      }
      r.value = (pts[static_cast<int>(spec.joint)] - point).norm();
      r.pass = r.value <= kReachTolM;
      break;
    }
  }
  return r;
}

}  // namespace simhuman::eval
