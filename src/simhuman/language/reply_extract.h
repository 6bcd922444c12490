#pragma once
/// Finding the plan in a language model's reply text. The reply is untrusted: it may be any
/// bytes (chatter, invalid UTF-8, deeply nested brackets, several JSON values). Nothing in it is
/// ever acted on except the one JSON value returned here, which callers then parse strictly as a
/// Chain of Contacts. No MuJoCo here.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "simhuman/core/status.h"

namespace simhuman::language {

/// Limits of ExtractPlanJson(); the defaults suit replies of a few KiB.
struct ExtractLimits {
  /// Brackets deeper than this make a candidate invalid (a plan needs depth 4).
  int max_depth = 32;
  /// At most this many candidate start positions are tried (bounds the work on hostile text).
  int max_candidates = 64;
};

/// Returns the JSON value that holds the plan in `reply`:
/// 1. the first ```json (or ```JSON) fenced block whose content parses as a JSON object or
///    array, then any other ``` fenced block that does;
/// 2. otherwise, scanning from the start, the first balanced {...} or [...] (brackets inside
///    JSON strings ignored) that parses as JSON; a value shaped like a plan (an object with
///    "steps" or "chain of contacts", or an array whose first element is an array) is preferred
///    over an earlier value that is not (e.g. "[1]" in chatter before the plan).
/// Errors are InvalidArgument starting with "llm reply: " and say what was expected, with a
/// short printable preview of the reply. Never throws; thread-safe.
core::StatusOr<nlohmann::json> ExtractPlanJson(std::string_view reply,
                                               const ExtractLimits& limits = {});

/// A printable one-line preview of untrusted text for error messages: at most `max_chars`
/// characters, control and non-ASCII bytes replaced by '?', "..." appended when cut.
std::string Preview(std::string_view text, size_t max_chars = 80);

}  // namespace simhuman::language
