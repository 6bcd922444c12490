#pragma once
/// Small builders of plans in simhuman's JSON form (plan/contact_chain.h), shared by the suite
/// generators.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace simhuman::eval {

inline nlohmann::json PlanPair(const std::string& object, const std::string& part,
                               const std::string& joint, const std::string& contact,
                               const std::string& direction) {
  return {{"object", object},
          {"part", part},
          {"joint", joint},
          {"contact", contact},
          {"direction", direction}};
}

inline nlohmann::json PlanGetClose(const std::string& object, const std::string& side) {
  return {{"object", object}, {"part", "none"}, {"joint", "none"}, {"direction", side}};
}

inline nlohmann::json PlanStep(const std::string& label, std::vector<nlohmann::json> pairs) {
  return {{"label", label}, {"pairs", pairs}};
}

inline nlohmann::json PlanOf(std::vector<nlohmann::json> steps) { return {{"steps", steps}}; }

}  // namespace simhuman::eval
