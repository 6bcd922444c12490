#pragma once
/// For the render module's tests only: a tiny lit scene (checker floor, red box at the origin,
/// blue ball on +x) loaded from a temporary file.

#include <mujoco/mujoco.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace simhuman::render::testing {

inline constexpr char kTestSceneXml[] = R"(
<mujoco model="render_test">
  <visual>
    <headlight ambient="0.3 0.3 0.3" diffuse="0.4 0.4 0.4"/>
  </visual>
  <asset>
    <texture name="grid" type="2d" builtin="checker" rgb1="0.55 0.6 0.65"
             rgb2="0.3 0.35 0.4" width="256" height="256"/>
    <material name="grid" texture="grid" texrepeat="4 4" texuniform="true"/>
  </asset>
  <worldbody>
    <light name="top" pos="0 0 4" dir="0 0 -1"/>
    <geom name="floor" type="plane" size="4 4 0.1" material="grid"/>
    <body name="box" pos="0 0 0.25">
      <geom name="box" type="box" size="0.25 0.25 0.25" rgba="0.9 0.1 0.1 1"/>
    </body>
    <body name="ball" pos="0.9 0 0.2">
      <geom name="ball" type="sphere" size="0.2" rgba="0.1 0.2 0.9 1"/>
    </body>
  </worldbody>
</mujoco>
)";

/// Loads kTestSceneXml from a file in `dir`; nullptr (and the reason in *error) on failure.
inline mjModel* LoadTestScene(const std::string& dir, std::string* error) {
  // the pid keeps tests that run at the same time (ctest -j) off each other's file
  const std::string path = dir + "/simhuman_render_test_scene_" + std::to_string(getpid()) + ".xml";
  {
    std::ofstream out(path);
    out << kTestSceneXml;
  }
  char err[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, err, sizeof(err));
  std::remove(path.c_str());
  if (m == nullptr && error != nullptr) *error = err;
  return m;
}

}  // namespace simhuman::render::testing
