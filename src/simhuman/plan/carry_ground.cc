// Grounding of carry steps (carry.h, GroundCarryStep): the object, the team, its mass against the
// team's capacity, the stand points, and the destination on the floor, clear of other objects.

#include <algorithm>
#include <cmath>
#include <set>

#include "simhuman/core/footprint.h"
#include "simhuman/core/json_reader.h"
#include "simhuman/plan/carry.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/plan/metrics.h"

namespace simhuman::plan {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kCarrierRadiusM = 0.25;  // a standing carrier's footprint (as world/scene.cc)
constexpr double kClearanceM = 0.05;      // a put-down object clears other objects by this
constexpr double kBesideGapM = 0.15;      // gap between a reference object and what is put beside
constexpr double kHumanHeightM = 1.8;     // objects above this height block nobody

// an object's footprint on the floor: its local bounds in x and y, turned by its yaw
struct Footprint {
  Vector2d centre;
  Vector2d axis_x, axis_y;
  Vector2d half;
  double Extent(const Vector2d& n) const {
    return half.x() * std::abs(axis_x.dot(n)) + half.y() * std::abs(axis_y.dot(n));
  }
};

Footprint FootprintAt(const core::CatalogObject& o, const core::Pose& pose) {
  const auto [lo, hi] = o.LocalBounds();
  const double yaw = core::PoseYaw(pose);
  Footprint f;
  f.axis_x = Vector2d(std::cos(yaw), std::sin(yaw));
  f.axis_y = Vector2d(-std::sin(yaw), std::cos(yaw));
  const Vector2d lc = 0.5 * (lo + hi).head<2>();
  f.centre = pose.pos.head<2>() + lc.x() * f.axis_x + lc.y() * f.axis_y;
  f.half = 0.5 * (hi - lo).head<2>();
  return f;
}

// separating axes of two rectangles; true when they overlap by more than -margin
bool Overlap(const Footprint& a, const Footprint& b, double margin) {
  const Vector2d d = b.centre - a.centre;
  for (const Vector2d& n : {a.axis_x, a.axis_y, b.axis_x, b.axis_y}) {
    if (std::abs(d.dot(n)) >= a.Extent(n) + b.Extent(n) + margin) return false;
  }
  return true;
}

bool Blocks(const core::CatalogObject& o) {
  return o.collides && !o.shapes.empty() &&
         o.pose.pos.z() + o.LocalBounds().first.z() < kHumanHeightM;
}

std::string Xy(const Vector2d& p) {
  return "(" + core::FormatNumber(std::round(p.x() * 100) / 100) + ", " +
         core::FormatNumber(std::round(p.y() * 100) / 100) + ")";
}

std::string Describe(const core::CatalogObject& o) { return o.id + " (" + o.type + ")"; }

// "" when a carrier can stand at `p`; else why not
std::string StandBlocked(const core::SceneCatalog& scene, const std::string& carried,
                         const Vector2d& p) {
  if (std::max(std::abs(p.x()), std::abs(p.y())) > core::kFloorHalfSizeM - kCarrierRadiusM) {
    return "it is off the floor (which spans +-" + core::FormatNumber(core::kFloorHalfSizeM) +
           " m)";
  }
  for (const core::CatalogObject& o : scene.objects) {
    if (o.id == carried || !Blocks(o)) continue;
    if (core::FootprintDistance(o, p) < kCarrierRadiusM) return "it is inside " + Describe(o);
  }
  return "";
}

// "" when `object` can be put down at `pose` (on the floor, clear of everything, its carriers'
// stand points clear); else why not
std::string PutDownBlocked(const core::SceneCatalog& scene, const core::CatalogObject& object,
                           const core::CarryLayout& layout, const core::Pose& pose) {
  const Footprint f = FootprintAt(object, pose);
  const double reach = f.half.norm();
  if (std::max(std::abs(f.centre.x()), std::abs(f.centre.y())) > core::kFloorHalfSizeM - reach) {
    return "destination " + Xy(pose.pos.head<2>()) + " is off the floor (which spans +-" +
           core::FormatNumber(core::kFloorHalfSizeM) + " m)";
  }
  for (const core::CatalogObject& o : scene.objects) {
    if (o.id == object.id || !Blocks(o)) continue;
    if (Overlap(f, FootprintAt(o, o.pose), kClearanceM)) {
      return "destination " + Xy(pose.pos.head<2>()) + " puts " + object.id + " inside " +
             Describe(o) + " (their footprints overlap)";
    }
  }
  for (size_t k = 0; k < layout.holds.size(); ++k) {
    const Vector2d stand = pose.Apply(layout.holds[k].stand_local).head<2>();
    std::string why = StandBlocked(scene, object.id, stand);
    if (!why.empty()) {
      return "destination " + Xy(pose.pos.head<2>()) + " is unreachable: carrier " +
             std::to_string(k) + " would stand at " + Xy(stand) + " to put it down, and " + why;
    }
  }
  return "";
}

// yaws to try at a destination: the object's own, then a quarter turn either way, then a half
std::vector<double> CandidateYaws(double yaw) {
  return {yaw, yaw + M_PI / 2, yaw - M_PI / 2, yaw + M_PI};
}

// the pose that puts `object` (at `yaw`) beside `ref` at `side`, `kBesideGapM` clear of it
core::Pose BesidePose(const core::CatalogObject& object, const core::CatalogObject& ref,
                      Direction side, double yaw) {
  const Vector2d n = DirectionVector(side, ref.pose).head<2>().normalized();
  const Footprint rf = FootprintAt(ref, ref.pose);
  core::Pose at = core::Pose::FromYaw(Vector3d::Zero(), yaw);
  const Footprint of = FootprintAt(object, at);  // centre = the local bounds' centre, turned
  const Vector2d centre = rf.centre + n * (rf.Extent(n) + kBesideGapM + of.Extent(n));
  const Vector2d origin = centre - of.centre;
  return core::Pose::FromYaw(Vector3d(origin.x(), origin.y(), 0.0), core::WrapAngle(yaw));
}

// the side of a part a hand touches: the axis along which the hand lies farthest out
Direction HandSide(const core::CatalogObject& o, const std::string& part, const Vector3d& hand) {
  const core::CatalogPart* p = o.FindPart(part);
  if (p == nullptr) return Direction::kNone;
  const auto [lo, hi] = core::ShapesBounds(p->shapes);
  const Vector3d c = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  int best = 2;
  double best_ratio = -1;
  for (int i = 0; i < 3; ++i) {
    const double ratio = std::abs(hand[i] - c[i]) / std::max(half[i], 1e-6);
    if (ratio > best_ratio + 1e-9) {
      best_ratio = ratio;
      best = i;
    }
  }
  const bool pos = hand[best] >= c[best];
  if (best == 0) return pos ? Direction::kFront : Direction::kBack;
  if (best == 1) return pos ? Direction::kLeft : Direction::kRight;
  return pos ? Direction::kUp : Direction::kDown;
}

class CarryGrounder {
 public:
  CarryGrounder(ContactChain& chain, int s, core::SceneCatalog& scene)
      : chain_(chain), step_(chain.steps[s]), carry_(*step_.carry), scene_(scene) {
    base_ = step_.where.empty() ? "/steps/" + std::to_string(s) : step_.where;
    base_ += "/carry";
  }

  absl::Status Ground() {
    const core::CatalogObject* found = scene_.Find(carry_.object);
    if (found == nullptr) {
      return Error("object", "unknown object '" + carry_.object + "'; " + Carryable());
    }
    core::CatalogObject& object = *scene_.Find(carry_.object);
    if (!object.carry.carryable()) {
      return Error("object", Describe(object) + " cannot be carried: " +
                                 object.carry.not_carryable + "; " + Carryable());
    }
    SH_RETURN_IF_ERROR(CheckCarriers(object));
    const core::CarryLayout& layout =
        *object.carry.ForTeam(static_cast<int>(carry_.carriers.size()));
    SH_RETURN_IF_ERROR(CheckMass(object));
    for (size_t k = 0; k < layout.holds.size(); ++k) {
      const core::CarryHold& hold = layout.holds[static_cast<size_t>(carry_.carriers[k].hold)];
      const Vector2d stand = object.pose.Apply(hold.stand_local).head<2>();
      std::string why = StandBlocked(scene_, object.id, stand);
      if (!why.empty()) {
        return Error("object", "carrier " + std::to_string(k) + " (human " +
                                   std::to_string(carry_.carriers[k].agent) + ") cannot stand at " +
                                   Xy(stand) + " to lift " + object.id + ": " + why);
      }
    }
    SH_RETURN_IF_ERROR(GroundDestination(object, layout));
    step_.pairs.clear();
    for (const Carrier& c : carry_.carriers) {
      const core::CarryHold& hold = layout.holds[static_cast<size_t>(c.hold)];
      step_.pairs.push_back(HandPair(object, c.agent, core::BodyJoint::kLeftHand, hold.left_part,
                                     hold.left_hand_local));
      step_.pairs.push_back(HandPair(object, c.agent, core::BodyJoint::kRightHand, hold.right_part,
                                     hold.right_hand_local));
    }
    if (carry_.goal) object.pose = *carry_.goal;
    return absl::OkStatus();
  }

 private:
  absl::Status Error(const std::string& field, const std::string& message) const {
    std::string prefix = chain_.source.empty() ? std::string() : chain_.source + ": ";
    return absl::InvalidArgumentError(prefix + base_ + (field.empty() ? "" : "/" + field) + ": " +
                                      message);
  }

  std::string Carryable() const {
    std::vector<std::string> ids;
    for (const core::CatalogObject& o : scene_.objects) {
      if (o.carry.carryable()) ids.push_back(o.id);
    }
    return ids.empty() ? "the scene has no carryable objects"
                       : "carryable objects: " + core::JoinNames(ids);
  }

  static std::string Teams(const core::CarryInfo& info) {
    std::vector<std::string> sizes;
    for (const core::CarryLayout& l : info.layouts) sizes.push_back(std::to_string(l.carriers()));
    return core::JoinNames(sizes);
  }

  absl::Status CheckCarriers(const core::CatalogObject& object) {
    const int n = static_cast<int>(carry_.carriers.size());
    const int agents = scene_.num_agents();
    std::set<int> seen;
    for (int i = 0; i < n; ++i) {
      const int a = carry_.carriers[static_cast<size_t>(i)].agent;
      const std::string w = "carriers/" + std::to_string(i);
      if (a >= agents) {
        return Error(w, "agent index " + std::to_string(a) + " out of range; the scene has " +
                            std::to_string(agents) + " human(s), valid indices are 0.." +
                            std::to_string(agents - 1));
      }
      if (!seen.insert(a).second)
        return Error(w, "human " + std::to_string(a) + " is listed twice");
    }
    const core::CarryInfo& info = object.carry;
    if (n > info.max_carriers()) {
      return Error("carriers", std::to_string(n) + " carriers, but " + Describe(object) +
                                   " has held points for at most " +
                                   std::to_string(info.max_carriers()) +
                                   " (team sizes: " + Teams(info) + ")");
    }
    if (info.ForTeam(n) == nullptr) {
      return Error("carriers", Describe(object) + " needs " + std::to_string(info.min_carriers()) +
                                   " or more carriers (team sizes: " + Teams(info) + "), got " +
                                   std::to_string(n));
    }
    // holds: the given ones, the others in order of the free ones
    std::set<int> used;
    for (int i = 0; i < n; ++i) {
      const int h = carry_.carriers[static_cast<size_t>(i)].hold;
      if (h < 0) continue;
      const std::string w = "carriers/" + std::to_string(i) + "/hold";
      if (h >= n) {
        return Error(w, "hold " + std::to_string(h) + " out of range; a team of " +
                            std::to_string(n) + " has holds 0.." + std::to_string(n - 1));
      }
      if (!used.insert(h).second) return Error(w, "hold " + std::to_string(h) + " is taken twice");
    }
    int next = 0;
    for (Carrier& c : carry_.carriers) {
      if (c.hold >= 0) continue;
      while (used.count(next)) ++next;
      c.hold = next++;
    }
    return absl::OkStatus();
  }

  absl::Status CheckMass(const core::CatalogObject& object) const {
    const int n = static_cast<int>(carry_.carriers.size());
    if (object.mass_kg <= core::TeamCapacityKg(n)) return absl::OkStatus();
    std::string need;
    for (const core::CarryLayout& l : object.carry.layouts) {
      if (need.empty() && object.mass_kg <= core::TeamCapacityKg(l.carriers())) {
        need = "; it needs " + std::to_string(l.carriers()) + " carriers";
      }
    }
    if (need.empty()) {
      need = "; no team it has held points for (" + Teams(object.carry) + ") can lift it";
    }
    return Error("object", Describe(object) + " is too heavy for " + std::to_string(n) +
                               " carrier(s): it weighs " + core::FormatNumber(object.mass_kg) +
                               " kg and a team of " + std::to_string(n) + " lifts at most " +
                               core::FormatNumber(core::TeamCapacityKg(n)) +
                               " kg (13 kg alone, 20 kg per carrier in a team)" + need);
  }

  absl::Status GroundDestination(const core::CatalogObject& object,
                                 const core::CarryLayout& layout) {
    const CarryDestination& to = carry_.to;
    const double yaw = core::PoseYaw(object.pose);
    if (to.kind == CarryTarget::kFloor) {
      std::string first;
      const std::vector<double> yaws =
          to.yaw_rad ? std::vector<double>{*to.yaw_rad} : CandidateYaws(yaw);
      for (double y : yaws) {
        core::Pose pose = core::Pose::FromYaw(Vector3d(to.x_m, to.y_m, 0.0), core::WrapAngle(y));
        std::string why = PutDownBlocked(scene_, object, layout, pose);
        if (why.empty()) {
          carry_.goal = pose;
          return absl::OkStatus();
        }
        if (first.empty()) first = why;
      }
      return Error("to/point", first);
    }
    if (to.kind != CarryTarget::kBeside) return absl::OkStatus();
    const core::CatalogObject* ref = scene_.Find(to.object);
    if (ref == nullptr) {
      return Error("to/beside", "unknown object '" + to.object +
                                    "'; valid objects: " + core::JoinNames(scene_.ObjectIds()));
    }
    if (ref->id == object.id) {
      return Error("to/beside", "cannot put " + object.id + " beside itself");
    }
    std::vector<Direction> sides = {Direction::kFront, Direction::kBack, Direction::kLeft,
                                    Direction::kRight};
    if (to.side) {
      sides = {*to.side};
    } else {
      // nearest side to where the object is now first
      auto dist = [&](Direction d) {
        return (BesidePose(object, *ref, d, yaw).pos - object.pose.pos).head<2>().norm();
      };
      std::stable_sort(sides.begin(), sides.end(),
                       [&](Direction a, Direction b) { return dist(a) < dist(b); });
    }
    std::string reasons;
    for (Direction d : sides) {
      std::string first;
      for (double y : CandidateYaws(yaw)) {
        core::Pose pose = BesidePose(object, *ref, d, y);
        std::string why = PutDownBlocked(scene_, object, layout, pose);
        if (why.empty()) {
          carry_.goal = pose;
          carry_.goal_side = d;
          return absl::OkStatus();
        }
        if (first.empty()) first = why;
      }
      reasons += (reasons.empty() ? "" : "; ") + std::string(DirectionName(d)) + ": " + first;
    }
    return Error("to/beside", "no clear spot for " + object.id + " beside " + Describe(*ref) +
                                  " (" + reasons + ")");
  }

  ContactPair HandPair(const core::CatalogObject& object, int agent, core::BodyJoint joint,
                       const std::string& part, const Vector3d& hand_local) const {
    ContactPair p;
    p.object = object.id;
    p.part = part;
    p.joint = joint;
    p.joint_name = std::string(core::BodyJointName(joint));
    p.type = ContactType::kContact;
    p.direction = HandSide(object, part, hand_local);
    p.agent = agent;
    p.where = base_;
    return p;
  }

  ContactChain& chain_;
  ContactStep& step_;
  CarryStep& carry_;
  core::SceneCatalog& scene_;
  std::string base_;
};

}  // namespace

absl::Status GroundCarryStep(ContactChain& chain, int s, core::SceneCatalog& scene) {
  CarryGrounder g(chain, s, scene);
  return g.Ground();
}

}  // namespace simhuman::plan
