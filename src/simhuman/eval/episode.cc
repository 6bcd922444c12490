#include "simhuman/eval/episode.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "simhuman/control/policy/carry_controller.h"
#include "simhuman/control/policy/policy_controller.h"
#include "simhuman/core/json_io.h"
#include "simhuman/core/rng.h"
#include "simhuman/core/version.h"
#include "simhuman/world/embodiment.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::eval {

uint64_t ControllerSeed(uint64_t run_seed, int agent) {
  return core::DeriveSeed(run_seed, kControllerStream, static_cast<uint64_t>(agent));
}

core::StatusOr<std::vector<world::AgentSpec>> AgentSpecs(const world::SceneSpec& spec) {
  std::vector<world::AgentSpec> out;
  core::SceneCatalog catalog;
  bool seated = false;
  for (const world::HumanSpec& h : spec.humans) seated |= h.posture != "stand";
  if (seated) {
    SH_ASSIGN_OR_RETURN(catalog, world::BuildCatalog(spec));
  }
  for (size_t i = 0; i < spec.humans.size(); ++i) {
    core::StatusOr<world::AgentSpec> p =
        world::AgentFromHuman(spec.humans[i], static_cast<int>(i), catalog);
    if (!p.ok()) return core::Annotate(p.status(), "scene '" + spec.name + "'");
    out.push_back(*p);
  }
  return out;
}

core::StatusOr<std::unique_ptr<world::SimWorld>> BuildWorld(const world::SceneSpec& spec,
                                                            const core::SceneCatalog& catalog) {
  SH_ASSIGN_OR_RETURN(std::vector<world::AgentSpec> placements, AgentSpecs(spec));
  if (placements.empty()) {
    return absl::InvalidArgumentError("scene '" + spec.name + "' has no humans");
  }
  // a dexterous hand gets the tabletop physics (240 Hz, elliptic friction cones)
  bool dexterous = false;
  for (const world::AgentSpec& a : placements) {
    core::StatusOr<const world::Embodiment*> kind = world::FindEmbodiment(a.kind);
    dexterous |= kind.ok() && ((*kind)->right_hand || (*kind)->left_hand);
  }
  core::StatusOr<std::unique_ptr<world::SimWorld>> w = world::SimWorld::Create(
      catalog, placements, dexterous ? world::DexterousModelOptions() : world::ModelOptions());
  if (!w.ok()) return core::Annotate(w.status(), "scene '" + spec.name + "'");
  return w;
}

core::StatusOr<std::vector<std::unique_ptr<control::MpcController>>> MakeControllers(
    const world::SimWorld& world, const control::MpcConfig& config, uint64_t run_seed) {
  std::vector<std::unique_ptr<control::MpcController>> out;
  for (int a = 0; a < world.num_agents(); ++a) {
    SH_ASSIGN_OR_RETURN(
        std::unique_ptr<control::MpcController> c,
        control::MpcController::Create(&world, a, config, ControllerSeed(run_seed, a)));
    out.push_back(std::move(c));
  }
  return out;
}

control::EpisodeResult RunWithControllers(
    world::SimWorld& world, const plan::ContactChain& chain,
    const std::vector<std::unique_ptr<control::MpcController>>& controllers,
    const control::RunOptions& options, control::Trajectory* trajectory) {
  std::vector<control::Controller*> raw;
  for (const auto& c : controllers) raw.push_back(c.get());
  return control::RunEpisode(world, chain, raw, options, trajectory);
}

core::StatusOr<control::EpisodeResult> RunWithWalkPolicy(
    world::SimWorld& world, const plan::ContactChain& chain,
    const std::vector<std::unique_ptr<control::MpcController>>& controllers,
    const std::string& walk_policy, const control::RunOptions& options,
    control::Trajectory* trajectory, const std::string& carry_policy) {
  int first_carry = -1;
  for (size_t s = 0; s < chain.steps.size() && first_carry < 0; ++s) {
    if (chain.steps[s].carry) first_carry = static_cast<int>(s);
  }
  if (first_carry >= 0 && carry_policy.empty()) {
    return absl::FailedPreconditionError(
        "plan step " + std::to_string(first_carry + 1) + " carries '" +
        chain.steps[first_carry].carry->object +
        "': that needs a carry policy (--carry-policy FILE; simhuman train --task carry writes "
        "one; the default is assets/policies/carry.pt, which this checkout does not have)");
  }
  if (walk_policy.empty() && first_carry < 0) {
    return RunWithControllers(world, chain, controllers, options, trajectory);
  }
  std::vector<std::unique_ptr<control::WalkPolicyController>> walkers;
  std::vector<std::unique_ptr<control::WalkThenContactController>> combined;
  std::vector<std::unique_ptr<control::CarryPolicyController>> carriers;
  std::vector<control::Controller*> raw;
  for (int a = 0; a < world.num_agents(); ++a) {
    control::Controller* c = controllers[a].get();
    if (!walk_policy.empty()) {
      auto w = control::WalkPolicyController::Load(walk_policy, &world, a);
      if (!w.ok()) return core::Annotate(w.status(), "--policy");
      walkers.push_back(*std::move(w));
      combined.push_back(
          std::make_unique<control::WalkThenContactController>(walkers.back().get(), c));
      c = combined.back().get();
    }
    if (first_carry >= 0) {
      auto k = control::CarryPolicyController::Load(carry_policy, &world, a, c);
      if (!k.ok()) return core::Annotate(k.status(), "--carry-policy");
      carriers.push_back(*std::move(k));
      c = carriers.back().get();
    }
    raw.push_back(c);
  }
  control::RunOptions run = options;
  if (first_carry >= 0) {
    run.tracker.budget_s_per_step = std::max(run.tracker.budget_s_per_step, kCarryStepBudgetS);
  }
  return control::RunEpisode(world, chain, raw, run, trajectory);
}

std::string DefaultCarryPolicy(const std::string& flag) {
  if (!flag.empty()) return flag;
  std::string asset = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/policies/carry.pt";
  std::error_code ec;
  return std::filesystem::exists(asset, ec) ? asset : "";
}

std::string DefaultWalkPolicy(const std::string& flag) {
  if (!flag.empty()) return flag;
  std::string asset = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/policies/walk.pt";
  std::error_code ec;
  return std::filesystem::exists(asset, ec) ? asset : "";
}

std::string StepText(const plan::ContactStep& step) {
  if (!step.label.empty()) return step.label;
  std::string out;
  for (const plan::ContactPair& p : step.pairs) {
    std::string s;
    if (p.IsGetClose()) {
      s = "get close to " + p.object + " (" + std::string(plan::DirectionName(p.direction)) + ")";
    } else if (p.type == plan::ContactType::kNotCare) {
      continue;
    } else if (p.IsObjectPair()) {
      s = *p.subject_object + " " + p.subject_part + " on " + p.object + " " + p.part;
    } else {
      std::string joint = p.HasJoint() ? p.JointName() : "?";
      std::string target = p.part_joint ? p.part : p.object + " " + p.part;
      s = joint + (p.type == plan::ContactType::kContact ? " on " : " off ") + target;
    }
    if (!out.empty()) out += ", ";
    out += s;
  }
  return out.empty() ? "(no requirement)" : out;
}

nlohmann::ordered_json EpisodeResultJson(const control::EpisodeResult& r) {
  nlohmann::ordered_json j;
  j["success"] = r.success;
  j["steps_completed"] = r.steps_completed;
  j["steps_total"] = r.steps_total;
  j["contact_error_m"] =
      r.contact_error_m >= 0 ? nlohmann::ordered_json(r.contact_error_m) : nlohmann::ordered_json();
  j["contact_error_joint_centre_m"] = r.contact_error_joint_centre_m >= 0
                                          ? nlohmann::ordered_json(r.contact_error_joint_centre_m)
                                          : nlohmann::ordered_json();
  j["success_unihsi_points"] = r.success_unihsi_points;
  j["fell"] = r.fell;
  j["end_reason"] = r.end_reason;
  j["sim_time_s"] = r.sim_time_s;
  j["wall_time_s"] = r.wall_time_s;
  j["wall_per_sim"] = r.sim_time_s > 0 ? nlohmann::ordered_json(r.wall_time_s / r.sim_time_s)
                                       : nlohmann::ordered_json();
  j["step_completion_s"] = r.step_completion_s;
  j["pair_errors_m"] = r.pair_errors_m;
  return j;
}

nlohmann::ordered_json ProvenanceJson() {
  return nlohmann::ordered_json{{"git_revision", std::string(core::GitRevision())},
                                {"mujoco_version", mj_versionString()}};
}

std::vector<std::string> QposColumnNames(const mjModel* m) {
  std::vector<std::string> out(m->nq);
  for (int j = 0; j < m->njnt; ++j) {
    const char* raw = mj_id2name(m, mjOBJ_JOINT, j);
    std::string name = raw && raw[0] ? raw : "joint" + std::to_string(j);
    int adr = m->jnt_qposadr[j];
    int n = 1;
    if (m->jnt_type[j] == mjJNT_FREE) n = 7;
    if (m->jnt_type[j] == mjJNT_BALL) n = 4;
    for (int k = 0; k < n; ++k) {
      out[adr + k] = n == 1 ? name : name + "[" + std::to_string(k) + "]";
    }
  }
  return out;
}

absl::Status WriteTrajectoryCsv(const std::string& path, const mjModel* m,
                                const control::Trajectory& trajectory) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) {
    return absl::PermissionDeniedError("cannot write trajectory '" + path +
                                       "': " + std::strerror(errno));
  }
  out << "time_s,step";
  for (const std::string& c : QposColumnNames(m)) out << ',' << c;
  out << '\n';
  char buf[64];
  for (size_t f = 0; f < trajectory.time_s.size(); ++f) {
    std::snprintf(buf, sizeof(buf), "%.4f", trajectory.time_s[f]);
    out << buf << ',' << (f < trajectory.step_index.size() ? trajectory.step_index[f] : 0);
    for (double q : trajectory.qpos[f]) {
      std::snprintf(buf, sizeof(buf), "%.7g", q);
      out << ',' << buf;
    }
    out << '\n';
  }
  out.flush();
  if (!out) return absl::DataLossError("error writing trajectory '" + path + "'");
  return absl::OkStatus();
}

absl::Status WriteJsonFile(const std::string& path, const nlohmann::ordered_json& j) {
  return core::WriteFileAtomic(
      path, j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
}

}  // namespace simhuman::eval
