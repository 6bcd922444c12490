#include "simhuman/web/replay_html.h"

#include <cmath>
#include <memory>

#include "simhuman/core/json_io.h"
#include "simhuman/eval/episode.h"
#include "simhuman/web/scene_view.h"
#include "simhuman/web/viewer_page.h"

namespace simhuman::web {
namespace {

// a rate read back from rounded times (30.0003 Hz) is not above max_fps (30 Hz)
constexpr double kRateTol = 0.01;

struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// the result fields the page shows
nlohmann::json ResultSummary(const nlohmann::json& result) {
  if (!result.is_object()) return nullptr;
  nlohmann::json out = nlohmann::json::object();
  for (const char* key : {"success", "steps_completed", "steps_total", "end_reason", "fell",
                          "command", "scene", "preset", "seed"}) {
    if (result.contains(key)) out[key] = result[key];
  }
  return out;
}

}  // namespace

absl::StatusOr<nlohmann::json> ReplayData(const world::SimWorld& world,
                                          const plan::ContactChain& chain,
                                          const control::Trajectory& trajectory,
                                          const nlohmann::json& result,
                                          const ReplayHtmlOptions& options) {
  const mjModel* m = world.model();
  const size_t n = trajectory.qpos.size();
  if (n == 0) return absl::InvalidArgumentError("replay: the trajectory has no frames");
  if (!(options.max_fps > 0)) {
    return absl::InvalidArgumentError("replay: max_fps must be > 0, not " +
                                      std::to_string(options.max_fps));
  }
  for (size_t f = 0; f < n; ++f) {
    if (static_cast<int>(trajectory.qpos[f].size()) != m->nq) {
      return absl::InvalidArgumentError("replay: frame " + std::to_string(f) + " has " +
                                        std::to_string(trajectory.qpos[f].size()) +
                                        " qpos entries, the model has " + std::to_string(m->nq));
    }
  }
  const double fps = trajectory.fps > 0 ? trajectory.fps : 30.0;
  const size_t stride =
      static_cast<size_t>(std::max(1.0, std::ceil(fps / options.max_fps - kRateTol)));

  std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m));
  auto pose = [&](size_t f) {
    std::copy(trajectory.qpos[f].begin(), trajectory.qpos[f].end(), d->qpos);
    mj_kinematics(m, d.get());
  };
  pose(0);
  SceneView view = DescribeScene(world, d.get());
  core::SceneCatalog catalog = world.catalog();
  std::vector<float> poses, targets;
  nlohmann::json times = nlohmann::json::array(), steps = nlohmann::json::array();
  nlohmann::json offsets = nlohmann::json::array({0});
  int n_targets = 0;
  for (size_t f = 0; f < n; f += stride) {
    pose(f);
    AppendPoses(view, d.get(), &poses);
    const int step = f < trajectory.step_index.size() ? trajectory.step_index[f] : 0;
    n_targets += AppendTargets(world, chain, step, d.get(), &catalog, &targets);
    offsets.push_back(n_targets);
    const double t = f < trajectory.time_s.size() ? trajectory.time_s[f] : f / fps;
    times.push_back(std::round(t * 1e4) / 1e4);
    steps.push_back(step);
  }
  nlohmann::json step_texts = nlohmann::json::array();
  for (const plan::ContactStep& s : chain.steps) step_texts.push_back(eval::StepText(s));

  nlohmann::json data;
  data["mode"] = "replay";
  data["title"] = options.title;
  data["scene"] = std::move(view.json);
  data["steps"] = std::move(step_texts);
  data["result"] = ResultSummary(result);
  nlohmann::json& r = data["replay"];
  r["fps"] = fps / static_cast<double>(stride);
  r["times"] = std::move(times);
  r["steps"] = std::move(steps);
  r["poses"] = FloatsBase64(poses);
  r["target_offsets"] = std::move(offsets);
  r["targets"] = FloatsBase64(targets);
  return data;
}

absl::Status WriteReplayHtml(const std::string& path, const world::SimWorld& world,
                             const plan::ContactChain& chain, const control::Trajectory& trajectory,
                             const nlohmann::json& result, const ReplayHtmlOptions& options) {
  absl::StatusOr<nlohmann::json> data = ReplayData(world, chain, trajectory, result, options);
  if (!data.ok()) return data.status();
  return core::WriteFileAtomic(path, ViewerPageHtml(*data));
}

}  // namespace simhuman::web
