// The cores of the `simhuman` subcommands that write files (eval, train, export-policy, clip),
// and the command line itself, callable from Python. Output goes to Python's sys.stdout; a
// failure raises the exception of its exit code with the command's error message.
#include <pybind11/stl.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "simhuman/app/cli.h"
#include "simhuman/app/clip_command.h"
#include "simhuman/app/common.h"
#include "simhuman/app/eval_command.h"
#include "simhuman/app/train_command.h"
#include "simhuman/core/communicator.h"
#include "simhuman/core/json_io.h"
#include "simhuman/python/bindings.h"

namespace simhuman::python {
namespace {

// a streambuf writing whole lines to a Python file object (sys.stdout), taking the GIL per
// write, so commands can print while the GIL is released
class PythonLineBuf : public std::streambuf {
 public:
  explicit PythonLineBuf(const char* stream) : stream_(stream) {}
  ~PythonLineBuf() override { sync(); }

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return 0;
    pending_.push_back(static_cast<char>(c));
    if (c == '\n' || c == '\r') sync();
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    pending_.append(s, static_cast<size_t>(n));
    if (pending_.find_first_of("\r\n") != std::string::npos) sync();
    return n;
  }
  int sync() override {
    if (pending_.empty()) return 0;
    py::gil_scoped_acquire gil;
    py::object file = py::module_::import("sys").attr(stream_);
    file.attr("write")(py::bytes(pending_).attr("decode")("utf-8", "replace"));
    file.attr("flush")();
    pending_.clear();
    return 0;
  }

 private:
  const char* stream_;
  std::string pending_;
};

// runs `command(out, err)` with the GIL released, printing `out` to sys.stdout when `verbose`;
// a non-zero exit code raises the exception for it with err's text
void RunCommand(const std::function<int(std::ostream&, std::ostream&)>& command, bool verbose) {
  std::ostringstream err, quiet;
  int code = 0;
  {
    py::gil_scoped_release release;
    PythonLineBuf buf("stdout");
    std::ostream out(&buf);
    code = command(verbose ? out : static_cast<std::ostream&>(quiet), err);
  }
  if (code == app::kExitOk) return;
  std::string message = err.str();
  while (!message.empty() && message.back() == '\n') message.pop_back();
  if (message.empty()) message = "the command failed with exit code " + std::to_string(code);
  ThrowIfError(code == app::kExitBadInput ? absl::InvalidArgumentError(message)
                                          : absl::InternalError(message));
}

// a JSON file, or JSON lines, as Python data (None when the file does not exist)
py::object ReadJson(const std::filesystem::path& path, bool lines) {
  if (!std::filesystem::exists(path)) return py::none();
  std::string text = Unwrap(core::ReadFile(path.string()));
  if (!lines) return JsonToPy(Unwrap(core::ParseJson(text, path.string())));
  py::list out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty()) out.append(JsonToPy(Unwrap(core::ParseJson(line, path.string()))));
  }
  return out;
}

py::dict Eval(const app::EvalFlags& flags, bool verbose) {
  RunCommand(
      [&](std::ostream& out, std::ostream& err) {
        core::SerialCommunicator one;  // Python runs one process
        return app::EvalCommand(flags, out, err, one);
      },
      verbose);
  const std::filesystem::path dir(flags.out.empty() ? "out/eval_" + flags.suite : flags.out);
  py::dict r;
  r["out_dir"] = dir.string();
  r["summary"] = ReadJson(dir / "summary.json", false);
  r["episodes"] = ReadJson(dir / "episodes.jsonl", true);
  return r;
}

void BindEval(py::module_& m) {
  m.def(
      "eval",
      [](const std::string& suite, int episodes, uint64_t seed, const std::string& out_dir,
         const std::string& preset, const std::string& config, int video_every,
         const std::string& policy, const std::string& planner, const std::string& corpus,
         const std::string& physics_solver, bool video, bool verbose) {
        app::EvalFlags f;
        f.suite = suite;
        f.episodes = episodes;
        f.seed = seed;
        f.out = out_dir;
        f.preset = preset;
        f.preset_given = true;
        f.config = config;
        f.video_every = video_every;
        f.policy = policy;
        f.planner = planner;
        f.corpus = corpus;
        f.physics_solver = physics_solver;
        f.video = video;
        return Eval(f, verbose);
      },
      py::arg("suite"), py::arg("episodes") = 10, py::arg("seed") = 1, py::arg("out_dir") = "",
      py::arg("preset") = "fast", py::arg("config") = "", py::arg("video_every") = 0,
      py::arg("policy") = "", py::arg("planner") = "offline", py::arg("corpus") = "",
      py::arg("physics_solver") = "newton", py::arg("video") = false, py::arg("verbose") = true,
      "`simhuman eval`: runs a benchmark suite (suite_names()) and returns {'out_dir', "
      "'summary' (summary.json), 'episodes' (episodes.jsonl lines)}. The table rows are printed "
      "when `verbose`. BadInputError for bad arguments (the CLI's messages, naming the flag).");
}

void BindTrain(py::module_& m) {
  m.def(
      "train",
      [](const std::string& task, const std::string& steps, const std::string& out,
         const std::string& resume, const std::string& config, const py::object& seed, int envs,
         int threads, const std::string& init_from, const std::string& amp_clips, bool quiet) {
        app::TrainFlags f;
        f.task = task;
        f.steps = steps;
        f.steps_given = true;
        f.out = out;
        f.resume = resume;
        f.config = config;
        f.seed_given = !seed.is_none();
        if (f.seed_given) f.seed = seed.cast<uint64_t>();
        f.envs = envs;
        f.threads = threads;
        f.init_from = init_from;
        f.amp_clips = amp_clips;
        f.quiet = quiet;
        RunCommand(
            [&](std::ostream& o, std::ostream& e) {
              core::SerialCommunicator one;
              return app::TrainCommand(f, o, e, one);
            },
            true);
        const std::filesystem::path dir(resume.empty() ? out : resume);
        py::dict r;
        r["run_dir"] = dir.string();
        r["log"] = dir.empty() ? py::none() : ReadJson(dir / "log.jsonl", true);
        return r;
      },
      py::arg("task") = "walk", py::arg("steps") = "30M", py::arg("out") = "",
      py::arg("resume") = "", py::arg("config") = "", py::arg("seed") = py::none(),
      py::arg("envs") = 0, py::arg("threads") = 0, py::arg("init_from") = "",
      py::arg("amp_clips") = "", py::arg("quiet") = false,
      "`simhuman train`: PPO in C++ (resumable; Ctrl-C stops at a checkpoint). Returns "
      "{'run_dir', 'log' (log.jsonl lines)}.");
  m.def(
      "export_policy",
      [](const std::string& checkpoint, const std::string& out, const std::string& eval_summary) {
        RunCommand(
            [&](std::ostream& o, std::ostream& e) {
              return app::ExportPolicyCommand(checkpoint, out, eval_summary, o, e);
            },
            true);
      },
      py::arg("checkpoint"), py::arg("out"), py::arg("eval_summary") = "",
      "`simhuman export-policy`: the small policy file of a checkpoint, with provenance.");
}

void BindClip(py::module_& m) {
  m.def(
      "clip_convert",
      [](const std::string& bvh, const std::string& out, double fps) {
        app::ClipFlags f;
        f.bvh = bvh;
        f.out = out;
        f.fps = fps;
        RunCommand(
            [&](std::ostream& o, std::ostream& e) { return app::ClipConvertCommand(f, o, e); },
            true);
      },
      py::arg("bvh"), py::arg("out"), py::arg("fps") = 0.0,
      "`simhuman clip convert`: retargets a BVH file to a motion clip (.clip.json).");
  m.def(
      "clip_gait",
      [](const std::string& out, double seconds, double speed_mps, double fps) {
        app::ClipFlags f;
        f.out = out;
        f.seconds = seconds;
        f.speed_mps = speed_mps;
        f.fps = fps;
        RunCommand([&](std::ostream& o, std::ostream& e) { return app::ClipGaitCommand(f, o, e); },
                   true);
      },
      py::arg("out"), py::arg("seconds") = 10.0, py::arg("speed_mps") = 1.0, py::arg("fps") = 0.0,
      "`simhuman clip gait`: the walking task's reference gait as a motion clip.");
}

}  // namespace

void RegisterCommands(py::module_& m) {
  m.def(
      "cli",
      [](const std::vector<std::string>& args) {
        std::vector<std::string> argv = {"simhuman"};
        argv.insert(argv.end(), args.begin(), args.end());
        py::gil_scoped_release release;
        PythonLineBuf out_buf("stdout"), err_buf("stderr");
        std::ostream out(&out_buf), err(&err_buf);
        return app::RunCli(argv, out, err);
      },
      py::arg("args"),
      "Runs the command line (`simhuman ARGS...`) in this process; returns its exit code (0 "
      "ok, 1 internal, 2 bad input).");
  m.def("version", &app::VersionText, "simhuman's version, git revision and MuJoCo version.");
  BindEval(m);
  BindTrain(m);
  BindClip(m);
}

}  // namespace simhuman::python
