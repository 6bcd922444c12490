#pragma once
/// Sensors: what a simulated human perceives, read from the simulation at one instant. A sensor
/// is made by name from a JSON config (MakeSensor) and read by whoever builds a controller's
/// observation; today the ego-centric height map (heightmap.h), next the head camera.

#include <mujoco/mujoco.h>

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::perceive {

/// What a sensor reads from: the simulation at one instant, for one agent. Pointers are borrowed
/// for the call.
struct SensorInput {
  const world::SimWorld* world = nullptr;
  const mjData* data = nullptr;
  /// The scene as it is now (movable objects' poses synced from `data`).
  const core::SceneCatalog* catalog = nullptr;
  int agent = 0;
  double time_s = 0;
};

/// One reading: row-major values and their shape (e.g. {16, 16} for a height map, {H, W, 3}
/// for an RGB image).
struct SensorReading {
  std::vector<float> values;
  std::vector<int> shape;
  double time_s = 0;  ///< simulation time the reading shows
};

/// A sensor of one agent. Not thread-safe: one instance per agent and thread.
class Sensor {
 public:
  virtual ~Sensor() = default;
  /// The registry name, e.g. "heightmap".
  virtual std::string name() const = 0;
  /// Reads the sensor into `out` (resized as needed). Errors: a sensor that cannot read now
  /// (e.g. a camera without a GL context), naming the sensor.
  virtual absl::Status Read(const SensorInput& in, SensorReading* out) = 0;
  /// The sensor's settings as JSON (round-trips through MakeSensor).
  virtual nlohmann::json Config() const = 0;
};

/// Makes a sensor from a JSON config (an object; {} takes the defaults).
using SensorFactory =
    std::function<core::StatusOr<std::unique_ptr<Sensor>>(const nlohmann::json& config)>;

/// The sensor registered as `name`, configured by `config`. Errors (InvalidArgument): an unknown
/// name (listing SensorNames()) or a bad config (naming the key, the value and what is valid).
core::StatusOr<std::unique_ptr<Sensor>> MakeSensor(std::string_view name,
                                                   const nlohmann::json& config);

/// Names of the registered sensors.
std::vector<std::string> SensorNames();

}  // namespace simhuman::perceive
