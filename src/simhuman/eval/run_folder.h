#pragma once
/// Reading back what `simhuman run` wrote (docs/FORMATS.md "Run and eval outputs"): the scene
/// (scene.json), rebuilt into the same MuJoCo model, and the recorded trajectory
/// (trajectory.csv), checked column by column against that model. Used by the exporters
/// (`simhuman export`) and anything else that replays a finished run.

#include <memory>
#include <string>

#include "simhuman/control/runner.h"
#include "simhuman/core/status.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

/// A finished run, loaded: its scene, the simulation rebuilt from it (qpos layout as recorded)
/// and the trajectory.
struct RunFolder {
  std::string dir;
  world::SceneSpec scene;
  std::unique_ptr<world::SimWorld> world;
  control::Trajectory trajectory;  ///< fps: the mean recording rate (30 when unclear)
};

/// Parses trajectory.csv text recorded on model `m`: the header must be "time_s,step" and then
/// exactly eval::QposColumnNames(m); each row the same number of finite numbers. Errors are
/// InvalidArgument "where:line: what" (naming the first differing column, a bad value and its
/// column, a short row, no rows, times that go backwards).
core::StatusOr<control::Trajectory> ParseTrajectoryCsv(const std::string& text,
                                                       const std::string& where, const mjModel* m);

/// Loads DIR/scene.json and DIR/trajectory.csv. NotFound names a missing folder or file;
/// the scene's and the trajectory's errors are passed on with the file name.
core::StatusOr<RunFolder> LoadRunFolder(const std::string& dir);

}  // namespace simhuman::eval
