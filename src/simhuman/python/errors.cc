#include <Python.h>

#include <string>

#include "absl/status/status.h"
#include "simhuman/core/json_io.h"
#include "simhuman/python/bindings.h"

namespace simhuman::python {
namespace {

// the classes created by RegisterErrors (module lifetime; never freed)
PyObject* g_error = nullptr;
PyObject* g_bad_input = nullptr;
PyObject* g_not_found = nullptr;
PyObject* g_clarification = nullptr;
PyObject* g_unavailable = nullptr;

PyObject* NewClass(py::module_& m, const char* name, PyObject* bases, const char* doc) {
  const std::string qualified = std::string("simhuman.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (!cls) throw py::error_already_set();
  m.add_object(name, py::reinterpret_borrow<py::object>(cls));
  return cls;
}

// raises `cls(message)` with .code (and .question for a clarifying question) set
[[noreturn]] void Raise(PyObject* cls, const absl::Status& status) {
  const std::string message(status.message());
  py::object e = py::reinterpret_borrow<py::object>(cls)(message);
  e.attr("code") = absl::StatusCodeToString(status.code());
  if (cls == g_clarification) e.attr("question") = message;
  PyErr_SetObject(cls, e.ptr());
  throw py::error_already_set();
}

}  // namespace

void RegisterErrors(py::module_& m) {
  g_error = NewClass(m, "Error", PyExc_Exception,
                     "A simhuman failure; the message is the C++ status message and `code` the "
                     "status code name (e.g. 'INTERNAL').");
  py::tuple bad = py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError));
  g_bad_input = NewClass(m, "BadInputError", bad.ptr(),
                         "Bad input: a flag, file content or name; the message names the "
                         "culprit (JSON pointer, key) and lists what would be valid.");
  py::tuple nf = py::make_tuple(py::handle(g_error), py::handle(PyExc_FileNotFoundError));
  g_not_found = NewClass(m, "NotFoundError", nf.ptr(),
                         "A missing file or an unknown scene name (the message lists the valid "
                         "names).");
  g_clarification = NewClass(m, "ClarificationNeeded", g_error,
                             "The command is ambiguous in this scene: `question` is the "
                             "planner's clarifying question, listing the candidates.");
  g_unavailable = NewClass(m, "UnavailableError", g_error,
                           "A backend is missing: no EGL display, no LLM server, no ffmpeg.");
}

void ThrowIfError(const absl::Status& status) {
  switch (status.code()) {
    case absl::StatusCode::kOk:
      return;
    case absl::StatusCode::kInvalidArgument:
    case absl::StatusCode::kOutOfRange:
    case absl::StatusCode::kAlreadyExists:
      Raise(g_bad_input, status);
    case absl::StatusCode::kNotFound:
      Raise(g_not_found, status);
    case absl::StatusCode::kUnavailable:
    case absl::StatusCode::kDeadlineExceeded:
      Raise(g_unavailable, status);
    default:
      Raise(g_error, status);
  }
}

void ThrowPlannerError(const absl::Status& status) {
  if (absl::IsFailedPrecondition(status)) Raise(g_clarification, status);
  ThrowIfError(status);
}

py::object JsonToPy(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

nlohmann::json PyToJson(const py::handle& obj, const std::string& what) {
  std::string text;
  try {
    text = py::module_::import("json")
               .attr("dumps")(obj, py::arg("allow_nan") = false)
               .cast<std::string>();
  } catch (const py::error_already_set& e) {
    ThrowIfError(absl::InvalidArgumentError(
        what +
        ": expected JSON-like data (dict, list, str, finite number, bool, None): " + e.what()));
  }
  core::StatusOr<nlohmann::json> j = core::ParseJson(text, what);
  ThrowIfError(j.status());
  return std::move(*j);
}

void ThrowValueError(const std::string& message) { throw py::value_error(message); }

}  // namespace simhuman::python
