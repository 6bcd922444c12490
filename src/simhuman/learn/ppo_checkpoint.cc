#include "simhuman/learn/ppo_checkpoint.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace simhuman::learn {
namespace fs = std::filesystem;

absl::Status SaveArchiveAtomic(torch::serialize::OutputArchive& ar, const std::string& path) {
  std::string tmp = path + ".tmp";
  try {
    ar.save_to(tmp);
  } catch (const c10::Error& e) {
    return absl::PermissionDeniedError(tmp + ": cannot write: " + e.what_without_backtrace());
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) return absl::PermissionDeniedError(path + ": cannot replace: " + ec.message());
  return absl::OkStatus();
}

void TrainingProgress::Write(torch::serialize::OutputArchive& ar) const {
  ar.write("iteration", c10::IValue(iteration));
  ar.write("env_steps", c10::IValue(env_steps));
  ar.write("episodes", c10::IValue(episodes));
  ar.write("wall_s", c10::IValue(wall_s));
  ar.write("best_success", c10::IValue(best_success));
}

bool TrainingProgress::Read(torch::serialize::InputArchive& ar) {
  c10::IValue it, steps, eps, wall, best;
  if (!ar.try_read("iteration", it) || !ar.try_read("env_steps", steps) ||
      !ar.try_read("episodes", eps) || !ar.try_read("wall_s", wall) ||
      !ar.try_read("best_success", best)) {
    return false;
  }
  iteration = it.toInt();
  env_steps = steps.toInt();
  episodes = eps.toInt();
  wall_s = wall.toDouble();
  best_success = best.toDouble();
  return true;
}

void WriteLearnerState(torch::serialize::OutputArchive& ar, ActorCritic& net, core::Rng& rng) {
  torch::serialize::OutputArchive c, o;
  net.critic->save(c);
  ar.write("critic", c);
  net.opt->save(o);
  ar.write("optim", o);
  std::ostringstream r;
  r << rng.engine();
  ar.write("rng", c10::IValue(r.str()));
}

absl::Status ReadLearnerState(torch::serialize::InputArchive& ar, const std::string& path,
                              ActorCritic& net, core::Rng& rng) {
  torch::serialize::InputArchive a, c, o;
  c10::IValue state;
  if (!ar.try_read("actor", a) || !ar.try_read("critic", c) || !ar.try_read("optim", o)) {
    return absl::DataLossError(path + ": actor, critic or optimizer state missing");
  }
  if (!ar.try_read("rng", state)) return absl::DataLossError(path + ": RNG state missing");
  net.actor->load(a);
  // torch's load replaces a parameter whatever its shape: compare with the built critic
  std::vector<std::vector<int64_t>> built;
  for (const auto& p : net.critic->parameters()) built.push_back(p.sizes().vec());
  net.critic->load(c);
  std::vector<torch::Tensor> loaded = net.critic->parameters();
  for (size_t k = 0; k < loaded.size(); ++k) {
    if (loaded[k].sizes().vec() != built[k]) {
      return absl::DataLossError(path +
                                 ": the value network's shape differs from its config "
                                 "(critic_hidden)");
    }
  }
  net.opt->load(o);
  std::istringstream r(state.toStringRef());
  r >> rng.engine();
  if (r.fail()) return absl::DataLossError(path + ": corrupt RNG state");
  return absl::OkStatus();
}

absl::Status CheckFiniteWeights(const ActorCritic& net, const std::string& path) {
  for (const auto& p : net.Params()) {
    if (!torch::isfinite(p).all().item<bool>()) {
      return absl::DataLossError(path + ": non-finite network weights");
    }
  }
  return absl::OkStatus();
}

void AppendJsonLine(const std::string& path, const nlohmann::json& line) {
  std::ofstream f(path, std::ios::app);
  f << line.dump() << "\n";
}

void TrimLogAfter(const std::string& path, int64_t env_steps) {
  std::ifstream in(path);
  if (!in) return;
  std::string line, kept;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_object() && j.value("env_steps", int64_t{0}) <= env_steps) kept += line + "\n";
  }
  in.close();
  std::ofstream(path + ".tmp") << kept;
  std::error_code ec;
  fs::rename(path + ".tmp", path, ec);
}

}  // namespace simhuman::learn
