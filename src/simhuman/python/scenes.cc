// simhuman.Scene, simhuman.Plan and the functions that make them.
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "simhuman/app/plan_command.h"
#include "simhuman/app/planner_factory.h"
#include "simhuman/core/json_io.h"
#include "simhuman/eval/episode.h"
#include "simhuman/plan/validate.h"
#include "simhuman/python/bindings.h"

namespace simhuman::python {
namespace {

std::shared_ptr<Scene> MakeScene(world::SceneSpec spec) {
  auto scene = std::make_shared<Scene>();
  scene->catalog = Unwrap(world::BuildCatalog(spec));
  scene->spec = std::move(spec);
  return scene;
}

// a JSON document given as text or as Python data
nlohmann::json JsonArg(const py::object& obj, const std::string& source) {
  if (py::isinstance<py::str>(obj)) {
    return Unwrap(core::ParseJson(obj.cast<std::string>(), source));
  }
  return PyToJson(obj, source);
}

// LLM planner options from a dict of the --llm-* flag names without the prefix
app::LlmFlags LlmFlagsFrom(const py::dict& llm) {
  app::LlmFlags flags;
  const std::vector<std::string> valid = {"url", "model", "timeout_s", "key_env", "fallback"};
  for (const auto& [key, value] : llm) {
    const std::string k = py::str(key);
    if (k == "url") {
      flags.url = value.cast<std::string>();
    } else if (k == "model") {
      flags.model = value.cast<std::string>();
    } else if (k == "timeout_s") {
      flags.timeout_s = value.cast<double>();
    } else if (k == "key_env") {
      flags.key_env = value.cast<std::string>();
    } else if (k == "fallback") {
      flags.fallback = value.cast<bool>();
    } else {
      ThrowIfError(absl::InvalidArgumentError("llm: unknown key '" + k +
                                              "'; valid keys are: " + core::JoinNames(valid)));
    }
  }
  return flags;
}

std::shared_ptr<Plan> PlanCommand(const std::shared_ptr<Scene>& scene, const std::string& command,
                                  const std::string& planner, const py::dict& llm) {
  const app::LlmFlags flags = LlmFlagsFrom(llm);
  core::StatusOr<language::PlanResult> result = absl::UnknownError("not planned");
  {
    py::gil_scoped_release release;  // an LLM planner waits on the network
    result = app::PlanCommandText(planner, flags, command, scene->spec, scene->catalog);
  }
  ThrowPlannerError(result.status());
  auto p = std::make_shared<Plan>();
  p->scene = scene;
  p->chain = std::move(result->chain);
  p->explanation = std::move(result->explanation);
  return p;
}

std::vector<std::string> StepTexts(const Plan& p) {
  std::vector<std::string> out;
  for (const plan::ContactStep& s : p.chain.steps) out.push_back(eval::StepText(s));
  return out;
}

void BindScene(py::module_& m) {
  py::class_<Scene, std::shared_ptr<Scene>>(
      m, "Scene",
      "A scene: objects and the humans that start in it. Make one with load_scene() or "
      "Scene.from_json(); immutable (edit to_dict() and make a new one).")
      .def_static(
          "from_json",
          [](const py::object& json, const std::string& source) {
            return MakeScene(Unwrap(world::ParseSceneJson(JsonArg(json, source), source)));
          },
          py::arg("json"), py::arg("source") = "<string>",
          "A scene from our scene JSON or a UniHSI ScenePlan entry, given as text or as a dict. "
          "BadInputError names `source` and the JSON pointer of the culprit.")
      .def_property_readonly("name", [](const Scene& s) { return s.spec.name; })
      .def_property_readonly(
          "object_ids",
          [](const Scene& s) {
            std::vector<std::string> ids;
            for (const world::ObjectSpec& o : s.spec.objects) ids.push_back(o.id);
            return ids;
          },
          "Object ids in scene order, e.g. ['chair000'].")
      .def_property_readonly(
          "objects", [](const Scene& s) { return JsonToPy(world::SceneToJson(s.spec)["objects"]); },
          "The objects as dicts (keys of the scene JSON).")
      .def_property_readonly(
          "humans", [](const Scene& s) { return JsonToPy(world::SceneToJson(s.spec)["humans"]); },
          "The humans as dicts (pos, yaw_deg, scale, posture, kind).")
      .def(
          "parts",
          [](const Scene& s, const std::string& object_id) {
            for (const core::CatalogObject& o : s.catalog.objects) {
              if (o.id != object_id) continue;
              std::vector<std::string> parts;
              for (const core::CatalogPart& part : o.parts) parts.push_back(part.name);
              return parts;
            }
            std::vector<std::string> ids;
            for (const core::CatalogObject& o : s.catalog.objects) ids.push_back(o.id);
            ThrowIfError(absl::NotFoundError("unknown object '" + object_id +
                                             "'; valid: " + core::JoinNames(ids)));
            return std::vector<std::string>();
          },
          py::arg("object_id"), "Part names of one object, e.g. ['seat surface', ...].")
      .def(
          "to_dict", [](const Scene& s) { return JsonToPy(world::SceneToJson(s.spec)); },
          "Our scene JSON as a dict (round-trips through Scene.from_json).")
      .def(
          "to_json",
          [](const Scene& s, int indent) { return world::SceneToJson(s.spec).dump(indent); },
          py::arg("indent") = 2)
      .def("__repr__", [](const Scene& s) {
        return "<simhuman.Scene '" + s.spec.name + "': " + std::to_string(s.spec.objects.size()) +
               " objects, " + std::to_string(s.spec.humans.size()) + " humans>";
      });

  m.def(
      "load_scene",
      [](const std::string& name) { return MakeScene(Unwrap(world::LoadScene(name))); },
      py::arg("name_or_path"),
      "A built-in scene (scene_names()) or a scene JSON file (ours or a UniHSI ScenePlan "
      "entry). NotFoundError lists the built-in names; BadInputError names the JSON pointer.");
  m.def("scene_names", &world::BuiltinSceneNames, "Names of the built-in scenes.");
}

void BindPlan(py::module_& m) {
  py::class_<Plan, std::shared_ptr<Plan>>(
      m, "Plan", "A Chain-of-Contacts plan grounded against a scene (plan() or Plan.from_json()).")
      .def_static(
          "from_json",
          [](const py::object& json, const std::shared_ptr<Scene>& scene,
             const std::string& source) {
            auto p = std::make_shared<Plan>();
            p->scene = scene;
            p->chain =
                Unwrap(plan::ParseAndGround(JsonArg(json, source).dump(), source, scene->catalog));
            return p;
          },
          py::arg("json"), py::arg("scene"), py::arg("source") = "<string>",
          "A plan from our plan JSON or UniHSI's chain-of-contacts form (text or dict), "
          "checked and grounded against `scene`; errors name the JSON pointer and valid names.")
      .def_readonly("scene", &Plan::scene)
      .def_readonly("explanation", &Plan::explanation, "One line per step (planner output).")
      .def_property_readonly("step_texts", &StepTexts,
                             "A short text per step, as progress lines show it.")
      .def("__len__", [](const Plan& p) { return p.chain.steps.size(); })
      .def(
          "to_dict", [](const Plan& p) { return JsonToPy(plan::ContactChainToJson(p.chain)); },
          "Our plan JSON as a dict.")
      .def(
          "to_json",
          [](const Plan& p, int indent) { return plan::ContactChainToJson(p.chain).dump(indent); },
          py::arg("indent") = 2)
      .def("__repr__", [](const Plan& p) {
        std::string s = "<simhuman.Plan: " + std::to_string(p.chain.steps.size()) + " steps";
        for (const std::string& t : StepTexts(p)) s += "; " + t;
        return s + ">";
      });

  m.def(
      "load_plan",
      [](const std::string& path, const std::shared_ptr<Scene>& scene) {
        auto p = std::make_shared<Plan>();
        p->scene = scene;
        p->chain = Unwrap(plan::LoadAndGroundFile(path, scene->catalog));
        return p;
      },
      py::arg("path"), py::arg("scene"), "A plan file, checked and grounded against `scene`.");
  m.def("plan", &PlanCommand, py::arg("scene"), py::arg("command"), py::arg("planner") = "offline",
        py::arg("llm") = py::dict(),
        "Plans a text command in `scene` with a planner (planner_names()). `llm` holds the LLM "
        "planner's options: url, model, timeout_s, key_env, fallback (as the --llm-* flags). "
        "ClarificationNeeded (with .question) when the command is ambiguous; BadInputError "
        "when it is not understood or names what the scene lacks.");
  m.def("planner_names", &app::PlannerNames, "Names plan() accepts as `planner`.");
}

}  // namespace

void RegisterScenes(py::module_& m) {
  BindScene(m);
  BindPlan(m);
}

}  // namespace simhuman::python
