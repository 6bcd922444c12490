// The `simhuman._native` extension module; simhuman/__init__.py re-exports it.
#include <pybind11/pybind11.h>

#include "simhuman/python/bindings.h"
#include "simhuman/world/health.h"

PYBIND11_MODULE(_native, m) {
  m.doc() = "simhuman's C++ core: scenes, planners, episodes, rendering, eval, training envs.";
  // MuJoCo's errors and warnings go to our handlers (as in `simhuman`'s main)
  simhuman::world::InstallMujocoHandlers();
  simhuman::python::RegisterErrors(m);
  simhuman::python::RegisterScenes(m);
  simhuman::python::RegisterEpisodes(m);
  simhuman::python::RegisterVecEnv(m);
  simhuman::python::RegisterCommands(m);
}
