#include "simhuman/plan/contact_chain.h"

#include <array>
#include <utility>

#include "simhuman/core/json_io.h"
#include "simhuman/core/scene_catalog.h"

namespace simhuman::plan {
namespace {

constexpr std::array<std::string_view, 3> kContactTypeNames = {"contact", "not contact",
                                                               "not care"};
constexpr std::array<std::string_view, 7> kDirectionNames = {"up",   "down",  "front", "back",
                                                             "left", "right", "none"};
constexpr std::string_view kChainOfContactsKey = "chain of contacts";
// tuple layout: [object, part, joint, contact, direction]
constexpr std::array<std::string_view, 5> kTupleFields = {"object", "part", "joint", "contact",
                                                          "direction"};

bool IsNone(std::string_view name) {
  return core::NormalizeName(name, core::TrailingDigits::kKeep) == kNoneName;
}

// JSON pointer token escaping (RFC 6901)
std::string Token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string Join(std::string_view base, std::string_view key) {
  return std::string(base) + "/" + Token(key);
}
std::string Join(std::string_view base, size_t index) {
  return std::string(base) + "/" + std::to_string(index);
}

// the whole document is the empty pointer; spell it out so messages stay readable
std::string Display(std::string_view pointer) {
  return pointer.empty() ? std::string("(root)") : std::string(pointer);
}

std::string Quote(std::string_view s) { return "'" + std::string(s) + "'"; }

std::string ValidJointsText() {
  return "valid joints: " + core::JoinNames(core::BodyJointNames()) +
         " (or 'none' in a get-close pair)";
}

class Parser {
 public:
  explicit Parser(std::string_view source) : source_(source) {}

  absl::StatusOr<ContactChain> Parse(const nlohmann::json& j) {
    chain_.source = source_;
    if (j.is_array()) {
      chain_.form = ChainForm::kTuple;
      SH_RETURN_IF_ERROR(ParseTupleSteps(j, ""));
    } else if (j.is_object()) {
      if (j.contains("steps")) {
        chain_.form = ChainForm::kSimhuman;
        SH_RETURN_IF_ERROR(ParseObjectForm(j));
      } else if (j.contains(std::string(kChainOfContactsKey))) {
        SH_RETURN_IF_ERROR(ParseScenePlanEntry(j, ""));
      } else if (j.size() == 1 && j.begin().value().is_object() &&
                 j.begin().value().contains(std::string(kChainOfContactsKey))) {
        // a ScenePlan entry wrapped in its key, as UniHSI's files write it ({"0000": {...}})
        SH_RETURN_IF_ERROR(ParseScenePlanEntry(j.begin().value(), Join("", j.begin().key())));
      } else {
        return Error("",
                     "expected key 'steps' (simhuman form) or 'chain of contacts' (UniHSI "
                     "form), or a bare list of steps");
      }
    } else {
      return Error("", std::string("expected a JSON object or array, got ") + j.type_name());
    }
    return std::move(chain_);
  }

 private:
  absl::Status Error(std::string_view pointer, std::string_view message) const {
    return absl::InvalidArgumentError(source_ + ": " + Display(pointer) + ": " +
                                      std::string(message));
  }
  // prefixes errors of core's JSON helpers (which name the pointer) with the source
  absl::Status Wrap(const absl::Status& status) const { return core::Annotate(status, source_); }
  template <typename T>
  absl::StatusOr<T> Wrap(absl::StatusOr<T> value) const {
    if (!value.ok()) return core::Annotate(value.status(), source_);
    return value;
  }

  // a UniHSI ScenePlan entry {"obj": {...}, "chain of contacts": [...]} at `where`
  absl::Status ParseScenePlanEntry(const nlohmann::json& j, const std::string& where) {
    chain_.form = ChainForm::kTuple;
    SH_RETURN_IF_ERROR(
        Wrap(core::CheckKeys(j, {std::string(kChainOfContactsKey), "obj"}, Display(where))));
    const std::string key(kChainOfContactsKey);
    return ParseTupleSteps(j.at(key), Join(where, key));
  }

  // ---- simhuman object form ----

  absl::Status ParseObjectForm(const nlohmann::json& j) {
    SH_RETURN_IF_ERROR(Wrap(core::CheckKeys(j, {"steps"}, Display(""))));
    const nlohmann::json& steps = j.at("steps");
    const std::string where = Join("", "steps");
    if (!steps.is_array()) {
      return Error(where, std::string("expected an array of steps, got ") + steps.type_name());
    }
    if (steps.empty()) return Error(where, "plan has no steps");
    for (size_t s = 0; s < steps.size(); ++s) {
      SH_RETURN_IF_ERROR(ParseObjectStep(steps[s], Join(where, s)));
    }
    return absl::OkStatus();
  }

  absl::Status ParseObjectStep(const nlohmann::json& j, const std::string& where) {
    SH_RETURN_IF_ERROR(Wrap(core::CheckKeys(j, {"label", "pairs", "carry"}, where)));
    ContactStep step;
    step.where = where;
    if (j.contains("label")) {
      SH_ASSIGN_OR_RETURN(step.label, Wrap(core::GetString(j, "label", where)));
    }
    if (j.contains("carry")) {
      if (j.contains("pairs")) {
        return Error(Join(where, "pairs"),
                     "a carry step takes no 'pairs': its hand contacts come from the carried "
                     "object's held points; remove 'pairs' or 'carry'");
      }
      SH_ASSIGN_OR_RETURN(step.carry, Wrap(ParseCarryJson(j.at("carry"), Join(where, "carry"))));
      chain_.steps.push_back(std::move(step));
      return absl::OkStatus();
    }
    if (!j.contains("pairs")) {
      return Error(where, "missing required array 'pairs' (or 'carry' for a carry step)");
    }
    const nlohmann::json& pairs = j.at("pairs");
    const std::string pairs_where = Join(where, "pairs");
    if (!pairs.is_array()) {
      return Error(pairs_where,
                   std::string("expected an array of pairs, got ") + pairs.type_name());
    }
    if (pairs.empty()) return Error(pairs_where, "step has no pairs");
    chain_.steps.push_back(std::move(step));
    for (size_t p = 0; p < pairs.size(); ++p) {
      SH_RETURN_IF_ERROR(ParseObjectPair(pairs[p], Join(pairs_where, p)));
    }
    return absl::OkStatus();
  }

  absl::Status ParseObjectPair(const nlohmann::json& j, const std::string& where) {
    SH_RETURN_IF_ERROR(Wrap(core::CheckKeys(j,
                                            {"object", "part", "joint", "contact", "direction",
                                             "agent", "subject_object", "subject_part"},
                                            where)));
    ContactPair pair;
    pair.where = where;
    SH_ASSIGN_OR_RETURN(pair.object, Wrap(core::GetString(j, "object", where)));
    SH_ASSIGN_OR_RETURN(std::string part, Wrap(core::GetString(j, "part", where)));
    std::string joint(kNoneName);
    if (j.contains("subject_object") || j.contains("subject_part")) {
      // an object-object pair: a part of a movable object instead of a body joint
      if (j.contains("joint")) {
        return Error(Join(where, "joint"),
                     "an object-object pair (with 'subject_object') takes no 'joint'; remove one "
                     "of them");
      }
      if (!j.contains("subject_object")) {
        return Error(where, "'subject_part' needs 'subject_object' (the movable object's id)");
      }
      if (!j.contains("subject_part")) {
        return Error(where, "'subject_object' needs 'subject_part' (a part of that object)");
      }
      SH_ASSIGN_OR_RETURN(std::string subject, Wrap(core::GetString(j, "subject_object", where)));
      SH_ASSIGN_OR_RETURN(pair.subject_part, Wrap(core::GetString(j, "subject_part", where)));
      pair.subject_object = subject;
    } else {
      SH_ASSIGN_OR_RETURN(joint, Wrap(core::GetString(j, "joint", where)));
    }
    std::optional<std::string> contact;
    if (j.contains("contact")) {
      SH_ASSIGN_OR_RETURN(contact, Wrap(core::GetString(j, "contact", where)));
    }
    SH_ASSIGN_OR_RETURN(std::string direction, Wrap(core::GetString(j, "direction", where)));
    if (j.contains("agent")) {
      const nlohmann::json& a = j.at("agent");
      if (!a.is_number_integer()) {
        return Error(Join(where, "agent"),
                     std::string("expected a non-negative integer, got ") + a.type_name());
      }
      if (a.get<int64_t>() < 0 || a.get<int64_t>() > 1000000) {
        return Error(Join(where, "agent"),
                     "agent index must be >= 0, got " + std::to_string(a.get<int64_t>()));
      }
      pair.agent = a.get<int>();
    }
    return FinishPair(std::move(pair), part, joint, contact, direction);
  }

  // ---- UniHSI tuple form ----

  absl::Status ParseTupleSteps(const nlohmann::json& steps, const std::string& where) {
    if (!steps.is_array()) {
      return Error(where, std::string("expected an array of steps, got ") + steps.type_name());
    }
    if (steps.empty()) return Error(where, "plan has no steps");
    for (size_t s = 0; s < steps.size(); ++s) {
      const nlohmann::json& pairs = steps[s];
      const std::string step_where = Join(where, s);
      if (!pairs.is_array()) {
        return Error(
            step_where,
            std::string("expected a step (an array of 5-element pairs), got ") + pairs.type_name());
      }
      if (pairs.empty()) return Error(step_where, "step has no pairs");
      ContactStep step;
      step.where = step_where;
      chain_.steps.push_back(std::move(step));
      for (size_t p = 0; p < pairs.size(); ++p) {
        SH_RETURN_IF_ERROR(ParseTuplePair(pairs[p], Join(step_where, p)));
      }
    }
    return absl::OkStatus();
  }

  absl::Status ParseTuplePair(const nlohmann::json& j, const std::string& where) {
    constexpr char kLayout[] = "[object, part, joint, contact, direction]";
    if (!j.is_array()) {
      return Error(where,
                   std::string("expected a contact pair ") + kLayout + ", got " + j.type_name());
    }
    if (j.size() != kTupleFields.size()) {
      return Error(where, std::string("a contact pair needs 5 elements ") + kLayout + ", got " +
                              std::to_string(j.size()));
    }
    std::array<std::string, 5> f;
    for (size_t i = 0; i < f.size(); ++i) {
      if (!j[i].is_string()) {
        return Error(Join(where, i), "expected a string (" + std::string(kTupleFields[i]) +
                                         "), got " + j[i].type_name());
      }
      f[i] = j[i].get<std::string>();
    }
    ContactPair pair;
    pair.where = where;
    pair.object = f[0];
    return FinishPair(std::move(pair), f[1], f[2], f[3], f[4]);
  }

  // ---- shared ----

  // fills part, joint, contact and direction, then runs the structural checks
  absl::Status FinishPair(ContactPair pair, const std::string& part, const std::string& joint,
                          const std::optional<std::string>& contact, const std::string& direction) {
    ContactStep& step = chain_.steps.back();
    const int s = static_cast<int>(chain_.steps.size()) - 1;
    const int p = static_cast<int>(step.pairs.size());
    const ChainForm form = chain_.form;
    auto field = [&](std::string_view name) {
      if (form == ChainForm::kSimhuman) return Join(pair.where, name);
      for (size_t i = 0; i < kTupleFields.size(); ++i) {
        if (kTupleFields[i] == name) return Join(pair.where, i);
      }
      return pair.where;
    };

    if (pair.object.empty() || IsNone(pair.object)) {
      return Error(field("object"), "every pair needs an object id, got " + Quote(pair.object));
    }
    pair.part = IsNone(part) ? std::string(kNoneName) : part;
    if (!IsNone(joint)) {
      // a standard joint is known at once; other body points are the agent's (grounding)
      pair.joint_name = core::NormalizeName(joint, core::TrailingDigits::kKeep);
      pair.joint = core::ParseBodyJoint(pair.joint_name);
      if (pair.joint_name.empty()) {
        return Error(field("joint"), "empty joint name; " + ValidJointsText());
      }
    }
    const bool get_close = IsNone(part) && IsNone(joint) && !pair.subject_object;

    // contact type: required except for get-close pairs, which take "none" (tuple form) or
    // nothing (simhuman form)
    const std::string contact_where = field("contact");
    if (get_close) {
      if (form == ChainForm::kTuple && !IsNone(*contact)) {
        return Error(contact_where,
                     "a get-close pair (part and joint 'none') needs contact "
                     "'none', got " +
                         Quote(*contact));
      }
      if (contact && !IsNone(*contact)) {
        return Error(contact_where,
                     "a get-close pair (part and joint 'none') takes no contact type; remove "
                     "'contact' or set it to 'none', got " +
                         Quote(*contact));
      }
      pair.type = ContactType::kNotCare;
    } else {
      const std::string valid = "valid contact types: " + core::JoinNames(ContactTypeNames());
      if (!contact) return Error(pair.where, "missing required string 'contact'; " + valid);
      if (IsNone(*contact)) {
        return Error(contact_where,
                     "contact 'none' is only valid in a get-close pair (part, joint and contact "
                     "all 'none'); " +
                         valid);
      }
      std::optional<ContactType> type = ParseContactType(*contact);
      if (!type)
        return Error(contact_where, "unknown contact type " + Quote(*contact) + "; " + valid);
      pair.type = *type;
    }

    std::optional<Direction> dir = ParseDirection(direction);
    if (!dir) {
      return Error(field("direction"),
                   "unknown direction " + Quote(direction) +
                       "; valid directions: " + core::JoinNames(DirectionNames()));
    }
    pair.direction = *dir;

    step.pairs.push_back(std::move(pair));
    return CheckPairShape(chain_, s, p);
  }

  std::string source_;
  ContactChain chain_;
};

}  // namespace

std::string_view ContactTypeName(ContactType type) {
  return kContactTypeNames[static_cast<int>(type)];
}

std::optional<ContactType> ParseContactType(std::string_view name) {
  const std::string c = core::NormalizeName(name, core::TrailingDigits::kKeep);
  for (size_t i = 0; i < kContactTypeNames.size(); ++i) {
    if (kContactTypeNames[i] == c) return static_cast<ContactType>(i);
  }
  return std::nullopt;
}

std::vector<std::string> ContactTypeNames() {
  return std::vector<std::string>(kContactTypeNames.begin(), kContactTypeNames.end());
}

std::string_view DirectionName(Direction direction) {
  return kDirectionNames[static_cast<int>(direction)];
}

std::optional<Direction> ParseDirection(std::string_view name) {
  const std::string c = core::NormalizeName(name, core::TrailingDigits::kKeep);
  for (size_t i = 0; i < kDirectionNames.size(); ++i) {
    if (kDirectionNames[i] == c) return static_cast<Direction>(i);
  }
  return std::nullopt;
}

std::vector<std::string> DirectionNames() {
  return std::vector<std::string>(kDirectionNames.begin(), kDirectionNames.end());
}

bool IsSideDirection(Direction direction) {
  return direction == Direction::kFront || direction == Direction::kBack ||
         direction == Direction::kLeft || direction == Direction::kRight;
}

bool ContactPair::IsGetClose() const { return !HasJoint() && !subject_object && part == kNoneName; }

std::string ContactPair::JointName() const {
  if (!joint_name.empty()) return joint_name;
  if (joint) return std::string(core::BodyJointName(*joint));
  return std::string(kNoneName);
}

std::string FieldPointer(const ContactChain& chain, int step, int pair, std::string_view field) {
  const ContactPair& p = chain.steps.at(step).pairs.at(pair);
  std::string base = p.where;
  if (base.empty()) {
    base = "/steps/" + std::to_string(step) + "/pairs/" + std::to_string(pair);
  }
  if (chain.form == ChainForm::kTuple && !p.where.empty()) {
    for (size_t i = 0; i < kTupleFields.size(); ++i) {
      if (kTupleFields[i] == field) return Join(base, i);
    }
    return base;
  }
  return Join(base, field);
}

absl::Status CheckPairShape(const ContactChain& chain, int step, int pair) {
  const ContactPair& p = chain.steps.at(step).pairs.at(pair);
  auto error = [&](std::string_view field, const std::string& message) {
    std::string prefix = chain.source.empty() ? std::string() : chain.source + ": ";
    return absl::InvalidArgumentError(prefix + FieldPointer(chain, step, pair, field) + ": " +
                                      message);
  };
  if (p.agent < 0)
    return error("agent", "agent index must be >= 0, got " + std::to_string(p.agent));
  const bool part_none = IsNone(p.part);
  if (p.subject_object) {
    if (p.HasJoint()) {
      return error("joint", "an object-object pair (with 'subject_object') takes no joint");
    }
    if (p.subject_object->empty() || IsNone(*p.subject_object)) {
      return error("subject_object", "an object-object pair needs the id of a movable object");
    }
    if (p.subject_part.empty() || IsNone(p.subject_part)) {
      return error("subject_part",
                   "an object-object pair needs a part of " + Quote(*p.subject_object));
    }
    if (part_none || p.part.empty()) {
      return error("part", "an object-object pair needs a part of " + Quote(p.object));
    }
    if (*p.subject_object == p.object) {
      return error("subject_object", "object " + Quote(p.object) + " cannot be placed on itself");
    }
    return absl::OkStatus();
  }
  if (part_none && p.HasJoint()) {
    return error("part", "part is 'none' but joint is " + Quote(p.JointName()) +
                             ": a get-close pair has part, joint and contact all 'none'; any "
                             "other pair names an object part or a body joint as its part");
  }
  if (!part_none && !p.HasJoint()) {
    if (p.part.empty()) return error("part", "part name is empty");
    return error("joint", "joint is 'none' but part is " + Quote(p.part) +
                              ": a get-close pair has part, joint and contact all 'none'; " +
                              ValidJointsText());
  }
  if (p.IsGetClose()) {
    if (!IsSideDirection(p.direction)) {
      return error("direction",
                   "a get-close pair (part and joint 'none') needs the side of the "
                   "object to stand at; valid directions: front, back, left, "
                   "right; got " +
                       Quote(DirectionName(p.direction)));
    }
    return absl::OkStatus();
  }
  if (core::NormalizeName(p.part, core::TrailingDigits::kKeep) ==
      core::NormalizeName(p.JointName(), core::TrailingDigits::kKeep)) {
    return error("part", "joint " + Quote(p.JointName()) + " cannot contact itself");
  }
  return absl::OkStatus();
}

absl::StatusOr<ContactChain> ParseContactChainJson(const nlohmann::json& j,
                                                   std::string_view source) {
  Parser parser(source);
  return parser.Parse(j);
}

absl::StatusOr<ContactChain> ParseContactChain(std::string_view text, std::string_view source) {
  SH_ASSIGN_OR_RETURN(nlohmann::json j, core::ParseJson(text, source));
  return ParseContactChainJson(j, source);
}

absl::StatusOr<ContactChain> LoadContactChainFile(const std::string& path) {
  SH_ASSIGN_OR_RETURN(std::string text, core::ReadFile(path));
  return ParseContactChain(text, path);
}

nlohmann::json ContactChainToJson(const ContactChain& chain) {
  nlohmann::json steps = nlohmann::json::array();
  for (const ContactStep& step : chain.steps) {
    if (step.carry) {
      nlohmann::json js = nlohmann::json::object();
      if (!step.label.empty()) js["label"] = step.label;
      js["carry"] = CarryToJson(*step.carry);
      steps.push_back(std::move(js));
      continue;
    }
    nlohmann::json pairs = nlohmann::json::array();
    for (const ContactPair& p : step.pairs) {
      nlohmann::json jp = nlohmann::json::object();
      jp["object"] = p.object;
      jp["part"] = p.part;
      if (p.subject_object) {
        jp["subject_object"] = *p.subject_object;
        jp["subject_part"] = p.subject_part;
      } else {
        jp["joint"] = p.JointName();
      }
      if (!p.IsGetClose()) jp["contact"] = std::string(ContactTypeName(p.type));
      jp["direction"] = std::string(DirectionName(p.direction));
      if (p.agent != 0) jp["agent"] = p.agent;
      pairs.push_back(std::move(jp));
    }
    nlohmann::json js = nlohmann::json::object();
    if (!step.label.empty()) js["label"] = step.label;
    js["pairs"] = std::move(pairs);
    steps.push_back(std::move(js));
  }
  return nlohmann::json{{"steps", std::move(steps)}};
}

}  // namespace simhuman::plan
