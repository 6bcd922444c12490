#include "simhuman/eval/reachability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <utility>

#include "simhuman/core/geometry.h"
#include "simhuman/plan/metrics.h"

namespace simhuman::eval {
namespace {

std::string Metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

// horizontal distance from (x, y) to the nearest point of the part's solids at the object's pose
double HorizontalDistance(const core::CatalogObject& object, const core::CatalogPart& part,
                          const Eigen::Vector2d& xy) {
  std::vector<core::Shape> world;
  for (const core::Shape& s : part.shapes) {
    core::Shape w = s;
    w.pose = object.pose.Compose(s.pose);
    world.push_back(w);
  }
  auto [lo, hi] = core::ShapesBounds(world);
  // probe at the part's mid height, so the nearest point differs only horizontally for the
  // upright solids our objects are made of
  Eigen::Vector3d probe(xy.x(), xy.y(), 0.5 * (lo.z() + hi.z()));
  Eigen::Vector3d nearest = core::NearestPointOnShapes(part.shapes, object.pose, probe);
  return (nearest - probe).head<2>().norm();
}

// where a step leaves agent `a` (horizontal): at the stand point of its get-close pair, or on
// the part its pelvis contacts (a seat, a mattress: the part's point nearest to where it was);
// elsewhere where it was (hands reach from the spot)
Eigen::Vector2d WhereStepLeaves(const plan::ContactStep& step, const core::SceneCatalog& scene,
                                int a, const Eigen::Vector2d& before) {
  for (const plan::ContactPair& pair : step.pairs) {
    if (pair.agent != a) continue;
    const core::CatalogObject* object = scene.Find(pair.object);
    if (object == nullptr || object->shapes.empty()) continue;
    if (pair.IsGetClose() && plan::IsSideDirection(pair.direction)) {
      return plan::StandPoint(*object, pair.direction, plan::PairParams{}.stand_off_m).head<2>();
    }
  }
  for (const plan::ContactPair& pair : step.pairs) {
    if (pair.agent != a || pair.type != plan::ContactType::kContact) continue;
    if (pair.joint != core::BodyJoint::kPelvis || pair.part_joint || pair.IsObjectPair()) continue;
    const core::CatalogObject* object = scene.Find(pair.object);
    const core::CatalogPart* part = object ? object->FindPart(pair.part) : nullptr;
    if (part == nullptr || part->shapes.empty()) continue;
    auto [lo, hi] = core::ShapesBounds(part->shapes);
    Eigen::Vector3d mid = object->pose.Apply(0.5 * (lo + hi));
    Eigen::Vector3d nearest = core::NearestPointOnShapes(
        part->shapes, object->pose, Eigen::Vector3d(before.x(), before.y(), mid.z()));
    return nearest.head<2>();
  }
  return before;
}

}  // namespace

absl::Status CheckWithinReach(const plan::ContactChain& chain, const core::SceneCatalog& scene,
                              const std::vector<world::HumanSpec>& humans, double max_reach_m) {
  std::set<std::pair<int, std::string>> approached;  // (agent, object id)
  std::vector<Eigen::Vector2d> where_now;            // where each agent stands or sits
  for (const world::HumanSpec& h : humans) where_now.push_back(h.pos_xy);
  for (size_t s = 0; s < chain.steps.size(); ++s) {
    const plan::ContactStep& step = chain.steps[s];
    // nearest checked part per (agent, object) in this step
    struct Nearest {
      double distance_m = std::numeric_limits<double>::infinity();
      std::string part;
    };
    std::vector<std::pair<std::pair<int, std::string>, Nearest>> checks;
    std::set<std::pair<int, std::string>> closing;  // get-close pairs of this step
    // a carry walks its carriers to the object's stand points itself
    if (step.carry) {
      for (const plan::ContactPair& pair : step.pairs) approached.insert({pair.agent, pair.object});
      continue;
    }
    for (const plan::ContactPair& pair : step.pairs) {
      std::pair<int, std::string> key(pair.agent, pair.object);
      if (pair.IsGetClose()) {
        closing.insert(key);
        continue;
      }
      if (pair.type != plan::ContactType::kContact || pair.part_joint) continue;
      if (pair.IsObjectPair()) continue;  // object on object: no body point to reach with
      if (approached.count(key)) continue;
      const core::CatalogObject* object = scene.Find(pair.object);
      const core::CatalogPart* part = object ? object->FindPart(pair.part) : nullptr;
      if (part == nullptr || pair.agent < 0 || pair.agent >= static_cast<int>(humans.size())) {
        return absl::InvalidArgumentError("plan is not grounded against the scene at " +
                                          pair.where + " (object '" + pair.object + "', part '" +
                                          pair.part + "')");
      }
      double d = HorizontalDistance(*object, *part, where_now[pair.agent]);
      auto it =
          std::find_if(checks.begin(), checks.end(), [&](const auto& c) { return c.first == key; });
      if (it == checks.end()) {
        checks.push_back({key, {d, part->name}});
      } else if (d < it->second.distance_m) {
        it->second = {d, part->name};
      }
    }
    for (const auto& [key, nearest] : checks) {
      if (closing.count(key)) continue;
      double limit = max_reach_m * humans[key.first].scale;
      if (nearest.distance_m > limit) {
        std::string n = std::to_string(s + 1);
        std::string where = step.where.empty() ? "/steps/" + std::to_string(s) : step.where;
        std::string prefix = chain.source.empty() ? std::string() : chain.source + ": ";
        std::string from = s == 0 ? "where human " + std::to_string(key.first) + " starts"
                                  : "where step " + std::to_string(s) + " leaves human " +
                                        std::to_string(key.first);
        return absl::InvalidArgumentError(
            prefix + "step " + n + " (" + where + "): object '" + key.second + "' (part '" +
            nearest.part + "') is " + Metres(nearest.distance_m) + " m from " + from +
            ", beyond the " + Metres(limit) + " m a human reaches without walking; add a " +
            "get-close step for '" + key.second + "' before step " + n +
            " (the human then walks there)");
      }
    }
    for (const auto& c : checks) approached.insert(c.first);
    // walking to an object leaves every other object behind
    for (const auto& key : closing) {
      for (auto it = approached.begin(); it != approached.end();) {
        it = it->first == key.first ? approached.erase(it) : std::next(it);
      }
    }
    approached.insert(closing.begin(), closing.end());
    for (size_t a = 0; a < where_now.size(); ++a) {
      where_now[a] = WhereStepLeaves(step, scene, static_cast<int>(a), where_now[a]);
    }
  }
  return absl::OkStatus();
}

}  // namespace simhuman::eval
