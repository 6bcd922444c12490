#include "simhuman/eval/eval_runner.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "simhuman/core/rng.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/reachability.h"
#include "simhuman/eval/replay.h"
#include "simhuman/plan/validate.h"

namespace simhuman::eval {
namespace {

nlohmann::ordered_json NumberOrNull(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
}

}  // namespace

bool StandsOnItsFeet(const plan::BodyPoints& body) {
  using J = core::BodyJoint;
  auto leg = [&](J hip, J knee, J foot) {
    return (body.at(hip) - body.at(knee)).norm() + (body.at(knee) - body.at(foot)).norm();
  };
  const double length = 0.5 * (leg(J::kLeftHip, J::kLeftKnee, J::kLeftFoot) +
                               leg(J::kRightHip, J::kRightKnee, J::kRightFoot));
  const Eigen::Vector3d hips = 0.5 * (body.at(J::kLeftHip) + body.at(J::kRightHip));
  const double foot_z = std::min(body.at(J::kLeftFoot).z(), body.at(J::kRightFoot).z());
  const Eigen::Vector3d up = body.at(J::kHead) - hips;
  return length > 0 && hips.z() - foot_z >= 0.7 * length && up.norm() > 0 &&
         up.z() >= std::cos(M_PI / 4) * up.norm();
}

bool GetCloseHumansStand(const plan::ContactStep& last,
                         const std::vector<plan::BodyPoints>& agents) {
  for (const plan::ContactPair& p : last.pairs) {
    if (!p.IsGetClose()) continue;
    if (p.agent < 0 || p.agent >= static_cast<int>(agents.size())) return false;
    if (!StandsOnItsFeet(agents[p.agent])) return false;
  }
  return true;
}

void JudgeEpisode(bool last_step_holds, EpisodeRecord* record) {
  record->held = record->result.success && last_step_holds && !record->result.fell;
  record->success = record->result.success && record->held && record->extra.pass;
}

Summary Summarize(std::string_view suite, const std::vector<EpisodeRecord>& records,
                  int episodes_requested) {
  Summary s;
  s.suite = std::string(suite);
  s.episodes = static_cast<int>(records.size());
  s.episodes_requested = episodes_requested;
  if (records.empty()) return s;
  int successes = 0, falls = 0, extra_pass = 0, n_error = 0, n_error_jc = 0;
  int n_unihsi = 0, successes_unihsi = 0;
  double steps = 0, steps_total = 0, error_sum = 0, error_jc_sum = 0;
  for (const EpisodeRecord& r : records) {
    successes += r.success;
    if (r.unihsi_recorded) {
      ++n_unihsi;
      successes_unihsi += r.success && r.result.success_unihsi_points;
    }
    falls += r.result.fell;
    extra_pass += r.extra.pass;
    steps += r.result.steps_completed;
    steps_total += r.result.steps_total;
    if (r.result.contact_error_m >= 0) {
      error_sum += r.result.contact_error_m;
      ++n_error;
    }
    if (r.result.contact_error_joint_centre_m >= 0) {
      error_jc_sum += r.result.contact_error_joint_centre_m;
      ++n_error_jc;
    }
    s.sim_time_s += r.result.sim_time_s;
    s.wall_time_s += r.result.wall_time_s;
  }
  const double n = static_cast<double>(records.size());
  s.success_rate = successes / n;
  s.fall_rate = falls / n;
  s.extra_pass_rate = extra_pass / n;
  s.success_steps = steps / n;
  s.steps_total = steps_total / n;
  if (n_error > 0) s.contact_error_m = error_sum / n_error;
  if (n_error_jc > 0) s.contact_error_joint_centre_m = error_jc_sum / n_error_jc;
  if (n_unihsi > 0) s.success_rate_unihsi_points = successes_unihsi / static_cast<double>(n_unihsi);
  std::vector<MotionMetrics> motion;
  for (const EpisodeRecord& r : records) {
    if (r.motion) motion.push_back(*r.motion);
  }
  if (!motion.empty()) s.motion = MeanMotionMetrics(motion);
  s.wall_per_sim = s.sim_time_s > 0 ? s.wall_time_s / s.sim_time_s : 0.0;
  return s;
}

const std::vector<std::string>& ScalableSuites() {
  static const std::vector<std::string> names = {"sit", "sit-far", "lie", "lie-far"};
  return names;
}

nlohmann::ordered_json EpisodeRecordJson(const EpisodeRecord& r) {
  nlohmann::ordered_json j;
  j["episode"] = r.index;
  j["seed"] = r.seed;
  j["variant"] = r.variant;
  j["success"] = r.success;
  j["plan_success"] = r.result.success;
  const nlohmann::ordered_json result = EpisodeResultJson(r.result);
  for (const auto& [key, value] : result.items()) {
    if (key != "success") j[key] = value;
  }
  j["held"] = r.held;
  j["held_pair_errors_m"] = r.held_pair_errors_m;
  if (!r.extra.metric.empty()) {
    j["extra_check"] = r.extra.metric;
    j["extra_pass"] = r.extra.pass;
    j[r.extra.metric] = NumberOrNull(r.extra.value);
  }
  if (!r.sheet_path.empty()) j["contact_sheet"] = r.sheet_path;
  if (!r.render_error.empty()) j["render_error"] = r.render_error;
  if (r.motion) j["motion"] = MotionMetricsJson(*r.motion);
  j["scene"] = r.scene;
  j["plan"] = r.plan;
  return j;
}

core::StatusOr<EpisodeRecord> EpisodeRecordFromJson(const nlohmann::json& j) {
  EpisodeRecord r;
  try {
    r.index = j.at("episode").get<int>();
    r.seed = j.at("seed").get<uint64_t>();
    r.variant = j.at("variant").get<std::string>();
    r.success = j.at("success").get<bool>();
    r.held = j.at("held").get<bool>();
    r.held_pair_errors_m =
        j.value("held_pair_errors_m", std::vector<double>());  // absent before session 33
    control::EpisodeResult& res = r.result;
    res.success = j.at("plan_success").get<bool>();
    res.steps_completed = j.at("steps_completed").get<int>();
    res.steps_total = j.at("steps_total").get<int>();
    const nlohmann::json& err = j.at("contact_error_m");
    res.contact_error_m = err.is_null() ? -1.0 : err.get<double>();
    // absent in journals written before session 13
    const nlohmann::json jc = j.value("contact_error_joint_centre_m", nlohmann::json());
    res.contact_error_joint_centre_m = jc.is_null() ? -1.0 : jc.get<double>();
    // absent in journals written before session 31
    r.unihsi_recorded = j.contains("success_unihsi_points");
    res.success_unihsi_points = j.value("success_unihsi_points", false);
    res.fell = j.at("fell").get<bool>();
    res.end_reason = j.at("end_reason").get<std::string>();
    res.sim_time_s = j.at("sim_time_s").get<double>();
    res.wall_time_s = j.at("wall_time_s").get<double>();
    if (j.contains("extra_check")) {
      r.extra.metric = j.at("extra_check").get<std::string>();
      r.extra.pass = j.at("extra_pass").get<bool>();
      const nlohmann::json& v = j.at(r.extra.metric);
      r.extra.value = v.is_null() ? std::nan("") : v.get<double>();
    }
    r.sheet_path = j.value("contact_sheet", std::string());
    r.render_error = j.value("render_error", std::string());
    if (j.contains("motion")) {
      core::StatusOr<MotionMetrics> m = MotionMetricsFromJson(j.at("motion"));
      if (!m.ok()) return m.status();
      r.motion = *m;
    }
  } catch (const nlohmann::json::exception& e) {
    return absl::InvalidArgumentError(std::string("not an episode record: ") + e.what());
  }
  return r;
}

nlohmann::ordered_json SummaryJson(const Summary& s, const EvalOptions& options) {
  nlohmann::ordered_json j;
  j["suite"] = s.suite;
  j["episodes"] = s.episodes;
  j["episodes_requested"] = s.episodes_requested;
  j["success_rate"] = s.success_rate;
  j["success_rate_unihsi_points"] = s.success_rate_unihsi_points
                                        ? nlohmann::ordered_json(*s.success_rate_unihsi_points)
                                        : nlohmann::ordered_json();
  j["contact_error_m"] =
      s.contact_error_m ? nlohmann::ordered_json(*s.contact_error_m) : nlohmann::ordered_json();
  j["contact_error_joint_centre_m"] = s.contact_error_joint_centre_m
                                          ? nlohmann::ordered_json(*s.contact_error_joint_centre_m)
                                          : nlohmann::ordered_json();
  j["success_steps"] = s.success_steps;
  j["steps_total"] = s.steps_total;
  j["fall_rate"] = s.fall_rate;
  j["extra_pass_rate"] = s.extra_pass_rate;
  j["wall_per_sim"] = s.wall_per_sim;
  j["sim_time_s"] = s.sim_time_s;
  j["wall_time_s"] = s.wall_time_s;
  j["seed"] = options.seed;
  j["preset"] = options.config.preset;
  j["walk_policy"] = options.walk_policy;
  j["human_scale"] = options.human_scale;
  j["config"] = options.config.ToJson();
  if (s.motion) j["motion"] = MotionMetricsJson(*s.motion);
  const nlohmann::ordered_json provenance = ProvenanceJson();
  for (const auto& [key, value] : provenance.items()) j[key] = value;
  return j;
}

core::StatusOr<EpisodeRecord> RunSuiteEpisode(const EvalOptions& options, int index) {
  const uint64_t seed = core::DeriveSeed(options.seed, static_cast<uint64_t>(index));
  const std::string who = "suite " + options.suite + ", episode " + std::to_string(index) +
                          " (seed " + std::to_string(seed) + ")";
  auto internal = [&](const absl::Status& st) {
    return absl::InternalError(who + ": " + std::string(st.message()));
  };
  core::StatusOr<EpisodeSpec> spec = MakeEpisodeSpec(options.suite, seed);
  if (!spec.ok()) return internal(spec.status());
  for (world::HumanSpec& h : spec->scene.humans) h.scale = options.human_scale;
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(spec->scene);
  if (!catalog.ok()) return internal(catalog.status());
  core::StatusOr<plan::ContactChain> chain = plan::ParseContactChainJson(spec->plan, who);
  if (!chain.ok()) return internal(chain.status());
  absl::Status st = plan::ValidateAndGround(*chain, *catalog);
  if (st.ok()) st = CheckWithinReach(*chain, *catalog, spec->scene.humans);
  if (!st.ok()) return internal(st);
  core::StatusOr<std::unique_ptr<world::SimWorld>> sim = BuildWorld(spec->scene, *catalog);
  if (!sim.ok()) return internal(sim.status());
  core::StatusOr<std::vector<std::unique_ptr<control::MpcController>>> controllers =
      MakeControllers(**sim, options.config, seed);
  if (!controllers.ok()) return internal(controllers.status());

  const bool render = options.video_every > 0 && index % options.video_every == 0;
  control::RunOptions run;
  run.record = true;  // the motion metrics read the frames (30 per second)
  // after the plan completes the episode goes on for kEvalSettleS: the final pose must hold
  run.settle_s = kEvalSettleS;
  run.fall_head_height_m = options.config.fall_head_height_m;
  control::Trajectory trajectory;
  EpisodeRecord rec;
  rec.index = index;
  rec.seed = seed;
  rec.variant = spec->variant;
  core::StatusOr<control::EpisodeResult> result =
      RunWithWalkPolicy(**sim, *chain, *controllers, options.walk_policy, run, &trajectory);
  if (!result.ok()) return result.status();
  rec.result = *result;
  rec.extra =
      EvaluateExtra(*spec, (*sim)->catalog(), (*sim)->BodyPoints((*sim)->data(), spec->agent));
  // the last step's pairs at the end of the settle time
  core::SceneCatalog now = (*sim)->catalog();
  (*sim)->SyncCatalog((*sim)->data(), &now);
  const std::vector<plan::BodyPoints> bodies = control::AllBodyPoints(**sim, (*sim)->data());
  plan::StepEval last = plan::EvaluateStep(chain->steps.back(), now, bodies, run.pair);
  JudgeEpisode(last.complete && GetCloseHumansStand(chain->steps.back(), bodies), &rec);
  for (const plan::PairEval& e : last.pairs) rec.held_pair_errors_m.push_back(e.distance_m);
  rec.motion = TrajectoryMotionMetrics(**sim, spec->agent, trajectory.time_s, trajectory.qpos);
  rec.scene = world::SceneToJson(spec->scene);
  rec.plan = spec->plan;
  if (render) {
    ReplayOptions replay;
    replay.sheet_path =
        (std::filesystem::path(options.out_dir) / ("ep" + std::to_string(index) + ".png")).string();
    absl::Status rs = RenderReplay(**sim, *chain, trajectory, replay);
    if (rs.ok()) {
      rec.sheet_path = replay.sheet_path;
    } else {
      rec.render_error = std::string(rs.message());
    }
  }
  return rec;
}

}  // namespace simhuman::eval
