#include "simhuman/app/carry_eval_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "simhuman/app/common.h"
#include "simhuman/eval/episode.h"
#include "simhuman/learn/carry_eval.h"

namespace simhuman::app {
namespace {

const char kCommand[] = "eval";

std::string Line(const learn::CarryEpisode& e) {
  char buf[200];
  std::snprintf(buf, sizeof(buf), "%4d %7.1f %6.2f %7.1f %-4s %-4s %7.1f %8.1f  %-10s %s", e.index,
                e.mass_kg, e.side_m, e.dist_m, e.success ? "yes" : "no", e.fell ? "yes" : "no",
                e.time_s, 100 * e.final_dist_m, e.last_phase.c_str(), e.end_reason.c_str());
  return buf;
}

}  // namespace

int CarryEvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err) {
  learn::CarryEvalOptions o;
  o.policy = eval::DefaultCarryPolicy(flags.policy);
  o.episodes = flags.episodes;
  o.seed = flags.seed;
  o.approach_policy = flags.approach_policy;
  o.walker = flags.walker;
  o.lift_policy = flags.lift_policy;
  o.deliver_policy = flags.deliver_policy;
  o.model_squats = flags.model_squats;
  if (o.policy.empty()) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError(
                           "--suite carry needs --policy FILE, a carry policy (simhuman train "
                           "--task carry writes RUN/policy.pt; this checkout has no "
                           "assets/policies/carry.pt)"));
  }
  const std::string dir = flags.out.empty() ? "out/eval_carry" : flags.out;
  absl::Status made = MakeOutputDir(dir);
  if (!made.ok()) return ReportError(err, kCommand, made);
  std::ofstream lines(dir + "/episodes.jsonl", std::ios::trunc);
  out << "simhuman eval: suite carry, " << o.episodes << " episodes, seed " << o.seed << ", policy "
      << o.policy << (o.approach_policy.empty() ? std::string() : ", approach " + o.approach_policy)
      << (o.walker.empty() ? std::string() : ", walker " + o.walker)
      << (o.lift_policy.empty() ? std::string() : ", lift " + o.lift_policy)
      << (o.deliver_policy.empty() ? std::string() : ", deliver " + o.deliver_policy)
      << (o.model_squats ? ", model-based squats" : "") << " -> " << dir << std::endl;
  out << "  ep mass_kg side_m dist_m ok   fell  time_s  end_cm  phase      end" << std::endl;
  core::StatusOr<learn::CarryEvalSummary> s =
      learn::RunCarryEval(o, nullptr, [&](const learn::CarryEpisode& e) {
        out << Line(e) << std::endl;
        lines << learn::CarryEpisodeJson(e).dump() << "\n" << std::flush;
      });
  if (!s.ok()) return ReportError(err, kCommand, s.status());
  nlohmann::ordered_json summary = learn::CarrySummaryJson(*s, o);
  const nlohmann::ordered_json provenance = eval::ProvenanceJson();
  for (const auto& [key, value] : provenance.items()) summary[key] = value;
  absl::Status ws = eval::WriteJsonFile(dir + "/summary.json", summary);
  if (!ws.ok()) return ReportError(err, kCommand, ws);
  char buf[200];
  std::snprintf(
      buf, sizeof(buf), "\nsummary: success %.1f%%  falls %.1f%%  precision %s",
      100 * s->success_rate, 100 * s->fall_rate,
      s->precision_m >= 0 ? (std::to_string(100 * s->precision_m) + " cm").c_str() : "n/a");
  out << buf << std::endl;
  for (size_t b = 0; b < s->mass_bin_labels.size(); ++b) {
    const int n = s->mass_bin_episodes[b];
    out << "  " << s->mass_bin_labels[b] << ": " << s->mass_bin_successes[b] << "/" << n
        << std::endl;
  }
  out << "wrote " << dir << "/summary.json and " << dir << "/episodes.jsonl" << std::endl;
  return kExitOk;
}

}  // namespace simhuman::app
