#include "simhuman/web/live_session.h"

#include <cmath>
#include <limits>

#include "simhuman/control/task.h"
#include "simhuman/eval/episode.h"
#include "simhuman/web/clarify.h"

namespace simhuman::web {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kMotionM = 0.05;  // pelvis displacement that counts as the first motion
// a real-time lag beyond this is dropped rather than caught up (after a pause, a slow stretch)
constexpr double kMaxLagS = 0.25;

double Ms(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// the humans stand by: one step whose pairs (one per human, its pelvis and the first part of
// the first object) are "not care", so it is always satisfied and held until interrupted. A
// scene without objects has no such step (the session then holds the world still).
std::optional<plan::ContactChain> StandBy(const core::SceneCatalog& catalog, int num_agents) {
  if (catalog.objects.empty() || catalog.objects[0].parts.empty()) return std::nullopt;
  plan::ContactChain chain;
  plan::ContactStep step;
  step.label = "stand by";
  for (int a = 0; a < num_agents; ++a) {
    plan::ContactPair p;
    p.object = catalog.objects[0].id;
    p.part = catalog.objects[0].parts[0].name;
    p.joint = core::BodyJoint::kPelvis;
    p.type = plan::ContactType::kNotCare;
    p.agent = a;
    step.pairs.push_back(p);
  }
  chain.steps.push_back(step);
  return chain;
}

bool IsUtf8Text(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    int n = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
    if (n < 0 || (c < 0x20 && c != '\t') || i + n >= s.size() + (n == 0 ? 1 : 0)) return false;
    for (int k = 1; k <= n; ++k) {
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return false;
    }
    i += n + 1;
  }
  return true;
}

const char* PlannerPosture(control::Posture p) {
  switch (p) {
    case control::Posture::kSit:
      return "sit";
    case control::Posture::kLieBack:
    case control::Posture::kLieSide:
      return "lie";
    default:
      return "stand";
  }
}

}  // namespace

absl::Status LiveOptions::Validate() const {
  if (!(speed >= 0) || !std::isfinite(speed)) {
    return absl::InvalidArgumentError("speed " + std::to_string(speed) +
                                      " is invalid; valid: >= 0 (0: as fast as possible)");
  }
  if (!(frame_hz > 0 && frame_hz <= 240)) {
    return absl::InvalidArgumentError("frame_hz " + std::to_string(frame_hz) +
                                      " is invalid; valid: (0, 240]");
  }
  if (max_queued < 1) return absl::InvalidArgumentError("max_queued must be >= 1");
  if (max_command_bytes < 1) return absl::InvalidArgumentError("max_command_bytes must be >= 1");
  return absl::OkStatus();
}

core::StatusOr<std::unique_ptr<LiveSession>> LiveSession::Start(
    const world::SceneSpec& scene, std::unique_ptr<language::Planner> planner,
    const LiveOptions& options) {
  SH_RETURN_IF_ERROR(options.Validate());
  std::unique_ptr<LiveSession> s(new LiveSession());
  s->options_ = options;
  s->scene_ = scene;
  SH_ASSIGN_OR_RETURN(core::SceneCatalog catalog, world::BuildCatalog(scene));
  SH_ASSIGN_OR_RETURN(s->world_, eval::BuildWorld(scene, catalog));
  SH_ASSIGN_OR_RETURN(s->controllers_,
                      eval::MakeControllers(*s->world_, options.config, options.seed));
  s->planner_ = std::move(planner);
  mj_kinematics(s->world_->model(), s->world_->data());
  s->view_ = DescribeScene(*s->world_, s->world_->data());
  s->scene_json_ = {{"title", "simhuman live: " + scene.name}, {"scene", s->view_.json}};
  s->frame_catalog_ = s->world_->catalog();
  s->planner_catalog_ = s->world_->catalog();
  s->status_ = {{"state", "idle"}, {"message", "type a command"},      {"question", ""},
                {"command", ""},   {"steps", nlohmann::json::array()}, {"plan", 0},
                {"paused", false}};
  s->idle_ = StandBy(s->world_->catalog(), s->world_->num_agents());
  s->Publish(plan::ContactChain(), 0);
  s->sim_thread_ = std::thread([p = s.get()] { p->SimLoop(); });
  s->plan_thread_ = std::thread([p = s.get()] { p->PlanLoop(); });
  return s;
}

LiveSession::~LiveSession() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stopping_ = true;
  }
  cv_.notify_all();
  if (sim_thread_.joinable()) sim_thread_.join();
  if (plan_thread_.joinable()) plan_thread_.join();
}

bool LiveSession::stopping() const {
  std::lock_guard<std::mutex> lock(mu_);
  return stopping_;
}

absl::Status LiveSession::SubmitCommand(const std::string& text) {
  if (text.size() > options_.max_command_bytes) {
    return absl::OutOfRangeError("the command is " + std::to_string(text.size()) +
                                 " bytes; the limit is " +
                                 std::to_string(options_.max_command_bytes));
  }
  if (!IsUtf8Text(text)) {
    return absl::InvalidArgumentError(
        "the command is not UTF-8 text (control characters or "
        "broken multi-byte sequences)");
  }
  if (text.find_first_not_of(" \t") == std::string::npos) {
    return absl::InvalidArgumentError("the command is empty; type e.g. \"sit on the chair\"");
  }
  std::lock_guard<std::mutex> lock(mu_);
  if (static_cast<int>(queue_.size()) >= options_.max_queued) {
    return absl::ResourceExhaustedError(std::to_string(queue_.size()) +
                                        " commands are waiting for the planner; try again when "
                                        "they are planned");
  }
  queue_.push_back({text, Clock::now()});
  cv_.notify_all();
  return absl::OkStatus();
}

absl::Status LiveSession::Answer(const std::string& text) {
  std::string command, question;
  core::SceneCatalog catalog;
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (status_["state"] != "question") {
      return absl::FailedPreconditionError("no question is waiting for an answer; send a command");
    }
    command = question_command_;
    question = status_["question"].get<std::string>();
    catalog = planner_catalog_;
  }
  if (text.size() > options_.max_command_bytes) return SubmitCommand(text);
  SH_ASSIGN_OR_RETURN(std::string rewritten, AnswerQuestion(command, question, text, catalog));
  return SubmitCommand(rewritten);
}

void LiveSession::SetPaused(bool paused) {
  std::lock_guard<std::mutex> lock(mu_);
  paused_ = paused;
  status_["paused"] = paused;
  ++status_seq_;
  cv_.notify_all();
}

void LiveSession::Reset() {
  std::lock_guard<std::mutex> lock(mu_);
  reset_requested_ = true;
  cv_.notify_all();
}

std::optional<LiveFrame> LiveSession::WaitFrame(uint64_t after_seq,
                                                std::chrono::milliseconds timeout) const {
  std::unique_lock<std::mutex> lock(mu_);
  cv_.wait_for(lock, timeout, [&] { return stopping_ || frame_.seq > after_seq; });
  if (stopping_ || frame_.seq <= after_seq) return std::nullopt;
  return frame_;
}

nlohmann::json LiveSession::Status() const {
  std::lock_guard<std::mutex> lock(mu_);
  nlohmann::json j = status_;
  j["seq"] = status_seq_;
  return j;
}

uint64_t LiveSession::status_seq() const {
  std::lock_guard<std::mutex> lock(mu_);
  return status_seq_;
}

nlohmann::json LiveSession::State() const {
  std::lock_guard<std::mutex> lock(mu_);
  nlohmann::json j = status_;
  j["seq"] = status_seq_;
  j["sim_time_s"] = sim_time_s_;
  j["real_time_factor"] = rtf_;
  j["frames"] = frame_.seq;
  j["queued"] = queue_.size();
  j["pelvis"] = nlohmann::json::array();
  for (const Eigen::Vector3d& p : pelvis_) j["pelvis"].push_back({p.x(), p.y(), p.z()});
  j["latency_first_frame_ms"] = first_frame_ms_;
  j["latency_first_motion_ms"] = first_motion_ms_;
  return j;
}

void LiveSession::SetStatus(const std::string& state, const std::string& message) {
  status_["state"] = state;
  status_["message"] = message;
  if (state != "question") status_["question"] = "";
  ++status_seq_;
  cv_.notify_all();
}

// ---- planner thread ----------------------------------------------------------------------

void LiveSession::PlanLoop() {
  while (true) {
    Command command;
    {
      std::unique_lock<std::mutex> lock(mu_);
      cv_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      command = queue_.front();
      queue_.pop_front();
      status_["command"] = command.text;
      SetStatus("planning", "planning \"" + command.text + "\"");
    }
    PlanOne(command);
  }
}

void LiveSession::PlanOne(const Command& command) {
  language::PlanContext context;
  core::SceneCatalog catalog;
  {
    std::lock_guard<std::mutex> lock(mu_);
    catalog = planner_catalog_;
    context.agents = agents_;
  }
  context.scene = &catalog;
  core::StatusOr<language::PlanResult> planned = planner_->Plan(command.text, context);
  std::lock_guard<std::mutex> lock(mu_);
  if (!planned.ok() && absl::IsFailedPrecondition(planned.status())) {
    question_command_ = command.text;
    status_["question"] = std::string(planned.status().message());
    SetStatus("question", "");
    return;
  }
  if (!planned.ok()) {
    SetStatus("error",
              "cannot do \"" + command.text + "\": " + std::string(planned.status().message()));
    return;
  }
  for (size_t s = 0; s < planned->chain.steps.size(); ++s) {
    if (planned->chain.steps[s].carry) {
      SetStatus("error", "cannot do \"" + command.text + "\": step " + std::to_string(s + 1) +
                             " carries an object, which needs the carry controller (not in the "
                             "live view yet)");
      return;
    }
  }
  nlohmann::json steps = nlohmann::json::array();
  for (const plan::ContactStep& s : planned->chain.steps) steps.push_back(eval::StepText(s));
  pending_ = std::move(planned->chain);
  pending_received_ = command.received;
  status_["steps"] = std::move(steps);
  status_["plan"] = ++plan_id_;
  SetStatus("running", "doing \"" + command.text + "\"");
}

// ---- simulation thread -------------------------------------------------------------------

void LiveSession::SimLoop() {
  std::optional<plan::ContactChain> chain = idle_;
  pace_wall0_ = rtf_wall0_ = Clock::now();
  pace_sim0_ = rtf_sim0_ = world_->data()->time;
  while (true) {
    {
      std::unique_lock<std::mutex> lock(mu_);
      if (!chain) {
        // nothing to do and no stand-by step: hold the world still until told otherwise
        cv_.wait_for(lock, std::chrono::duration<double>(1.0 / options_.frame_hz),
                     [&] { return stopping_ || pending_ || reset_requested_; });
      }
      if (stopping_) return;
      if (reset_requested_) {
        reset_requested_ = false;
        pending_.reset();
        world_->Reset();
        chain = idle_;
        status_["steps"] = nlohmann::json::array();
        SetStatus("idle", "reset: the humans are back where they started");
      }
      if (pending_) {
        chain = std::move(pending_);
        pending_.reset();
        latency_t0_ = pending_received_;
        latency_pelvis0_.reset();
        first_frame_ms_ = first_motion_ms_ = -1;
      }
    }
    if (!chain) {
      Publish(plan::ContactChain(), 0);
      continue;
    }
    control::RunOptions run;
    run.record = false;
    run.record_fps = options_.frame_hz;
    run.settle_s = std::numeric_limits<double>::infinity();  // hold the last step until told
    run.on_frame = [&](double, int step) { return OnFrame(*chain, step); };
    run.behind_real_time = [&](double) { return BehindRealTime(); };
    const bool idle = idle_ && chain->steps.size() == 1 && chain->steps[0].label == "stand by";
    run.progress = [&](const control::ProgressEvent& e) {
      if (idle || e.ended) return;
      std::lock_guard<std::mutex> lock(mu_);
      const std::string text = eval::StepText(chain->steps[e.step]);
      if (!e.completed) {
        SetStatus("error", "step " + std::to_string(e.step + 1) + " ('" + text +
                               "') ran out of time; the human could not do it from here");
      } else if (e.step + 1 == e.steps_total) {
        SetStatus("done", "done: " + text + " (holding it; type the next command)");
      } else {
        SetStatus("running", "step " + std::to_string(e.step + 1) + " done: " + text);
      }
    };
    // the controllers are kept across episodes; each episode's steps are new ones to them
    run.controller_step_offset = step_offset_;
    step_offset_ += static_cast<int>(chain->steps.size());
    const double t0 = world_->data()->time;
    core::StatusOr<control::EpisodeResult> result =
        eval::RunWithWalkPolicy(*world_, *chain, controllers_, options_.walk_policy, run, nullptr);
    if (!result.ok()) {
      // the walking policy could not be loaded: carry on without it
      std::lock_guard<std::mutex> lock(mu_);
      SetStatus("error", "walking policy: " + std::string(result.status().message()) +
                             "; walking with the MPC instead");
      options_.walk_policy.clear();
      continue;
    }
    if (result->end_reason == "interrupted") continue;
    EndOfEpisode(result->end_reason, result->fell);
    chain = idle_;
    if (world_->data()->time <= t0) {
      // an episode that ended before simulating anything would spin: start over instead
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      world_->Reset();
    }
  }
}

void LiveSession::EndOfEpisode(const std::string& reason, bool fell) {
  std::lock_guard<std::mutex> lock(mu_);
  if (fell || reason.rfind("unstable", 0) == 0 || reason.rfind("controller", 0) == 0) {
    world_->Reset();
    SetStatus("error",
              std::string(fell ? "the human fell" : "the simulation failed (" + reason + ")") +
                  "; it was put back where it started. Try another command.");
  } else if (reason == "timeout") {
    SetStatus("error",
              "the human could not finish the plan in time; it stands by. Try another command.");
  } else {
    SetStatus("idle", "done (" + reason + ")");
  }
  status_["steps"] = nlohmann::json::array();
}

bool LiveSession::OnFrame(const plan::ContactChain& chain, int step) {
  Publish(chain, step);
  Pace();
  std::unique_lock<std::mutex> lock(mu_);
  if (paused_) {
    cv_.wait(lock, [&] { return stopping_ || !paused_ || pending_ || reset_requested_; });
    pace_wall0_ = Clock::now();
    pace_sim0_ = world_->data()->time;
  }
  return !(stopping_ || pending_ || reset_requested_);
}

// whether the simulation is behind its pace (the MPC then replans less often); sim thread
bool LiveSession::BehindRealTime() const { return options_.speed > 0 && BehindS(Clock::now()) > 0; }

// seconds the simulation is behind its pace (negative: ahead), at wall time `now`
double LiveSession::BehindS(std::chrono::steady_clock::time_point now) const {
  const double due_s = (world_->data()->time - pace_sim0_) / options_.speed;
  return std::chrono::duration<double>(now - pace_wall0_).count() - due_s;
}

// waits so that simulated time runs at options_.speed x wall time
void LiveSession::Pace() {
  const double sim = world_->data()->time;
  const Clock::time_point now = Clock::now();
  const double wall_s = std::chrono::duration<double>(now - rtf_wall0_).count();
  if (wall_s >= 1.0) {
    std::lock_guard<std::mutex> lock(mu_);
    rtf_ = (sim - rtf_sim0_) / wall_s;
    rtf_wall0_ = now;
    rtf_sim0_ = sim;
  }
  if (options_.speed <= 0) return;
  const double behind_s = BehindS(now);
  if (behind_s > kMaxLagS) {
    pace_wall0_ = now;
    pace_sim0_ = sim;
  } else if (behind_s < 0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(-behind_s));
  }
}

void LiveSession::Publish(const plan::ContactChain& chain, int step) {
  const mjData* d = world_->data();
  std::vector<float> poses, targets;
  AppendPoses(view_, d, &poses);
  AppendTargets(*world_, chain, step, d, &frame_catalog_, &targets);
  std::vector<language::AgentStart> agents(world_->num_agents());
  std::vector<Eigen::Vector3d> pelvis(world_->num_agents());
  for (int a = 0; a < world_->num_agents(); ++a) {
    pelvis[a] = world_->BodyPoints(d, a)[static_cast<int>(core::BodyJoint::kPelvis)];
    agents[a].x_m = pelvis[a].x();
    agents[a].y_m = pelvis[a].y();
    agents[a].yaw_rad = world::PelvisYaw(d, world_->agent(a));
    if (!chain.steps.empty()) {
      const int i = std::clamp<int>(step, 0, static_cast<int>(chain.steps.size()) - 1);
      agents[a].posture = PlannerPosture(
          control::BuildStepTask(chain.steps[i], frame_catalog_, a, world_->agent(a).scale, {})
              .posture);
    }
  }
  nlohmann::json j;
  std::lock_guard<std::mutex> lock(mu_);
  j["seq"] = frame_.seq + 1;
  j["t"] = std::round(d->time * 1e4) / 1e4;
  j["plan"] = plan_id_;
  j["step"] = step;
  j["poses"] = FloatsBase64(poses);
  j["targets"] = FloatsBase64(targets);
  frame_.seq += 1;
  frame_.json = std::make_shared<const std::string>(j.dump());
  sim_time_s_ = d->time;
  agents_ = std::move(agents);
  pelvis_ = pelvis;
  planner_catalog_ = frame_catalog_;
  // latencies of the newest plan
  if (latency_t0_ && !pelvis.empty()) {
    const Clock::time_point now = Clock::now();
    if (first_frame_ms_ < 0) first_frame_ms_ = Ms(*latency_t0_, now);
    if (!latency_pelvis0_) latency_pelvis0_ = pelvis[0];
    if ((pelvis[0] - *latency_pelvis0_).norm() > kMotionM) {
      first_motion_ms_ = Ms(*latency_t0_, now);
      latency_t0_.reset();
    }
  }
  cv_.notify_all();
}

}  // namespace simhuman::web
