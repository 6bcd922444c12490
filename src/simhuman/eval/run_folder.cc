#include "simhuman/eval/run_folder.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "simhuman/core/json_io.h"
#include "simhuman/eval/episode.h"

namespace simhuman::eval {
namespace {

std::vector<std::string> SplitCommas(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

absl::Status LineError(const std::string& where, int line, const std::string& what) {
  return absl::InvalidArgumentError(where + ":" + std::to_string(line) + ": " + what);
}

// the header: "time_s,step" then the model's qpos columns, in order
absl::Status CheckHeader(const std::string& header, const std::string& where, const mjModel* m) {
  const std::vector<std::string> cols = SplitCommas(header);
  std::vector<std::string> expected = {"time_s", "step"};
  for (const std::string& c : QposColumnNames(m)) expected.push_back(c);
  for (size_t i = 0; i < std::max(cols.size(), expected.size()); ++i) {
    const std::string got = i < cols.size() ? cols[i] : "(end of line)";
    const std::string want = i < expected.size() ? expected[i] : "(end of line)";
    if (got != want) {
      return LineError(where, 1,
                       "column " + std::to_string(i + 1) + " is '" + got + "', the model of " +
                           "scene.json expects '" + want +
                           "' (the trajectory was recorded on a different scene or build)");
    }
  }
  return absl::OkStatus();
}

}  // namespace

core::StatusOr<control::Trajectory> ParseTrajectoryCsv(const std::string& text,
                                                       const std::string& where, const mjModel* m) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) return LineError(where, 1, "empty file, expected a header");
  SH_RETURN_IF_ERROR(CheckHeader(line, where, m));
  control::Trajectory tr;
  tr.nq = m->nq;
  const size_t ncols = 2 + static_cast<size_t>(m->nq);
  int n = 1;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line == "\r") continue;
    const std::vector<std::string> cols = SplitCommas(line);
    if (cols.size() != ncols) {
      return LineError(where, n,
                       "the row has " + std::to_string(cols.size()) + " values, the header " +
                           std::to_string(ncols));
    }
    std::vector<double> v(ncols);
    for (size_t i = 0; i < ncols; ++i) {
      char* end = nullptr;
      v[i] = std::strtod(cols[i].c_str(), &end);
      if (cols[i].empty() || end != cols[i].c_str() + cols[i].size() || !std::isfinite(v[i])) {
        return LineError(
            where, n,
            "column " + std::to_string(i + 1) + ": '" + cols[i] + "' is not a finite number");
      }
    }
    if (!tr.time_s.empty() && v[0] < tr.time_s.back()) {
      return LineError(where, n, "time_s goes backwards");
    }
    tr.time_s.push_back(v[0]);
    tr.step_index.push_back(static_cast<int>(v[1]));
    tr.qpos.emplace_back(v.begin() + 2, v.end());
  }
  if (tr.qpos.empty()) return LineError(where, n, "no frames after the header");
  // the recording rate: the mean rate over the rows before the last (the final state, off the
  // grid; the rows are the first simulation steps at or after each 1/fps tick, so single
  // spacings jitter by a step), rounded to a whole rate when that is within 5%
  if (tr.time_s.size() >= 3) {
    const size_t last = tr.time_s.size() - 2;
    const double span = tr.time_s[last] - tr.time_s[0];
    if (span > 1e-6) {
      const double fps = last / span;
      tr.fps = std::abs(fps - std::round(fps)) < 0.05 * fps ? std::round(fps) : fps;
    }
  }
  return tr;
}

core::StatusOr<RunFolder> LoadRunFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return absl::NotFoundError("run folder '" + dir +
                               "' does not exist (give the --out folder of `simhuman run`)");
  }
  RunFolder run;
  run.dir = dir;
  const std::string scene_path = (fs::path(dir) / "scene.json").string();
  const std::string traj_path = (fs::path(dir) / "trajectory.csv").string();
  for (const std::string& p : {scene_path, traj_path}) {
    if (!fs::is_regular_file(p, ec)) {
      return absl::NotFoundError("'" + p + "' is missing; a run folder holds scene.json and " +
                                 "trajectory.csv (written by `simhuman run --out DIR`)");
    }
  }
  SH_ASSIGN_OR_RETURN(run.scene, world::LoadScene(scene_path));
  SH_ASSIGN_OR_RETURN(const core::SceneCatalog catalog, world::BuildCatalog(run.scene));
  SH_ASSIGN_OR_RETURN(run.world, BuildWorld(run.scene, catalog));
  SH_ASSIGN_OR_RETURN(const std::string text, core::ReadFile(traj_path));
  SH_ASSIGN_OR_RETURN(run.trajectory, ParseTrajectoryCsv(text, traj_path, run.world->model()));
  return run;
}

}  // namespace simhuman::eval
