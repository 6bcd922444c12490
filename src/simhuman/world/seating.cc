#include "simhuman/world/seating.h"

#include <string>

#include "simhuman/core/geometry.h"

namespace simhuman::world {

std::optional<double> SeatTopUnder(const core::SceneCatalog& scene, const Eigen::Vector2d& xy) {
  std::optional<double> top;
  for (const core::CatalogObject& o : scene.objects) {
    // the point in the object's frame, against each seat solid's box bounds
    const Eigen::Vector3d local =
        o.pose.quat.conjugate() * (Eigen::Vector3d(xy.x(), xy.y(), 0) - o.pose.pos);
    for (const char* name : {"seat surface", "mattress"}) {  // a bed's edge seats too
      const core::CatalogPart* seat = o.FindPart(name);
      if (!seat) continue;
      for (const core::Shape& s : seat->shapes) {
        const auto [lo, hi] = core::ShapesBounds({s});
        if (local.x() < lo.x() || local.x() > hi.x() || local.y() < lo.y() || local.y() > hi.y()) {
          continue;
        }
        const double z = o.pose.pos.z() + hi.z();
        if (!top || z > *top) top = z;
      }
    }
  }
  return top;
}

core::StatusOr<AgentSpec> AgentFromHuman(const HumanSpec& human, int index,
                                         const core::SceneCatalog& scene) {
  const std::string where = "/humans/" + std::to_string(index);
  AgentSpec p;
  p.x = human.pos_xy.x();
  p.y = human.pos_xy.y();
  p.yaw_rad = human.yaw_rad;
  p.scale = human.scale;
  p.kind = human.kind;
  if (human.posture == "stand") return p;
  if (human.posture != "sit") {
    return absl::InvalidArgumentError(where + "/posture: '" + human.posture +
                                      "' starts are not simulated yet; valid postures to start "
                                      "in: stand, sit (on a seat)");
  }
  const std::optional<double> seat = SeatTopUnder(scene, human.pos_xy);
  if (!seat) {
    return absl::InvalidArgumentError(
        where + "/posture: 'sit' needs a seat under the human's position (" +
        std::to_string(human.pos_xy.x()) + ", " + std::to_string(human.pos_xy.y()) +
        "); place it on an object with a seat surface (chair, armchair, sofa, stool) or a "
        "mattress (bed)");
  }
  p.seated_pelvis_z = *seat + SeatedPelvisAboveSeat(human.scale);
  SH_ASSIGN_OR_RETURN(const Embodiment* kind, FindEmbodiment(human.kind));
  p.hold_pelvis = kind->right_hand || kind->left_hand;
  return p;
}

}  // namespace simhuman::world
