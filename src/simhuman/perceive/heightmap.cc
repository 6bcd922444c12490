#include "simhuman/perceive/heightmap.h"

#include <algorithm>
#include <cmath>

#include "simhuman/core/json_io.h"

namespace simhuman::perceive {

void BuildHeightmap(const core::SceneCatalog& scene, const Eigen::Vector3d& pelvis, double yaw_rad,
                    int size, double cell_m, std::vector<float>* out) {
  out->assign(static_cast<size_t>(size) * size, 0.0f);
  double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  // only objects that can reach into the map's square
  const double half_diag = 0.7072 * size * cell_m;
  std::vector<const core::CatalogObject*> near;
  for (const auto& o : scene.objects) {
    if (!o.collides || o.shapes.empty()) continue;
    auto [lo, hi] = o.LocalBounds();
    double radius = std::max(lo.head<2>().norm(), hi.head<2>().norm()) +
                    std::max(std::abs(lo.x()), std::abs(hi.x()));
    if ((o.pose.pos.head<2>() - pelvis.head<2>()).norm() < half_diag + radius) near.push_back(&o);
  }
  for (int i = 0; i < size; ++i) {
    for (int j = 0; j < size; ++j) {
      double lx = (i - (size - 1) / 2.0) * cell_m, ly = (j - (size - 1) / 2.0) * cell_m;
      Eigen::Vector3d probe(pelvis.x() + c * lx - s * ly, pelvis.y() + s * lx + c * ly, 3.0);
      float h = 0;
      for (const core::CatalogObject* o : near) {
        for (const auto& shape : o->shapes) {
          // a vertical probe hits the shape if the nearest point of a low point is under it
          Eigen::Vector3d low(probe.x(), probe.y(), -1.0);
          Eigen::Vector3d np = core::NearestPointOnShape(shape, o->pose, probe);
          Eigen::Vector3d np_low = core::NearestPointOnShape(shape, o->pose, low);
          if ((np.head<2>() - probe.head<2>()).norm() < 1e-6 &&
              (np_low.head<2>() - probe.head<2>()).norm() < 1e-6) {
            h = std::max(h, static_cast<float>(np.z()));
          }
        }
      }
      (*out)[static_cast<size_t>(i) * size + j] = h;
    }
  }
}

absl::Status HeightmapSensor::Read(const SensorInput& in, SensorReading* out) {
  if (!in.world || !in.data || !in.catalog) {
    return absl::InvalidArgumentError("heightmap: the sensor input has no world, data or catalog");
  }
  const world::AgentIndex& ix = in.world->agent(in.agent);
  const mjtNum* pelvis = in.data->xpos + 3 * ix.pelvis_body;
  BuildHeightmap(*in.catalog, Eigen::Vector3d(pelvis[0], pelvis[1], pelvis[2]),
                 world::PelvisYaw(in.data, ix), size_, cell_m_, &out->values);
  out->shape = {size_, size_};
  out->time_s = in.time_s;
  return absl::OkStatus();
}

nlohmann::json HeightmapSensor::Config() const { return {{"size", size_}, {"cell_m", cell_m_}}; }

core::StatusOr<std::unique_ptr<Sensor>> MakeHeightmapSensor(const nlohmann::json& config) {
  const std::string where = "/sensors/heightmap";
  SH_RETURN_IF_ERROR(core::CheckKeys(config, {"size", "cell_m"}, where));
  double size = 16, cell_m = 0.1;
  if (config.contains("size")) {
    SH_ASSIGN_OR_RETURN(size, core::GetNumber(config, "size", where));
  }
  if (config.contains("cell_m")) {
    SH_ASSIGN_OR_RETURN(cell_m, core::GetNumber(config, "cell_m", where));
  }
  if (size != std::floor(size) || size < 1 || size > 128) {
    return absl::InvalidArgumentError(where + "/size: " + std::to_string(size) +
                                      " is invalid; valid are whole numbers in [1, 128]");
  }
  if (!(cell_m >= 0.01 && cell_m <= 1.0)) {
    return absl::InvalidArgumentError(where + "/cell_m: " + std::to_string(cell_m) +
                                      " is invalid; valid range is [0.01, 1]");
  }
  return std::unique_ptr<Sensor>(new HeightmapSensor(static_cast<int>(size), cell_m));
}

}  // namespace simhuman::perceive
