#include "simhuman/control/manip/table_world.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "simhuman/world/objects.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/seating.h"

namespace simhuman::control::manip {

core::StatusOr<TableWorld> MakeTableWorld(uint64_t seed, const std::string& kind) {
  TableWorld t;
  SH_ASSIGN_OR_RETURN(t.ts, world::GenerateTabletop(seed, kind));
  SH_ASSIGN_OR_RETURN(t.catalog, world::BuildCatalog(t.ts.scene));
  SH_ASSIGN_OR_RETURN(world::AgentSpec human,
                      world::AgentFromHuman(t.ts.scene.humans[0], 0, t.catalog));
  SH_ASSIGN_OR_RETURN(t.world,
                      world::SimWorld::Create(t.catalog, {human}, world::DexterousModelOptions()));
  mj_forward(t.world->model(), t.world->data());
  return t;
}

namespace {

// the object's half width at height z above its base (its own frame): the least distance from
// its bounds' centre line out to where its solids end, over 24 horizontal directions
double HalfWidthAtHeight(const core::CatalogObject& o, double z) {
  const auto [lo, hi] = o.LocalBounds();
  const Eigen::Vector3d axis(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z() + z);
  const double reach = (hi - lo).head<2>().norm();
  double least = reach;
  for (int k = 0; k < 24; ++k) {
    const double a = 2 * M_PI * k / 24;
    const Eigen::Vector3d dir(std::cos(a), std::sin(a), 0);
    double in = 0, out = reach;  // inside at the axis, outside beyond the bounds
    for (int it = 0; it < 30; ++it) {
      const double mid = 0.5 * (in + out);
      const Eigen::Vector3d p = axis + mid * dir;
      ((core::NearestPointOnShapes(o.shapes, core::Pose(), p) - p).norm() < 1e-9 ? in : out) = mid;
    }
    least = std::min(least, in);
  }
  return least;
}

// the height of the object's centroid above its base, standing (a 24^3 grid over its bounds)
double CentroidHeight(const core::CatalogObject& o) {
  const auto [lo, hi] = o.LocalBounds();
  constexpr int kN = 24;
  double sum = 0;
  int inside = 0;
  for (int i = 0; i < kN; ++i) {
    for (int j = 0; j < kN; ++j) {
      for (int k = 0; k < kN; ++k) {
        const Eigen::Vector3d f((i + 0.5) / kN, (j + 0.5) / kN, (k + 0.5) / kN);
        const Eigen::Vector3d p = lo + f.cwiseProduct(hi - lo);
        if ((core::NearestPointOnShapes(o.shapes, core::Pose(), p) - p).norm() > 1e-12) continue;
        sum += p.z() - lo.z();
        ++inside;
      }
    }
  }
  return inside > 0 ? sum / inside : 0.5 * (hi.z() - lo.z());
}

}  // namespace

void SizeFromCatalog(const core::CatalogObject& o, TabletopGoal* g) {
  const auto [lo, hi] = o.LocalBounds();
  const Eigen::Vector3d ext = hi - lo;
  g->height_m = ext.z();
  g->half_width_m = 0.5 * std::min(ext.x(), ext.y());
  g->shape = o.type == "box"      ? GraspShape::kBox
             : o.type == "sphere" ? GraspShape::kSphere
                                  : GraspShape::kCylinder;
  if (o.type != "box" && o.type != "sphere" && o.type != "cylinder") {
    // gripped where it is widest in the band the hand may grip (a cone low, a vase at its belly)
    const TabletopOptions rule;
    const double hi_z = std::min(rule.grip_max_m, g->height_m - rule.grip_below_top_m);
    double best_z = GripHeightM(*g, rule);
    double best_w = HalfWidthAtHeight(o, best_z);
    for (double z = rule.grip_min_m; z <= hi_z + 1e-9; z += 0.005) {
      const double w = HalfWidthAtHeight(o, z);
      if (w > best_w + 1e-3) std::tie(best_z, best_w) = std::make_pair(z, w);
    }
    g->grip_height_m = best_z;
    g->half_width_m = best_w;
    // DASH's 5 cm rule, or 60 % of where its own centre stands when that is lower (a cone)
    g->min_com_above_target_m = std::min(g->min_com_above_target_m, 0.6 * CentroidHeight(o));
  }
}

core::StatusOr<TabletopGoal> TabletopSceneGoal(const world::TabletopScene& ts,
                                               const world::SimWorld& w) {
  const world::ObjectSpec* obj = nullptr;
  for (const world::ObjectSpec& o : ts.scene.objects) {
    if (o.id == ts.task.object_id) obj = &o;
  }
  if (!obj) return absl::InternalError("tabletop task object missing: " + ts.task.object_id);
  TabletopGoal g;
  g.object_body = mj_name2id(w.model(), mjOBJ_BODY, world::ObjectBodyName(obj->id).c_str());
  auto size = [&](const char* key) {
    auto it = obj->size.find(key);
    return it == obj->size.end() ? world::DefaultSizes(obj->type).at(key) : it->second;
  };
  if (obj->type == "box") {
    g.shape = GraspShape::kBox;
    g.half_width_m = size("width") / 2;
    g.height_m = size("height");
  } else if (obj->type == "cylinder") {
    g.shape = GraspShape::kCylinder;
    g.half_width_m = size("radius");
    g.height_m = size("height");
  } else if (obj->type == "sphere") {
    g.shape = GraspShape::kSphere;
    g.half_width_m = size("radius");
    g.height_m = 2 * g.half_width_m;
  } else {
    // a zero-shot shape: the grasp knows only its bounds (a round footprint, graspable as a
    // cylinder that wide)
    const core::CatalogObject* built = w.catalog().Find(obj->id);
    if (!built) return absl::InternalError("tabletop task object not built: " + obj->id);
    SizeFromCatalog(*built, &g);
  }
  g.planned_pos = obj->pos;
  g.target = ts.task.target_world;
  if (!ts.task.target_id.empty()) {
    g.support_body =
        mj_name2id(w.model(), mjOBJ_BODY, world::ObjectBodyName(ts.task.target_id).c_str());
  }
  return g;
}

}  // namespace simhuman::control::manip
