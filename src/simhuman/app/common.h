#pragma once
/// Shared pieces of the `simhuman` commands: exit codes, configuration from flags, output
/// folders.

#include <ostream>
#include <string>

#include "absl/status/status.h"
#include "simhuman/control/mpc/mpc_config.h"
#include "simhuman/core/status.h"

namespace simhuman::app {

/// The command did what was asked (for `run`: the episode ran, whether or not the plan
/// succeeded).
inline constexpr int kExitOk = 0;
/// An internal failure: rendering, encoding, an unexpected simulator or set-up error.
inline constexpr int kExitInternal = 1;
/// Bad input: usage, flags, a missing or malformed file, an unknown name, an unreachable plan.
inline constexpr int kExitBadInput = 2;

/// kExitBadInput for statuses caused by the input (InvalidArgument, NotFound, OutOfRange,
/// AlreadyExists, PermissionDenied), kExitInternal otherwise, kExitOk for OK.
int ExitCodeFor(const absl::Status& status);

/// Prints "simhuman <command>: error: <message>" on one line to `err` and returns
/// ExitCodeFor(status).
int ReportError(std::ostream& err, const std::string& command, const absl::Status& status);

/// The MPC configuration from --preset and --config. Without a config file: the preset (an
/// unknown name is InvalidArgument listing the presets). With one: MpcConfig::FromJson of the
/// file, strictly, where keys the file leaves out come from the preset the file names, or else
/// from `preset`; a file naming another preset than an explicit --preset is an error. Errors
/// name the file (and the JSON pointer); a NaN or Infinity, which JSON cannot hold, is pointed
/// out as such. An unknown preset (no file) is reported against "--preset".
core::StatusOr<control::MpcConfig> ResolveConfig(const std::string& preset, bool preset_given,
                                                 const std::string& config_path);

/// Creates `dir` and its parents. PermissionDenied naming `dir` on failure.
absl::Status MakeOutputDir(const std::string& dir);

}  // namespace simhuman::app
