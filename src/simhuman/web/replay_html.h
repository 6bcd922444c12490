#pragma once
/// `simhuman replay DIR --html FILE` and `run --html`: one self-contained HTML file (the viewer
/// page of viewer_page.h with every frame inlined) that plays a recorded episode in any browser,
/// offline.

#include <nlohmann/json.hpp>
#include <string>

#include "absl/status/status.h"
#include "simhuman/control/runner.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::web {

/// How the replay is made.
struct ReplayHtmlOptions {
  std::string title = "simhuman replay";
  /// Frames above this rate are dropped (every k-th frame is kept), to bound the file size.
  double max_fps = 30.0;
};

/// The page data of a replay (docs/FORMATS.md, "Replay page"): the scene's bodies, the plan's
/// step texts, and per kept frame the time, step, moving-body poses (float32 base64) and
/// contact targets. Poses come from mj_kinematics of each frame's qpos, on a private mjData
/// (world.data() is not touched). `result` (result.json, may be null) is shown on the page.
/// Errors: InvalidArgument for an empty trajectory, a frame whose qpos size is not the model's,
/// or max_fps <= 0.
absl::StatusOr<nlohmann::json> ReplayData(const world::SimWorld& world,
                                          const plan::ContactChain& chain,
                                          const control::Trajectory& trajectory,
                                          const nlohmann::json& result,
                                          const ReplayHtmlOptions& options = {});

/// Writes the replay page of ReplayData() atomically to `path` (errors name it).
absl::Status WriteReplayHtml(const std::string& path, const world::SimWorld& world,
                             const plan::ContactChain& chain, const control::Trajectory& trajectory,
                             const nlohmann::json& result, const ReplayHtmlOptions& options = {});

}  // namespace simhuman::web
