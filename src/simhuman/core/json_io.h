#pragma once
/// Reading files and JSON strictly, with errors that name the file, line and column. The typed
/// getters for parsed JSON (CheckKeys, GetNumber, ReadNumber, ...) are in core/json_reader.h.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "simhuman/core/json_reader.h"
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

}  // namespace simhuman::core
