#include "simhuman/eval/sceneplan_levels.h"

#include <string>
#include <vector>

#include "simhuman/eval/plan_json.h"
#include "simhuman/plan/metrics.h"
#include "simhuman/world/objects.h"
#include "simhuman/world/room.h"

namespace simhuman::eval {
namespace {

using nlohmann::json;

// starts: this far from the first object's front stand point, with this much room
constexpr double kStartLoM = 1.0, kStartHiM = 6.0, kStartClearanceM = 0.45;

const char* Side(bool left) { return left ? "left" : "right"; }

// one pose of UniHSI's Tables 8-9 on object `o`: the pairs added to the base step
struct Pose {
  std::string label;
  std::vector<json> pairs;
};

// both sides' pairs (direction none, Table 8) or one side's (direction up)
Pose SidedPose(const std::string& o, const std::string& what, const std::string& part_fmt,
               const std::string& joint, core::Rng& rng) {
  Pose p;
  const int pick = rng.UniformInt(0, 2);  // 0 left, 1 right, 2 both
  for (int s = 0; s < 2; ++s) {
    if (pick != 2 && pick != s) continue;
    const std::string side = Side(s == 0);
    std::string part = part_fmt == "knee"  ? side + " knee"
                       : part_fmt == "arm" ? side + " arm"
                                           : part_fmt;
    p.pairs.push_back(PlanPair(o, part, side + " " + joint, "contact", pick == 2 ? "none" : "up"));
  }
  p.label = (pick == 2 ? std::string("both ") : std::string(Side(pick == 0)) + " ") + what;
  return p;
}

Pose SeatPose(const std::string& o, const std::string& type, core::Rng& rng) {
  // a sofa's arms are 0.7-0.9 m from the middle of its seat, where the human sits: out of reach
  const bool arms = type == "armchair";
  const bool back = type == "chair" || type == "armchair" || type == "sofa";
  std::vector<int> kinds = {0, 1, 2};              // knees, stomach, foot on knee
  if (back) kinds.insert(kinds.end(), {3, 4});     // lean back, lean forward
  if (arms) kinds.insert(kinds.end(), {5, 6, 7});  // hands on arms, elbows, hands off
  switch (kinds[rng.UniformInt(0, static_cast<int>(kinds.size()) - 1)]) {
    case 0:
      return SidedPose(o, "hand(s) on the knees", "knee", "hand", rng);
    case 1: {
      Pose p = SidedPose(o, "hand(s) on the stomach", "pelvis", "hand", rng);
      for (json& j : p.pairs) j["direction"] = "none";  // Table 8: none, one hand or both
      return p;
    }
    case 2: {
      const bool right = rng.Uniform() < 0.5;
      return {std::string(Side(!right)) + " foot on the " + Side(right) + " knee",
              {PlanPair(o, std::string(Side(right)) + " knee", std::string(Side(!right)) + " foot",
                        "contact", "none")}};
    }
    case 3:
      return {"lean back", {PlanPair(o, "back surface", "torso", "contact", "none")}};
    case 4:
      return {"lean forward", {PlanPair(o, "back surface", "torso", "not contact", "none")}};
    case 5:
      return SidedPose(o, "hand(s) on the armrests", "arm", "hand", rng);
    case 6:
      return SidedPose(o, "elbow(s) on the armrests", "arm", "elbow", rng);
    default:
      return {"hands off the armrests",
              {PlanPair(o, "left arm", "left hand", "not contact", "none"),
               PlanPair(o, "right arm", "right hand", "not contact", "none")}};
  }
}

// a lying pose (Table 9); `head_up` replaces the head-on-pillow pair
Pose LiePose(const std::string& o, core::Rng& rng, bool* head_up) {
  *head_up = false;
  switch (rng.UniformInt(0, 4)) {
    case 0: {
      Pose p;
      const int pick = rng.UniformInt(0, 2);
      for (int s = 0; s < 2; ++s) {
        if (pick == 2 || pick == s)
          p.pairs.push_back(
              PlanPair(o, "mattress", std::string(Side(s == 0)) + " knee", "not contact", "none"));
      }
      p.label = pick == 2 ? "knees up" : std::string(Side(pick == 0)) + " knee up";
      return p;
    }
    case 1: {
      Pose p = SidedPose(o, "hand(s) on the pillow", "pillow", "hand", rng);
      for (json& j : p.pairs) j["direction"] = "none";
      return p;
    }
    case 2: {
      const bool left = rng.Uniform() < 0.5;  // on the left side: right shoulder off
      return {
          std::string("on the ") + Side(left) + " side",
          {PlanPair(o, "mattress", std::string(Side(!left)) + " shoulder", "not contact", "none")}};
    }
    case 3: {
      const bool right = rng.Uniform() < 0.5;
      return {std::string(Side(!right)) + " foot on the " + Side(right) + " knee",
              {PlanPair(o, std::string(Side(right)) + " knee", std::string(Side(!right)) + " foot",
                        "contact", "up")}};
    }
    default:
      *head_up = true;
      return {"head up", {}};
  }
}

json SitPair(const std::string& o) {
  return PlanPair(o, "seat surface", "pelvis", "contact", "up");
}

std::vector<json> LieBase(const std::string& o, bool head_up) {
  return {PlanPair(o, "mattress", "pelvis", "contact", "up"),
          head_up ? PlanPair(o, "pillow", "head", "not contact", "none")
                  : PlanPair(o, "pillow", "head", "contact", "up")};
}

// appends a visit to a seat or bed: walk there, sit (or sit on the edge and lie), then `poses`
// pose steps, each after a stand-up and sit-again with probability `resit`
void AppendVisit(const std::string& o, const std::string& type, int poses, double resit,
                 core::Rng& rng, std::vector<json>* steps) {
  steps->push_back(PlanStep("walk to " + o, {PlanGetClose(o, "front")}));
  if (type == "bed") {
    steps->push_back(
        PlanStep("sit on the edge of " + o, {PlanPair(o, "mattress", "pelvis", "contact", "up"),
                                             PlanPair(o, "pillow", "head", "not contact", "up")}));
    steps->push_back(PlanStep("lie on " + o, LieBase(o, false)));
    for (int k = 0; k < poses; ++k) {
      bool head_up = false;
      Pose p = LiePose(o, rng, &head_up);
      std::vector<json> pairs = LieBase(o, head_up);
      pairs.insert(pairs.end(), p.pairs.begin(), p.pairs.end());
      steps->push_back(PlanStep("lie on " + o + ", " + p.label, pairs));
    }
    return;
  }
  steps->push_back(PlanStep("sit on " + o, {SitPair(o)}));
  for (int k = 0; k < poses; ++k) {
    if (rng.Uniform() < resit) {
      steps->push_back(PlanStep("stand up from " + o, {PlanGetClose(o, "front")}));
      steps->push_back(PlanStep("sit on " + o + " again", {SitPair(o)}));
    }
    Pose p = SeatPose(o, type, rng);
    std::vector<json> pairs = {SitPair(o)};
    pairs.insert(pairs.end(), p.pairs.begin(), p.pairs.end());
    steps->push_back(PlanStep("sit on " + o + ", " + p.label, pairs));
  }
}

// the room, the start 1-6 m from `first`'s front stand point, into `out`
core::Status FinishEpisode(const world::Room& room, const world::RoomRequest& req,
                           const std::string& first, std::vector<json> steps, core::Rng& rng,
                           EpisodeSpec* out) {
  out->scene.objects = room.scene.objects;
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(out->scene);
  if (!catalog.ok()) return absl::InternalError(std::string(catalog.status().message()));
  const core::CatalogObject* obj = catalog->Find(first);
  if (obj == nullptr) return absl::InternalError("sceneplan: no object " + first);
  const Eigen::Vector3d stand =
      plan::StandPoint(*obj, plan::Direction::kFront, plan::PairParams{}.stand_off_m);
  core::StatusOr<world::HumanSpec> h = world::RandomStart(
      room.scene, req, stand.head<2>(), kStartLoM, kStartHiM, kStartClearanceM, rng);
  if (!h.ok()) return absl::InternalError(std::string(h.status().message()));
  out->scene.humans = {*h};
  out->object_id = first;
  out->plan = PlanOf(std::move(steps));
  return absl::OkStatus();
}

core::Status Internal(const core::Status& st) {
  return st.ok() ? st : absl::InternalError("sceneplan room: " + std::string(st.message()));
}

}  // namespace

core::Status MakeScenePlanMid(core::Rng& rng, EpisodeSpec* out) {
  // UniHSI's medium plans are on chairs, armchairs, sofas and beds (a stool stays in the room)
  static const char* const kTargets[] = {"chair", "armchair", "sofa", "bed"};
  const std::string type = kTargets[rng.UniformInt(0, 3)];
  static const char* const kOthers[] = {"desk", "bed", "sofa", "armchair", "chair", "stool"};
  world::RoomRequest req;
  req.items = {type};
  for (int k = 0; k < 2; ++k) req.items.push_back(kOthers[rng.UniformInt(0, 5)]);
  core::StatusOr<world::Room> room = world::GenerateRoom(req, rng);
  if (!room.ok()) return Internal(room.status());
  const std::string o = room->item_ids[0][0];
  std::vector<json> steps;
  const int poses = rng.UniformInt(type == "bed" ? 1 : 2, type == "bed" ? 3 : 4);
  AppendVisit(o, type, poses, 0.25, rng, &steps);
  if (rng.Uniform() < 0.5)
    steps.push_back(PlanStep("stand up from " + o, {PlanGetClose(o, "front")}));
  out->variant = type + ": " + std::to_string(steps.size()) + " steps";
  return FinishEpisode(*room, req, o, std::move(steps), rng, out);
}

core::Status MakeScenePlanHard(core::Rng& rng, EpisodeSpec* out) {
  static const char* const kSeats[] = {"sofa", "armchair"};
  const std::string seat = kSeats[rng.UniformInt(0, 1)];
  world::RoomRequest req;
  req.items = {"desk", "bed", seat, "stool"};
  core::StatusOr<world::Room> room = world::GenerateRoom(req, rng);
  if (!room.ok()) return Internal(room.status());
  const std::string laptop = room->item_ids[0][1], chair = room->item_ids[0][2];
  const std::string bed = room->item_ids[1][0], sofa = room->item_ids[2][0];
  // the desk: sit, then both hands on the keyboard while seated (two objects at once)
  std::vector<json> steps = {
      PlanStep("walk to " + chair, {PlanGetClose(chair, "front")}),
      PlanStep("sit on " + chair, {SitPair(chair)}),
      PlanStep("sit on " + chair + ", both hands on " + laptop,
               {SitPair(chair), PlanPair(laptop, "keyboard", "left hand", "contact", "none"),
                PlanPair(laptop, "keyboard", "right hand", "contact", "none")}),
      PlanStep("stand up from " + chair, {PlanGetClose(chair, "front")})};
  // then one or both of: the seat, the bed (in a random order)
  std::vector<std::pair<std::string, std::string>> visits;
  const int pick = rng.UniformInt(0, 3);
  if (pick == 0 || pick >= 2) visits.push_back({sofa, seat});
  if (pick >= 1) visits.push_back({bed, "bed"});
  if (pick == 3) std::swap(visits[0], visits[1]);
  for (size_t v = 0; v < visits.size(); ++v) {
    const auto& [id, type] = visits[v];
    AppendVisit(id, type, rng.UniformInt(0, 1), 0.0, rng, &steps);
    if (v + 1 < visits.size() || rng.Uniform() < 0.5)
      steps.push_back(PlanStep("stand up from " + id, {PlanGetClose(id, "front")}));
  }
  std::string names = "desk";
  for (const auto& v : visits) names += "+" + v.second;
  out->variant = names + ": " + std::to_string(steps.size()) + " steps";
  return FinishEpisode(*room, req, chair, std::move(steps), rng, out);
}

}  // namespace simhuman::eval
