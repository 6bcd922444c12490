#include "simhuman/eval/eval_job.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "simhuman/core/rng.h"
#include "simhuman/eval/episode.h"

namespace simhuman::eval {
namespace {
namespace fs = std::filesystem;

constexpr char kEpisodesFile[] = "episodes.jsonl";
constexpr char kSummaryFile[] = "summary.json";
constexpr char kJournalPrefix[] = "episodes.rank";
// how often rank 0 looks for the other ranks' episodes once its own are done
constexpr std::chrono::milliseconds kPollPeriod{20};

std::string InDir(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

// the options every rank must agree on
std::string Fingerprint(const EvalOptions& o) {
  nlohmann::ordered_json j{{"suite", o.suite},
                           {"episodes", o.episodes},
                           {"seed", o.seed},
                           {"out_dir", o.out_dir},
                           {"config", o.config.ToJson()},
                           {"video_every", o.video_every},
                           {"walk_policy", o.walk_policy},
                           {"human_scale", o.human_scale},
                           {"resume", o.resume}};
  return j.dump();
}

std::string RecordLine(const EpisodeRecord& rec) {
  return EpisodeRecordJson(rec).dump(-1, ' ', false,
                                     nlohmann::ordered_json::error_handler_t::replace);
}

std::vector<std::string> JournalFiles(const std::string& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(kJournalPrefix, 0) == 0 && e.path().extension() == ".jsonl") {
      out.push_back(e.path().string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// the episodes finished so far, by index: their JSON lines and records
struct Finished {
  std::map<int, std::string> lines;
  std::map<int, EpisodeRecord> records;

  // adds a line (the first line of an episode wins); errors name `where`
  absl::Status Add(const std::string& line, const EvalOptions& o, const std::string& where) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) return absl::InvalidArgumentError(where + ": not a JSON line");
    core::StatusOr<EpisodeRecord> rec = EpisodeRecordFromJson(j);
    if (!rec.ok()) return core::Annotate(rec.status(), where);
    if (rec->index < 0 || rec->index >= o.episodes) {
      return absl::InvalidArgumentError(where + ": episode " + std::to_string(rec->index) +
                                        " is outside --episodes " + std::to_string(o.episodes) +
                                        "; resume with the flags of the run that wrote it");
    }
    const uint64_t seed = core::DeriveSeed(o.seed, static_cast<uint64_t>(rec->index));
    if (rec->seed != seed) {
      return absl::InvalidArgumentError(where + ": episode " + std::to_string(rec->index) +
                                        " has seed " + std::to_string(rec->seed) + " but --seed " +
                                        std::to_string(o.seed) + " gives " + std::to_string(seed) +
                                        "; resume with the flags of the run that wrote it");
    }
    if (lines.count(rec->index)) return absl::OkStatus();
    lines.emplace(rec->index, line);
    records.emplace(rec->index, std::move(*rec));
    return absl::OkStatus();
  }

  Summary Summarize(const EvalOptions& o) const {
    std::vector<EpisodeRecord> v;
    for (const auto& [i, r] : records) v.push_back(r);
    return eval::Summarize(o.suite, v, o.episodes);
  }
};

// the finished episodes of `path`; a last line cut short by a killed process is not finished
absl::Status ReadFinished(const std::string& path, const EvalOptions& o, Finished* finished) {
  std::ifstream f(path);
  if (!f) return absl::OkStatus();
  std::vector<std::string> lines;
  for (std::string line; std::getline(f, line);) lines.push_back(line);
  for (size_t n = 0; n < lines.size(); ++n) {
    if (lines[n].empty()) continue;
    const bool last = n + 1 == lines.size();
    if (last && nlohmann::json::parse(lines[n], nullptr, false).is_discarded()) break;
    SH_RETURN_IF_ERROR(finished->Add(lines[n], o, path + ":" + std::to_string(n + 1)));
  }
  return absl::OkStatus();
}

// the run being resumed must be this run: its summary.json names the same settings
absl::Status CheckResumable(const EvalOptions& o) {
  const std::string path = InDir(o.out_dir, kSummaryFile);
  std::ifstream f(path);
  if (!f) {
    return absl::NotFoundError(path +
                               ": nothing to resume (no summary.json); start the run "
                               "without --resume");
  }
  nlohmann::json s = nlohmann::json::parse(f, nullptr, false);
  if (!s.is_object()) return absl::InvalidArgumentError(path + ": not a summary.json");
  const nlohmann::json want{{"suite", o.suite},
                            {"seed", o.seed},
                            {"episodes_requested", o.episodes},
                            {"walk_policy", o.walk_policy},
                            {"config", o.config.ToJson()}};
  if (s.value("human_scale", 1.0) != o.human_scale) {
    return absl::InvalidArgumentError(path + ": the run being resumed has human_scale " +
                                      std::to_string(s.value("human_scale", 1.0)) +
                                      " but this one has " + std::to_string(o.human_scale) +
                                      "; resume with the flags of the run that wrote it");
  }
  for (const auto& [key, value] : want.items()) {
    if (!s.contains(key) || s[key] != value) {
      return absl::InvalidArgumentError(path + ": the run being resumed has " + key + " " +
                                        (s.contains(key) ? s[key].dump() : std::string("(none)")) +
                                        " but this one has " + value.dump() +
                                        "; resume with the flags of the run that wrote it");
    }
  }
  return absl::OkStatus();
}

// writes the lines in episode order to `path` atomically
absl::Status WriteLines(const std::string& path, const std::map<int, std::string>& lines) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::trunc);
    for (const auto& [i, line] : lines) f << line << '\n';
    f.flush();
    if (!f) return absl::PermissionDeniedError("cannot write '" + tmp + "'");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) return absl::PermissionDeniedError("cannot write '" + path + "': " + ec.message());
  return absl::OkStatus();
}

void RemoveJournals(const std::string& dir) {
  for (const std::string& j : JournalFiles(dir)) {
    std::error_code ec;
    fs::remove(j, ec);
  }
}

// rank 0's start: the output folder made, the finished episodes of the run being resumed
// gathered into episodes.jsonl (journals folded in and removed), summary.json written
absl::Status PrepareRoot(const EvalOptions& o, Finished* finished) {
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  if (ec) {
    return absl::PermissionDeniedError("cannot create output directory '" + o.out_dir +
                                       "': " + ec.message());
  }
  const std::vector<std::string> journals = JournalFiles(o.out_dir);
  const std::string episodes = InDir(o.out_dir, kEpisodesFile);
  if (o.resume) {
    SH_RETURN_IF_ERROR(CheckResumable(o));
    SH_RETURN_IF_ERROR(ReadFinished(episodes, o, finished));
    for (const std::string& j : journals) SH_RETURN_IF_ERROR(ReadFinished(j, o, finished));
  } else if (!journals.empty()) {
    return absl::AlreadyExistsError("'" + o.out_dir + "' holds an unfinished multi-rank run (" +
                                    journals.front() +
                                    "); continue it with --resume or choose another --out");
  }
  SH_RETURN_IF_ERROR(WriteLines(episodes, finished->lines));
  RemoveJournals(o.out_dir);
  return WriteJsonFile(InDir(o.out_dir, kSummaryFile), SummaryJson(finished->Summarize(o), o));
}

// rank 0 during the job: takes finished episodes (its own and the other ranks') and keeps
// summary.json current
class RootCollector {
 public:
  RootCollector(const EvalOptions& o, const EvalHooks& hooks, Finished* finished)
      : o_(o), hooks_(hooks), finished_(finished) {}

  absl::Status Add(const std::string& line, int rank) {
    SH_RETURN_IF_ERROR(finished_->Add(line, o_, "episode line from rank " + std::to_string(rank)));
    const Summary s = finished_->Summarize(o_);
    SH_RETURN_IF_ERROR(WriteJsonFile(InDir(o_.out_dir, kSummaryFile), SummaryJson(s, o_)));
    nlohmann::json j = nlohmann::json::parse(line);
    if (hooks_.on_episode) hooks_.on_episode(finished_->records.at(j["episode"].get<int>()), s);
    return absl::OkStatus();
  }

  // the other ranks' messages: "E<line>" a finished episode, "X" a rank that is done
  absl::Status Take(const std::vector<std::pair<int, std::string>>& messages) {
    absl::Status st;
    for (const auto& [rank, m] : messages) {
      if (m.empty()) continue;
      if (m[0] == 'X') ++ranks_done_;
      if (m[0] == 'E') st.Update(Add(m.substr(1), rank));
    }
    return st;
  }
  int ranks_done() const { return ranks_done_; }

 private:
  const EvalOptions& o_;
  const EvalHooks& hooks_;
  Finished* finished_;
  int ranks_done_ = 0;
};

// the episodes still to run, from rank 0's list of finished ones
core::StatusOr<std::vector<int>> ToRun(core::Communicator& comm, const EvalOptions& o,
                                       const Finished& finished) {
  std::string list;
  for (const auto& [i, line] : finished.lines) list += std::to_string(i) + " ";
  SH_RETURN_IF_ERROR(comm.Broadcast(&list, 0));
  std::set<int> done;
  std::istringstream in(list);
  for (int i; in >> i;) done.insert(i);
  std::vector<int> out;
  for (int i = 0; i < o.episodes; ++i) {
    if (!done.count(i)) out.push_back(i);
  }
  return out;
}

}  // namespace

std::string JournalPath(const std::string& out_dir, int rank) {
  return InDir(out_dir, kJournalPrefix + std::to_string(rank) + ".jsonl");
}

core::StatusOr<Summary> RunEval(const EvalOptions& options, const EvalHooks& hooks,
                                core::Communicator& comm) {
  SH_RETURN_IF_ERROR(core::CheckSameOnAllRanks(comm, "eval options", Fingerprint(options)));
  const int ranks = comm.size(), rank = comm.rank();
  if (options.episodes < ranks) {
    return absl::InvalidArgumentError(
        "--episodes " + std::to_string(options.episodes) + " is fewer than the " +
        std::to_string(ranks) + " ranks of this job; valid: --episodes >= " +
        std::to_string(ranks) + ", or mpirun -n <= " + std::to_string(options.episodes));
  }
  Finished finished;
  absl::Status st = absl::OkStatus();
  if (rank == 0) {
    st = PrepareRoot(options, &finished);
  } else {
    // the folder of a rank on another node (rank 0's is made in PrepareRoot)
    std::error_code ec;
    fs::create_directories(options.out_dir, ec);
  }
  SH_RETURN_IF_ERROR(core::AgreeOk(comm, st));
  SH_ASSIGN_OR_RETURN(const std::vector<int> to_run, ToRun(comm, options, finished));

  // rank 0 appends to episodes.jsonl, the others to their journals
  const std::string own_file =
      rank == 0 ? InDir(options.out_dir, kEpisodesFile) : JournalPath(options.out_dir, rank);
  std::ofstream own(own_file, rank == 0 ? std::ios::app : std::ios::trunc);
  st = own ? absl::OkStatus() : absl::PermissionDeniedError("cannot write '" + own_file + "'");
  SH_RETURN_IF_ERROR(core::AgreeOk(comm, st));
  if (rank == 0 && hooks.on_start) {
    EvalStart start{{}, to_run, ranks};
    for (const auto& [i, line] : finished.lines) start.finished.push_back(i);
    hooks.on_start(start);
  }

  RootCollector root(options, hooks, &finished);
  absl::Status local;
  for (size_t k = static_cast<size_t>(rank); k < to_run.size() && local.ok();
       k += static_cast<size_t>(ranks)) {
    core::StatusOr<EpisodeRecord> rec = RunSuiteEpisode(options, to_run[k]);
    if (!rec.ok()) {
      local = rec.status();
      break;
    }
    const std::string line = RecordLine(*rec);
    own << line << '\n';
    own.flush();
    if (!own) {
      local = absl::DataLossError("error writing '" + own_file + "'");
      break;
    }
    if (rank == 0) {
      local.Update(root.Add(line, 0));
      local.Update(root.Take(comm.Poll()));
    } else {
      comm.PostToRoot("E" + line);
    }
  }
  // rank 0 shows the others' episodes as they come until every rank is done
  if (rank != 0) comm.PostToRoot("X");
  while (rank == 0 && root.ranks_done() < ranks - 1) {
    std::vector<std::pair<int, std::string>> got = comm.Poll();
    if (got.empty()) std::this_thread::sleep_for(kPollPeriod);
    local.Update(root.Take(got));
  }
  // ranks done early wait here idle, not spinning in the collectives below
  SH_RETURN_IF_ERROR(comm.Barrier());
  core::StatusOr<std::vector<std::pair<int, std::string>>> rest = comm.FinishPosts();
  if (rest.ok()) local.Update(root.Take(*rest));
  SH_RETURN_IF_ERROR(core::AgreeOk(comm, rest.ok() ? local : rest.status()));

  // every episode finished: the files in episode order, the journals removed
  Summary summary = finished.Summarize(options);
  if (rank == 0) {
    st = WriteLines(InDir(options.out_dir, kEpisodesFile), finished.lines);
    if (st.ok()) {
      st = WriteJsonFile(InDir(options.out_dir, kSummaryFile), SummaryJson(summary, options));
    }
    if (st.ok()) RemoveJournals(options.out_dir);
  }
  SH_RETURN_IF_ERROR(core::AgreeOk(comm, st));
  return summary;
}

}  // namespace simhuman::eval
