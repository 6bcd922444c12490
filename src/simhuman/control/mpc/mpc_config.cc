#include "simhuman/control/mpc/mpc_config.h"

#include "simhuman/core/field_table.h"

namespace simhuman::control {
namespace {

using core::NumberRange;
using F = core::Field<MpcConfig>;

const std::vector<std::string>& PresetNames() {
  static const std::vector<std::string> kNames = {"fast", "quality"};
  return kNames;
}

// one table drives reading, validation and JSON output
const core::FieldTable<MpcConfig>& Table() {
  const NumberRange kWeight = NumberRange::Closed(0, 1e6);
  static const core::FieldTable<MpcConfig> kTable(
      "mpc config",
      {F("preset", &MpcConfig::preset, "the preset missing keys come from").OneOf(PresetNames()),
       F("samples", &MpcConfig::samples, "rollouts per replan").In(NumberRange::Closed(2, 1024)),
       F("knots", &MpcConfig::knots, "spline knots over the horizon")
           .In(NumberRange::Closed(2, 16)),
       F("horizon_s", &MpcConfig::horizon_s, "rollout length, s").In(NumberRange::Closed(0.05, 5)),
       F("plan_dt_s", &MpcConfig::plan_dt_s, "planning model time step, s")
           .In(NumberRange::Closed(0.002, 0.05)),
       F("replan_s", &MpcConfig::replan_s, "control period, s").In(NumberRange::Closed(0.005, 1)),
       F("noise_rad", &MpcConfig::noise_rad, "knot perturbation std dev, rad")
           .In(NumberRange::Closed(0, 1)),
       F("small_noise_fraction", &MpcConfig::small_noise_fraction,
         "share of samples drawn at 0.3x noise")
           .In(NumberRange::Closed(0, 1)),
       F("ramp_speed_rad_s", &MpcConfig::ramp_speed_rad_s, "reference ramp speed, rad/s")
           .In(NumberRange::Closed(0.05, 20)),
       F("min_ramp_s", &MpcConfig::min_ramp_s, "shortest reference ramp, s")
           .In(NumberRange::Closed(0, 20)),
       F("max_ramp_s", &MpcConfig::max_ramp_s, "longest reference ramp, s")
           .In(NumberRange::Closed(0, 30)),
       F("threads", &MpcConfig::threads, "rollout threads").In(NumberRange::Closed(1, 64)),
       F("max_replan_s", &MpcConfig::max_replan_s,
         "longest interval between replans when behind real time, s")
           .In(NumberRange::Closed(0, 1)),
       F("w_track", &MpcConfig::w_track, "cost weight: reference tracking").In(kWeight),
       F("w_contact", &MpcConfig::w_contact, "cost weight: contact terms").In(kWeight),
       F("w_balance", &MpcConfig::w_balance, "cost weight: capture point").In(kWeight),
       F("w_upright", &MpcConfig::w_upright, "cost weight: torso upright").In(kWeight),
       F("w_effort", &MpcConfig::w_effort, "cost weight: actuator force").In(kWeight),
       F("w_ctrl", &MpcConfig::w_ctrl, "cost weight: servo targets off the reference").In(kWeight),
       F("w_velocity", &MpcConfig::w_velocity, "cost weight: joint velocities").In(kWeight),
       F("w_com_velocity", &MpcConfig::w_com_velocity, "cost weight: centre-of-mass speed")
           .In(kWeight),
       F("w_fall", &MpcConfig::w_fall, "cost weight: head below its safe height").In(kWeight),
       F("aim_gain", &MpcConfig::aim_gain, "hand aim correction gain (0: off)")
           .In(NumberRange::Closed(0, 2)),
       F("hand_servo_gain", &MpcConfig::hand_servo_gain, "hand servo gain (0: off)")
           .In(NumberRange::Closed(0, 1)),
       F("hand_servo_max_rad", &MpcConfig::hand_servo_max_rad,
         "largest hand servo offset per arm joint, rad")
           .In(NumberRange::Closed(0, 1.5)),
       F("fall_head_height_m", &MpcConfig::fall_head_height_m,
         "head height below which the episode ends as a fall, m (scaled)")
           .In(NumberRange::Closed(0, 2))});
  return kTable;
}

}  // namespace

absl::Status MpcConfig::Validate() const {
  SH_RETURN_IF_ERROR(Table().Validate(*this));
  if (min_ramp_s > max_ramp_s) {
    return absl::InvalidArgumentError("mpc config: min_ramp_s must not exceed max_ramp_s");
  }
  if (replan_s > horizon_s) {
    return absl::InvalidArgumentError("mpc config: replan_s must not exceed horizon_s");
  }
  return absl::OkStatus();
}

nlohmann::json MpcConfig::ToJson() const { return Table().ToJson(*this); }

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
                                    "'; valid presets are: " + core::JoinNames(PresetNames()));
}

absl::StatusOr<MpcConfig> MpcConfig::FromJson(const nlohmann::json& j, std::string_view where) {
  auto read = [&]() -> absl::StatusOr<MpcConfig> {
    SH_RETURN_IF_ERROR(core::CheckKeys(j, Table().Keys(), "/"));
    // the preset first: it gives the keys the file leaves out
    std::string preset = "fast";
    if (j.contains("preset")) {
      SH_ASSIGN_OR_RETURN(preset,
                          core::ReadName(j.at("preset"), "/preset", PresetNames(), "preset"));
    }
    SH_ASSIGN_OR_RETURN(MpcConfig c, Preset(preset));
    SH_RETURN_IF_ERROR(Table().Read(j, "/", &c));
    SH_RETURN_IF_ERROR(c.Validate());
    return c;
  };
  absl::StatusOr<MpcConfig> c = read();
  if (!c.ok() && !where.empty()) return core::Annotate(c.status(), where);
  return c;
}

}  // namespace simhuman::control
