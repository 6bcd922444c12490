#pragma once
/// One table per config struct drives its strict JSON reading, its validation and its JSON
/// output. Each row names a key, the struct member it fills (double, int, int64_t, uint64_t,
/// bool, std::string, std::vector<int>, std::vector<double> or std::vector<std::string>), what is
/// valid (a range, a list of names, a minimum length) and a short doc:
///
///   const core::FieldTable<MpcConfig>& Table() {
///     using F = core::Field<MpcConfig>;
///     static const core::FieldTable<MpcConfig> kTable(
///         "mpc config", {F("samples", &MpcConfig::samples, "rollouts per replan")
///                            .In(core::NumberRange::Closed(2, 1024)),
///                        F("preset", &MpcConfig::preset, "preset").OneOf({"fast", "quality"})});
///     return kTable;
///   }
///
/// Read(): unknown keys are errors naming the key and listing the valid keys; a wrong type is an
/// error naming the JSON pointer and the expected type; missing keys keep the struct's values.
/// Validate(): the first invalid field, named with its key, value and valid range or names.
/// Tables are immutable after construction and safe to share between threads.

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "simhuman/core/json_reader.h"
#include "simhuman/core/status.h"

namespace simhuman::core {

/// What one field accepts, independent of the struct it lives in.
struct FieldSpec {
  std::string key;
  std::string doc;                 ///< one line: meaning and units
  NumberRange range;               ///< numbers, and each entry of an int array
  std::vector<std::string> names;  ///< strings and each entry of a string array; empty: any
  size_t min_items = 0;            ///< arrays: fewest entries
  bool non_empty = false;          ///< strings and each entry of a string array: not ""
};

// The non-template part: one overload per member type (field_table.cc).
namespace field_internal {

/// Reads `v` (pointer `ptr`) into `out`: type errors only; ranges and names are Validate's.
Status Read(const nlohmann::json& v, const std::string& ptr, double* out);
Status Read(const nlohmann::json& v, const std::string& ptr, int* out);
Status Read(const nlohmann::json& v, const std::string& ptr, int64_t* out);
Status Read(const nlohmann::json& v, const std::string& ptr, uint64_t* out);
Status Read(const nlohmann::json& v, const std::string& ptr, bool* out);
Status Read(const nlohmann::json& v, const std::string& ptr, std::string* out);
Status Read(const nlohmann::json& v, const std::string& ptr, std::vector<int>* out);
Status Read(const nlohmann::json& v, const std::string& ptr, std::vector<double>* out);
Status Read(const nlohmann::json& v, const std::string& ptr, std::vector<std::string>* out);

/// "<table> '<key>' = <value> is invalid; <what is valid>" when `value` breaks `spec`.
Status Check(std::string_view table, const FieldSpec& spec, double value);
Status Check(std::string_view table, const FieldSpec& spec, int value);
Status Check(std::string_view table, const FieldSpec& spec, int64_t value);
Status Check(std::string_view table, const FieldSpec& spec, uint64_t value);
Status Check(std::string_view table, const FieldSpec& spec, bool value);
Status Check(std::string_view table, const FieldSpec& spec, const std::string& value);
Status Check(std::string_view table, const FieldSpec& spec, const std::vector<int>& value);
Status Check(std::string_view table, const FieldSpec& spec, const std::vector<double>& value);
Status Check(std::string_view table, const FieldSpec& spec, const std::vector<std::string>& value);

/// Aborts (a bug in a table) on a duplicate or empty key.
void CheckUniqueKeys(const std::vector<std::string>& keys);

}  // namespace field_internal

/// One row of a FieldTable<T>: a key, the member of T it fills, and what is valid.
template <typename T>
class Field {
 public:
  using Member =
      std::variant<double T::*, int T::*, int64_t T::*, uint64_t T::*, bool T::*, std::string T::*,
                   std::vector<int> T::*, std::vector<double> T::*, std::vector<std::string> T::*>;

  /// `member` must be a pointer to one of the Member types.
  template <typename M>
  Field(std::string key, M T::*member, std::string doc) : member_(member) {
    spec_.key = std::move(key);
    spec_.doc = std::move(doc);
  }

  /// Valid numbers (numeric fields; each entry of an int array). Default: any finite number.
  Field& In(const NumberRange& range) {
    spec_.range = range;
    return *this;
  }
  /// Valid strings (string fields; each entry of a string array). Default: any.
  Field& OneOf(std::vector<std::string> names) {
    spec_.names = std::move(names);
    return *this;
  }
  /// Fewest entries of an array field.
  Field& MinItems(size_t n) {
    spec_.min_items = n;
    return *this;
  }
  /// No empty string (string fields; each entry of a string array).
  Field& NonEmpty() {
    spec_.non_empty = true;
    return *this;
  }

  const FieldSpec& spec() const { return spec_; }
  const Member& member() const { return member_; }

 private:
  FieldSpec spec_;
  Member member_;
};

/// The field table of config struct T (see the top of this file).
template <typename T>
class FieldTable {
 public:
  /// `name` starts validation messages ("mpc config 'samples' = 0 is invalid; ..."). Keys must
  /// be unique and non-empty (checked: a violation aborts).
  FieldTable(std::string name, std::vector<Field<T>> fields)
      : name_(std::move(name)), fields_(std::move(fields)) {
    field_internal::CheckUniqueKeys(Keys());
  }

  const std::string& name() const { return name_; }
  const std::vector<Field<T>>& fields() const { return fields_; }

  /// The keys in table order.
  std::vector<std::string> Keys() const {
    std::vector<std::string> keys;
    keys.reserve(fields_.size());
    for (const Field<T>& f : fields_) keys.push_back(f.spec().key);
    return keys;
  }

  /// Reads the members present in the JSON object `j` (whose pointer is `ptr`, "/" for the root)
  /// over `*out`; members not in `j` keep their values. Errors: `j` not an object, an unknown
  /// key ("<ptr>: unknown key 'k'; valid keys are: ..."), a wrong type ("<ptr>/<key>: expected
  /// an integer, got string"). On error `*out` is unchanged. Does not validate ranges or names.
  Status Read(const nlohmann::json& j, std::string_view ptr, T* out) const {
    SH_RETURN_IF_ERROR(CheckKeys(j, Keys(), ptr));
    T next = *out;
    for (const Field<T>& f : fields_) {
      auto it = j.find(f.spec().key);
      if (it == j.end()) continue;
      const std::string at = JsonPointer(ptr, f.spec().key);
      SH_RETURN_IF_ERROR(std::visit(
          [&](auto member) { return field_internal::Read(*it, at, &(next.*member)); }, f.member()));
    }
    *out = std::move(next);
    return absl::OkStatus();
  }

  /// OK when every field holds a valid value; otherwise the first invalid one, in table order.
  Status Validate(const T& value) const {
    for (const Field<T>& f : fields_) {
      SH_RETURN_IF_ERROR(std::visit(
          [&](auto member) { return field_internal::Check(name_, f.spec(), value.*member); },
          f.member()));
    }
    return absl::OkStatus();
  }

  /// Every field of `value` as a JSON object (numbers, booleans, strings, arrays).
  nlohmann::json ToJson(const T& value) const {
    nlohmann::json j = nlohmann::json::object();
    for (const Field<T>& f : fields_) {
      std::visit([&](auto member) { j[f.spec().key] = value.*member; }, f.member());
    }
    return j;
  }

 private:
  std::string name_;
  std::vector<Field<T>> fields_;
};

}  // namespace simhuman::core
