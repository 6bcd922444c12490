#pragma once
/// A scripted fake OpenAI-compatible chat-completions server for tests (test code only; not part
/// of the library): an httplib::Server on a free port of 127.0.0.1, in its own thread, that
/// answers POST /v1/chat/completions with the next canned reply of its script and records every
/// request it gets.

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace simhuman::language::testing {

/// One canned answer.
struct FakeReply {
  int status = 200;
  std::string body;  ///< the raw HTTP body
  std::vector<std::pair<std::string, std::string>> headers;
  double delay_s = 0.0;  ///< wait this long before answering (cut short when the server stops)
  /// > 0: send the body chunked, 16 bytes every trickle_s seconds (a slow stream)
  double trickle_s = 0.0;

  /// A 200 chat completion whose message content is `content`.
  static FakeReply Completion(const std::string& content) {
    nlohmann::json j = {{"id", "chatcmpl-fake"},
                        {"object", "chat.completion"},
                        {"model", "fake"},
                        {"choices",
                         {{{"index", 0},
                           {"message", {{"role", "assistant"}, {"content", content}}},
                           {"finish_reason", "stop"}}}}};
    FakeReply r;
    r.body = j.dump();
    return r;
  }
  /// An error status with an OpenAI-style error body.
  static FakeReply Error(int status, const std::string& message) {
    FakeReply r;
    r.status = status;
    r.body = nlohmann::json({{"error", {{"message", message}, {"type", "fake"}}}}).dump();
    return r;
  }
};

/// What the server received.
struct RecordedRequest {
  std::string path;
  std::string authorization;  ///< the Authorization header, "" when absent
  std::string body;
  nlohmann::json json;  ///< the parsed body (discarded when not JSON)
};

/// The fake server. Starts in the constructor, stops in the destructor. Thread-safe.
class FakeChatServer {
 public:
  FakeChatServer() {
    server_.set_tcp_nodelay(true);
    server_.Post("/v1/chat/completions",
                 [this](const httplib::Request& req, httplib::Response& res) { Handle(req, res); });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~FakeChatServer() {
    {
      std::lock_guard<std::mutex> lock(mu_);
      stopping_ = true;
    }
    cv_.notify_all();
    server_.stop();
    thread_.join();
  }
  FakeChatServer(const FakeChatServer&) = delete;
  FakeChatServer& operator=(const FakeChatServer&) = delete;

  /// Appends canned replies; each request takes the next one. An empty script answers 500.
  void Push(FakeReply reply) {
    std::lock_guard<std::mutex> lock(mu_);
    script_.push_back(std::move(reply));
  }
  void Push(const std::vector<FakeReply>& replies) {
    for (const FakeReply& r : replies) Push(r);
  }

  /// Base URL to give the client: "http://127.0.0.1:<port>/v1".
  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/v1"; }
  int port() const { return port_; }

  std::vector<RecordedRequest> requests() const {
    std::lock_guard<std::mutex> lock(mu_);
    return requests_;
  }

 private:
  void Handle(const httplib::Request& req, httplib::Response& res) {
    FakeReply reply;
    {
      std::unique_lock<std::mutex> lock(mu_);
      RecordedRequest r;
      r.path = req.path;
      r.authorization =
          req.has_header("Authorization") ? req.get_header_value("Authorization") : "";
      r.body = req.body;
      r.json = nlohmann::json::parse(req.body, nullptr, false);
      requests_.push_back(std::move(r));
      if (script_.empty()) {
        reply = FakeReply::Error(500, "fake server: script exhausted");
      } else {
        reply = std::move(script_.front());
        script_.pop_front();
      }
      if (reply.delay_s > 0) {
        cv_.wait_for(lock, std::chrono::duration<double>(reply.delay_s),
                     [this] { return stopping_; });
      }
    }
    res.status = reply.status;
    for (const auto& [k, v] : reply.headers) res.set_header(k, v);
    if (reply.trickle_s <= 0) {
      res.set_content(reply.body, "application/json");
      return;
    }
    res.set_chunked_content_provider(
        "application/json", [this, body = reply.body, trickle_s = reply.trickle_s](
                                size_t offset, httplib::DataSink& sink) {
          {
            std::unique_lock<std::mutex> lock(mu_);
            if (cv_.wait_for(lock, std::chrono::duration<double>(trickle_s),
                             [this] { return stopping_; })) {
              return false;
            }
          }
          if (offset >= body.size()) {
            sink.done();
            return true;
          }
          size_t n = std::min<size_t>(16, body.size() - offset);
          return sink.write(body.data() + offset, n);
        });
  }

  httplib::Server server_;
  std::thread thread_;
  int port_ = -1;
  mutable std::mutex mu_;
  std::condition_variable cv_;
  bool stopping_ = false;
  std::deque<FakeReply> script_;
  std::vector<RecordedRequest> requests_;
};

}  // namespace simhuman::language::testing
