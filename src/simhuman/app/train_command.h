#pragma once
/// `simhuman train`: PPO training runs with a progress bar, checkpoints and resume.

#include <cstdint>
#include <ostream>
#include <string>

#include "absl/status/status.h"

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
  bool steps_given = false, seed_given = false;
  bool quiet = false;  ///< no progress bar (logs still written)
};

/// Parses "30M", "500k", "1e6", "123" into a count. InvalidArgument naming the text.
absl::Status ParseStepCount(const std::string& text, int64_t* out);

/// Runs or resumes training until the step target, printing a progress bar to `out`.
int TrainCommand(const TrainFlags& flags, std::ostream& out, std::ostream& err);

/// `simhuman export-policy --checkpoint C --out F`: writes the small policy file.
int ExportPolicyCommand(const std::string& checkpoint, const std::string& out_path,
                        std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
