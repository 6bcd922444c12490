#include "simhuman/perceive/sensor.h"

#include <utility>

#include "simhuman/perceive/heightmap.h"

namespace simhuman::perceive {
namespace {

// the registry: a new sensor adds one line here
const std::vector<std::pair<std::string, SensorFactory>>& Registry() {
  static const std::vector<std::pair<std::string, SensorFactory>> sensors = {
      {"heightmap", MakeHeightmapSensor},
  };
  return sensors;
}

}  // namespace

core::StatusOr<std::unique_ptr<Sensor>> MakeSensor(std::string_view name,
                                                   const nlohmann::json& config) {
  for (const auto& [n, make] : Registry()) {
    if (n == name) return make(config.is_null() ? nlohmann::json::object() : config);
  }
  return absl::InvalidArgumentError("unknown sensor '" + std::string(name) +
                                    "'; valid sensors are: " + core::JoinNames(SensorNames()));
}

std::vector<std::string> SensorNames() {
  std::vector<std::string> out;
  for (const auto& entry : Registry()) out.push_back(entry.first);
  return out;
}

}  // namespace simhuman::perceive
