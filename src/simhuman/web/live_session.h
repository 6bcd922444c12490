#pragma once
/// The simulation behind `simhuman serve`: one world simulated continuously on its own thread by
/// the runner and controllers `simhuman run` uses (eval::RunWithWalkPolicy), paced to real
/// time, publishing frames at 30 Hz; typed commands go through a planner on a second thread,
/// and a new plan interrupts the running one at the next frame (RunOptions::on_frame), the
/// human carrying it out from wherever it is. Between plans the human stands by (a step with no
/// requirement); after a plan's last step it holds that step's contacts.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "absl/status/status.h"
#include "simhuman/control/mpc/mpc_config.h"
#include "simhuman/control/mpc/mpc_controller.h"
#include "simhuman/core/status.h"
#include "simhuman/language/planner.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/web/scene_view.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::web {

/// Settings of a live session.
struct LiveOptions {
  control::MpcConfig config;  ///< the controllers' (a preset or a file)
  uint64_t seed = 1;          ///< controllers' seed (eval::ControllerSeed)
  std::string walk_policy;    ///< get-close steps walked by this policy; empty: MPC only
  double speed = 1.0;         ///< simulated seconds per wall second; 0: as fast as it goes
  double frame_hz = 30.0;     ///< frames published per simulated second
  int max_queued = 4;         ///< commands waiting for the planner; more are refused
  size_t max_command_bytes = 500;
  /// Validate(): speed >= 0, frame_hz in (0, 240], max_queued >= 1, max_command_bytes >= 1.
  absl::Status Validate() const;
};

/// One published frame: its number and its JSON text ({"seq", "t", "plan", "step", "poses",
/// "targets"}; docs/FORMATS.md).
struct LiveFrame {
  uint64_t seq = 0;
  std::shared_ptr<const std::string> json;
};

/// A running session. All public methods are thread-safe.
class LiveSession {
 public:
  /// Builds the world of `scene` and its controllers and starts the simulation and planner
  /// threads. Errors: the scene's, the controllers' and options.Validate()'s.
  static core::StatusOr<std::unique_ptr<LiveSession>> Start(
      const world::SceneSpec& scene, std::unique_ptr<language::Planner> planner,
      const LiveOptions& options);
  /// Stops and joins the threads.
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  /// Queues a command for the planner. Errors: InvalidArgument (empty, or not UTF-8 text),
  /// OutOfRange (longer than max_command_bytes), ResourceExhausted (max_queued waiting).
  absl::Status SubmitCommand(const std::string& text);
  /// Answers the pending clarifying question (the command is planned again with the chosen
  /// object named). Errors: FailedPrecondition when no question is pending, the answer's
  /// (InvalidArgument, listing the choices), and SubmitCommand's.
  absl::Status Answer(const std::string& text);
  /// Pauses or resumes the simulation.
  void SetPaused(bool paused);
  /// Puts the world back in its initial state (the human stands by).
  void Reset();

  /// The newest frame if its seq > `after_seq`, waiting up to `timeout` for one; nullopt on
  /// timeout or when the session stops.
  std::optional<LiveFrame> WaitFrame(uint64_t after_seq, std::chrono::milliseconds timeout) const;
  /// The status ({"seq", "state": "idle"|"planning"|"running"|"done"|"question"|"error", "message",
  /// "question", "command", "steps", "plan", "paused"}) and its change counter.
  nlohmann::json Status() const;
  uint64_t status_seq() const;
  /// Status() plus sim time, real-time factor, the humans' pelvis positions, queue length and
  /// the last command's latencies (for /api/state and tests).
  nlohmann::json State() const;
  /// {"title", "scene": SceneView::json}.
  const nlohmann::json& scene_json() const { return scene_json_; }
  bool stopping() const;

 private:
  struct Command {
    std::string text;
    std::chrono::steady_clock::time_point received;
  };
  LiveSession() = default;
  void SimLoop();
  void PlanLoop();
  void PlanOne(const Command& command);
  bool OnFrame(const plan::ContactChain& chain, int step);
  void Publish(const plan::ContactChain& chain, int step);
  void EndOfEpisode(const std::string& reason, bool fell);
  void SetStatus(const std::string& state, const std::string& message);  // mu_ held
  void Pace();
  bool BehindRealTime() const;
  double BehindS(std::chrono::steady_clock::time_point now) const;

  LiveOptions options_;
  world::SceneSpec scene_;
  std::unique_ptr<world::SimWorld> world_;  // owned by the sim thread once started
  std::vector<std::unique_ptr<control::MpcController>> controllers_;
  std::unique_ptr<language::Planner> planner_;
  SceneView view_;
  nlohmann::json scene_json_;
  core::SceneCatalog frame_catalog_;        // sim thread scratch
  std::optional<plan::ContactChain> idle_;  // the stand-by step, if the scene allows one

  mutable std::mutex mu_;
  mutable std::condition_variable cv_;
  bool stopping_ = false;
  bool paused_ = false;
  bool reset_requested_ = false;
  std::deque<Command> queue_;
  std::optional<plan::ContactChain> pending_;  // planned, waiting to interrupt the running plan
  std::optional<std::chrono::steady_clock::time_point> pending_received_;
  LiveFrame frame_;
  nlohmann::json status_;
  uint64_t status_seq_ = 0;
  int plan_id_ = 0;
  std::string question_command_;              // the command the pending question is about
  core::SceneCatalog planner_catalog_;        // movable poses as of the last frame
  std::vector<language::AgentStart> agents_;  // as of the last frame
  std::vector<Eigen::Vector3d> pelvis_;       // as of the last frame
  double sim_time_s_ = 0;
  double rtf_ = 0;  // simulated / wall seconds over the last second
  // latencies of the newest plan: command received -> its first frame, -> pelvis moved 5 cm
  std::optional<std::chrono::steady_clock::time_point> latency_t0_;
  std::optional<Eigen::Vector3d> latency_pelvis0_;
  double first_frame_ms_ = -1, first_motion_ms_ = -1;

  // sim thread only
  int step_offset_ = 0;  // RunOptions::controller_step_offset of the next episode
  std::chrono::steady_clock::time_point pace_wall0_;
  double pace_sim0_ = 0;
  std::chrono::steady_clock::time_point rtf_wall0_;
  double rtf_sim0_ = 0;

  std::thread sim_thread_, plan_thread_;
};

}  // namespace simhuman::web
