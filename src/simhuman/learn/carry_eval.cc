#include "simhuman/learn/carry_eval.h"

#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/carry_env.h"

namespace simhuman::learn {
namespace {

constexpr double kMassBinEdges[] = {2.0, 5.0, 8.0, 11.0};
constexpr int kMassBins = 4;

absl::Status CheckRange(const char* what, double lo, double hi, double min_lo, double max_hi) {
  if (lo >= min_lo && hi <= max_hi && lo <= hi) return absl::OkStatus();
  return absl::InvalidArgumentError(std::string("carry suite: ") + what + " [" +
                                    std::to_string(lo) + ", " + std::to_string(hi) +
                                    "] is invalid; valid: min <= max within [" +
                                    std::to_string(min_lo) + ", " + std::to_string(max_hi) + "]");
}

int MassBin(double kg) {
  int b = 0;
  while (b + 1 < kMassBins && kg >= kMassBinEdges[b + 1]) ++b;
  return b;
}

// The policies of one run, and which of them acts in a phase.
struct Policies {
  control::LoadedPolicy* carry = nullptr;     // every phase no other policy takes
  control::LoadedPolicy* approach = nullptr;  // a walking policy for the approach
  control::LoadedPolicy* walker = nullptr;    // a walking policy for every walking phase
  control::LoadedPolicy* lift = nullptr;      // a carry-lift policy
  control::LoadedPolicy* deliver = nullptr;   // a carry-deliver policy
  bool model_squats = false;                  // no policy in the lift and the put-down

  // the acting policy in `phase` (null: none, zero action), and whether it is a walking one (fed
  // the walking part of the observation, its arm outputs unused)
  control::LoadedPolicy* Acting(control::CarryPhase phase, bool* walking) const {
    using control::CarryPhase;
    *walking = false;
    if (model_squats && (phase == CarryPhase::kLift || phase == CarryPhase::kPutDown)) {
      return nullptr;
    }
    control::LoadedPolicy* p = nullptr;
    if (phase == CarryPhase::kApproach) p = walker ? walker : approach;
    if (phase == CarryPhase::kCarry || phase == CarryPhase::kRetreat) p = walker;
    if (phase == CarryPhase::kLift) p = lift;
    if ((phase == CarryPhase::kCarry || phase == CarryPhase::kPutDown) && deliver) p = deliver;
    *walking = p && (p == walker || p == approach);
    return p ? p : carry;
  }
};

// runs one episode on env 0 of `task` with the policies' mean actions
CarryEpisode RunOne(const CarryEvalOptions& o, int index, const Policies& pols, CarryTask& task) {
  CarryEpisode ep;
  ep.index = index;
  const uint64_t seed = core::DeriveSeed(o.seed, static_cast<uint64_t>(index));
  core::Rng rng(core::DeriveSeed(seed, 1));
  ep.side_m = 0.5 * rng.Uniform(o.min_scale, o.max_scale);
  ep.mass_kg = rng.Uniform(o.min_mass_kg, o.max_mass_kg);
  ep.dist_m = rng.Uniform(o.min_dist_m, o.max_dist_m);
  const double dir = rng.Uniform(-M_PI, M_PI), yaw = rng.Uniform(-M_PI, M_PI);
  const int max_steps =
      static_cast<int>((o.base_time_s + 2.5 * ep.dist_m) / control::kWalkPolicyDt);
  task.SetEvaluation(max_steps);
  const int od = task.obs_dim(), ad = task.act_dim();
  std::vector<float> obs(od), act(ad);
  task.Reset(0, seed, obs.data());
  const Eigen::Vector2d dest = ep.dist_m * Eigen::Vector2d(std::cos(dir), std::sin(dir));
  task.SetBox(0, ep.side_m, ep.mass_kg, Eigen::Vector3d::Zero(), yaw, dest, obs.data());
  torch::NoGradGuard no_grad;
  StepInfo info;
  int steps = 0;
  for (; steps < max_steps; ++steps) {
    bool walking = false;
    control::LoadedPolicy* acting = pols.Acting(task.state(0).phase, &walking);
    if (acting) {
      torch::Tensor x = torch::from_blob(obs.data(), {1, walking ? control::kWalkObsDim : od});
      torch::Tensor a = acting->actor->forward(acting->norm.Normalize(x)).contiguous();
      std::copy(a.data_ptr<float>(), a.data_ptr<float>() + ad, act.begin());
    } else {
      std::fill(act.begin(), act.end(), 0.f);
    }
    // a walking policy never trained its arm outputs (the walk task ignores them)
    for (int j = 0; walking && j < ad; ++j) {
      if (!control::WalkActionUsed(j)) act[j] = 0.f;
    }
    task.Step(0, act.data(), obs.data(), &info);
    if (info.terminated || info.truncated) break;
  }
  ep.time_s = (steps + 1) * control::kWalkPolicyDt;
  ep.fell = task.last_failure(0) == CarryFailure::kFall;
  ep.success = info.success && !ep.fell;
  ep.end_reason = ep.success        ? "success"
                  : info.terminated ? CarryFailureName(task.last_failure(0))
                                    : "timeout";
  ep.last_phase = control::CarryPhaseName(task.state(0).phase);
  control::CarryBox box = control::ReadCarryBox(task.model(0), task.data(0), task.box_geom());
  ep.final_dist_m = (dest - box.pos.head<2>()).norm();
  return ep;
}

// the policy file `path` given as `flag`, which must hold a `task` policy of `obs_dim` inputs
// walking the carry policy's reference gait `gait` (and gripping as `grip` says, for a carry
// task); `use` says what it is for
core::StatusOr<control::LoadedPolicy> LoadPhasePolicy(const std::string& flag,
                                                      const std::string& path,
                                                      const std::string& task, int obs_dim,
                                                      const std::string& use,
                                                      const control::PolicyMeta& carry) {
  core::StatusOr<control::LoadedPolicy> p = control::LoadPolicyFile(path);
  if (!p.ok()) {
    return absl::InvalidArgumentError(flag + " '" + path +
                                      "': " + std::string(p.status().message()));
  }
  if (p->meta.task != task || p->meta.obs_dim != obs_dim ||
      p->meta.act_dim != control::kWalkActDim) {
    return absl::InvalidArgumentError(flag + " '" + path + "' holds a '" + p->meta.task +
                                      "' policy (obs " + std::to_string(p->meta.obs_dim) + "); " +
                                      use + " needs a '" + task + "' policy (obs " +
                                      std::to_string(obs_dim) + ")");
  }
  if (p->meta.variant != carry.variant) {
    return absl::InvalidArgumentError(flag + " '" + path + "' walks the '" + p->meta.variant +
                                      "' gait; the carry policy walks '" + carry.variant + "'");
  }
  if (task != "walk" && p->meta.carry_grip != carry.carry_grip) {
    return absl::InvalidArgumentError(
        flag + " '" + path + "' was trained " + (p->meta.carry_grip ? "with" : "without") +
        " gripping hands and the carry policy " + (carry.carry_grip ? "with" : "without") +
        " them (carry_grip): train both alike");
  }
  p->actor->eval();
  return p;
}

}  // namespace

core::StatusOr<CarryEvalSummary> RunCarryEval(
    const CarryEvalOptions& o, std::vector<CarryEpisode>* episodes,
    const std::function<void(const CarryEpisode&)>& on_episode) {
  if (o.episodes < 1) {
    return absl::InvalidArgumentError("carry suite: --episodes " + std::to_string(o.episodes) +
                                      " is invalid; valid: an integer >= 1");
  }
  SH_RETURN_IF_ERROR(CheckRange("distance (m)", o.min_dist_m, o.max_dist_m, 0.5, 100));
  SH_RETURN_IF_ERROR(CheckRange("mass (kg)", o.min_mass_kg, o.max_mass_kg, 0.1, 60));
  SH_RETURN_IF_ERROR(CheckRange("scale", o.min_scale, o.max_scale, 0.2, 3));
  core::StatusOr<control::LoadedPolicy> pol = control::LoadPolicyFile(o.policy);
  if (!pol.ok()) {
    return absl::InvalidArgumentError("--policy '" + o.policy +
                                      "': " + std::string(pol.status().message()));
  }
  if (pol->meta.task != "carry" || pol->meta.obs_dim != control::kCarryObsDim ||
      pol->meta.act_dim != control::kCarryActDim) {
    return absl::InvalidArgumentError(
        "--policy '" + o.policy + "' holds a '" + pol->meta.task + "' policy (obs " +
        std::to_string(pol->meta.obs_dim) + "); the carry suite needs a 'carry' policy (obs " +
        std::to_string(control::kCarryObsDim) + "): simhuman train --task carry");
  }
  pol->actor->eval();
  std::optional<control::LoadedPolicy> approach, walker, lift, deliver;
  const std::string walk_use = "walking (e.g. assets/policies/walk.pt)";
  if (!o.approach_policy.empty()) {
    SH_ASSIGN_OR_RETURN(approach, LoadPhasePolicy("--approach-policy", o.approach_policy, "walk",
                                                  control::kWalkObsDim, "the approach", pol->meta));
  }
  if (!o.walker.empty()) {
    SH_ASSIGN_OR_RETURN(walker, LoadPhasePolicy("--walker", o.walker, "walk", control::kWalkObsDim,
                                                walk_use, pol->meta));
  }
  if (o.model_squats && (!o.lift_policy.empty() || !o.deliver_policy.empty())) {
    return absl::InvalidArgumentError(
        std::string("--model-squats and ") +
        (o.lift_policy.empty() ? "--deliver-policy" : "--lift-policy") +
        " both drive a squat: give one of them (--model-squats: the lift and the put-down; "
        "--lift-policy: the lift; --deliver-policy: the carry and the put-down)");
  }
  if (!o.lift_policy.empty()) {
    SH_ASSIGN_OR_RETURN(
        lift, LoadPhasePolicy("--lift-policy", o.lift_policy, "carry-lift", control::kCarryObsDim,
                              "the lift (simhuman train --task carry-lift)", pol->meta));
  }
  if (!o.deliver_policy.empty()) {
    SH_ASSIGN_OR_RETURN(
        deliver, LoadPhasePolicy(
                     "--deliver-policy", o.deliver_policy, "carry-deliver", control::kCarryObsDim,
                     "the carry and put-down (simhuman train --task carry-deliver)", pol->meta));
  }
  Policies pols;
  pols.carry = &*pol;
  if (approach) pols.approach = &*approach;
  if (walker) pols.walker = &*walker;
  if (lift) pols.lift = &*lift;
  if (deliver) pols.deliver = &*deliver;
  pols.model_squats = o.model_squats;
  SH_ASSIGN_OR_RETURN(std::unique_ptr<CarryTask> task,
                      CarryTask::Create(1, pol->meta.variant, pol->meta.carry_grip));
  task->set_squat_support(o.model_squats);
  task->set_curriculum(1.0);
  CarryEvalSummary s;
  s.mass_bin_episodes.assign(kMassBins, 0);
  s.mass_bin_successes.assign(kMassBins, 0);
  for (int b = 0; b < kMassBins; ++b) {
    const double hi = b + 1 < kMassBins ? kMassBinEdges[b + 1] : o.max_mass_kg;
    s.mass_bin_labels.push_back(std::to_string(static_cast<int>(kMassBinEdges[b])) + "-" +
                                std::to_string(static_cast<int>(std::round(hi))) + " kg");
  }
  double precision_sum = 0;
  int successes = 0, falls = 0;
  for (int i = 0; i < o.episodes; ++i) {
    CarryEpisode ep = RunOne(o, i, pols, *task);
    successes += ep.success;
    falls += ep.fell;
    if (ep.success) precision_sum += ep.final_dist_m;
    const int b = MassBin(ep.mass_kg);
    ++s.mass_bin_episodes[b];
    s.mass_bin_successes[b] += ep.success;
    if (on_episode) on_episode(ep);
    if (episodes) episodes->push_back(ep);
  }
  s.episodes = o.episodes;
  s.success_rate = static_cast<double>(successes) / o.episodes;
  s.fall_rate = static_cast<double>(falls) / o.episodes;
  s.precision_m = successes > 0 ? precision_sum / successes : -1;
  return s;
}

nlohmann::ordered_json CarryEpisodeJson(const CarryEpisode& e) {
  return {{"episode", e.index},         {"mass_kg", e.mass_kg},
          {"side_m", e.side_m},         {"dist_m", e.dist_m},
          {"success", e.success},       {"fell", e.fell},
          {"end_reason", e.end_reason}, {"last_phase", e.last_phase},
          {"time_s", e.time_s},         {"final_dist_m", e.final_dist_m}};
}

nlohmann::ordered_json CarrySummaryJson(const CarryEvalSummary& s, const CarryEvalOptions& o) {
  nlohmann::ordered_json by_mass = nlohmann::ordered_json::array();
  for (size_t b = 0; b < s.mass_bin_labels.size(); ++b) {
    const int n = s.mass_bin_episodes[b];
    by_mass.push_back(
        {{"mass", s.mass_bin_labels[b]},
         {"episodes", n},
         {"success_rate", n > 0 ? static_cast<double>(s.mass_bin_successes[b]) / n : 0.0}});
  }
  return {{"suite", "carry"},
          {"episodes", s.episodes},
          {"success_rate", s.success_rate},
          {"precision_m", s.precision_m},
          {"fall_rate", s.fall_rate},
          {"success_by_mass", by_mass},
          {"policy", o.policy},
          {"approach_policy", o.approach_policy},
          {"walker", o.walker},
          {"lift_policy", o.lift_policy},
          {"deliver_policy", o.deliver_policy},
          {"model_squats", o.model_squats},
          {"seed", o.seed},
          {"dist_m", {o.min_dist_m, o.max_dist_m}},
          {"mass_kg", {o.min_mass_kg, o.max_mass_kg}},
          {"scale", {o.min_scale, o.max_scale}},
          {"success_rule",
           "per episode: box at rest on the floor within 0.2 m of the destination for 1 s after "
           "the put-down, no fall"}};
}

}  // namespace simhuman::learn
