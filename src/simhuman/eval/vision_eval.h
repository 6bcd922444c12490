#pragma once
/// Training and scoring the vision module (issue 16; DASH Table 2): `simhuman train --task
/// vision` and `simhuman eval --suite vision`.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "simhuman/core/status.h"
#include "simhuman/eval/vision_frames.h"
#include "simhuman/perceive/vision/vision_model.h"

namespace simhuman::eval {

/// Settings of training (one field table drives JSON reading, validation and output).
struct VisionTrainConfig {
  int width = 240, height = 180;
  double fovy_deg = 60;
  int planning_scenes = 1200;
  int planning_views = 2;
  int placing_episodes = 300;
  int placing_frames = 12;
  /// Held-object frames from anywhere on the way (the loop reads the object in the hand from
  /// the start of transport), not only over the destination as the eval's placing stage
  double placing_near_m = 1.0;
  double gaze_jitter_m = 0.05;
  double position_noise_m = 0.02;
  /// VisionFrameOptions::held_tilt_share / held_tilt_max_deg (0: the held objects as the
  /// scripted grasp leaves them)
  double held_tilt_share = 0;
  double held_tilt_max_deg = 30;
  int epochs = 25;
  int batch = 128;
  double lr = 1e-3;
  double val_fraction = 0.1;
  uint64_t seed = 1;
  int min_pixels = 12;

  /// Reads the keys present in `j` over the defaults; errors name the JSON pointer or key.
  static core::StatusOr<VisionTrainConfig> FromJson(const nlohmann::json& j);
  nlohmann::json ToJson() const;
  /// The first invalid field, with its key, value and valid range.
  core::Status Validate() const;
};

/// What training measured, for the provenance file.
struct VisionTrainReport {
  int frames = 0, samples = 0, train_samples = 0, val_samples = 0;
  double data_s = 0, train_s = 0;
  perceive::VisionLosses last_train, val;
  nlohmann::json ToJson() const;
};

/// Renders the training frames (stream 0; the eval suite uses stream 1), learns the colour
/// table and trains the network. `log` (optional) gets one line per epoch.
core::StatusOr<std::unique_ptr<perceive::VisionModel>> TrainVisionModel(
    const VisionTrainConfig& config, VisionTrainReport* report,
    const std::function<void(const std::string&)>& log = {});

/// DASH Table 2's metrics for one stage.
struct VisionStageMetrics {
  int frames = 0;
  int objects = 0;  ///< truth objects in view (>= visible_pixels pixels, none on the edge)
  int at_edge = 0;  ///< objects cut by the frame's edge (not scored: no estimate is made)
  int matched = 0;  ///< of those, with an estimate within match_m
  int shape_ok = 0, colour_ok = 0;
  double abs_err_cm[3] = {0, 0, 0};            ///< sums over matched objects (world x, y, z)
  double height_err_cm = 0, width_err_cm = 0;  ///< sums over matched objects
  double up_err_deg = 0;                       ///< sum over matched non-spheres
  double yaw_err_deg = 0;  ///< sum over matched boxes (face yaw, modulo 90 degrees)
  int yaw_count = 0;
  int up_count = 0;
  int false_positives = 0;  ///< estimates matched to no visible object
  int task_objects = 0, task_matched = 0, task_shape_ok = 0;  ///< the object being moved
  double task_abs_err_cm[3] = {0, 0, 0};
  double frame_s = 0;   ///< vision inference time, sum over frames (one thread)
  double render_s = 0;  ///< the renderer's time, sum over frames
  double fit_s = 0;     ///< planning: the silhouette fit's time (silhouette.h), sum over frames
  nlohmann::json ToJson() const;
};

struct VisionEvalOptions {
  std::string model;  ///< a model file (its camera size and field of view are used)
  int planning_scenes = 200;
  int placing_episodes = 100;
  uint64_t seed = 1;
  int visible_pixels = 30;
  double match_m = 0.10;
  /// Planning frames: the estimates fitted to their silhouettes (perceive/vision/silhouette.h), as
  /// the task planner uses them; the network alone is scored beside them as "planning-network".
  bool silhouette = true;
};

/// Scores `options.model` on held-out generated scenes (stream 1), per stage: "planning",
/// "placing", "stacking" (and "planning-network" with options.silhouette). Errors: the model file
/// (naming it), the renderer.
core::StatusOr<std::map<std::string, VisionStageMetrics>> RunVisionEval(
    const VisionEvalOptions& options,
    const std::function<void(const VisionFrame& frame,
                             const std::vector<perceive::ObjectEstimate>& estimates,
                             const VisionStageMetrics& stage_so_far)>& on_frame = {});

}  // namespace simhuman::eval
