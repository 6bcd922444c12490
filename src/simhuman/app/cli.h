#pragma once
/// The `simhuman` command line: `run`, `eval`, `scenes`, `--version`. The only place that
/// prints to stdout.

#include <ostream>
#include <string>
#include <vector>

#include "simhuman/core/communicator.h"

namespace simhuman::app {

/// The version line printed by --version: "simhuman 0.1.0 (git <rev>, MuJoCo <version>)".
std::string VersionText();

/// Runs the command line `args` (args[0] is the program name) and returns the process exit
/// code (see common.h: 0 ok, 1 internal failure, 2 bad input). Normal output goes to `out`,
/// errors and warnings to `err`; nothing is read from stdin. Unknown flags, missing required
/// flags and bad values are reported on one line naming the flag, with a hint to --help.
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// As RunCli, as one rank of the job `comm` (`eval` and `train` split their work over its
/// ranks; a command line that fails to parse on one rank stops all of them).
int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
           core::Communicator& comm);

/// main(): installs the MuJoCo error handlers, starts the job's communicator (MPI under
/// mpirun, dist/mpi_communicator.h), checks that every rank runs the same binary (a hash of
/// /proc/self/exe), and runs RunCli; rank 0 prints to std::cout / std::cerr, the others are
/// silent.
int Main(int argc, char** argv);

}  // namespace simhuman::app
