#include "simhuman/eval/run_record.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "absl/strings/numbers.h"
#include "absl/strings/str_split.h"
#include "simhuman/core/json_io.h"
#include "simhuman/eval/episode.h"
#include "simhuman/plan/validate.h"

namespace simhuman::eval {
namespace {

constexpr char kRunFiles[] = "scene.json, plan.json, trajectory.csv and result.json";

absl::Status RowError(const std::string& path, size_t line, const std::string& what) {
  return absl::InvalidArgumentError(path + ":" + std::to_string(line) + ": " + what);
}

}  // namespace

core::StatusOr<control::Trajectory> ReadTrajectoryCsv(const std::string& path, const mjModel* m) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError("cannot read trajectory '" + path + "'");
  std::string header;
  std::getline(in, header);
  std::vector<std::string> want = {"time_s", "step"};
  for (const std::string& c : QposColumnNames(m)) want.push_back(c);
  std::vector<std::string> got = absl::StrSplit(header, ',');
  if (got != want) {
    for (size_t i = 0; i < want.size(); ++i) {
      if (i >= got.size() || got[i] != want[i]) {
        return RowError(path, 1,
                        "column " + std::to_string(i + 1) + " is '" +
                            (i < got.size() ? got[i] : std::string("(missing)")) +
                            "', the model's is '" + want[i] +
                            "' (the run's scene.json does not match its trajectory)");
      }
    }
    return RowError(path, 1,
                    "has " + std::to_string(got.size()) + " columns, the model has " +
                        std::to_string(want.size()));
  }
  control::Trajectory t;
  t.nq = m->nq;
  std::string line;
  for (size_t n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    std::vector<absl::string_view> cells = absl::StrSplit(line, ',');
    if (cells.size() != want.size()) {
      return RowError(path, n,
                      "has " + std::to_string(cells.size()) + " values, the header " +
                          std::to_string(want.size()));
    }
    std::vector<double> row(cells.size());
    for (size_t c = 0; c < cells.size(); ++c) {
      if (!absl::SimpleAtod(cells[c], &row[c]) || !std::isfinite(row[c])) {
        return RowError(
            path, n,
            "column '" + want[c] + "' holds '" + std::string(cells[c]) + "', not a finite number");
      }
    }
    if (!t.time_s.empty() && row[0] < t.time_s.back()) {
      return RowError(path, n, "time_s goes backwards");
    }
    t.time_s.push_back(row[0]);
    t.step_index.push_back(static_cast<int>(row[1]));
    t.qpos.emplace_back(row.begin() + 2, row.end());
  }
  if (t.qpos.empty()) return RowError(path, 2, "the trajectory has no frames");
  if (t.time_s.size() >= 3) {
    const size_t last = t.time_s.size() - 2;
    const double span = t.time_s[last] - t.time_s[0];
    if (span > 1e-6) {
      const double fps = last / span;
      t.fps = std::abs(fps - std::round(fps)) < 0.05 * fps ? std::round(fps) : fps;
    }
  }
  return t;
}

core::StatusOr<RunRecord> LoadRunRecord(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return absl::NotFoundError("run folder '" + dir +
                               "' does not exist; a run folder (simhuman "
                               "run --out DIR) holds " +
                               kRunFiles);
  }
  const fs::path d(dir);
  for (const char* name : {"scene.json", "trajectory.csv"}) {
    if (!fs::exists(d / name, ec)) {
      return absl::NotFoundError("run folder '" + dir + "' has no " + name +
                                 "; a run folder holds " + kRunFiles);
    }
  }
  RunRecord r;
  SH_ASSIGN_OR_RETURN(r.scene, world::LoadScene((d / "scene.json").string()));
  SH_ASSIGN_OR_RETURN(r.catalog, world::BuildCatalog(r.scene));
  SH_ASSIGN_OR_RETURN(r.world, BuildWorld(r.scene, r.catalog));
  if (fs::exists(d / "plan.json", ec)) {
    SH_ASSIGN_OR_RETURN(r.chain,
                        plan::LoadAndGroundFile((d / "plan.json").string(), r.world->catalog()));
  }
  SH_ASSIGN_OR_RETURN(r.trajectory,
                      ReadTrajectoryCsv((d / "trajectory.csv").string(), r.world->model()));
  if (fs::exists(d / "result.json", ec)) {
    SH_ASSIGN_OR_RETURN(r.result, core::ReadJsonFile((d / "result.json").string()));
  }
  return r;
}

}  // namespace simhuman::eval
