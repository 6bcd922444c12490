#include "simhuman/app/vision_command.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>

#include "absl/strings/str_format.h"
#include "simhuman/app/common.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/vision_eval.h"
#include "simhuman/perceive/vision/draw.h"
#include "simhuman/render/image_io.h"

namespace simhuman::app {

std::string DefaultVisionModel() {
  return std::string(SIMHUMAN_SOURCE_DIR) + "/assets/vision/vision.pt";
}

absl::Status CheckVisionModelFile(const std::string& path) {
  if (std::filesystem::is_regular_file(path)) return absl::OkStatus();
  return absl::NotFoundError(path +
                             ": cannot open the vision model file (make one with "
                             "`simhuman train --task vision`)");
}

int VisionTrainCommand(const TrainFlags& flags, std::ostream& out, std::ostream& err) {
  const char* cmd = "train";
  if (!flags.resume.empty() || flags.steps_given || flags.envs || flags.threads ||
      !flags.amp_clips.empty() || !flags.init_from.empty()) {
    return ReportError(err, cmd,
                       absl::InvalidArgumentError(
                           "--task vision takes --out, --config and --seed only (--steps, "
                           "--resume, --envs, --threads, --amp-clips and --init-from are PPO's)"));
  }
  if (flags.out.empty()) {
    return ReportError(err, cmd, absl::InvalidArgumentError("--out is required"));
  }
  eval::VisionTrainConfig cfg;
  if (!flags.config.empty()) {
    std::ifstream f(flags.config);
    if (!f) return ReportError(err, cmd, absl::NotFoundError(flags.config + ": cannot open"));
    nlohmann::json j = nlohmann::json::parse(f, nullptr, false);
    if (j.is_discarded()) {
      return ReportError(err, cmd, absl::InvalidArgumentError(flags.config + ": not JSON"));
    }
    auto c = eval::VisionTrainConfig::FromJson(j);
    if (!c.ok()) return ReportError(err, cmd, core::Annotate(c.status(), flags.config));
    cfg = *c;
  }
  if (flags.seed_given) cfg.seed = flags.seed;
  if (absl::Status s = MakeOutputDir(flags.out); !s.ok()) return ReportError(err, cmd, s);
  out << "simhuman train: task vision, " << cfg.planning_scenes << " planning scenes x "
      << cfg.planning_views << " views, " << cfg.placing_episodes << " placing episodes, "
      << cfg.epochs << " epochs -> " << flags.out << std::endl;
  eval::VisionTrainReport report;
  auto model = eval::TrainVisionModel(cfg, &report, [&](const std::string& line) {
    if (!flags.quiet) out << "  " << line << std::endl;
  });
  if (!model.ok()) return ReportError(err, cmd, model.status());
  const std::string path = flags.out + "/vision.pt";
  if (absl::Status s = (*model)->Save(path); !s.ok()) return ReportError(err, cmd, s);
  nlohmann::ordered_json prov;
  prov["command"] = "simhuman train --task vision --out " + flags.out +
                    (flags.config.empty() ? "" : " --config " + flags.config) + " --seed " +
                    std::to_string(cfg.seed);
  prov["config"] = cfg.ToJson();
  prov["report"] = report.ToJson();
  const nlohmann::ordered_json provenance = eval::ProvenanceJson();
  for (const auto& [k, v] : provenance.items()) prov[k] = v;
  if (absl::Status s = eval::WriteJsonFile(flags.out + "/vision.json", prov); !s.ok()) {
    return ReportError(err, cmd, s);
  }
  out << "data " << report.data_s << " s (" << report.frames << " frames, " << report.samples
      << " blobs), training " << report.train_s << " s; validation: position "
      << report.val.position_cm << " cm, height " << report.val.height_cm << " cm\nwrote " << path
      << " and " << flags.out << "/vision.json" << std::endl;
  return kExitOk;
}

int VisionEvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err) {
  const char* cmd = "eval";
  if (flags.episodes < 1) {
    return ReportError(err, cmd, absl::InvalidArgumentError("--episodes must be >= 1"));
  }
  eval::VisionEvalOptions o;
  o.model = flags.vision_model.empty() ? DefaultVisionModel() : flags.vision_model;
  o.planning_scenes = flags.episodes;
  o.placing_episodes = flags.episodes;
  o.seed = flags.seed;
  o.silhouette = !flags.no_silhouette;
  if (absl::Status s = CheckVisionModelFile(o.model); !s.ok()) return ReportError(err, cmd, s);
  const std::string dir = flags.out.empty() ? "out/eval_vision" : flags.out;
  if (absl::Status s = MakeOutputDir(dir); !s.ok()) return ReportError(err, cmd, s);
  out << "simhuman eval: suite vision, model " << o.model << ", " << o.planning_scenes
      << " planning scenes and " << o.placing_episodes << " pick-and-place episodes, seed "
      << o.seed << " -> " << dir << std::endl;
  std::map<std::string, std::vector<std::vector<uint8_t>>> sheets;
  int w = 0, h = 0;
  auto s = eval::RunVisionEval(
      o, [&](const eval::VisionFrame& f, const std::vector<perceive::ObjectEstimate>& est,
             const eval::VisionStageMetrics&) {
        std::vector<std::vector<uint8_t>>& sheet = sheets[f.stage];
        if (sheet.size() >= 8) return;
        std::vector<uint8_t> rgb = f.rgb;
        std::vector<Eigen::Vector3d> truth;
        for (const perceive::ObjectTruth& t : f.truth) {
          if (t.pixels > 0) truth.push_back(t.centre);
        }
        // planning: the outlines the fitted estimates cast, then the estimates
        if (f.stage == "planning" && o.silhouette) perceive::DrawOutlines(f.camera, est, &rgb);
        perceive::DrawEstimates(f.camera, est, truth, &rgb);
        sheet.push_back(std::move(rgb));
        w = f.camera.width;
        h = f.camera.height;
      });
  if (!s.ok()) return ReportError(err, cmd, s.status());
  nlohmann::ordered_json summary;
  summary["suite"] = "vision";
  summary["model"] = o.model;
  summary["seed"] = o.seed;
  summary["episodes"] = flags.episodes;
  for (const auto& [stage, m] : *s) {
    summary["stages"][stage] = m.ToJson();
    const nlohmann::json j = m.ToJson();
    char buf[480];
    std::snprintf(buf, sizeof(buf),
                  "%-16s frames %4d  objects %5d  detected %5.1f%%  shape %5.1f%%  colour %5.1f%%  "
                  "position MAE x/y/z %.2f / %.2f / %.2f cm  up %.1f deg  false pos %d  "
                  "vision %.2f ms/frame (render %.2f%s)",
                  stage.c_str(), m.frames, m.objects, j["detection_rate_pct"].get<double>(),
                  j["shape_accuracy_pct"].get<double>(), j["colour_accuracy_pct"].get<double>(),
                  j["position_mae_cm_xyz"][0].get<double>(),
                  j["position_mae_cm_xyz"][1].get<double>(),
                  j["position_mae_cm_xyz"][2].get<double>(), j["up_axis_error_deg"].get<double>(),
                  m.false_positives, j["vision_ms_per_frame"].get<double>(),
                  j["render_ms_per_frame"].get<double>(),
                  m.fit_s > 0 ? absl::StrFormat(", silhouette fit %.1f",
                                                j["silhouette_fit_ms_per_frame"].get<double>())
                                    .c_str()
                              : "");
    out << buf << std::endl;
    if (!sheets[stage].empty()) {
      const std::string png = dir + "/frames_" + stage + ".png";
      if (absl::Status ws = render::WriteContactSheet(png, sheets[stage], w, h, 4); !ws.ok()) {
        return ReportError(err, cmd, ws);
      }
    }
  }
  const nlohmann::ordered_json provenance = eval::ProvenanceJson();
  for (const auto& [k, v] : provenance.items()) summary[k] = v;
  if (absl::Status ws = eval::WriteJsonFile(dir + "/summary.json", summary); !ws.ok()) {
    return ReportError(err, cmd, ws);
  }
  out << "wrote " << dir << "/summary.json and " << dir << "/frames_<stage>.png" << std::endl;
  return kExitOk;
}

}  // namespace simhuman::app
