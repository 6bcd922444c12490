#pragma once
/// `simhuman replay DIR --html FILE`: a recorded run (the folder `simhuman run` wrote) as one
/// self-contained HTML page that plays it in any browser, offline.

#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace simhuman::app {

/// The flags of `simhuman replay`.
struct ReplayFlags {
  std::string run_dir;  ///< a `simhuman run --out` folder
  std::string html;     ///< the HTML file to write
  double max_fps = 30;  ///< frames above this rate are dropped
};

/// Adds `simhuman replay` to `app`, its flags into `flags`; returns the subcommand.
CLI::App* AddReplayCommand(CLI::App& app, ReplayFlags* flags);

/// Writes the page; one line naming it on `out`. Errors (one line on `err`): kExitBadInput for
/// a missing or malformed run folder or bad flags, kExitInternal when the file cannot be
/// written.
int ReplayCommand(const ReplayFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
