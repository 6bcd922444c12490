#include "simhuman/language/prompt.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/footprint.h"
#include "simhuman/core/json_io.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::language {
namespace {

constexpr std::string_view kOpen = "{{";
constexpr std::string_view kClose = "}}";
// an object whose footprint is closer than this to a human is "close"; farther needs a
// get-close step first
constexpr double kCloseDistanceM = 1.0;
constexpr double kRadToDeg = 180.0 / M_PI;

std::string Fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  std::string s = buf;
  if (s == "-0.00" || s == "-0.0" || s == "-0") s.erase(0, 1);
  return s;
}

double YawOf(const core::Pose& pose) {
  const Eigen::Quaterniond& q = pose.quat;
  return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                    1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
}

// "in front of", "behind", "to the left of", "to the right of" `ref`, seen in ref's frame
std::string SideWords(const core::CatalogObject& ref, const Eigen::Vector3d& p_world) {
  double yaw = YawOf(ref.pose);
  Eigen::Vector2d d(p_world.x() - ref.pose.pos.x(), p_world.y() - ref.pose.pos.y());
  double fx = std::cos(yaw) * d.x() + std::sin(yaw) * d.y();
  double fy = -std::sin(yaw) * d.x() + std::cos(yaw) * d.y();
  if (std::abs(fx) >= std::abs(fy)) return fx >= 0 ? "in front of" : "behind";
  return fy >= 0 ? "to the left of" : "to the right of";
}

double Distance2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

// floor distance from `p_world` to the object's footprint (its LocalBounds in x and y)

std::string Describe(const core::CatalogObject& o) {
  std::string kind = o.color.empty() ? o.type : o.color + " " + o.type;
  return o.id + " (" + kind + (o.movable ? ", movable" : "") + ")";
}

// names between {{ and }} in `text`
std::vector<std::string> Placeholders(std::string_view text) {
  std::vector<std::string> names;
  size_t pos = 0;
  while ((pos = text.find(kOpen, pos)) != std::string_view::npos) {
    size_t end = text.find(kClose, pos + kOpen.size());
    if (end == std::string_view::npos) break;
    names.emplace_back(text.substr(pos + kOpen.size(), end - pos - kOpen.size()));
    pos = end + kClose.size();
  }
  return names;
}

core::Status CheckOne(std::string_view text, std::string_view source,
                      const std::vector<std::string>& required) {
  std::vector<std::string> valid = PromptPlaceholderNames();
  std::vector<std::string> found = Placeholders(text);
  for (const std::string& name : found) {
    if (std::find(valid.begin(), valid.end(), name) == valid.end()) {
      return absl::InvalidArgumentError(std::string(source) + ": unknown placeholder '{{" + name +
                                        "}}'; valid placeholders: " + core::JoinNames(valid));
    }
  }
  for (const std::string& name : required) {
    if (std::find(found.begin(), found.end(), name) == found.end()) {
      return absl::InvalidArgumentError(std::string(source) + ": the required placeholder '{{" +
                                        name + "}}' is missing");
    }
  }
  return absl::OkStatus();
}

}  // namespace

std::vector<std::string> PromptPlaceholderNames() {
  return {"objects",       "parts",      "layout",  "humans", "joints",
          "contact_types", "directions", "command", "errors"};
}

core::Status CheckPromptTemplates(const PromptTemplates& templates, std::string_view source) {
  std::string s(source);
  SH_RETURN_IF_ERROR(CheckOne(templates.system, s + "/system.txt", {}));
  SH_RETURN_IF_ERROR(CheckOne(templates.user, s + "/user.txt", {"command"}));
  SH_RETURN_IF_ERROR(CheckOne(templates.repair, s + "/repair.txt", {"errors"}));
  return absl::OkStatus();
}

core::StatusOr<PromptTemplates> LoadPromptTemplates(const std::string& dir) {
  PromptTemplates t;
  SH_ASSIGN_OR_RETURN(t.system, core::ReadFile(dir + "/system.txt"));
  SH_ASSIGN_OR_RETURN(t.user, core::ReadFile(dir + "/user.txt"));
  SH_ASSIGN_OR_RETURN(t.repair, core::ReadFile(dir + "/repair.txt"));
  SH_RETURN_IF_ERROR(CheckPromptTemplates(t, dir));
  return t;
}

core::StatusOr<std::string> FillTemplate(std::string_view text,
                                         const std::map<std::string, std::string>& values,
                                         std::string_view source) {
  std::string out;
  size_t pos = 0;
  while (true) {
    size_t open = text.find(kOpen, pos);
    size_t close = open == std::string_view::npos ? open : text.find(kClose, open + kOpen.size());
    if (close == std::string_view::npos) {
      out.append(text.substr(pos));
      return out;
    }
    std::string name(text.substr(open + kOpen.size(), close - open - kOpen.size()));
    auto it = values.find(name);
    if (it == values.end()) {
      return absl::InvalidArgumentError(std::string(source) + ": no value for placeholder '{{" +
                                        name + "}}'");
    }
    out.append(text.substr(pos, open - pos));
    out.append(it->second);
    pos = close + kClose.size();
  }
}

std::map<std::string, std::string> DescribeScene(const core::SceneCatalog& scene,
                                                 const std::vector<AgentStart>& agents_in) {
  std::map<std::string, std::string> v;
  std::vector<AgentStart> agents = agents_in;
  if (agents.empty()) agents.emplace_back();

  // objects: "The room has OBJECTS: [chair000 (red chair), bed001 (bed)]."
  std::string objects;
  for (const core::CatalogObject& o : scene.objects) {
    objects += (objects.empty() ? "" : ", ") + Describe(o);
  }
  v["objects"] = objects.empty() ? "(no objects)" : objects;

  // parts, one sentence per object
  std::string parts;
  for (const core::CatalogObject& o : scene.objects) {
    parts += "The [OBJECT: " + o.id + "] has PARTS: [" + core::JoinNames(o.PartNames()) + "].\n";
  }
  v["parts"] = parts.empty() ? "(no parts)\n" : parts;

  // layout: where each object is, and where its nearest neighbour is relative to it
  std::string layout;
  for (const core::CatalogObject& o : scene.objects) {
    layout += "The [OBJECT: " + o.id + "] is at x = " + Fixed(o.pose.pos.x(), 2) +
              " m, y = " + Fixed(o.pose.pos.y(), 2) + " m";
    if (o.pose.pos.z() > 0.05) layout += ", z = " + Fixed(o.pose.pos.z(), 2) + " m";
    layout += ", its front facing " + Fixed(YawOf(o.pose) * kRadToDeg, 0) + " degrees.";
    const core::CatalogObject* nearest = nullptr;
    double best = 0.0;
    for (const core::CatalogObject& other : scene.objects) {
      if (&other == &o) continue;
      double d = Distance2d(o.pose.pos, other.pose.pos);
      if (!nearest || d < best) {
        nearest = &other;
        best = d;
      }
    }
    if (nearest) {
      bool above = o.pose.pos.z() > nearest->pose.pos.z() + 0.05 && best < 0.5;
      layout += " It is " + Fixed(best, 1) + " m from [OBJECT: " + nearest->id + "], " +
                (above ? "upon it" : SideWords(*nearest, o.pose.pos) + " it") + ".";
    }
    layout += "\n";
  }
  v["layout"] = layout.empty() ? "(empty room)\n" : layout;

  // humans: where each starts and how far each object is
  std::string humans;
  for (size_t a = 0; a < agents.size(); ++a) {
    const AgentStart& s = agents[a];
    Eigen::Vector3d p(s.x_m, s.y_m, 0.0);
    humans += "Human " + std::to_string(a) + " (agent " + std::to_string(a) + ") is " +
              (s.posture == "sit"   ? "sitting"
               : s.posture == "lie" ? "lying"
                                    : "standing") +
              " at x = " + Fixed(s.x_m, 2) + " m, y = " + Fixed(s.y_m, 2) + " m.";
    for (const core::CatalogObject& o : scene.objects) {
      double d = core::FootprintDistance(o, p.head<2>());
      humans += " [OBJECT: " + o.id + "] is " + Fixed(d, 1) + " m away" +
                (d < kCloseDistanceM ? " (close)" : " (not close)") + ".";
    }
    humans += "\n";
  }
  v["humans"] = humans;

  v["joints"] = core::JoinNames(core::BodyJointNames());
  v["contact_types"] = core::JoinNames(plan::ContactTypeNames());
  v["directions"] = core::JoinNames(plan::DirectionNames());
  return v;
}

std::string QuoteCommand(std::string_view command) {
  return nlohmann::json(std::string(command))
      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace simhuman::language
