// simhuman._native.VecEnv: learn::VecEnv for Python. Observations, rewards and flags are numpy
// views of the C++ buffers (no copy per step); Step runs on the C++ worker threads with the GIL
// released. simhuman/vector.py puts the Gymnasium vector API on top.
#include "simhuman/learn/vec_env.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/learn/ppo.h"
#include "simhuman/python/bindings.h"

namespace simhuman::python {
namespace {

class VecEnvHandle {
 public:
  VecEnvHandle(const std::string& task, int num_envs, int threads, uint64_t seed,
               const std::string& physics_solver, const std::string& walk_gait) {
    if (num_envs < 1 || num_envs > 65536) {
      ThrowValueError("num_envs " + std::to_string(num_envs) + " is invalid; valid: 1..65536");
    }
    if (threads < 1 || threads > 256) {
      ThrowValueError("threads " + std::to_string(threads) + " is invalid; valid: 1..256");
    }
    if (physics_solver != "newton" && physics_solver != "pgs") {
      ThrowValueError("physics_solver '" + physics_solver + "' is unknown; valid: newton, pgs");
    }
    core::StatusOr<std::unique_ptr<learn::VecTask>> t = absl::UnknownError("not made");
    {
      py::gil_scoped_release release;
      t = learn::MakeVecTask(task, num_envs, physics_solver, walk_gait);
    }
    env_ = std::make_unique<learn::VecEnv>(Unwrap(std::move(t)), threads, seed);
    actions_.resize(static_cast<size_t>(num_envs) * env_->act_dim());
  }

  learn::VecEnv& env() { return *env_; }

  // new episodes everywhere: from `seed` (episode counters from 0) or, without one, continuing
  // the episode counters so no episode repeats
  void Reset(const py::object& seed) {
    uint64_t base = env_->episodes_started();
    if (!seed.is_none()) {
      if (!py::isinstance<py::int_>(seed) || seed < py::int_(0) ||
          seed > py::int_(std::numeric_limits<uint64_t>::max())) {
        ThrowValueError("seed " + std::string(py::repr(seed)) +
                        " is invalid; valid: an integer in [0, 2**64)");
      }
      env_->set_seed(seed.cast<uint64_t>());
      base = 0;
    }
    py::gil_scoped_release release;
    env_->ResetAll(base);
  }

  void Step(const py::handle& actions) {
    const float* data = CheckedActions(actions);
    py::gil_scoped_release release;
    env_->Step(data);
  }

 private:
  std::string ExpectedShape() const {
    return "(" + std::to_string(env_->num_envs()) + ", " + std::to_string(env_->act_dim()) + ")";
  }

  // the actions as E x A contiguous float32 (float64 and float16 are converted), or ValueError
  // naming the expected shape
  const float* CheckedActions(const py::handle& obj) {
    const int e = env_->num_envs(), a = env_->act_dim();
    py::array arr = py::array::ensure(obj);
    if (!arr) {
      ThrowValueError("actions: expected a numpy array of shape " + ExpectedShape() +
                      " and dtype float32, got " + std::string(py::str(py::type::of(obj))));
    }
    const char kind = arr.dtype().kind();
    std::vector<py::ssize_t> shape(arr.shape(), arr.shape() + arr.ndim());
    std::string got = "(";
    for (size_t i = 0; i < shape.size(); ++i) got += (i ? ", " : "") + std::to_string(shape[i]);
    got += shape.size() == 1 ? ",)" : ")";
    if (kind != 'f') {
      ThrowValueError("actions: expected dtype float32 and shape " + ExpectedShape() +
                      ", got dtype " + std::string(py::str(arr.dtype())) + " and shape " + got);
    }
    if (arr.ndim() != 2 || shape[0] != e || shape[1] != a) {
      ThrowValueError("actions: expected shape " + ExpectedShape() + " (num_envs, act_dim), got " +
                      got);
    }
    auto f = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(arr);
    const float* p = f.data();
    // a NaN or infinity would reach MuJoCo's controls (which zeroes them silently)
    for (int i = 0; i < e * a; ++i) {
      if (!std::isfinite(p[i])) {
        ThrowValueError("actions[" + std::to_string(i / a) + ", " + std::to_string(i % a) +
                        "] is " + std::to_string(p[i]) + "; valid: finite numbers");
      }
    }
    if (f.ptr() == obj.ptr()) return p;  // the caller's own buffer, alive during the call
    std::copy(p, p + static_cast<size_t>(e) * a, actions_.begin());
    return actions_.data();
  }

  std::unique_ptr<learn::VecEnv> env_;
  std::vector<float> actions_;  // converted actions
};

// a numpy view of `data` kept alive by `owner` (writable: the C++ side only writes these)
template <typename T>
py::array View(const py::object& owner, const T* data, std::vector<py::ssize_t> shape,
               const char* dtype) {
  py::dtype dt(dtype);
  std::vector<py::ssize_t> strides(shape.size(), dt.itemsize());
  for (int i = static_cast<int>(shape.size()) - 2; i >= 0; --i)
    strides[i] = strides[i + 1] * shape[i + 1];
  py::array a(dt, shape, strides, data, owner);
  return a;
}

py::dict EpisodeStats(VecEnvHandle& h) {
  std::vector<double> ret;
  std::vector<int> len;
  std::vector<bool> success, terminated;
  for (const learn::EpisodeStats& s : h.env().finished()) {
    ret.push_back(s.ret);
    len.push_back(s.length);
    success.push_back(s.success);
    terminated.push_back(s.terminated);
  }
  py::dict d;
  d["r"] = ret;
  d["l"] = len;
  d["success"] = success;
  d["terminated"] = terminated;
  return d;
}

}  // namespace

void RegisterVecEnv(py::module_& m) {
  py::class_<VecEnvHandle>(m, "VecEnv",
                           "learn::VecEnv: E copies of a training task stepped by C++ threads "
                           "with automatic resets. Use simhuman.vector.make() for the Gymnasium "
                           "vector API.")
      .def(py::init<const std::string&, int, int, uint64_t, const std::string&,
                    const std::string&>(),
           py::arg("task") = "walk", py::arg("num_envs") = 128, py::arg("threads") = 2,
           py::arg("seed") = 1, py::arg("physics_solver") = "newton", py::arg("walk_gait") = "")
      .def("reset", &VecEnvHandle::Reset, py::arg("seed") = py::none(),
           "Starts new episodes in every env (from `seed` when given).")
      .def("step", &VecEnvHandle::Step, py::arg("actions"),
           "Steps every env with actions [num_envs, act_dim] (float32; other float dtypes are "
           "converted). ValueError names the expected shape.")
      .def_property_readonly("num_envs", [](VecEnvHandle& h) { return h.env().num_envs(); })
      .def_property_readonly("obs_dim", [](VecEnvHandle& h) { return h.env().obs_dim(); })
      .def_property_readonly("act_dim", [](VecEnvHandle& h) { return h.env().act_dim(); })
      .def_property_readonly("task", [](VecEnvHandle& h) { return h.env().task().name(); })
      .def_property_readonly("seed", [](VecEnvHandle& h) { return h.env().seed(); })
      .def_property_readonly("action_limit",
                             [](VecEnvHandle& h) { return h.env().task().action_limit(); })
      .def_property_readonly(
          "action_used",
          [](VecEnvHandle& h) {
            std::vector<bool> used;
            for (int j = 0; j < h.env().act_dim(); ++j)
              used.push_back(h.env().task().action_used(j));
            return used;
          },
          "Per action entry, whether the task uses it (walk: the arm entries are unused).")
      .def_property(
          "curriculum", [](VecEnvHandle& h) { return h.env().task().curriculum(); },
          [](VecEnvHandle& h, double c) {
            if (!(c >= 0 && c <= 1)) ThrowValueError("curriculum must be in [0, 1]");
            h.env().task().set_curriculum(c);
          })
      .def(
          "views",
          [](py::object self) {
            VecEnvHandle& h = self.cast<VecEnvHandle&>();
            learn::VecEnv& env = h.env();
            const py::ssize_t e = env.num_envs(), d = env.obs_dim();
            py::dict v;
            v["obs"] = View(self, env.obs().data(), {e, d}, "float32");
            v["final_obs"] = View(self, env.terminal_obs().data(), {e, d}, "float32");
            v["rewards"] = View(self, env.rewards().data(), {e}, "float32");
            v["terminated"] = View(self, env.terminated().data(), {e}, "bool");
            v["truncated"] = View(self, env.truncated().data(), {e}, "bool");
            return v;
          },
          "Numpy views of the C++ buffers (obs, final_obs, rewards, terminated, "
          "truncated), valid for the env's life; step() and reset() overwrite them in place.")
      .def("episode_stats", &EpisodeStats,
           "The episodes that ended in the last step, in env order: r (return), l (length), "
           "success, terminated.");
}

}  // namespace simhuman::python
