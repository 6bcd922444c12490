#pragma once
/// The ego-centric height map sensor (UniHSI's scene awareness): the height of the scene's
/// solids above the floor on a square grid around an agent's pelvis, turned with its heading.

#include <Eigen/Core>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/perceive/sensor.h"

namespace simhuman::perceive {

/// Builds a `size` x `size` height map (row-major, cells of `cell_m`, row index along the
/// agent's forward axis, centred on `pelvis`, turned by `yaw_rad`) from the catalog's colliding
/// shapes: the top of every shape under each cell's centre, 0 where there is none. Ray-free.
void BuildHeightmap(const core::SceneCatalog& scene, const Eigen::Vector3d& pelvis, double yaw_rad,
                    int size, double cell_m, std::vector<float>* out);

/// The height map as a sensor: config {"size": cells per side (1-128, default 16), "cell_m":
/// cell size in metres (0.01-1, default 0.1)}; readings have shape {size, size}.
class HeightmapSensor : public Sensor {
 public:
  HeightmapSensor(int size, double cell_m) : size_(size), cell_m_(cell_m) {}
  std::string name() const override { return "heightmap"; }
  absl::Status Read(const SensorInput& in, SensorReading* out) override;
  nlohmann::json Config() const override;
  int size() const { return size_; }
  double cell_m() const { return cell_m_; }

 private:
  int size_;
  double cell_m_;
};

/// HeightmapSensor from its JSON config (the registry's factory).
core::StatusOr<std::unique_ptr<Sensor>> MakeHeightmapSensor(const nlohmann::json& config);

}  // namespace simhuman::perceive
