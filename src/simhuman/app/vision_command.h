#pragma once
/// The vision module's commands (issue 16): `simhuman train --task vision` and
/// `simhuman eval --suite vision`.

#include <ostream>

#include "simhuman/app/eval_command.h"
#include "simhuman/app/train_command.h"

namespace simhuman::app {

/// The model shipped in the checkout (assets/vision/vision.pt).
std::string DefaultVisionModel();

/// NotFound naming `path` when it is not a file (checked before an output folder is made).
absl::Status CheckVisionModelFile(const std::string& path);

/// `simhuman train --task vision --out DIR [--config F] [--seed S]`: renders the training
/// frames, trains, writes DIR/vision.pt and DIR/vision.json (config, measured losses, times,
/// git revision, command). --steps, --resume and the PPO flags do not apply (refused by name).
int VisionTrainCommand(const TrainFlags& flags, std::ostream& out, std::ostream& err);

/// `simhuman eval --suite vision [--vision-model F] [--episodes N] [--out DIR]`: DASH Table 2's
/// metrics on N held-out planning scenes and N pick-and-place episodes; DIR/summary.json and
/// annotated frames DIR/frames_<stage>.png.
int VisionEvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
