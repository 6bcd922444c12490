#pragma once
/// The HTTP side of `simhuman serve` (cpp-httplib): the viewer page, the scene, a state
/// snapshot, frames and status by Server-Sent Events, and the driver's commands. Several tabs
/// may watch; the one holding the driver token (leased, renewed by the page every few seconds)
/// may command. Endpoints and their errors: docs/FORMATS.md, "Live server".

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>

#include "absl/status/status.h"
#include "simhuman/web/live_session.h"

namespace httplib {
class Server;
}

namespace simhuman::web {

/// Where and how the server listens.
struct ServerOptions {
  std::string bind = "127.0.0.1";  ///< any other address must be asked for (--bind)
  int port = 8080;                 ///< 0: any free port (port() tells which)
  int max_streams = 8;             ///< concurrent /api/events streams; more get 429
  double driver_lease_s = 10.0;    ///< a driver token not renewed for this long is free again
  size_t max_body_bytes = 16384;   ///< larger request bodies get 413
};

/// The server. Serve() blocks; Stop() may be called from any thread.
class LiveServer {
 public:
  /// `session` must outlive the server. It may be null until set_session(), so that the address
  /// is bound (and a port in use reported) before a session is built.
  LiveServer(LiveSession* session, const ServerOptions& options);
  /// The session the routes serve; call before Serve().
  void set_session(LiveSession* session) { session_ = session; }
  ~LiveServer();
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  /// Binds the address. Errors: Unavailable naming "address:port" when it cannot be bound (the
  /// port is in use, or the address is not this machine's).
  absl::Status Bind();
  /// The bound port (after Bind()).
  int port() const { return port_; }
  /// Serves until Stop() (returns at once if Stop() came first). Call after Bind().
  void Serve();
  void Stop();

 private:
  void Routes();
  /// The token holder's check; renews its lease. Empty when `token` drives, else an error.
  std::string CheckDriver(const std::string& token);

  LiveSession* session_;
  ServerOptions options_;
  std::unique_ptr<httplib::Server> http_;
  std::string page_;
  int port_ = 0;
  std::atomic<int> streams_{0};
  std::atomic<bool> serving_{false};
  std::atomic<bool> stopping_{false};  // event streams end, Serve() returns
  std::mutex driver_mu_;
  std::string driver_token_;
  std::chrono::steady_clock::time_point driver_seen_;
  double page_fps_ = -1;  // frames per second the driving page renders (its heartbeat)
};

}  // namespace simhuman::web
