#include "simhuman/language/reply_extract.h"

#include <cctype>
#include <optional>
#include <vector>

namespace simhuman::language {
namespace {

constexpr std::string_view kFence = "```";

// end (one past) of the balanced JSON value that starts with '{' or '[' at `begin`, ignoring
// brackets inside strings; nullopt when it is unbalanced, mismatched or nested too deep
std::optional<size_t> BalancedEnd(std::string_view text, size_t begin, int max_depth) {
  std::vector<char> closers;
  bool in_string = false;
  bool escaped = false;
  for (size_t i = begin; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      if (static_cast<int>(closers.size()) >= max_depth) return std::nullopt;
      closers.push_back(c == '{' ? '}' : ']');
    } else if (c == '}' || c == ']') {
      if (closers.empty() || closers.back() != c) return std::nullopt;
      closers.pop_back();
      if (closers.empty()) return i + 1;
    }
  }
  return std::nullopt;
}

// parses `text` as one JSON object or array no deeper than `max_depth`; nullopt otherwise
std::optional<nlohmann::json> TryParse(std::string_view text, int max_depth) {
  size_t b = text.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos || (text[b] != '{' && text[b] != '[')) return std::nullopt;
  std::optional<size_t> end = BalancedEnd(text, b, max_depth);
  if (!end) return std::nullopt;
  if (text.find_first_not_of(" \t\r\n", *end) != std::string_view::npos) return std::nullopt;
  try {
    nlohmann::json j = nlohmann::json::parse(text.begin() + b, text.begin() + *end, nullptr,
                                             /*allow_exceptions=*/false);
    if (j.is_discarded()) return std::nullopt;
    return j;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // e.g. a number out of range
  }
}

bool LooksLikePlan(const nlohmann::json& j) {
  if (j.is_object()) return j.contains("steps") || j.contains("chain of contacts");
  return j.is_array() && !j.empty() && j.front().is_array();
}

struct Fenced {
  std::string tag;  // lower case info string, e.g. "json"
  std::string_view content;
};

// every ``` fenced block; an unclosed last fence runs to the end of the text (cut replies)
std::vector<Fenced> FencedBlocks(std::string_view text) {
  std::vector<Fenced> blocks;
  size_t pos = 0;
  while (true) {
    size_t open = text.find(kFence, pos);
    if (open == std::string_view::npos) break;
    size_t line_end = text.find('\n', open + kFence.size());
    if (line_end == std::string_view::npos) break;
    Fenced block;
    for (size_t i = open + kFence.size(); i < line_end; ++i) {
      unsigned char c = static_cast<unsigned char>(text[i]);
      if (!std::isspace(c)) block.tag += static_cast<char>(std::tolower(c));
    }
    size_t close = text.find(kFence, line_end + 1);
    size_t content_end = close == std::string_view::npos ? text.size() : close;
    block.content = text.substr(line_end + 1, content_end - line_end - 1);
    blocks.push_back(block);
    if (close == std::string_view::npos) break;
    pos = close + kFence.size();
  }
  return blocks;
}

}  // namespace

std::string Preview(std::string_view text, size_t max_chars) {
  std::string out;
  for (size_t i = 0; i < text.size() && out.size() < max_chars; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    out += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : (c == '\n' ? ' ' : '?');
  }
  if (text.size() > max_chars) out += "...";
  return out;
}

core::StatusOr<nlohmann::json> ExtractPlanJson(std::string_view reply,
                                               const ExtractLimits& limits) {
  // 1. fenced blocks: ```json first, then untagged or other tags
  std::vector<Fenced> blocks = FencedBlocks(reply);
  for (int pass = 0; pass < 2; ++pass) {
    for (const Fenced& block : blocks) {
      if ((block.tag == "json") != (pass == 0)) continue;
      if (std::optional<nlohmann::json> j = TryParse(block.content, limits.max_depth)) {
        return std::move(*j);
      }
    }
  }

  // 2. balanced values in the text, a plan-shaped one preferred
  std::optional<nlohmann::json> first;
  int candidates = 0;
  size_t pos = 0;
  while (pos < reply.size() && candidates < limits.max_candidates) {
    size_t start = reply.find_first_of("{[", pos);
    if (start == std::string_view::npos) break;
    ++candidates;
    std::optional<size_t> end = BalancedEnd(reply, start, limits.max_depth);
    std::optional<nlohmann::json> j;
    if (end) j = TryParse(reply.substr(start, *end - start), limits.max_depth);
    if (!j) {
      pos = start + 1;
      continue;
    }
    if (LooksLikePlan(*j)) return std::move(*j);
    if (!first) first = std::move(j);
    pos = *end;  // skip values nested inside this one
  }
  if (first) return std::move(*first);

  if (reply.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return absl::InvalidArgumentError(
        "llm reply: the reply is empty; expected a plan as JSON (a ```json fenced block or a "
        "JSON object with \"steps\")");
  }
  return absl::InvalidArgumentError(
      "llm reply: no JSON plan found; expected a ```json fenced block or a JSON object with "
      "\"steps\" (or a UniHSI list of steps); the reply starts: '" +
      Preview(reply) + "'");
}

}  // namespace simhuman::language
