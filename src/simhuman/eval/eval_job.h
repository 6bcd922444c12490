#pragma once
/// `simhuman eval` of a plan suite as a job over the ranks of a core::Communicator (one
/// process, or `mpirun -n K`), without the printing.
///
/// Sharding: the episodes still to run, in index order, go round-robin to the ranks (episode
/// i to rank i mod K on a fresh run); an episode's seed is DeriveSeed(seed, i) whichever rank
/// runs it, so the results do not depend on K.
///
/// Files in out_dir: rank 0 appends each episode it finishes to episodes.jsonl, rank r > 0 to
/// its journal episodes.rank<r>.jsonl (both flushed at once), and sends the line to rank 0,
/// which rewrites summary.json with what it has. At the end rank 0 writes episodes.jsonl in
/// episode order and summary.json, byte for byte what one process writes apart from the
/// timing fields (wall_time_s, wall_per_sim), and removes the journals. A job that stops
/// early (a rank killed, an error) leaves every finished episode in these files; with
/// `resume` the next job reads them, reports the missing episodes and runs only those.

#include <functional>
#include <vector>

#include "simhuman/core/communicator.h"
#include "simhuman/eval/eval_runner.h"

namespace simhuman::eval {

/// What a job found at its start (rank 0).
struct EvalStart {
  std::vector<int> finished;  ///< episodes kept from an earlier run (resume)
  std::vector<int> to_run;    ///< episodes this job runs, in index order
  int ranks = 1;
};

/// Called on rank 0 only. `on_episode` gets every finished episode of the job, its own and
/// the other ranks' (those rebuilt with EpisodeRecordFromJson, without scene and plan), in
/// the order they reach rank 0, with the summary of all finished episodes so far.
struct EvalHooks {
  std::function<void(const EvalStart&)> on_start;
  std::function<void(const EpisodeRecord&, const Summary&)> on_episode;
};

/// The journal file of rank `rank` (> 0) in `out_dir`.
std::string JournalPath(const std::string& out_dir, int rank);

/// Runs the job; collective (every rank calls it with the same options, checked by a hash).
/// Errors (the same on every rank): options that differ across ranks (InvalidArgument);
/// fewer episodes than ranks (InvalidArgument); an output folder that cannot be created or
/// written (PermissionDenied, naming it); with `resume`, finished files of another run
/// (InvalidArgument naming the file, line or key); without `resume`, journals of an unfinished
/// multi-rank run in out_dir (AlreadyExists: continue it with --resume); and RunSuiteEpisode's
/// errors, prefixed with the rank. Finished episodes stay written after any error.
core::StatusOr<Summary> RunEval(const EvalOptions& options, const EvalHooks& hooks,
                                core::Communicator& comm);

}  // namespace simhuman::eval
