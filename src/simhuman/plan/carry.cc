#include "simhuman/plan/carry.h"

#include <cmath>
#include <sstream>

#include "simhuman/core/json_reader.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::plan {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
// agent indices are small; this only keeps a typo like 1e9 from allocating
constexpr int kMaxAgentIndex = 1000000;

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

core::StatusOr<Carrier> ParseCarrier(const nlohmann::json& j, const std::string& where) {
  Carrier c;
  const core::NumberRange agents = {0, kMaxAgentIndex, false, false};
  if (j.is_number()) {
    SH_ASSIGN_OR_RETURN(c.agent, core::ReadInt(j, where, agents));
    return c;
  }
  if (!j.is_object()) {
    return core::JsonError(where, std::string("expected an agent index or {\"agent\", \"hold\"}, "
                                              "got ") +
                                      j.type_name());
  }
  SH_RETURN_IF_ERROR(core::CheckKeys(j, {"agent", "hold"}, where));
  SH_RETURN_IF_ERROR(core::RequireKey(j, "agent", where));
  SH_ASSIGN_OR_RETURN(c.agent,
                      core::ReadInt(j.at("agent"), core::JsonPointer(where, "agent"), agents));
  if (j.contains("hold")) {
    SH_ASSIGN_OR_RETURN(c.hold, core::ReadInt(j.at("hold"), core::JsonPointer(where, "hold"),
                                              {0, kMaxAgentIndex, false, false}));
  }
  return c;
}

core::StatusOr<CarryDestination> ParseDestination(const nlohmann::json& j,
                                                  const std::string& where) {
  CarryDestination to;
  if (j.is_string()) {
    if (j.get<std::string>() != "here") {
      return core::JsonError(where, "unknown destination '" + j.get<std::string>() +
                                        "'; valid: \"here\", {\"point\": [x, y]}, "
                                        "{\"beside\": <object id>}, or no 'to' (lift and hold)");
    }
    to.kind = CarryTarget::kHere;
    return to;
  }
  if (!j.is_object()) {
    return core::JsonError(where, std::string("expected \"here\" or an object with 'point' or "
                                              "'beside', got ") +
                                      j.type_name());
  }
  SH_RETURN_IF_ERROR(core::CheckKeys(j, {"point", "yaw_deg", "beside", "side"}, where));
  if (j.contains("point") == j.contains("beside")) {
    return core::JsonError(where,
                           "a destination needs exactly one of 'point' ([x, y] on the "
                           "floor) and 'beside' (an object id)");
  }
  if (j.contains("point")) {
    if (j.contains("side")) {
      return core::JsonError(core::JsonPointer(where, "side"),
                             "'side' goes with 'beside', not with 'point'");
    }
    to.kind = CarryTarget::kFloor;
    SH_ASSIGN_OR_RETURN(std::vector<double> xy,
                        core::ReadNumbers(j.at("point"), core::JsonPointer(where, "point"), 2, 2));
    to.x_m = xy[0];
    to.y_m = xy[1];
    SH_ASSIGN_OR_RETURN(std::optional<double> yaw_deg,
                        core::ReadOptionalNumber(j, "yaw_deg", where));
    if (yaw_deg) to.yaw_rad = *yaw_deg * kDegToRad;
    return to;
  }
  if (j.contains("yaw_deg")) {
    return core::JsonError(core::JsonPointer(where, "yaw_deg"),
                           "'yaw_deg' goes with 'point', not with 'beside'");
  }
  to.kind = CarryTarget::kBeside;
  SH_ASSIGN_OR_RETURN(to.object,
                      core::ReadString(j.at("beside"), core::JsonPointer(where, "beside")));
  if (j.contains("side")) {
    const std::string sw = core::JsonPointer(where, "side");
    SH_ASSIGN_OR_RETURN(std::string side, core::ReadString(j.at("side"), sw));
    std::optional<Direction> d = ParseDirection(side);
    if (!d || !IsSideDirection(*d)) {
      return core::JsonError(sw, "unknown side '" + side +
                                     "'; valid sides: front, back, left, right (or omit 'side')");
    }
    to.side = d;
  }
  return to;
}

}  // namespace

std::string CarryTargetName(CarryTarget target) {
  switch (target) {
    case CarryTarget::kHold:
      return "hold";
    case CarryTarget::kFloor:
      return "point";
    case CarryTarget::kBeside:
      return "beside";
    case CarryTarget::kHere:
      return "here";
  }
  return "hold";
}

std::vector<int> CarryStep::Agents() const {
  std::vector<int> out;
  for (const Carrier& c : carriers) out.push_back(c.agent);
  return out;
}

core::StatusOr<CarryStep> ParseCarryJson(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) {
    return core::JsonError(where, std::string("expected an object {\"object\", \"carriers\", "
                                              "\"to\"}, got ") +
                                      j.type_name());
  }
  SH_RETURN_IF_ERROR(core::CheckKeys(j, {"object", "carriers", "to"}, where));
  CarryStep c;
  SH_ASSIGN_OR_RETURN(c.object, core::GetString(j, "object", where));
  if (c.object.empty()) return core::JsonError(core::JsonPointer(where, "object"), "empty id");
  SH_RETURN_IF_ERROR(core::RequireKey(j, "carriers", where));
  const nlohmann::json& carriers = j.at("carriers");
  const std::string cw = core::JsonPointer(where, "carriers");
  if (!carriers.is_array() || carriers.empty()) {
    return core::JsonError(cw, "expected a non-empty list of carriers (agent indices)");
  }
  for (size_t i = 0; i < carriers.size(); ++i) {
    SH_ASSIGN_OR_RETURN(Carrier carrier, ParseCarrier(carriers[i], core::JsonPointer(cw, i)));
    c.carriers.push_back(carrier);
  }
  if (j.contains("to")) {
    SH_ASSIGN_OR_RETURN(c.to, ParseDestination(j.at("to"), core::JsonPointer(where, "to")));
  }
  return c;
}

nlohmann::json CarryToJson(const CarryStep& carry) {
  nlohmann::json j = nlohmann::json::object();
  j["object"] = carry.object;
  nlohmann::json carriers = nlohmann::json::array();
  for (const Carrier& c : carry.carriers) {
    if (c.hold < 0) {
      carriers.push_back(c.agent);
    } else {
      carriers.push_back({{"agent", c.agent}, {"hold", c.hold}});
    }
  }
  j["carriers"] = std::move(carriers);
  switch (carry.to.kind) {
    case CarryTarget::kHold:
      break;
    case CarryTarget::kHere:
      j["to"] = "here";
      break;
    case CarryTarget::kFloor:
      j["to"] = {{"point", {carry.to.x_m, carry.to.y_m}}};
      if (carry.to.yaw_rad) j["to"]["yaw_deg"] = *carry.to.yaw_rad / kDegToRad;
      break;
    case CarryTarget::kBeside:
      j["to"] = {{"beside", carry.to.object}};
      if (carry.to.side) j["to"]["side"] = std::string(DirectionName(*carry.to.side));
      break;
  }
  return j;
}

std::string CarrySummary(const CarryStep& carry) {
  std::string by;
  for (const Carrier& c : carry.carriers) {
    by += (by.empty() ? "" : ",") + std::to_string(c.agent);
  }
  std::string out = "carry " + carry.object + " by " + by;
  switch (carry.to.kind) {
    case CarryTarget::kHold:
      return out + " and hold";
    case CarryTarget::kHere:
      return out + " to here";
    case CarryTarget::kFloor:
      return out + " to point (" + Num(carry.to.x_m) + ", " + Num(carry.to.y_m) + ")";
    case CarryTarget::kBeside:
      out += " to beside " + carry.to.object;
      if (carry.to.side) out += " " + std::string(DirectionName(*carry.to.side));
      return out;
  }
  return out;
}

}  // namespace simhuman::plan
