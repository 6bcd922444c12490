#include "simhuman/language/http_chat_client.h"

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "simhuman/core/json_io.h"
#include "simhuman/language/reply_extract.h"

namespace simhuman::language {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxRetries = 10;

std::string Num(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// splits seconds into the (sec, usec) pair httplib wants
void SetTimeouts(httplib::Client& client, double seconds) {
  auto sec = static_cast<time_t>(seconds);
  auto usec = static_cast<time_t>(std::lround((seconds - static_cast<double>(sec)) * 1e6));
  client.set_connection_timeout(sec, usec);
  client.set_read_timeout(sec, usec);
  client.set_write_timeout(sec, usec);
}

// the message a server put in an error body ({"error": {"message": ...}} or {"error": "..."}),
// else a preview of the body
std::string ServerMessage(const std::string& body) {
  nlohmann::json j = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (j.is_object() && j.contains("error")) {
    const nlohmann::json& e = j["error"];
    if (e.is_string()) return Preview(e.get<std::string>(), 200);
    if (e.is_object() && e.contains("message") && e["message"].is_string()) {
      return Preview(e["message"].get<std::string>(), 200);
    }
  }
  return Preview(body, 200);
}

// seconds from a Retry-After header (delta-seconds form); nullopt for a date or garbage
std::optional<double> RetryAfterSeconds(const httplib::Result& res) {
  if (!res->has_header("Retry-After")) return std::nullopt;
  std::string v = res->get_header_value("Retry-After");
  if (v.empty() || v.size() > 12 || v.find_first_not_of("0123456789.") != std::string::npos) {
    return std::nullopt;
  }
  char* end = nullptr;
  double s = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || !std::isfinite(s) || s < 0) return std::nullopt;
  return s;
}

// the text of choices[0].message.content in a chat completion body
core::StatusOr<std::string> ContentOf(const std::string& body) {
  nlohmann::json j = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    return absl::UnavailableError("the reply is not JSON (not a chat completion); it starts: '" +
                                  Preview(body) + "'");
  }
  if (j.is_object() && j.contains("error")) {
    return absl::UnavailableError("the server reported an error: " + ServerMessage(body));
  }
  if (!j.is_object() || !j.contains("choices") || !j["choices"].is_array() ||
      j["choices"].empty()) {
    return absl::UnavailableError(
        "the reply is not a chat completion: expected a non-empty array /choices; it starts: '" +
        Preview(body) + "'");
  }
  const nlohmann::json& choice = j["choices"][0];
  if (!choice.is_object() || !choice.contains("message") || !choice["message"].is_object()) {
    return absl::UnavailableError("the reply is not a chat completion: missing /choices/0/message");
  }
  const nlohmann::json& message = choice["message"];
  if (!message.contains("content") || !message["content"].is_string()) {
    return absl::UnavailableError(
        "the reply has no text: /choices/0/message/content is missing or not a string");
  }
  return message["content"].get<std::string>();
}

}  // namespace

core::Status ChatClientOptions::Validate() const {
  std::string scheme_host_port, path;
  if (core::Status s = SplitUrl(url, &scheme_host_port, &path); !s.ok()) {
    return absl::InvalidArgumentError("url: " + std::string(s.message()));
  }
  if (model.empty() || model.size() > 256) {
    return absl::InvalidArgumentError(
        "model: a model name is required (1 to 256 characters), e.g. qwen2.5-7b-instruct");
  }
  if (!(timeout_s > 0.0 && timeout_s <= 3600.0)) {
    return absl::InvalidArgumentError("timeout_s: must be in (0, 3600] seconds, got " +
                                      Num(timeout_s));
  }
  if (max_retries < 0 || max_retries > kMaxRetries) {
    return absl::InvalidArgumentError("max_retries: must be in [0, " + std::to_string(kMaxRetries) +
                                      "], got " + std::to_string(max_retries));
  }
  if (!(backoff_s >= 0.0 && backoff_s <= 60.0)) {
    return absl::InvalidArgumentError("backoff_s: must be in [0, 60] seconds, got " +
                                      Num(backoff_s));
  }
  if (!(max_backoff_s >= 0.0 && max_backoff_s <= 300.0)) {
    return absl::InvalidArgumentError("max_backoff_s: must be in [0, 300] seconds, got " +
                                      Num(max_backoff_s));
  }
  if (max_reply_bytes < 1024 || max_reply_bytes > (64u << 20)) {
    return absl::InvalidArgumentError("max_reply_bytes: must be in [1024, 67108864], got " +
                                      std::to_string(max_reply_bytes));
  }
  if (!(temperature >= 0.0 && temperature <= 2.0)) {
    return absl::InvalidArgumentError("temperature: must be in [0, 2], got " + Num(temperature));
  }
  if (max_tokens < 0 || max_tokens > 1000000) {
    return absl::InvalidArgumentError("max_tokens: must be in [0, 1000000] (0: not sent), got " +
                                      std::to_string(max_tokens));
  }
  return absl::OkStatus();
}

core::Status SplitUrl(const std::string& url, std::string* scheme_host_port, std::string* path) {
  auto bad = [&](const std::string& why) {
    return absl::InvalidArgumentError("invalid URL '" + Preview(url, 200) + "': " + why +
                                      "; expected http://host[:port][/path] or https://..., e.g. "
                                      "http://127.0.0.1:8080/v1");
  };
  for (char c : url) {
    unsigned char u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u >= 0x7f) return bad("it contains a space or a control or non-ASCII byte");
  }
  size_t sep = url.find("://");
  if (sep == std::string::npos) return bad("no scheme");
  std::string scheme = url.substr(0, sep);
  std::transform(scheme.begin(), scheme.end(), scheme.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (scheme != "http" && scheme != "https") return bad("scheme '" + scheme + "' is not http(s)");
  size_t authority_begin = sep + 3;
  size_t path_begin = url.find('/', authority_begin);
  std::string authority =
      url.substr(authority_begin, path_begin == std::string::npos ? std::string::npos
                                                                  : path_begin - authority_begin);
  if (authority.find('@') != std::string::npos) {
    return bad(
        "credentials in the URL are not accepted; put the API key in the environment "
        "variable named by the key option");
  }
  if (url.find_first_of("?#") != std::string::npos)
    return bad("a query or fragment is not allowed");
  std::string host = authority;
  size_t colon = authority.rfind(':');
  if (colon != std::string::npos && authority.find(']') == std::string::npos) {
    host = authority.substr(0, colon);
    std::string port = authority.substr(colon + 1);
    if (port.empty() || port.size() > 5 ||
        port.find_first_not_of("0123456789") != std::string::npos || std::stoi(port) < 1 ||
        std::stoi(port) > 65535) {
      return bad("port '" + port + "' is not in 1..65535");
    }
  }
  if (host.empty()) return bad("no host");
  *scheme_host_port = scheme + "://" + authority;
  *path = path_begin == std::string::npos ? std::string() : url.substr(path_begin);
  while (!path->empty() && path->back() == '/') path->pop_back();
  return absl::OkStatus();
}

HttpChatClient::HttpChatClient(ChatClientOptions options) : options_(std::move(options)) {}

core::StatusOr<std::string> HttpChatClient::Complete(const std::vector<ChatMessage>& messages) {
  last_attempts_ = 0;
  SH_RETURN_IF_ERROR(options_.Validate());
  std::string scheme_host_port, base_path;
  SH_RETURN_IF_ERROR(SplitUrl(options_.url, &scheme_host_port, &base_path));
  const std::string endpoint = options_.url + "/chat/completions";

  // invalid UTF-8 in messages is replaced, never thrown on
  nlohmann::json request = {{"model", options_.model},
                            {"messages", nlohmann::json::array()},
                            {"temperature", options_.temperature},
                            {"stream", false}};
  if (options_.max_tokens > 0) request["max_tokens"] = options_.max_tokens;
  for (const ChatMessage& m : messages) {
    request["messages"].push_back({{"role", m.role}, {"content", m.content}});
  }
  const std::string body = request.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);

  // never let the key reach a message, even if a server echoes it back
  auto scrub = [this](core::Status s) {
    if (options_.api_key.empty() || s.ok()) return s;
    std::string m(s.message());
    for (size_t p = m.find(options_.api_key); p != std::string::npos;
         p = m.find(options_.api_key, p)) {
      m.replace(p, options_.api_key.size(), "<redacted>");
    }
    return core::Status(s.code(), m);
  };
  auto fail = [&](absl::StatusCode code, const std::string& what) {
    return scrub(core::Status(code, "LLM server " + endpoint + ": " + what));
  };

  const int attempts = 1 + options_.max_retries;
  double backoff_s = options_.backoff_s;
  std::string last_error;
  for (int attempt = 1; attempt <= attempts; ++attempt) {
    last_attempts_ = attempt;
    httplib::Client client(scheme_host_port);
    client.set_tcp_nodelay(true);
    client.set_keep_alive(false);
    client.set_follow_location(false);
    SetTimeouts(client, options_.timeout_s);

    httplib::Request req;
    req.method = "POST";
    req.path = base_path + "/chat/completions";
    req.headers = {{"Content-Type", "application/json"}, {"Accept", "application/json"}};
    if (!options_.api_key.empty()) {
      req.headers.emplace("Authorization", "Bearer " + options_.api_key);
    }
    req.body = body;
    std::string reply;
    bool too_big = false;
    bool too_slow = false;
    const Clock::time_point start = Clock::now();
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(options_.timeout_s));
    req.content_receiver = [&](const char* data, size_t n, uint64_t, uint64_t) {
      if (reply.size() + n > options_.max_reply_bytes) {
        too_big = true;
        return false;
      }
      if (Clock::now() > deadline) {
        too_slow = true;
        return false;
      }
      reply.append(data, n);
      return true;
    };

    httplib::Result res = client.send(req);
    const double elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
    std::optional<double> retry_after_s;
    if (too_big) {
      return fail(absl::StatusCode::kUnavailable, "the reply is larger than max_reply_bytes (" +
                                                      std::to_string(options_.max_reply_bytes) +
                                                      " bytes)");
    }
    if (!res) {
      httplib::Error e = res.error();
      bool timed_out = too_slow || e == httplib::Error::ConnectionTimeout ||
                       (e == httplib::Error::Read && elapsed_s >= 0.9 * options_.timeout_s);
      if (timed_out) {
        return fail(absl::StatusCode::kDeadlineExceeded,
                    "no complete reply within the timeout of " + Num(options_.timeout_s) + " s");
      }
      bool retryable = e == httplib::Error::Connection || e == httplib::Error::Read ||
                       e == httplib::Error::Write || e == httplib::Error::Unknown;
      last_error =
          "request failed: " + httplib::to_string(e) +
          (e == httplib::Error::Connection ? " (is the server running at that address?)" : "");
      if (!retryable) return fail(absl::StatusCode::kUnavailable, last_error);
    } else if (res->status >= 200 && res->status < 300) {
      core::StatusOr<std::string> content = ContentOf(reply);
      if (!content.ok())
        return fail(content.status().code(), std::string(content.status().message()));
      return content;
    } else if (res->status == 429 || res->status >= 500) {
      last_error = "HTTP " + std::to_string(res->status) + ": " + ServerMessage(reply);
      retry_after_s = RetryAfterSeconds(res);
    } else {
      std::string hint;
      if (res->status == 401 || res->status == 403) {
        hint = " (check the API key environment variable)";
      } else if (res->status == 404) {
        hint = " (check the URL, e.g. http://127.0.0.1:8080/v1, and the model name)";
      }
      return fail(absl::StatusCode::kUnavailable,
                  "HTTP " + std::to_string(res->status) + hint + ": " + ServerMessage(reply));
    }
    if (attempt == attempts) break;
    // back off before the next attempt; a server's Retry-After is honoured up to the cap
    double wait_s = std::min(retry_after_s.value_or(backoff_s), options_.max_backoff_s);
    backoff_s *= 2.0;
    std::this_thread::sleep_for(std::chrono::duration<double>(wait_s));
  }
  return fail(absl::StatusCode::kUnavailable, last_error + " (after " + std::to_string(attempts) +
                                                  (attempts == 1 ? " attempt)" : " attempts)"));
}

}  // namespace simhuman::language
