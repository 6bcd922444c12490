#pragma once
/// Reading back what `simhuman run` wrote into its output folder (scene.json, plan.json,
/// trajectory.csv, result.json; docs/FORMATS.md), to replay or export a run after the fact.

#include <mujoco/mujoco.h>

#include <memory>
#include <nlohmann/json.hpp>
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
  plan::ContactChain chain;
  control::Trajectory trajectory;
  nlohmann::json result;  ///< result.json; null when the folder has none
};

/// Loads the run folder `dir`. Errors name the file (and the line or column): NotFound for a
/// missing folder or file (listing the files a run folder holds), InvalidArgument for a
/// malformed one or a trajectory whose columns are not the model's.
core::StatusOr<RunRecord> LoadRunRecord(const std::string& dir);

/// Reads a trajectory CSV (WriteTrajectoryCsv's format) for the model `m`: the header must name
/// exactly QposColumnNames(m); fps is taken from the time column (30 when there is one frame).
/// Errors name `path`, the line and the column.
core::StatusOr<control::Trajectory> ReadTrajectoryCsv(const std::string& path, const mjModel* m);

}  // namespace simhuman::eval
