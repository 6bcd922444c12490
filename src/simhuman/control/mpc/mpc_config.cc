#include "simhuman/control/mpc/mpc_config.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "simhuman/core/json_io.h"

namespace simhuman::control {
namespace {

// one table drives validation and JSON io
struct Field {
  const char* name;
  double MpcConfig::*d;
  int MpcConfig::*i;
  double lo, hi;
};

const std::vector<Field>& Fields() {
  static const std::vector<Field> f = {
      {"samples", nullptr, &MpcConfig::samples, 2, 1024},
      {"knots", nullptr, &MpcConfig::knots, 2, 16},
      {"horizon_s", &MpcConfig::horizon_s, nullptr, 0.05, 5},
      {"plan_dt_s", &MpcConfig::plan_dt_s, nullptr, 0.002, 0.05},
      {"replan_s", &MpcConfig::replan_s, nullptr, 0.005, 1},
      {"noise_rad", &MpcConfig::noise_rad, nullptr, 0, 1},
      {"small_noise_fraction", &MpcConfig::small_noise_fraction, nullptr, 0, 1},
      {"ramp_speed_rad_s", &MpcConfig::ramp_speed_rad_s, nullptr, 0.05, 20},
      {"min_ramp_s", &MpcConfig::min_ramp_s, nullptr, 0, 20},
      {"max_ramp_s", &MpcConfig::max_ramp_s, nullptr, 0, 30},
      {"threads", nullptr, &MpcConfig::threads, 1, 64},
      {"w_track", &MpcConfig::w_track, nullptr, 0, 1e6},
      {"w_contact", &MpcConfig::w_contact, nullptr, 0, 1e6},
      {"w_balance", &MpcConfig::w_balance, nullptr, 0, 1e6},
      {"w_upright", &MpcConfig::w_upright, nullptr, 0, 1e6},
      {"w_effort", &MpcConfig::w_effort, nullptr, 0, 1e6},
      {"w_ctrl", &MpcConfig::w_ctrl, nullptr, 0, 1e6},
      {"w_velocity", &MpcConfig::w_velocity, nullptr, 0, 1e6},
      {"w_com_velocity", &MpcConfig::w_com_velocity, nullptr, 0, 1e6},
      {"w_fall", &MpcConfig::w_fall, nullptr, 0, 1e6},
      {"aim_gain", &MpcConfig::aim_gain, nullptr, 0, 2},
      {"hand_servo_gain", &MpcConfig::hand_servo_gain, nullptr, 0, 1},
      {"hand_servo_max_rad", &MpcConfig::hand_servo_max_rad, nullptr, 0, 1.5},
      {"fall_head_height_m", &MpcConfig::fall_head_height_m, nullptr, 0, 2},
  };
  return f;
}

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

absl::Status MpcConfig::Validate() const {
  for (const Field& f : Fields()) {
    double v = f.d ? this->*(f.d) : static_cast<double>(this->*(f.i));
    if (!std::isfinite(v) || v < f.lo || v > f.hi) {
      return absl::InvalidArgumentError("mpc config '" + std::string(f.name) + "' = " + Num(v) +
                                        " is invalid; valid range is [" + Num(f.lo) + ", " +
                                        Num(f.hi) + "]");
    }
  }
  if (min_ramp_s > max_ramp_s) {
    return absl::InvalidArgumentError("mpc config: min_ramp_s must not exceed max_ramp_s");
  }
  if (replan_s > horizon_s) {
    return absl::InvalidArgumentError("mpc config: replan_s must not exceed horizon_s");
  }
  return absl::OkStatus();
}

nlohmann::json MpcConfig::ToJson() const {
  nlohmann::json j;
  j["preset"] = preset;
  for (const Field& f : Fields()) {
    if (f.d) {
      j[f.name] = this->*(f.d);
    } else {
      j[f.name] = this->*(f.i);
    }
  }
  return j;
}

absl::StatusOr<MpcConfig> MpcConfig::Preset(std::string_view name) {
  MpcConfig c;
  if (name == "fast") return c;
  if (name == "quality") {
    c.preset = "quality";
    c.samples = 32;
    c.replan_s = 0.02;
    return c;
  }
  return absl::InvalidArgumentError("unknown preset '" + std::string(name) +
                                    "'; valid presets are: fast, quality");
}

absl::StatusOr<MpcConfig> MpcConfig::FromJson(const nlohmann::json& j, std::string_view where) {
  if (!j.is_object()) {
    return absl::InvalidArgumentError(std::string(where) + ": expected a JSON object");
  }
  std::vector<std::string> keys = {"preset"};
  for (const Field& f : Fields()) keys.push_back(f.name);
  SH_RETURN_IF_ERROR(core::CheckKeys(j, keys, where));
  std::string preset = "fast";
  if (j.contains("preset")) {
    SH_ASSIGN_OR_RETURN(preset, core::GetString(j, "preset", where));
  }
  SH_ASSIGN_OR_RETURN(MpcConfig c, Preset(preset));
  for (const Field& f : Fields()) {
    if (!j.contains(f.name)) continue;
    SH_ASSIGN_OR_RETURN(double v, core::GetNumber(j, f.name, where));
    if (f.d) {
      c.*(f.d) = v;
    } else {
      if (v != std::floor(v)) {
        return absl::InvalidArgumentError(std::string(where) + "/" + f.name +
                                          ": expected an integer");
      }
      c.*(f.i) = static_cast<int>(v);
    }
  }
  SH_RETURN_IF_ERROR(c.Validate());
  return c;
}

}  // namespace simhuman::control
