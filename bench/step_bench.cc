// Measures the cost of SimWorld::Step (mj_step + health check) against a raw mj_step of the
// same model, interleaved in one run so machine noise hits both alike. Prints JSON.
//   build/simhuman_step_bench [scene] [steps]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "simhuman/world/scene.h"
#include "simhuman/world/sim_world.h"

using namespace simhuman;

int main(int argc, char** argv) {
  std::string scene = argc > 1 ? argv[1] : "living_room";
  int steps = argc > 2 ? std::atoi(argv[2]) : 20000;
  auto spec = world::LoadScene(scene);
  if (!spec.ok()) {
    std::fprintf(stderr, "%s\n", std::string(spec.status().message()).c_str());
    return 2;
  }
  auto cat = world::BuildCatalog(*spec);
  if (!cat.ok()) return 2;
  std::vector<world::AgentSpec> agents;
  for (const auto& h : spec->humans)
    agents.push_back({h.pos_xy.x(), h.pos_xy.y(), h.yaw_rad, h.scale});
  auto w = world::SimWorld::Create(*cat, agents);
  if (!w.ok()) return 2;
  const mjModel* m = (*w)->model();
  mjData* raw = mj_makeData(m);
  mjData* start = mj_copyData(nullptr, m, (*w)->data());
  double t_raw = 0, t_ours = 0;
  const int kBlocks = 20, per = steps / kBlocks;
  for (int b = 0; b < kBlocks; ++b) {
    // same start state for both; alternate which goes first
    mj_copyData(raw, m, start);
    mj_copyData((*w)->data(), m, start);
    for (int order = 0; order < 2; ++order) {
      bool ours_now = (order == 0) == (b % 2 == 0);
      auto t0 = std::chrono::steady_clock::now();
      if (ours_now) {
        for (int i = 0; i < per; ++i) (*w)->Step();
      } else {
        for (int i = 0; i < per; ++i) mj_step(m, raw);
      }
      double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      (ours_now ? t_ours : t_raw) += dt;
    }
  }
  int n = per * kBlocks;
  std::printf(
      "{\"scene\": \"%s\", \"steps\": %d, \"raw_mj_step_us\": %.2f, \"simworld_step_us\": %.2f, "
      "\"ratio\": %.3f}\n",
      scene.c_str(), n, 1e6 * t_raw / n, 1e6 * t_ours / n, t_ours / t_raw);
  mj_deleteData(raw);
  mj_deleteData(start);
  return 0;
}
