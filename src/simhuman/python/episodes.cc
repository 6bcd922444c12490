// simhuman.run() and the simhuman.Episode it returns.
#include <mujoco/mujoco.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/control/mpc/mpc_config.h"
#include "simhuman/core/body_joint.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/reachability.h"
#include "simhuman/eval/replay.h"
#include "simhuman/python/bindings.h"
#include "simhuman/render/camera.h"
#include "simhuman/render/offscreen.h"

namespace simhuman::python {
namespace {

// one episode that ran: its world stays alive for rendering and body points
struct Episode {
  std::shared_ptr<Plan> plan;
  std::unique_ptr<world::SimWorld> world;
  control::Trajectory trajectory;
  control::EpisodeResult result;
  nlohmann::ordered_json record;  // result.json's content
};

// the MPC settings: a preset, or a dict of MpcConfig keys (its "preset" or `preset`)
control::MpcConfig ResolveMpcConfig(const std::string& preset, const py::object& config) {
  if (config.is_none()) return Unwrap(control::MpcConfig::Preset(preset));
  nlohmann::json j = PyToJson(config, "config");
  if (!j.is_object()) {
    ThrowIfError(absl::InvalidArgumentError("config: expected a dict of MPC settings, got " +
                                            std::string(j.type_name())));
  }
  if (!j.contains("preset")) j["preset"] = preset;
  return Unwrap(control::MpcConfig::FromJson(j, "config"));
}

// the walking policy file: "default" is assets/policies/walk.pt when present, None none
std::string ResolveWalkPolicy(const py::object& walk_policy) {
  if (walk_policy.is_none()) return "";
  const std::string s = py::str(walk_policy);
  return eval::DefaultWalkPolicy(s == "default" ? "" : s);
}

py::dict ProgressDict(const control::ProgressEvent& e) {
  py::dict d;
  d["step"] = e.step;
  d["steps_total"] = e.steps_total;
  d["time_s"] = e.time_s;
  d["distance_m"] = e.distance_m;
  d["completed"] = e.completed;
  d["ended"] = e.ended;
  d["label"] = e.label;
  return d;
}

std::shared_ptr<Episode> Run(const std::shared_ptr<Plan>& plan, uint64_t seed,
                             const std::string& preset, const py::object& config, double settle_s,
                             const py::object& walk_policy, const py::object& progress) {
  if (!std::isfinite(settle_s) || settle_s < 0) {
    ThrowValueError("settle_s " + std::to_string(settle_s) +
                    " is invalid; valid: a finite number of seconds >= 0");
  }
  const Scene& scene = *plan->scene;
  const control::MpcConfig mpc = ResolveMpcConfig(preset, config);
  ThrowIfError(eval::CheckWithinReach(plan->chain, scene.catalog, scene.spec.humans));
  Unwrap(eval::AgentSpecs(scene.spec));
  auto ep = std::make_shared<Episode>();
  ep->plan = plan;
  ep->world = Unwrap(eval::BuildWorld(scene.spec, scene.catalog));
  auto controllers = Unwrap(eval::MakeControllers(*ep->world, mpc, seed));
  const std::string policy = ResolveWalkPolicy(walk_policy);

  control::RunOptions options;
  options.settle_s = settle_s;
  options.fall_head_height_m = mpc.fall_head_height_m;
  options.record = true;
  // an exception of the callback is kept and raised after the episode (not through the runner)
  std::unique_ptr<py::error_already_set> callback_error;
  if (!progress.is_none()) {
    options.progress = [&progress, &callback_error](const control::ProgressEvent& e) {
      py::gil_scoped_acquire gil;
      if (callback_error) return;
      try {
        progress(ProgressDict(e));
      } catch (py::error_already_set& err) {
        callback_error = std::make_unique<py::error_already_set>(std::move(err));
      }
    };
  }
  core::StatusOr<control::EpisodeResult> result = absl::UnknownError("not run");
  {
    py::gil_scoped_release release;
    result = eval::RunWithWalkPolicy(*ep->world, plan->chain, controllers, policy, options,
                                     &ep->trajectory);
  }
  if (callback_error) throw std::move(*callback_error);
  ep->result = Unwrap(std::move(result));
  // the keys of `simhuman run`'s result.json
  nlohmann::ordered_json& j = ep->record;
  j = eval::EpisodeResultJson(ep->result);
  j["seed"] = seed;
  j["preset"] = mpc.preset;
  j["scene"] = scene.spec.name;
  j["config"] = mpc.ToJson();
  j["settle_s"] = settle_s;
  j["walk_policy"] = policy;
  const nlohmann::ordered_json provenance = eval::ProvenanceJson();
  for (const auto& [key, value] : provenance.items()) j[key] = value;
  return ep;
}

// every frame's body points, [T, agents, kNumBodyJoints, 3]
py::array_t<double> BodyPoints(const Episode& ep) {
  const mjModel* m = ep.world->model();
  const int frames = static_cast<int>(ep.trajectory.qpos.size());
  const int agents = ep.world->num_agents();
  py::array_t<double> out({frames, agents, core::kNumBodyJoints, 3});
  auto w = out.mutable_unchecked<4>();
  mjData* d = mj_makeData(m);
  for (int t = 0; t < frames; ++t) {
    std::copy(ep.trajectory.qpos[t].begin(), ep.trajectory.qpos[t].end(), d->qpos);
    mj_kinematics(m, d);
    for (int a = 0; a < agents; ++a) {
      const auto points = ep.world->BodyPoints(d, a);
      for (int k = 0; k < core::kNumBodyJoints; ++k) {
        for (int c = 0; c < 3; ++c) w(t, a, k, c) = points[k][c];
      }
    }
  }
  mj_deleteData(d);
  return out;
}

py::array_t<double> BodyPoint(const Episode& ep, const std::string& name, int agent) {
  const std::vector<std::string> names = core::BodyJointNames();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) {
    ThrowIfError(absl::InvalidArgumentError("body point '" + name +
                                            "' is unknown; valid: " + core::JoinNames(names)));
  }
  if (agent < 0 || agent >= ep.world->num_agents()) {
    ThrowValueError("agent " + std::to_string(agent) + " is out of range; valid: 0.." +
                    std::to_string(ep.world->num_agents() - 1));
  }
  py::array_t<double> all = BodyPoints(ep);
  const int k = static_cast<int>(it - names.begin());
  const int frames = static_cast<int>(ep.trajectory.qpos.size());
  py::array_t<double> out({frames, 3});
  auto r = all.unchecked<4>();
  auto w = out.mutable_unchecked<2>();
  for (int t = 0; t < frames; ++t) {
    for (int c = 0; c < 3; ++c) w(t, c) = r(t, agent, k, c);
  }
  return out;
}

py::array_t<double> Qpos(const Episode& ep) {
  const int frames = static_cast<int>(ep.trajectory.qpos.size());
  const int nq = ep.world->model()->nq;
  py::array_t<double> out({frames, nq});
  for (int t = 0; t < frames; ++t) {
    std::copy(ep.trajectory.qpos[t].begin(), ep.trajectory.qpos[t].end(), out.mutable_data(t, 0));
  }
  return out;
}

void CheckImageSize(int width, int height) {
  if (width < 16 || height < 16 || width > 4096 || height > 4096) {
    ThrowValueError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is invalid; valid: 16..4096 pixels per side");
  }
}

// frames [N, H, W, 3] uint8 of the recorded frames `indices` (all when empty), from a camera
// framing the humans (side view like the videos) or `camera` (dict of render::CameraSpec)
py::array_t<uint8_t> RenderFrames(const Episode& ep, std::vector<int> indices, int width,
                                  int height, const py::object& camera) {
  CheckImageSize(width, height);
  const int frames = static_cast<int>(ep.trajectory.qpos.size());
  if (indices.empty()) {
    for (int t = 0; t < frames; ++t) indices.push_back(t);
  }
  for (int& t : indices) {
    if (t < 0) t += frames;
    if (t < 0 || t >= frames) {
      ThrowValueError("frame index out of range; valid: -" + std::to_string(frames) + ".." +
                      std::to_string(frames - 1) + " (" + std::to_string(frames) + " frames)");
    }
  }
  render::CameraSpec fixed;
  const bool follow = camera.is_none();
  if (!follow) {
    const py::dict c = camera.cast<py::dict>();
    for (const auto& [key, value] : c) {
      const std::string k = py::str(key);
      if (k == "lookat") {
        const std::vector<double> v = value.cast<std::vector<double>>();
        if (v.size() != 3) ThrowValueError("camera['lookat']: expected 3 numbers (x, y, z)");
        fixed.lookat = Eigen::Vector3d(v[0], v[1], v[2]);
      } else if (k == "distance_m") {
        fixed.distance_m = value.cast<double>();
      } else if (k == "azimuth_deg") {
        fixed.azimuth_deg = value.cast<double>();
      } else if (k == "elevation_deg") {
        fixed.elevation_deg = value.cast<double>();
      } else {
        ThrowValueError("camera: unknown key '" + k +
                        "'; valid keys are: lookat, distance_m, azimuth_deg, elevation_deg");
      }
    }
  }
  py::array_t<uint8_t> out({static_cast<int>(indices.size()), height, width, 3});
  absl::Status status;
  {
    py::gil_scoped_release release;
    const mjModel* m = ep.world->model();
    auto renderer = render::OffscreenRenderer::Create(m, width, height);
    status = renderer.status();
    mjData* d = mj_makeData(m);
    std::vector<int> bodies;
    for (int a = 0; a < ep.world->num_agents(); ++a) {
      const std::vector<int>& b = ep.world->agent(a).bodies;
      bodies.insert(bodies.end(), b.begin(), b.end());
    }
    std::vector<uint8_t> rgb;
    for (size_t n = 0; status.ok() && n < indices.size(); ++n) {
      const std::vector<double>& q = ep.trajectory.qpos[indices[n]];
      std::copy(q.begin(), q.end(), d->qpos);
      mj_kinematics(m, d);
      const render::CameraSpec cam = follow
                                         ? render::FrameBodies(m, d, bodies, 135.0, -15.0, 1.5,
                                                               static_cast<double>(width) / height)
                                         : fixed;
      status = (*renderer)->Render(d, cam, &rgb);
      if (status.ok()) {
        std::copy(rgb.begin(), rgb.end(), out.mutable_data(static_cast<int>(n), 0, 0, 0));
      }
    }
    mj_deleteData(d);
  }
  ThrowIfError(status);
  return out;
}

void RenderVideo(const Episode& ep, const std::string& video_path, const std::string& sheet_path,
                 int width, int height) {
  CheckImageSize(width, height);
  if (video_path.empty() && sheet_path.empty()) {
    ThrowValueError(
        "render_video: give video_path (an .mp4 file), sheet_path (a .png file) or "
        "both");
  }
  eval::ReplayOptions replay;
  replay.video_path = video_path;
  replay.sheet_path = sheet_path;
  replay.width = width;
  replay.height = height;
  absl::Status st;
  {
    py::gil_scoped_release release;
    st = eval::RenderReplay(*ep.world, ep.plan->chain, ep.trajectory, replay);
  }
  ThrowIfError(st);
}

// the files `simhuman run` writes (without the video)
void Save(const Episode& ep, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) ThrowIfError(absl::PermissionDeniedError("cannot create '" + dir + "': " + ec.message()));
  const std::filesystem::path out(dir);
  absl::Status st =
      eval::WriteJsonFile((out / "scene.json").string(), world::SceneToJson(ep.plan->scene->spec));
  if (st.ok()) {
    st =
        eval::WriteJsonFile((out / "plan.json").string(), plan::ContactChainToJson(ep.plan->chain));
  }
  if (st.ok()) {
    st = eval::WriteTrajectoryCsv((out / "trajectory.csv").string(), ep.world->model(),
                                  ep.trajectory);
  }
  if (st.ok()) st = eval::WriteJsonFile((out / "result.json").string(), ep.record);
  ThrowIfError(st);
}

}  // namespace

void RegisterEpisodes(py::module_& m) {
  py::class_<Episode, std::shared_ptr<Episode>>(
      m, "Episode",
      "One episode that ran (run()): its result, the recorded trajectory (numpy arrays, one row "
      "per recorded frame at `fps`) and rendering.")
      .def_property_readonly("success", [](const Episode& e) { return e.result.success; })
      .def_property_readonly(
          "result", [](const Episode& e) { return JsonToPy(e.record); },
          "The result as `simhuman run` writes it to result.json (success, steps_completed, "
          "steps_total, contact_error_m, fell, end_reason, sim/wall times, seed, config, ...).")
      .def_readonly("plan", &Episode::plan)
      .def_property_readonly("fps", [](const Episode& e) { return e.trajectory.fps; })
      .def_property_readonly(
          "time_s",
          [](const Episode& e) { return py::array_t<double>(py::cast(e.trajectory.time_s)); },
          "Time of each recorded frame, s [T].")
      .def_property_readonly(
          "step_index",
          [](const Episode& e) { return py::array_t<int>(py::cast(e.trajectory.step_index)); },
          "Plan step being worked on at each frame [T].")
      .def_property_readonly("qpos", &Qpos, "Joint positions of the whole model [T, nq].")
      .def_property_readonly(
          "qpos_names", [](const Episode& e) { return eval::QposColumnNames(e.world->model()); },
          "Names of the qpos columns (trajectory.csv's header).")
      .def_property_readonly(
          "body_points", &BodyPoints,
          "World positions (m) of the 15 standard body points of every human at every frame, "
          "[T, humans, 15, 3], in body_point_names() order.")
      .def("body_point", &BodyPoint, py::arg("name"), py::arg("agent") = 0,
           "One body point's world position (m) over time, [T, 3]; e.g. body_point('pelvis')[:, "
           "2] is the pelvis height.")
      .def_property_readonly(
          "step_completion_s", [](const Episode& e) { return e.result.step_completion_s; },
          "Time each completed step completed, s.")
      .def_property_readonly(
          "pair_errors_m", [](const Episode& e) { return e.result.pair_errors_m; },
          "Per step, the contact error (m) of each contact and not-contact pair.")
      .def("render_frames", &RenderFrames, py::arg("frames") = std::vector<int>(),
           py::arg("width") = 480, py::arg("height") = 360, py::arg("camera") = py::none(),
           "Renders recorded frames (indices; all when empty) to RGB images [N, H, W, 3] uint8. "
           "The camera frames the humans unless `camera` (lookat, distance_m, azimuth_deg, "
           "elevation_deg) is given. UnavailableError without an EGL display.")
      .def("render_video", &RenderVideo, py::arg("video_path") = "", py::arg("sheet_path") = "",
           py::arg("width") = 640, py::arg("height") = 480,
           "Writes the episode's MP4 video and/or contact-sheet PNG, as `simhuman run --video`.")
      .def("save", &Save, py::arg("out_dir"),
           "Writes result.json, trajectory.csv, scene.json and plan.json, as `simhuman run`.")
      .def("__repr__", [](const Episode& e) {
        return "<simhuman.Episode success=" + std::string(e.result.success ? "True" : "False") +
               " steps " + std::to_string(e.result.steps_completed) + "/" +
               std::to_string(e.result.steps_total) + " end '" + e.result.end_reason + "'>";
      });

  m.def("run", &Run, py::arg("plan"), py::arg("seed") = 1, py::arg("preset") = "fast",
        py::arg("config") = py::none(), py::arg("settle_s") = 1.5,
        py::arg("walk_policy") = "default", py::arg("progress") = py::none(),
        "Runs `plan` in its scene with the MPC controllers (and the walking policy for get-close "
        "steps: 'default' is assets/policies/walk.pt when present, None walks with the MPC, or a "
        "policy file). `config` is a dict of MpcConfig keys over the preset; `progress` is "
        "called with a dict per completed step. The physics runs with the GIL released.");
  m.def("body_point_names", &core::BodyJointNames,
        "Names of the 15 standard body points, in Episode.body_points order.");
}

}  // namespace simhuman::python
