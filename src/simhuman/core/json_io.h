#pragma once
/// Reading files and JSON strictly, with errors that name the file, line and column.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "simhuman/core/status.h"

namespace simhuman::core {

/// Reads a whole file. NotFound names the path.
StatusOr<std::string> ReadFile(const std::string& path);

/// Writes a file atomically (temp file + rename).
Status WriteFileAtomic(const std::string& path, std::string_view contents);

/// Parses JSON text; a syntax error names `source` (a file name or "<string>") with line and
/// column.
StatusOr<nlohmann::json> ParseJson(std::string_view text, std::string_view source);

/// Reads and parses a JSON file.
StatusOr<nlohmann::json> ReadJsonFile(const std::string& path);

/// Fails if `obj` (must be an object) has keys not in `allowed`; names the JSON pointer
/// `where` and lists the allowed keys.
Status CheckKeys(const nlohmann::json& obj, const std::vector<std::string>& allowed,
                 std::string_view where);

/// Typed getters: a missing key (when required) or a wrong type is an error naming
/// `where/key`. Non-finite numbers are rejected.
StatusOr<double> GetNumber(const nlohmann::json& obj, const std::string& key,
                           std::string_view where);
StatusOr<std::string> GetString(const nlohmann::json& obj, const std::string& key,
                                std::string_view where);

}  // namespace simhuman::core
