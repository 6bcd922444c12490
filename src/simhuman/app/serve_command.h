#pragma once
/// `simhuman serve --scene S [--port 8080] [--bind ADDR]`: the live web view (web/server.h)
/// with a command box, until Ctrl-C.

#include <cstdint>
#include <ostream>
#include <string>

#include "simhuman/app/llm_flags.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace simhuman::app {

/// The flags of `simhuman serve`.
struct ServeFlags {
  std::string scene;
  int port = 8080;
  std::string bind = "127.0.0.1";
  std::string planner = "offline";
  LlmFlags llm;
  uint64_t seed = 1;
  std::string preset = "fast";
  bool preset_given = false;
  std::string config;
  std::string policy;
  bool no_walk = false;
  double speed = 1.0;  ///< simulated seconds per wall second
};

/// Adds `simhuman serve` to `app`, its flags into `flags`; `preset` is set to the --preset
/// option. Returns the subcommand.
CLI::App* AddServeCommand(CLI::App& app, ServeFlags* flags, CLI::Option** preset);

/// Serves until SIGINT or SIGTERM. Prints the address on `out`. Errors (one line on `err`):
/// kExitBadInput for bad flags or scenes, kExitInternal when the address cannot be bound (the
/// message names it).
int ServeCommand(const ServeFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
