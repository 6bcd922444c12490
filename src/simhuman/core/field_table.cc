#include "simhuman/core/field_table.h"

#include <algorithm>
#include <set>
#include <type_traits>

#include "simhuman/core/check.h"

namespace simhuman::core::field_internal {
namespace {

using nlohmann::json;

template <typename V>
Status Store(StatusOr<V> read, V* out) {
  if (!read.ok()) return read.status();
  *out = std::move(read).value();
  return absl::OkStatus();
}

Status Invalid(std::string_view table, const FieldSpec& spec, const std::string& value,
               const std::string& valid) {
  return absl::InvalidArgumentError(std::string(table) + " '" + spec.key + "' = " + value +
                                    " is invalid; " + valid);
}

// JSON-quoted; invalid UTF-8 is replaced rather than thrown on
std::string Quoted(const std::string& s) {
  return json(s).dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string Shown(int v) { return std::to_string(v); }
std::string Shown(double v) { return FormatNumber(v); }

template <typename V>
std::string ListOf(const std::vector<V>& values) {
  std::string out = "[";
  for (size_t i = 0; i < values.size(); ++i) {
    if (i) out += ", ";
    if constexpr (std::is_same_v<V, std::string>) {
      out += Quoted(values[i]);
    } else if constexpr (std::is_same_v<V, double>) {
      out += FormatNumber(values[i]);
    } else {
      out += std::to_string(values[i]);
    }
  }
  return out + "]";
}

Status CheckNumber(std::string_view table, const FieldSpec& spec, double value,
                   const std::string& shown) {
  if (spec.range.Contains(value)) return absl::OkStatus();
  return Invalid(table, spec, shown, "valid range is " + spec.range.ToString());
}

// the reason `s` is not valid for `spec`, or "" when it is
std::string StringProblem(const FieldSpec& spec, const std::string& s) {
  if (spec.non_empty && s.empty()) return "it must not be empty";
  if (!spec.names.empty() &&
      std::find(spec.names.begin(), spec.names.end(), s) == spec.names.end()) {
    return "valid values are: " + JoinNames(spec.names);
  }
  return "";
}

Status CheckItems(std::string_view table, const FieldSpec& spec, size_t n,
                  const std::string& shown) {
  if (n >= spec.min_items) return absl::OkStatus();
  return Invalid(table, spec, shown,
                 "it needs at least " + std::to_string(spec.min_items) +
                     (spec.min_items == 1 ? " entry" : " entries"));
}

}  // namespace

Status Read(const json& v, const std::string& ptr, double* out) {
  return Store(ReadNumber(v, ptr), out);
}
Status Read(const json& v, const std::string& ptr, int* out) { return Store(ReadInt(v, ptr), out); }
Status Read(const json& v, const std::string& ptr, int64_t* out) {
  return Store(ReadInt64(v, ptr), out);
}
Status Read(const json& v, const std::string& ptr, uint64_t* out) {
  return Store(ReadUint64(v, ptr), out);
}
Status Read(const json& v, const std::string& ptr, bool* out) {
  return Store(ReadBool(v, ptr), out);
}
Status Read(const json& v, const std::string& ptr, std::string* out) {
  return Store(ReadString(v, ptr), out);
}
Status Read(const json& v, const std::string& ptr, std::vector<int>* out) {
  return Store(ReadInts(v, ptr), out);
}
Status Read(const json& v, const std::string& ptr, std::vector<double>* out) {
  return Store(ReadNumbers(v, ptr, 0, 1u << 20), out);
}
Status Read(const json& v, const std::string& ptr, std::vector<std::string>* out) {
  return Store(ReadStrings(v, ptr), out);
}

Status Check(std::string_view table, const FieldSpec& spec, double value) {
  return CheckNumber(table, spec, value, FormatNumber(value));
}
Status Check(std::string_view table, const FieldSpec& spec, int value) {
  return CheckNumber(table, spec, value, std::to_string(value));
}
Status Check(std::string_view table, const FieldSpec& spec, int64_t value) {
  return CheckNumber(table, spec, static_cast<double>(value), std::to_string(value));
}
Status Check(std::string_view table, const FieldSpec& spec, uint64_t value) {
  return CheckNumber(table, spec, static_cast<double>(value), std::to_string(value));
}
Status Check(std::string_view, const FieldSpec&, bool) { return absl::OkStatus(); }

Status Check(std::string_view table, const FieldSpec& spec, const std::string& value) {
  std::string problem = StringProblem(spec, value);
  if (problem.empty()) return absl::OkStatus();
  return Invalid(table, spec, Quoted(value), problem);
}

namespace {

template <typename V>
Status CheckNumbers(std::string_view table, const FieldSpec& spec, const std::vector<V>& value) {
  SH_RETURN_IF_ERROR(CheckItems(table, spec, value.size(), ListOf(value)));
  for (size_t i = 0; i < value.size(); ++i) {
    if (!spec.range.Contains(value[i])) {
      return Invalid(table, spec, ListOf(value),
                     "entry " + std::to_string(i) + " (" + Shown(value[i]) +
                         ") is outside the valid range " + spec.range.ToString());
    }
  }
  return absl::OkStatus();
}

}  // namespace

Status Check(std::string_view table, const FieldSpec& spec, const std::vector<int>& value) {
  return CheckNumbers(table, spec, value);
}
Status Check(std::string_view table, const FieldSpec& spec, const std::vector<double>& value) {
  return CheckNumbers(table, spec, value);
}

Status Check(std::string_view table, const FieldSpec& spec, const std::vector<std::string>& value) {
  SH_RETURN_IF_ERROR(CheckItems(table, spec, value.size(), ListOf(value)));
  for (size_t i = 0; i < value.size(); ++i) {
    std::string problem = StringProblem(spec, value[i]);
    if (!problem.empty()) {
      return Invalid(table, spec, ListOf(value), "entry " + std::to_string(i) + ": " + problem);
    }
  }
  return absl::OkStatus();
}

void CheckUniqueKeys(const std::vector<std::string>& keys) {
  std::set<std::string> seen;
  for (const std::string& k : keys) {
    SH_CHECK(!k.empty(), "a field table has an empty key");
    SH_CHECK(seen.insert(k).second, k.c_str());
  }
}

}  // namespace simhuman::core::field_internal
