#pragma once
/// `simhuman train`: PPO training runs with a progress bar, checkpoints and resume.

#include <cstdint>
#include <ostream>
#include <string>

#include "absl/status/status.h"
#include "simhuman/core/communicator.h"

namespace simhuman::app {

/// The flags of `simhuman train`.
struct TrainFlags {
  std::string task = "walk";
  std::string steps = "30M";  ///< total env steps; suffixes k, M, G
  std::string out;            ///< run folder (new run)
  std::string resume;         ///< run folder to continue
  std::string config;         ///< optional PpoConfig JSON
  uint64_t seed = 1;
  int envs = 0;     ///< 0: the config's default
  int threads = 0;  ///< 0: the config's default
  bool steps_given = false, seed_given = false, task_given = false;
  bool quiet = false;     ///< no progress bar (logs still written)
  std::string amp_clips;  ///< comma-separated clip/BVH paths (AMP on; replaces the config's)
  std::string init_from;  ///< policy file to start a new run's policy from (fine-tuning)
};

/// Parses "30M", "500k", "1e6", "123" into a count. InvalidArgument naming the text.
absl::Status ParseStepCount(const std::string& text, int64_t* out);

/// Runs or resumes training until the step target, printing a progress bar to `out`.
int TrainCommand(const TrainFlags& flags, std::ostream& out, std::ostream& err,
                 core::Communicator& comm);

/// `simhuman export-policy --checkpoint C --out F [--eval-summary S]`: writes the small policy
/// file F and its provenance F.json (without the extension): the run's config.json, the
/// checkpoint's steps and training wall time, the last log.jsonl line, the build's git
/// revision, and the `simhuman eval` summary S when given.
int ExportPolicyCommand(const std::string& checkpoint, const std::string& out_path,
                        const std::string& eval_summary, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
