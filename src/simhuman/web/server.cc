#include "simhuman/web/server.h"

#include <httplib.h>
#include <sys/socket.h>

#include <random>
#include <thread>

#include "simhuman/core/json_io.h"
#include "simhuman/web/viewer_page.h"

namespace simhuman::web {
namespace {

constexpr char kJson[] = "application/json";
constexpr char kEndpoints[] =
    "GET /, GET /api/scene, GET /api/state, GET /api/events, POST /api/drive, POST "
    "/api/command, POST /api/answer, POST /api/pause, POST /api/reset";
// threads beyond the event streams, for everything else
constexpr int kSpareThreads = 6;
// an event stream without news sends a comment this often (and finds dead peers)
constexpr std::chrono::milliseconds kKeepAlive{1000};

// JSON text; bytes of a request that are not UTF-8 (echoed in an error) become U+FFFD
std::string Dump(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void Reply(httplib::Response& res, int code, const nlohmann::json& body) {
  res.status = code;
  res.set_content(Dump(body), kJson);
}

void Fail(httplib::Response& res, int code, const std::string& message) {
  Reply(res, code, {{"error", message}});
}

// the HTTP status of a session error
int CodeFor(const absl::Status& st) {
  switch (st.code()) {
    case absl::StatusCode::kOutOfRange:
      return 413;
    case absl::StatusCode::kResourceExhausted:
      return 429;
    case absl::StatusCode::kFailedPrecondition:
      return 409;
    default:
      return 400;
  }
}

// a POST body: a JSON object with only `allowed` keys; an error message otherwise
std::string ParseBody(const httplib::Request& req, const std::vector<std::string>& allowed,
                      nlohmann::json* body) {
  if (req.body.empty()) {
    *body = nlohmann::json::object();
    return "";
  }
  core::StatusOr<nlohmann::json> j = core::ParseJson(req.body, "request body");
  if (!j.ok()) return std::string(j.status().message());
  if (!j->is_object()) return "the request body must be a JSON object, e.g. {\"text\": \"...\"}";
  for (const auto& [key, value] : j->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string valid;
      for (const std::string& a : allowed) valid += (valid.empty() ? "" : ", ") + a;
      return "unknown key '" + key + "' in the request body; valid keys: " + valid;
    }
  }
  *body = std::move(*j);
  return "";
}

// the string at `key` of `body`; an error message when it is missing or not a string
std::string StringField(const nlohmann::json& body, const char* key, bool required,
                        std::string* out) {
  if (!body.contains(key)) return required ? std::string("'") + key + "' is required" : "";
  if (!body[key].is_string()) return std::string("'") + key + "' must be a string";
  *out = body[key].get<std::string>();
  return "";
}

std::string NewToken() {
  std::random_device rd;  // a token must not be guessable, nor repeat across runs
  static const char kHex[] = "0123456789abcdef";
  std::string t;
  for (int i = 0; i < 32; ++i) t += kHex[rd() & 15u];
  return t;
}

}  // namespace

LiveServer::LiveServer(LiveSession* session, const ServerOptions& options)
    : session_(session), options_(options), http_(std::make_unique<httplib::Server>()) {
  page_ = ViewerPageHtml({{"mode", "live"}, {"api", "/api"}});
  const int threads = options_.max_streams + kSpareThreads;
  http_->new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  http_->set_payload_max_length(options_.max_body_bytes);
  http_->set_tcp_nodelay(true);
  // SO_REUSEADDR only: httplib's default also sets SO_REUSEPORT, with which a second server on
  // a port in use would share it silently instead of failing
  http_->set_socket_options([](int sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
  });
  http_->set_read_timeout(5, 0);
  http_->set_write_timeout(5, 0);
  Routes();
}

LiveServer::~LiveServer() { Stop(); }

absl::Status LiveServer::Bind() {
  const std::string where = options_.bind + ":" + std::to_string(options_.port);
  if (options_.port < 0 || options_.port > 65535) {
    return absl::InvalidArgumentError("port " + std::to_string(options_.port) +
                                      " is invalid; valid: 0 (any free port) to 65535");
  }
  if (options_.port == 0) {
    port_ = http_->bind_to_any_port(options_.bind);
    if (port_ > 0) return absl::OkStatus();
  } else if (http_->bind_to_port(options_.bind, options_.port)) {
    port_ = options_.port;
    return absl::OkStatus();
  }
  return absl::UnavailableError("cannot listen on " + where +
                                ": the port is in use (another simhuman serve?) or the address "
                                "is not this machine's; choose another with --port or --bind");
}

void LiveServer::Serve() {
  // either Stop() sees serving_ and waits for the listener to run, or this sees stopping_
  serving_ = true;
  if (!stopping_) http_->listen_after_bind();
  serving_ = false;
}

void LiveServer::Stop() {
  stopping_ = true;
  while (serving_ && !http_->is_running()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  http_->stop();
}

std::string LiveServer::CheckDriver(const std::string& token) {
  std::lock_guard<std::mutex> lock(driver_mu_);
  const auto now = std::chrono::steady_clock::now();
  if (token.empty() || token != driver_token_) {
    return "only the driving tab may do this (this one watches); the driver token is given by "
           "POST /api/drive when no other tab drives";
  }
  driver_seen_ = now;
  return "";
}

void LiveServer::Routes() {
  httplib::Server& s = *http_;
  s.Get("/", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(page_, "text/html; charset=utf-8");
  });
  s.Get("/api/scene", [this](const httplib::Request&, httplib::Response& res) {
    Reply(res, 200, session_->scene_json());
  });
  s.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) {
    nlohmann::json j = session_->State();
    std::lock_guard<std::mutex> lock(driver_mu_);
    j["page_fps"] = page_fps_;  // as the driving page last reported it
    j["driver"] =
        !driver_token_.empty() && std::chrono::steady_clock::now() - driver_seen_ <
                                      std::chrono::duration<double>(options_.driver_lease_s);
    Reply(res, 200, j);
  });
  s.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
    if (++streams_ > options_.max_streams) {
      --streams_;
      return Fail(res, 429,
                  std::to_string(options_.max_streams) + " pages are already watching; close one");
    }
    res.set_header("Cache-Control", "no-cache");
    auto last_frame = std::make_shared<uint64_t>(0);
    auto last_status = std::make_shared<uint64_t>(~0ull);
    res.set_chunked_content_provider(
        "text/event-stream",
        [this, last_frame, last_status](size_t, httplib::DataSink& sink) {
          std::string out;
          if (session_->status_seq() != *last_status) {
            nlohmann::json st = session_->Status();
            *last_status = st["seq"].get<uint64_t>();
            out += "event: status\ndata: " + Dump(st) + "\n\n";
          }
          std::optional<LiveFrame> f = session_->WaitFrame(*last_frame, kKeepAlive);
          if (stopping_ || session_->stopping()) return false;
          if (f) {
            *last_frame = f->seq;
            out += "event: frame\ndata: " + *f->json + "\n\n";
          }
          if (out.empty()) out = ": keep-alive\n\n";
          return sink.write(out.data(), out.size());  // false: the page has gone
        },
        [this](bool) { --streams_; });
  });
  s.Post("/api/drive", [this](const httplib::Request& req, httplib::Response& res) {
    nlohmann::json body;
    std::string token, e = ParseBody(req, {"token", "fps"}, &body);
    if (e.empty()) e = StringField(body, "token", false, &token);
    if (e.empty() && body.contains("fps") && !body["fps"].is_number()) e = "'fps' must be a number";
    if (!e.empty()) return Fail(res, 400, e);
    std::lock_guard<std::mutex> lock(driver_mu_);
    if (body.contains("fps")) page_fps_ = body["fps"].get<double>();
    const auto now = std::chrono::steady_clock::now();
    const bool held = !driver_token_.empty() &&
                      now - driver_seen_ < std::chrono::duration<double>(options_.driver_lease_s);
    if (held && token != driver_token_) {
      return Fail(res, 409, "another tab drives; this one watches until that tab closes");
    }
    if (!held) driver_token_ = NewToken();
    driver_seen_ = now;
    Reply(res, 200, {{"token", driver_token_}, {"lease_s", options_.driver_lease_s}});
  });
  // POST endpoints of the driver: {"token", ...}
  auto driven = [this](const std::vector<std::string>& keys,
                       std::function<void(const nlohmann::json&, httplib::Response&)> act) {
    return [this, keys, act](const httplib::Request& req, httplib::Response& res) {
      nlohmann::json body;
      std::string token, e = ParseBody(req, keys, &body);
      if (e.empty()) e = StringField(body, "token", true, &token);
      if (!e.empty()) return Fail(res, 400, e);
      e = CheckDriver(token);
      if (!e.empty()) return Fail(res, 403, e);
      act(body, res);
    };
  };
  auto text_endpoint = [this](bool answer) {
    return [this, answer](const nlohmann::json& body, httplib::Response& res) {
      std::string text, e = StringField(body, "text", true, &text);
      if (!e.empty()) return Fail(res, 400, e);
      absl::Status st = answer ? session_->Answer(text) : session_->SubmitCommand(text);
      if (!st.ok()) return Fail(res, CodeFor(st), std::string(st.message()));
      Reply(res, 202, {{"accepted", text}});
    };
  };
  s.Post("/api/command", driven({"token", "text"}, text_endpoint(false)));
  s.Post("/api/answer", driven({"token", "text"}, text_endpoint(true)));
  s.Post("/api/pause",
         driven({"token", "paused"}, [this](const nlohmann::json& body, httplib::Response& res) {
           if (!body.contains("paused") || !body["paused"].is_boolean()) {
             return Fail(res, 400, "'paused' (true or false) is required");
           }
           session_->SetPaused(body["paused"].get<bool>());
           Reply(res, 200, {{"paused", body["paused"]}});
         }));
  s.Post("/api/reset", driven({"token"}, [this](const nlohmann::json&, httplib::Response& res) {
           session_->Reset();
           Reply(res, 200, {{"reset", true}});
         }));
  s.set_error_handler(
      httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        std::string msg = res.status == 404 ? "no endpoint " + req.method + " " + req.path +
                                                  "; the endpoints are: " + kEndpoints
                          : res.status == 413 ? "the request body is too large"
                                              : "the request is malformed";
        Fail(res, res.status, msg);
        return httplib::Server::HandlerResponse::Handled;
      }));
  s.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    Fail(res, 500, "internal error while handling the request");
  });
}

}  // namespace simhuman::web
