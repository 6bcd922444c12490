#pragma once
/// A minimal client for OpenAI-compatible chat completions (POST <base url>/chat/completions),
/// as served by llama.cpp's server, Ollama, vLLM and hosted APIs. Bounded retries with backoff
/// for connection errors, 429 and 5xx; a per-attempt deadline; a cap on the reply size. The API
/// key is sent as "Authorization: Bearer <key>" and never appears in a status message. No
/// MuJoCo here; nothing is printed.

#include <string>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::language {

/// One chat message.
struct ChatMessage {
  std::string role;  ///< "system", "user" or "assistant"
  std::string content;
};

/// Settings of HttpChatClient. Validate() names the field at fault.
struct ChatClientOptions {
  /// Base URL of the API, "http://host[:port][/path]" or "https://...", e.g.
  /// "http://127.0.0.1:8080/v1"; "/chat/completions" is appended.
  std::string url = "http://127.0.0.1:8080/v1";
  std::string model;                ///< the "model" field of the request (required)
  std::string api_key;              ///< empty: no Authorization header
  double timeout_s = 60.0;          ///< per attempt: connect, send, and the whole reply
  int max_retries = 2;              ///< extra attempts after a retryable failure, 0..10
  double backoff_s = 0.5;           ///< first wait between attempts; doubles each retry
  double max_backoff_s = 8.0;       ///< cap of every wait, including a server's Retry-After
  size_t max_reply_bytes = 262144;  ///< a longer response body is an error
  double temperature = 0.0;         ///< 0..2
  int max_tokens = 2048;            ///< "max_tokens" of the request; 0: not sent

  /// OK, or InvalidArgument naming the field ("timeout_s: ...") and its valid range.
  core::Status Validate() const;
};

/// Splits "http[s]://host[:port][/path]" into "scheme://host[:port]" and the path without a
/// trailing '/'. InvalidArgument naming the URL otherwise.
core::Status SplitUrl(const std::string& url, std::string* scheme_host_port, std::string* path);

/// Sends chat requests to one server. Thread-compatible; one request at a time per instance.
class HttpChatClient {
 public:
  /// `options` must pass Validate() (checked again by Complete()).
  explicit HttpChatClient(ChatClientOptions options);

  /// Sends `messages` and returns the assistant's reply text (choices[0].message.content).
  /// Errors (never with the API key in them):
  /// - DeadlineExceeded: no complete reply within timeout_s (not retried);
  /// - Unavailable: connection failure, 429 or 5xx after max_retries retries, another HTTP
  ///   error status (with a short preview of the server's message), a body over
  ///   max_reply_bytes, or a body that is not a chat completion;
  /// - InvalidArgument: bad options.
  core::StatusOr<std::string> Complete(const std::vector<ChatMessage>& messages);

  /// Number of HTTP attempts made by the last Complete() call (for tests and logs).
  int last_attempts() const { return last_attempts_; }

 private:
  ChatClientOptions options_;
  int last_attempts_ = 0;
};

}  // namespace simhuman::language
