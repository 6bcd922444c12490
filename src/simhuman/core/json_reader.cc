#include "simhuman/core/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <type_traits>

namespace simhuman::core {
namespace {

using nlohmann::json;

std::string TypeName(const json& v) { return v.type_name(); }

// what a value is, for "got ..." in messages: numbers by value, everything else by type
std::string Found(const json& v) {
  if (v.is_number_float()) return FormatNumber(v.get<double>());
  if (v.is_number()) return v.dump();
  return TypeName(v);
}

Status OutsideRange(std::string_view ptr, const std::string& value, const NumberRange& range) {
  return JsonError(ptr, value + " is outside the valid range " + range.ToString());
}

// an integral JSON number that fits I, checked against `range`; exact for every JSON integer
template <typename I>
StatusOr<I> ReadInteger(const json& v, std::string_view ptr, const NumberRange& range) {
  using Limits = std::numeric_limits<I>;
  if (!v.is_number()) return JsonError(ptr, "expected an integer, got " + TypeName(v));
  const std::string fits = "expected an integer in [" + std::to_string(Limits::min()) + ", " +
                           std::to_string(Limits::max()) + "], got " + Found(v);
  I out = 0;
  if (v.is_number_unsigned()) {
    uint64_t u = v.get<uint64_t>();
    if constexpr (!std::is_same_v<I, uint64_t>) {
      if (u > static_cast<uint64_t>(Limits::max())) return JsonError(ptr, fits);
    }
    out = static_cast<I>(u);
  } else if (v.is_number_integer()) {
    int64_t s = v.get<int64_t>();
    if constexpr (!Limits::is_signed) {
      if (s < 0) return JsonError(ptr, fits);
    } else if constexpr (!std::is_same_v<I, int64_t>) {
      if (s < Limits::min() || s > Limits::max()) return JsonError(ptr, fits);
    }
    out = static_cast<I>(s);
  } else {
    double d = v.get<double>();
    if (!std::isfinite(d)) return JsonError(ptr, "number is not finite");
    if (d != std::floor(d)) return JsonError(ptr, "expected an integer, got " + Found(v));
    // the limits as doubles: min is a power of two (exact); max + 1 is one too
    const double lo = static_cast<double>(Limits::min());
    const double hi_excl = std::ldexp(1.0, Limits::digits);
    if (d < lo || d >= hi_excl) return JsonError(ptr, fits);
    out = static_cast<I>(d);
  }
  if (!range.Contains(static_cast<double>(out))) {
    return OutsideRange(ptr, std::to_string(out), range);
  }
  return out;
}

}  // namespace

std::string JsonPointer(std::string_view parent, std::string_view key) {
  std::string out = parent == "/" ? std::string() : std::string(parent);
  out += '/';
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string JsonPointer(std::string_view parent, size_t index) {
  return JsonPointer(parent, std::to_string(index));
}

bool NumberRange::Contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string NumberRange::ToString() const {
  // an infinite end is always open
  bool lo_excl = lo_open || std::isinf(lo);
  bool hi_excl = hi_open || std::isinf(hi);
  return std::string(lo_excl ? "(" : "[") + FormatNumber(lo) + ", " + FormatNumber(hi) +
         (hi_excl ? ")" : "]");
}

std::string FormatNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (v == std::floor(v) && std::abs(v) < 1e15) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.0f", v == 0 ? 0.0 : v);  // no "-0"
    return buf;
  }
  std::ostringstream s;
  s << v;
  return s.str();
}

Status JsonError(std::string_view ptr, std::string_view what) {
  return absl::InvalidArgumentError(std::string(ptr) + ": " + std::string(what));
}

Status RequireKey(const json& obj, std::string_view key, std::string_view ptr) {
  if (!obj.is_object()) return JsonError(ptr, "expected a JSON object, got " + TypeName(obj));
  if (!obj.contains(key)) return JsonError(JsonPointer(ptr, key), "missing required key");
  return absl::OkStatus();
}

Status CheckKeys(const json& obj, const std::vector<std::string>& allowed, std::string_view ptr) {
  if (!obj.is_object()) return JsonError(ptr, "expected a JSON object, got " + TypeName(obj));
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) {
      return JsonError(ptr,
                       "unknown key '" + it.key() + "'; valid keys are: " + JoinNames(allowed));
    }
  }
  return absl::OkStatus();
}

StatusOr<double> GetNumber(const json& obj, const std::string& key, std::string_view ptr) {
  std::string at = JsonPointer(ptr, key);
  if (!obj.is_object() || !obj.contains(key)) return JsonError(at, "missing required number");
  return ReadNumber(obj.at(key), at);
}

StatusOr<std::string> GetString(const json& obj, const std::string& key, std::string_view ptr) {
  std::string at = JsonPointer(ptr, key);
  if (!obj.is_object() || !obj.contains(key)) return JsonError(at, "missing required string");
  return ReadString(obj.at(key), at);
}

StatusOr<double> ReadNumber(const json& v, std::string_view ptr, const NumberRange& range) {
  if (!v.is_number()) return JsonError(ptr, "expected a number, got " + TypeName(v));
  double d = v.get<double>();
  if (!std::isfinite(d)) return JsonError(ptr, "number is not finite");
  if (!range.Contains(d)) return OutsideRange(ptr, FormatNumber(d), range);
  return d;
}

StatusOr<std::optional<double>> ReadOptionalNumber(const json& obj, std::string_view key,
                                                   std::string_view ptr, const NumberRange& range) {
  auto it = obj.find(key);
  if (it == obj.end()) return std::optional<double>();
  SH_ASSIGN_OR_RETURN(double d, ReadNumber(*it, JsonPointer(ptr, key), range));
  return std::optional<double>(d);
}

StatusOr<int> ReadInt(const json& v, std::string_view ptr, const NumberRange& range) {
  return ReadInteger<int>(v, ptr, range);
}

StatusOr<int64_t> ReadInt64(const json& v, std::string_view ptr, const NumberRange& range) {
  return ReadInteger<int64_t>(v, ptr, range);
}

StatusOr<uint64_t> ReadUint64(const json& v, std::string_view ptr, const NumberRange& range) {
  return ReadInteger<uint64_t>(v, ptr, range);
}

StatusOr<bool> ReadBool(const json& v, std::string_view ptr) {
  if (!v.is_boolean()) return JsonError(ptr, "expected true or false, got " + TypeName(v));
  return v.get<bool>();
}

StatusOr<std::string> ReadString(const json& v, std::string_view ptr) {
  if (!v.is_string()) return JsonError(ptr, "expected a string, got " + TypeName(v));
  return v.get<std::string>();
}

StatusOr<std::string> ReadName(const json& v, std::string_view ptr,
                               const std::vector<std::string>& valid, std::string_view noun) {
  SH_ASSIGN_OR_RETURN(std::string s, ReadString(v, ptr));
  if (std::find(valid.begin(), valid.end(), s) == valid.end()) {
    return JsonError(ptr, "unknown " + std::string(noun) + " '" + s + "'; valid " +
                              std::string(noun) + "s are: " + JoinNames(valid));
  }
  return s;
}

StatusOr<std::vector<double>> ReadNumbers(const json& v, std::string_view ptr, size_t min_len,
                                          size_t max_len) {
  if (!v.is_array() || v.size() < min_len || v.size() > max_len) {
    std::string want = min_len == max_len
                           ? std::to_string(min_len)
                           : std::to_string(min_len) + " or " + std::to_string(max_len);
    if (max_len > min_len + 1) {
      want = std::to_string(min_len) + " to " + std::to_string(max_len);
    }
    return JsonError(ptr,
                     "expected an array of " + want + " numbers, got " +
                         (v.is_array() ? "an array of " + std::to_string(v.size()) : TypeName(v)));
  }
  std::vector<double> out;
  out.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    SH_ASSIGN_OR_RETURN(double d, ReadNumber(v[i], JsonPointer(ptr, i)));
    out.push_back(d);
  }
  return out;
}

StatusOr<std::vector<int>> ReadInts(const json& v, std::string_view ptr, const NumberRange& each) {
  if (!v.is_array()) return JsonError(ptr, "expected an array of integers, got " + TypeName(v));
  std::vector<int> out;
  out.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    SH_ASSIGN_OR_RETURN(int x, ReadInt(v[i], JsonPointer(ptr, i), each));
    out.push_back(x);
  }
  return out;
}

StatusOr<std::vector<std::string>> ReadStrings(const json& v, std::string_view ptr) {
  if (!v.is_array()) return JsonError(ptr, "expected an array of strings, got " + TypeName(v));
  std::vector<std::string> out;
  out.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    SH_ASSIGN_OR_RETURN(std::string s, ReadString(v[i], JsonPointer(ptr, i)));
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace simhuman::core
