#pragma once
/// The strict JSON reader every parser of user files uses: JSON pointers for error locations,
/// numeric ranges, and typed getters whose errors name the pointer of the culprit, what was
/// expected and what was found ("/objects/0/pos/1: expected a number, got string").
/// Stateless and thread-safe. Config structs use it through core/field_table.h.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::core {

/// The JSON pointer (RFC 6901) of member `key` of the value at `parent`: "~" and "/" in the key
/// are escaped as "~0" and "~1". A `parent` of "" or "/" means the document root, so
/// JsonPointer("/", "objects") and JsonPointer("", "objects") are both "/objects".
std::string JsonPointer(std::string_view parent, std::string_view key);

/// The JSON pointer of entry `index` of the array at `parent` ("/objects/3").
std::string JsonPointer(std::string_view parent, size_t index);

/// An interval of finite numbers: each end closed, open or unbounded (an infinite end).
/// NaN and infinities are never inside.
struct NumberRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;  ///< (lo, ... instead of [lo, ...
  bool hi_open = false;  ///< ..., hi) instead of ..., hi]

  /// Every finite number.
  static NumberRange Any() { return {}; }
  /// [lo, hi].
  static NumberRange Closed(double lo, double hi) { return {lo, hi, false, false}; }
  /// [lo, inf).
  static NumberRange AtLeast(double lo) { return {lo, Inf(), false, false}; }
  /// (lo, inf).
  static NumberRange Above(double lo) { return {lo, Inf(), true, false}; }
  /// (lo, hi].
  static NumberRange AboveUpTo(double lo, double hi) { return {lo, hi, true, false}; }

  /// True for finite `v` inside the interval.
  bool Contains(double v) const;
  /// "[2, 1024]", "(0, 1]", "[1, inf)", "(-inf, inf)".
  std::string ToString() const;

 private:
  static double Inf() { return std::numeric_limits<double>::infinity(); }
};

/// A number for messages: integral values below 1e15 in full ("4096"), others with six
/// significant digits ("0.0003", "1e+20"), and "nan" / "inf" / "-inf".
std::string FormatNumber(double v);

/// InvalidArgument "<ptr>: <what>".
Status JsonError(std::string_view ptr, std::string_view what);

/// Fails unless `obj` is an object holding `key`: "<ptr>/<key>: missing required key".
/// `ptr` is the pointer of `obj`.
Status RequireKey(const nlohmann::json& obj, std::string_view key, std::string_view ptr);

/// Fails unless `obj` is an object whose keys are all in `allowed`:
/// "<ptr>: unknown key 'k'; valid keys are: a, b" or "<ptr>: expected a JSON object, got array".
Status CheckKeys(const nlohmann::json& obj, const std::vector<std::string>& allowed,
                 std::string_view ptr);

/// Required members of the object `obj` (pointer `ptr`): "<ptr>/<key>: missing required number"
/// (or string) when absent, otherwise as ReadNumber / ReadString.
StatusOr<double> GetNumber(const nlohmann::json& obj, const std::string& key, std::string_view ptr);
StatusOr<std::string> GetString(const nlohmann::json& obj, const std::string& key,
                                std::string_view ptr);

// Typed getters. Each reads the value `v` whose pointer is `ptr`; a wrong type is
// "<ptr>: expected <type>, got <JSON type>", a non-finite number "<ptr>: number is not finite",
// a value outside `range` "<ptr>: <value> is outside the valid range <range>".

/// A finite number inside `range`.
StatusOr<double> ReadNumber(const nlohmann::json& v, std::string_view ptr,
                            const NumberRange& range = NumberRange::Any());
/// Member `key` of the object `obj` (pointer `ptr`) read as ReadNumber; empty when absent.
StatusOr<std::optional<double>> ReadOptionalNumber(const nlohmann::json& obj, std::string_view key,
                                                   std::string_view ptr,
                                                   const NumberRange& range = NumberRange::Any());
/// An integral number (1, 1.0, 3e7) that fits an int and lies inside `range`; 1.5 is
/// "expected an integer, got 1.5", 3e9 "expected an integer in [-2147483648, 2147483647]".
StatusOr<int> ReadInt(const nlohmann::json& v, std::string_view ptr,
                      const NumberRange& range = NumberRange::Any());
/// As ReadInt, for int64_t (exact for every JSON integer in range).
StatusOr<int64_t> ReadInt64(const nlohmann::json& v, std::string_view ptr,
                            const NumberRange& range = NumberRange::Any());
/// As ReadInt, for uint64_t (exact up to 18446744073709551615; negative numbers are errors).
StatusOr<uint64_t> ReadUint64(const nlohmann::json& v, std::string_view ptr,
                              const NumberRange& range = NumberRange::Any());
/// true or false (numbers are not booleans).
StatusOr<bool> ReadBool(const nlohmann::json& v, std::string_view ptr);
/// A string.
StatusOr<std::string> ReadString(const nlohmann::json& v, std::string_view ptr);
/// A string that is one of `valid`; otherwise "<ptr>: unknown <noun> 'x'; valid <noun>s are:
/// a, b" (noun e.g. "posture", "value").
StatusOr<std::string> ReadName(const nlohmann::json& v, std::string_view ptr,
                               const std::vector<std::string>& valid,
                               std::string_view noun = "value");
/// An array of min_len..max_len finite numbers: "<ptr>: expected an array of 2 or 3 numbers,
/// got an array of 4"; a bad entry is named by its own pointer ("<ptr>/1").
StatusOr<std::vector<double>> ReadNumbers(const nlohmann::json& v, std::string_view ptr,
                                          size_t min_len, size_t max_len);
/// An array of exactly N finite numbers.
template <size_t N>
StatusOr<std::array<double, N>> ReadFixedNumbers(const nlohmann::json& v, std::string_view ptr) {
  SH_ASSIGN_OR_RETURN(std::vector<double> d, ReadNumbers(v, ptr, N, N));
  std::array<double, N> out;
  for (size_t i = 0; i < N; ++i) out[i] = d[i];
  return out;
}
/// An array of integers, each read as ReadInt with `each`.
StatusOr<std::vector<int>> ReadInts(const nlohmann::json& v, std::string_view ptr,
                                    const NumberRange& each = NumberRange::Any());
/// An array of strings.
StatusOr<std::vector<std::string>> ReadStrings(const nlohmann::json& v, std::string_view ptr);

}  // namespace simhuman::core
