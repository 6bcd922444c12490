#include "simhuman/world/room.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "simhuman/core/geometry.h"
#include "simhuman/world/objects.h"

namespace simhuman::world {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kYawJitterDeg = 10.0;
// a desk's chair: seat front edge this far from the table's edge (room to step in and sit)
constexpr double kDeskGapLoM = 0.55, kDeskGapHiM = 0.65;
// the laptop's near edge this far in from the table's edge
constexpr double kLaptopInsetM = 0.02;
// the start's floor: the room's grown by this much on every side
constexpr double kStartMarginM = 1.0;
constexpr int kStartTries = 500;

// a rectangle on the floor: centre, half extents along its own axes, yaw
struct Rect {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d half = Eigen::Vector2d::Zero();
  double yaw = 0;

  Eigen::Vector2d Axis(int k) const {
    return k == 0 ? Eigen::Vector2d(std::cos(yaw), std::sin(yaw))
                  : Eigen::Vector2d(-std::sin(yaw), std::cos(yaw));
  }
  // half the rectangle's extent along the unit vector `u`
  double Radius(const Eigen::Vector2d& u) const {
    return half.x() * std::abs(Axis(0).dot(u)) + half.y() * std::abs(Axis(1).dot(u));
  }
  // distance from a point to the rectangle (0 inside)
  double Distance(const Eigen::Vector2d& p) const {
    Eigen::Vector2d d = p - centre;
    double dx = std::max(std::abs(d.dot(Axis(0))) - half.x(), 0.0);
    double dy = std::max(std::abs(d.dot(Axis(1))) - half.y(), 0.0);
    return std::hypot(dx, dy);
  }
};

// separating-axis test of two rectangles grown by `gap` in total
bool Overlap(const Rect& a, const Rect& b, double gap) {
  const Eigen::Vector2d d = b.centre - a.centre;
  for (const Rect* r : {&a, &b}) {
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d u = r->Axis(k);
      if (std::abs(d.dot(u)) > a.Radius(u) + b.Radius(u) + gap) return false;
    }
  }
  return true;
}

bool IsSeatOrBed(const std::string& type) {
  return type == "chair" || type == "armchair" || type == "sofa" || type == "stool" ||
         type == "high_stool" || type == "bed";
}

// one member of a group: its spec relative to the group frame (pos, yaw) and its local bounds
struct Member {
  ObjectSpec spec;
  Eigen::Vector2d lo, hi;  // object frame, floor projection
};

core::StatusOr<Member> MakeMember(const std::string& type, core::Rng& rng) {
  Member m;
  m.spec = RandomObjectSpec(type, rng);
  m.spec.pos = Eigen::Vector3d::Zero();
  m.spec.yaw_rad = 0;
  core::StatusOr<core::CatalogObject> built = BuildObject(m.spec);
  if (!built.ok()) {
    return absl::InternalError("room: cannot build a random " + type + ": " +
                               std::string(built.status().message()));
  }
  auto [lo, hi] = built->LocalBounds();
  m.lo = lo.head<2>();
  m.hi = hi.head<2>();
  return m;
}

// the members of one item, placed in the group frame
core::StatusOr<std::vector<Member>> MakeGroup(const std::string& item, core::Rng& rng) {
  std::vector<Member> out;
  if (item != "desk") {
    SH_ASSIGN_OR_RETURN(Member m, MakeMember(item, rng));
    out.push_back(m);
    return out;
  }
  // the table at the origin (one sits at its +x), the chair at +x facing it, the laptop on the
  // board at the chair's edge (objects.h: a laptop's user is at its +x)
  SH_ASSIGN_OR_RETURN(Member table, MakeMember("table", rng));
  SH_ASSIGN_OR_RETURN(Member chair, MakeMember("chair", rng));
  SH_ASSIGN_OR_RETURN(Member laptop, MakeMember("laptop", rng));
  const double edge = table.hi.x();
  const double gap = rng.Uniform(kDeskGapLoM, kDeskGapHiM);
  chair.spec.pos = Eigen::Vector3d(edge + gap + chair.hi.x(), 0, 0);
  chair.spec.yaw_rad = M_PI;
  const double board_top = table.spec.size.count("height") ? table.spec.size.at("height")
                                                           : DefaultSizes("table").at("height");
  laptop.spec.pos = Eigen::Vector3d(edge - kLaptopInsetM - laptop.hi.x(), 0, board_top);
  out = {table, laptop, chair};
  return out;
}

// a member's floor rectangle in the group frame, grown at its front by the stand zone
Rect MemberRect(const Member& m, double stand_zone_m) {
  Eigen::Vector2d lo = m.lo, hi = m.hi;
  if (IsSeatOrBed(m.spec.type)) hi.x() += stand_zone_m;
  Rect r;
  const double c = std::cos(m.spec.yaw_rad), s = std::sin(m.spec.yaw_rad);
  Eigen::Vector2d mid = 0.5 * (lo + hi);
  r.centre =
      m.spec.pos.head<2>() + Eigen::Vector2d(c * mid.x() - s * mid.y(), s * mid.x() + c * mid.y());
  r.half = 0.5 * (hi - lo);
  r.yaw = m.spec.yaw_rad;
  return r;
}

// the rectangle moved by the group's placement
Rect Place(const Rect& r, const Eigen::Vector2d& at, double yaw) {
  Rect out = r;
  const double c = std::cos(yaw), s = std::sin(yaw);
  out.centre = at + Eigen::Vector2d(c * r.centre.x() - s * r.centre.y(),
                                    s * r.centre.x() + c * r.centre.y());
  out.yaw = r.yaw + yaw;
  return out;
}

bool InsideFloor(const Rect& r, double w, double d) {
  return std::abs(r.centre.x()) + r.Radius(Eigen::Vector2d::UnitX()) <= 0.5 * w &&
         std::abs(r.centre.y()) + r.Radius(Eigen::Vector2d::UnitY()) <= 0.5 * d;
}

std::string NewId(const std::string& type, int* counter) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s%03d", type.c_str(), (*counter)++);
  return buf;
}

// the floor rectangles of the scene's objects (their bounds, no zones)
std::vector<Rect> ObjectRects(const SceneSpec& scene) {
  std::vector<Rect> out;
  for (const ObjectSpec& o : scene.objects) {
    core::StatusOr<core::CatalogObject> built = BuildObject(o);
    if (!built.ok()) continue;
    auto [lo, hi] = built->LocalBounds();
    Member m{o, lo.head<2>(), hi.head<2>()};
    m.spec.type = "";  // no stand zone
    out.push_back(MemberRect(m, 0));
  }
  return out;
}

}  // namespace

const std::vector<std::string>& RoomItems() {
  static const std::vector<std::string> kItems = {"desk",  "bed",   "sofa",      "armchair",
                                                  "chair", "stool", "high_stool"};
  return kItems;
}

core::StatusOr<Room> GenerateRoom(const RoomRequest& req, core::Rng& rng) {
  if (!(req.width_m > 0 && req.depth_m > 0 && req.walkway_m >= 0 && req.stand_zone_m >= 0 &&
        req.max_tries > 0)) {
    return absl::InvalidArgumentError(
        "room: width_m and depth_m must be > 0, walkway_m and stand_zone_m >= 0, max_tries > 0");
  }
  Room room;
  std::vector<Rect> placed;
  int counter = 0;
  for (size_t i = 0; i < req.items.size(); ++i) {
    const std::string& item = req.items[i];
    if (std::find(RoomItems().begin(), RoomItems().end(), item) == RoomItems().end()) {
      return absl::InvalidArgumentError("room: unknown item '" + item +
                                        "'; valid items are: " + core::JoinNames(RoomItems()));
    }
    SH_ASSIGN_OR_RETURN(std::vector<Member> group, MakeGroup(item, rng));
    std::vector<Rect> local;
    for (const Member& m : group) local.push_back(MemberRect(m, req.stand_zone_m));
    bool done = false;
    for (int t = 0; t < req.max_tries && !done; ++t) {
      const double yaw = core::WrapAngle(rng.UniformInt(0, 3) * 0.5 * M_PI +
                                         rng.Uniform(-kYawJitterDeg, kYawJitterDeg) * kDegToRad);
      const Eigen::Vector2d at(rng.Uniform(-0.5 * req.width_m, 0.5 * req.width_m),
                               rng.Uniform(-0.5 * req.depth_m, 0.5 * req.depth_m));
      std::vector<Rect> rects;
      bool ok = true;
      for (const Rect& r : local) {
        rects.push_back(Place(r, at, yaw));
        ok = ok && InsideFloor(rects.back(), req.width_m, req.depth_m);
      }
      for (const Rect& r : rects) {
        for (const Rect& p : placed) ok = ok && !Overlap(r, p, req.walkway_m);
      }
      if (!ok) continue;
      done = true;
      placed.insert(placed.end(), rects.begin(), rects.end());
      std::vector<std::string> ids;
      const double c = std::cos(yaw), s = std::sin(yaw);
      for (const Member& m : group) {
        ObjectSpec o = m.spec;
        o.id = NewId(o.type, &counter);
        o.pos = Eigen::Vector3d(at.x() + c * m.spec.pos.x() - s * m.spec.pos.y(),
                                at.y() + s * m.spec.pos.x() + c * m.spec.pos.y(), m.spec.pos.z());
        o.yaw_rad = core::WrapAngle(m.spec.yaw_rad + yaw);
        ids.push_back(o.id);
        room.scene.objects.push_back(o);
      }
      room.item_ids.push_back(ids);
    }
    if (!done) {
      char buf[160];
      std::snprintf(buf, sizeof(buf),
                    "room: cannot furnish a %.1f x %.1f m floor: the %s (item %zu) does not fit "
                    "beside the %zu placed so far after %d draws",
                    req.width_m, req.depth_m, item.c_str(), i + 1, i, req.max_tries);
      return absl::ResourceExhaustedError(buf);
    }
  }
  return room;
}

core::StatusOr<HumanSpec> RandomStart(const SceneSpec& scene, const RoomRequest& req,
                                      const Eigen::Vector2d& from, double lo_m, double hi_m,
                                      double clearance_m, core::Rng& rng) {
  const std::vector<Rect> rects = ObjectRects(scene);
  const double hx = 0.5 * req.width_m + kStartMarginM, hy = 0.5 * req.depth_m + kStartMarginM;
  for (int t = 0; t < kStartTries; ++t) {
    const double r = rng.Uniform(lo_m, hi_m), a = rng.Uniform(0.0, 2 * M_PI);
    const Eigen::Vector2d p = from + r * Eigen::Vector2d(std::cos(a), std::sin(a));
    if (std::abs(p.x()) > hx || std::abs(p.y()) > hy) continue;
    bool free = true;
    for (const Rect& rect : rects) free = free && rect.Distance(p) >= clearance_m;
    if (!free) continue;
    HumanSpec h;
    h.pos_xy = p;
    h.yaw_rad = core::WrapAngle(rng.Uniform(0.0, 2 * M_PI));
    return h;
  }
  return absl::ResourceExhaustedError("room: no free start " + std::to_string(lo_m) + "-" +
                                      std::to_string(hi_m) + " m from the target after " +
                                      std::to_string(kStartTries) + " draws");
}

}  // namespace simhuman::world
