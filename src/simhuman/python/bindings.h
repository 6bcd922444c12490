#pragma once
/// The pieces of the `simhuman._native` Python module (pybind11), one Register function per
/// concept, all called from module.cc. Only this folder includes pybind11.
///
/// Errors: every absl::Status that reaches Python becomes an exception of the classes below,
/// with the status message unchanged (JSON pointers, file names, valid names).

#include <pybind11/pybind11.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/scene.h"

namespace simhuman::python {

namespace py = pybind11;

/// Creates the exception classes in `m`:
///   Error(Exception)                      every simhuman failure; `.code` is the status code name
///   BadInputError(Error, ValueError)      InvalidArgument, OutOfRange, AlreadyExists
///   NotFoundError(Error, FileNotFoundError)  NotFound (files, scene names)
///   ClarificationNeeded(Error)            the command is ambiguous; `.question` is the question
///   UnavailableError(Error)               no EGL display, no LLM server, no ffmpeg
void RegisterErrors(py::module_& m);

/// Throws the Python exception for `status` (does nothing when it is OK). FailedPrecondition
/// becomes Error here; only planners' statuses go through ThrowPlannerError.
void ThrowIfError(const absl::Status& status);

/// As ThrowIfError, but FailedPrecondition (an ambiguous command) is ClarificationNeeded.
void ThrowPlannerError(const absl::Status& status);

/// The value of `s`, or the exception for its status.
template <typename T>
T Unwrap(core::StatusOr<T> s) {
  ThrowIfError(s.status());
  return std::move(*s);
}

/// Throws Python's ValueError with `message` (bad arguments found in the binding itself).
[[noreturn]] void ThrowValueError(const std::string& message);

/// A loaded scene (Python class simhuman.Scene): the spec and its built catalog. Immutable
/// once made; shared by the plans and episodes made from it.
struct Scene {
  world::SceneSpec spec;
  core::SceneCatalog catalog;
};

/// A plan grounded against `scene` (Python class simhuman.Plan).
struct Plan {
  std::shared_ptr<Scene> scene;
  plan::ContactChain chain;
  std::vector<std::string> explanation;  ///< one line per step when a planner made it
};

/// `j` as Python objects (dict, list, str, float, int, bool, None).
py::object JsonToPy(const nlohmann::json& j);

/// A Python object (dict, list, str, number, bool, None) as JSON; BadInputError naming `what`
/// for anything else.
nlohmann::json PyToJson(const py::handle& obj, const std::string& what);

/// Scenes and plans: Scene, Plan, load_scene(), scene_names(), plan(), load_plan().
void RegisterScenes(py::module_& m);

/// Episodes: run() and the Episode it returns (result, trajectory, body points, rendering).
void RegisterEpisodes(py::module_& m);

/// The vectorized training environment over learn::VecEnv (simhuman.vector wraps it).
void RegisterVecEnv(py::module_& m);

/// The command-line cores: cli(), eval(), train(), export_policy(), clip_convert(),
/// clip_gait(), version().
void RegisterCommands(py::module_& m);

}  // namespace simhuman::python
