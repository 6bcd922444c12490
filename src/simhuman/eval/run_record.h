#pragma once
/// Reading back what `simhuman run` wrote into its output folder (scene.json, plan.json,
/// trajectory.csv, result.json; docs/FORMATS.md), to replay or export a run after the fact.

#include <mujoco/mujoco.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "simhuman/control/runner.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

/// A run folder, loaded: the world is rebuilt from scene.json, so its model matches the
/// trajectory's columns.
struct RunRecord {
  world::SceneSpec scene;
  core::SceneCatalog catalog;
  std::unique_ptr<world::SimWorld> world;
  /// plan.json, grounded against the scene; unset when the folder has none (exports of the
  /// motion do not need it, a replay page does).
  std::optional<plan::ContactChain> chain;
  control::Trajectory trajectory;
  nlohmann::json result;  ///< result.json; null when the folder has none
};

/// Loads the run folder `dir` (scene.json and trajectory.csv required; plan.json and
/// result.json when present). Errors name the file (and the line or column): NotFound for a
/// missing folder or file (listing the files a run folder holds), InvalidArgument for a
/// malformed one or a trajectory whose columns are not the model's.
core::StatusOr<RunRecord> LoadRunRecord(const std::string& dir);

/// Reads a trajectory CSV (WriteTrajectoryCsv's format) for the model `m`: the header must name
/// exactly QposColumnNames(m) and the times must not go backwards. fps is the mean recording
/// rate over the rows before the last (the final state is off the grid; the rows are the first
/// simulation steps at or after each tick, so single spacings jitter by a step), rounded to a
/// whole rate when within 5 % of one; 30 with fewer than 3 rows. Errors name `path`, the line and
/// the column.
core::StatusOr<control::Trajectory> ReadTrajectoryCsv(const std::string& path, const mjModel* m);

}  // namespace simhuman::eval
