#include "simhuman/eval/vision_eval.h"

#include <chrono>
#include <cmath>
#include <random>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "simhuman/core/field_table.h"
#include "simhuman/core/geometry.h"
#include "simhuman/perceive/vision/associate.h"
#include "simhuman/perceive/vision/silhouette.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::eval {

namespace {

using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

const core::FieldTable<VisionTrainConfig>& Table() {
  using F = core::Field<VisionTrainConfig>;
  using R = core::NumberRange;
  static const core::FieldTable<VisionTrainConfig> kTable(
      "vision config",
      {F("width", &VisionTrainConfig::width, "camera image width (pixels)").In(R::Closed(32, 640)),
       F("height", &VisionTrainConfig::height, "camera image height (pixels)")
           .In(R::Closed(24, 480)),
       F("fovy_deg", &VisionTrainConfig::fovy_deg, "vertical field of view (degrees)")
           .In(R::Closed(20, 120)),
       F("planning_scenes", &VisionTrainConfig::planning_scenes,
         "generated scenes at task planning")
           .In(R::Closed(1, 100000)),
       F("planning_views", &VisionTrainConfig::planning_views, "frames per planning scene")
           .In(R::Closed(1, 16)),
       F("placing_episodes", &VisionTrainConfig::placing_episodes,
         "pick-and-place episodes sampled while placing/stacking")
           .In(R::Closed(0, 100000)),
       F("placing_frames", &VisionTrainConfig::placing_frames, "frames per placing episode")
           .In(R::Closed(1, 200)),
       F("placing_near_m", &VisionTrainConfig::placing_near_m,
         "placing frames while the held object is within this of its destination (m)")
           .In(R::Closed(0.01, 2.0)),
       F("gaze_jitter_m", &VisionTrainConfig::gaze_jitter_m, "gaze point jitter (m)")
           .In(R::Closed(0, 0.3)),
       F("position_noise_m", &VisionTrainConfig::position_noise_m,
         "placing gaze aimed at the destination moved by up to this (m)")
           .In(R::Closed(0, 0.2)),
       F("held_tilt_share", &VisionTrainConfig::held_tilt_share,
         "share of placing frames with the held object tilted in the hand")
           .In(R::Closed(0, 1)),
       F("held_tilt_max_deg", &VisionTrainConfig::held_tilt_max_deg, "largest such tilt (degrees)")
           .In(R::Closed(0, 90)),
       F("epochs", &VisionTrainConfig::epochs, "passes over the samples").In(R::Closed(1, 1000)),
       F("batch", &VisionTrainConfig::batch, "minibatch size").In(R::Closed(1, 65536)),
       F("lr", &VisionTrainConfig::lr, "Adam learning rate").In(R::AboveUpTo(0, 1)),
       F("val_fraction", &VisionTrainConfig::val_fraction, "frames held out for validation")
           .In(R::Closed(0, 0.5)),
       F("seed", &VisionTrainConfig::seed, "scenes, initialisation and shuffling"),
       F("min_pixels", &VisionTrainConfig::min_pixels, "smallest blob taken as an object")
           .In(R::Closed(1, 10000))});
  return kTable;
}

}  // namespace

core::StatusOr<VisionTrainConfig> VisionTrainConfig::FromJson(const nlohmann::json& j) {
  VisionTrainConfig c;
  SH_RETURN_IF_ERROR(Table().Read(j, "", &c));
  SH_RETURN_IF_ERROR(c.Validate());
  return c;
}

nlohmann::json VisionTrainConfig::ToJson() const { return Table().ToJson(*this); }

core::Status VisionTrainConfig::Validate() const { return Table().Validate(*this); }

nlohmann::json VisionTrainReport::ToJson() const {
  auto losses = [](const perceive::VisionLosses& l) {
    return nlohmann::json{
        {"total", l.total},         {"shape_ce", l.shape},    {"position_cm", l.position_cm},
        {"height_cm", l.height_cm}, {"width_cm", l.width_cm}, {"up", l.up},
        {"box_yaw_deg", l.yaw_deg}};
  };
  return {{"frames", frames},
          {"samples", samples},
          {"train_samples", train_samples},
          {"val_samples", val_samples},
          {"data_s", data_s},
          {"train_s", train_s},
          {"last_train", losses(last_train)},
          {"val", losses(val)}};
}

core::StatusOr<std::unique_ptr<perceive::VisionModel>> TrainVisionModel(
    const VisionTrainConfig& c, VisionTrainReport* report,
    const std::function<void(const std::string&)>& log) {
  SH_RETURN_IF_ERROR(c.Validate());
  std::unique_ptr<perceive::VisionModel> model = perceive::VisionModel::Create(c.seed);
  model->min_pixels = c.min_pixels;
  model->width = c.width;
  model->height = c.height;
  model->fovy_deg = c.fovy_deg;
  VisionFrameOptions fo;
  fo.width = c.width;
  fo.height = c.height;
  fo.fovy_deg = c.fovy_deg;
  fo.planning_scenes = c.planning_scenes;
  fo.planning_views = c.planning_views;
  fo.placing_episodes = c.placing_episodes;
  fo.placing_frames = c.placing_frames;
  fo.placing_near_m = c.placing_near_m;
  fo.gaze_jitter_m = c.gaze_jitter_m;
  fo.position_noise_m = c.position_noise_m;
  fo.held_tilt_share = c.held_tilt_share;
  fo.held_tilt_max_deg = c.held_tilt_max_deg;
  fo.seed = c.seed;
  fo.stream = 0;
  // pass 1 keeps the frames (small: 160x120) and learns the colour table from all of them
  const auto t0 = Clock::now();
  std::vector<VisionFrame> frames;
  SH_RETURN_IF_ERROR(CollectVisionFrames(fo, [&](VisionFrame& f) {
    perceive::AddColourPixels(f.rgb, f.body_ids, f.truth, &model->colours());
    frames.push_back(std::move(f));
    if (log && frames.size() % 500 == 0) log(absl::StrCat("rendered ", frames.size(), " frames"));
  }));
  model->colours().Finish();
  std::vector<perceive::BlobSample> train, val;
  std::mt19937_64 rng(c.seed);
  std::uniform_real_distribution<double> uni(0, 1);
  for (VisionFrame& f : frames) {
    const std::vector<perceive::Blob> blobs =
        perceive::FindBlobs(f.rgb, f.camera.width, f.camera.height, model->colours(), c.min_pixels);
    std::vector<perceive::BlobSample> s =
        perceive::LabelledSamples(f.rgb, f.body_ids, f.camera, f.truth, blobs);
    std::vector<perceive::BlobSample>& to = uni(rng) < c.val_fraction ? val : train;
    for (perceive::BlobSample& x : s) to.push_back(std::move(x));
  }
  report->frames = static_cast<int>(frames.size());
  frames.clear();
  report->train_samples = static_cast<int>(train.size());
  report->val_samples = static_cast<int>(val.size());
  report->samples = report->train_samples + report->val_samples;
  report->data_s = Since(t0);
  if (train.empty()) return absl::InternalError("vision training found no blobs in its frames");
  const auto t1 = Clock::now();
  for (int e = 0; e < c.epochs; ++e) {
    // cosine decay of the learning rate to a tenth
    const double lr = c.lr * (0.55 + 0.45 * std::cos(M_PI * e / std::max(1, c.epochs - 1)));
    report->last_train = model->TrainEpoch(train, c.batch, lr, c.seed + e);
    if (log) {
      std::ostringstream line;
      line << "epoch " << e + 1 << "/" << c.epochs << ": loss " << report->last_train.total
           << ", shape " << report->last_train.shape << ", position "
           << report->last_train.position_cm << " cm, height " << report->last_train.height_cm
           << " cm, width " << report->last_train.width_cm << " cm, box yaw "
           << report->last_train.yaw_deg << " deg";
      if (!val.empty() && (e % 5 == 4 || e + 1 == c.epochs)) {
        report->val = model->Evaluate(val);
        line << " | val: shape " << report->val.shape << ", position " << report->val.position_cm
             << " cm, height " << report->val.height_cm << " cm, box yaw " << report->val.yaw_deg
             << " deg";
      }
      log(line.str());
    }
  }
  if (!val.empty()) report->val = model->Evaluate(val);
  report->train_s = Since(t1);
  return model;
}

nlohmann::json VisionStageMetrics::ToJson() const {
  auto pct = [](int a, int b) { return b > 0 ? 100.0 * a / b : 0.0; };
  auto mae = [&](const double* s, int n) {
    return nlohmann::json::array({n ? s[0] / n : 0.0, n ? s[1] / n : 0.0, n ? s[2] / n : 0.0});
  };
  return {{"frames", frames},
          {"objects_in_view", objects},
          {"detected", matched},
          {"detection_rate_pct", pct(matched, objects)},
          {"shape_accuracy_pct", pct(shape_ok, matched)},
          {"colour_accuracy_pct", pct(colour_ok, matched)},
          {"position_mae_cm_xyz", mae(abs_err_cm, matched)},
          {"up_axis_error_deg", up_count ? up_err_deg / up_count : 0.0},
          {"box_yaw_error_deg", yaw_count ? yaw_err_deg / yaw_count : 0.0},
          {"height_mae_cm", matched ? height_err_cm / matched : 0.0},
          {"width_mae_cm", matched ? width_err_cm / matched : 0.0},
          {"false_positives", false_positives},
          {"cut_by_frame_edge", at_edge},
          {"moved_object",
           {{"in_view", task_objects},
            {"detected", task_matched},
            {"shape_accuracy_pct", pct(task_shape_ok, task_matched)},
            {"position_mae_cm_xyz", mae(task_abs_err_cm, task_matched)}}},
          {"vision_ms_per_frame", frames ? 1000 * frame_s / frames : 0.0},
          {"silhouette_fit_ms_per_frame", frames ? 1000 * fit_s / frames : 0.0},
          {"render_ms_per_frame", frames ? 1000 * render_s / frames : 0.0}};
}

namespace {

// scores one frame's estimates against its truth: each object in the frame is matched to at most
// one estimate by position alone (Hungarian, within match_m), so shape and colour are scored
// fairly. Objects with at least visible_pixels pixels, none on the frame's edge, are scored; an
// estimate matching no object in the frame at all is a false positive.
void ScoreFrame(const VisionFrame& f, const std::vector<perceive::ObjectEstimate>& est,
                const VisionEvalOptions& o, VisionStageMetrics* m) {
  std::vector<int> in_frame;
  for (size_t i = 0; i < f.truth.size(); ++i) {
    if (f.truth[i].pixels > 0) in_frame.push_back(static_cast<int>(i));
  }
  ++m->frames;
  std::vector<std::vector<double>> cost(in_frame.size(), std::vector<double>(est.size()));
  for (size_t i = 0; i < in_frame.size(); ++i) {
    for (size_t j = 0; j < est.size(); ++j) {
      cost[i][j] = (f.truth[in_frame[i]].centre - est[j].centre).norm();
    }
  }
  const std::vector<int> a = perceive::HungarianAssign(cost);
  std::vector<char> used(est.size(), 0);
  for (size_t i = 0; i < in_frame.size(); ++i) {
    const bool hit = !a.empty() && a[i] >= 0 && cost[i][a[i]] <= o.match_m;
    if (hit) used[a[i]] = 1;
    const perceive::ObjectTruth& t = f.truth[in_frame[i]];
    if (t.at_edge) ++m->at_edge;
    if (t.pixels < o.visible_pixels || t.at_edge) continue;
    const bool task = in_frame[i] == f.task_object;
    ++m->objects;
    m->task_objects += task;
    if (!hit) continue;
    const perceive::ObjectEstimate& e = est[a[i]];
    ++m->matched;
    m->shape_ok += e.shape == t.shape;
    m->colour_ok += e.colour == t.colour;
    for (int k = 0; k < 3; ++k) m->abs_err_cm[k] += 100 * std::abs(e.centre[k] - t.centre[k]);
    m->height_err_cm += 100 * std::abs(e.height_m - t.height_m);
    m->width_err_cm += 100 * std::abs(e.width_m - t.width_m);
    if (task) {
      ++m->task_matched;
      m->task_shape_ok += e.shape == t.shape;
      for (int k = 0; k < 3; ++k) {
        m->task_abs_err_cm[k] += 100 * std::abs(e.centre[k] - t.centre[k]);
      }
    }
    if (t.shape == 0) {
      m->yaw_err_deg += std::abs(std::remainder(e.yaw_rad - t.yaw_rad, M_PI / 2)) * 180 / M_PI;
      ++m->yaw_count;
    }
    if (t.shape != 2) {
      m->up_err_deg += core::AngleFromCos(e.up.dot(t.up)) * 180 / M_PI;
      ++m->up_count;
    }
  }
  for (char u : used) m->false_positives += !u;
}

}  // namespace

core::StatusOr<std::map<std::string, VisionStageMetrics>> RunVisionEval(
    const VisionEvalOptions& o,
    const std::function<void(const VisionFrame&, const std::vector<perceive::ObjectEstimate>&,
                             const VisionStageMetrics&)>& on_frame) {
  SH_ASSIGN_OR_RETURN(std::unique_ptr<perceive::VisionModel> model,
                      perceive::VisionModel::Load(o.model));
  perceive::VisionModel::SetThreads(1);
  VisionFrameOptions fo;
  fo.planning_scenes = o.planning_scenes;
  fo.placing_episodes = o.placing_episodes;
  fo.seed = o.seed;
  fo.stream = 1;
  fo.gaze_jitter_m = 0.0;
  fo.width = model->width;
  fo.height = model->height;
  fo.fovy_deg = model->fovy_deg;
  std::map<std::string, VisionStageMetrics> out;
  SH_RETURN_IF_ERROR(CollectVisionFrames(fo, [&](VisionFrame& f) {
    const auto t0 = Clock::now();
    std::vector<perceive::ObjectEstimate> est = model->Estimate(f.rgb, f.camera);
    const double infer_s = Since(t0);
    if (o.silhouette && f.stage == "planning") {
      // the network alone, scored beside the fit the task planner uses
      VisionStageMetrics& net = out["planning-network"];
      net.frame_s += infer_s;
      net.render_s += f.render_s;
      ScoreFrame(f, est, o, &net);
      const auto t1 = Clock::now();
      perceive::SilhouetteOptions fit;
      fit.table_z = world::TableToWorld(Eigen::Vector3d::Zero()).z();  // the generator's table
      perceive::FitRestingSilhouettes(f.rgb, f.camera, model->colours(), fit, &est);
      out[f.stage].fit_s += Since(t1);
    }
    VisionStageMetrics& m = out[f.stage];
    m.frame_s += infer_s;
    m.render_s += f.render_s;
    ScoreFrame(f, est, o, &m);
    if (on_frame) on_frame(f, est, m);
  }));
  return out;
}

}  // namespace simhuman::eval
