#pragma once
/// Furnished rooms for UniHSI's ScenePlan levels (issue 20): a seeded generator that places
/// furniture groups (a desk: a table with a laptop on it and a chair at it; a bed; a sofa; an
/// armchair; a chair; a stool; a high stool) with the sizes, yaws and spacing of a real room,
/// keeps the floor in front of every seat and bed free to stand in, and places humans 1-6 m from
/// a given object at random headings. Plain data in, a SceneSpec out; no MuJoCo.

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"
#include "simhuman/world/scene.h"

namespace simhuman::world {

/// The furniture groups a room may hold ("desk" is table + laptop + chair).
const std::vector<std::string>& RoomItems();

/// What to furnish.
struct RoomRequest {
  std::vector<std::string> items;  ///< RoomItems() names, in placement order (repeats allowed)
  double width_m = 8.0;            ///< floor extent along x, centred on the origin
  double depth_m = 7.0;            ///< along y
  double walkway_m = 0.6;          ///< free floor between any two groups' footprints
  double stand_zone_m = 0.7;       ///< free floor in front of every seat and bed
  int max_tries = 300;             ///< placement draws per group before giving up
};

/// A furnished room: the scene (no humans yet) and, per item of the request, the object ids it
/// became (a desk: {table, laptop, chair}).
struct Room {
  SceneSpec scene;
  std::vector<std::vector<std::string>> item_ids;
};

/// Draws a room. Object ids are the type plus a 3-digit running index ("bed000", "table001",
/// "laptop002", "chair003", ...). Yaws are a quarter turn times k plus up to +-10 degrees; sizes
/// from RandomObjectSpec(); a desk's chair stands 0.55-0.65 m from the table's edge (room to
/// step in front of the seat) and its laptop 2 cm from that edge. Errors: InvalidArgument for
/// an unknown item (listing RoomItems()) or a non-positive size; ResourceExhausted when a group
/// does not fit without overlap after max_tries draws ("cannot furnish ...: the sofa does not
/// fit ..."), never a hang.
core::StatusOr<Room> GenerateRoom(const RoomRequest& request, core::Rng& rng);

/// A standing start for a human in `room`: `lo_m`-`hi_m` from the point `from` (e.g. an
/// object's stand point), any heading, at least `clearance_m` from every object's footprint and
/// inside the room's floor grown by 1 m. ResourceExhausted after 500 draws.
core::StatusOr<HumanSpec> RandomStart(const SceneSpec& scene, const RoomRequest& request,
                                      const Eigen::Vector2d& from, double lo_m, double hi_m,
                                      double clearance_m, core::Rng& rng);

}  // namespace simhuman::world
