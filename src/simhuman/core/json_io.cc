#include "simhuman/core/json_io.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace simhuman::core {

StatusOr<std::string> ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::NotFoundError("cannot open file '" + path + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return absl::DataLossError("error reading file '" + path + "'");
  return ss.str();
}

Status WriteFileAtomic(const std::string& path, std::string_view contents) {
  std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return absl::PermissionDeniedError("cannot write file '" + tmp + "'");
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    if (!out) return absl::DataLossError("error writing file '" + tmp + "'");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    return absl::PermissionDeniedError("cannot rename '" + tmp + "' to '" + path + "'");
  }
  return absl::OkStatus();
}

StatusOr<nlohmann::json> ParseJson(std::string_view text, std::string_view source) {
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    // convert the byte offset into line:column
    size_t byte = std::min<size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    int line = 1, col = 1;
    for (size_t i = 0; i < byte; ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    std::string what = e.what();
    size_t pos = what.find("syntax error");
    if (pos != std::string::npos) what = what.substr(pos);
    return absl::InvalidArgumentError(std::string(source) + ":" + std::to_string(line) + ":" +
                                      std::to_string(col) + ": invalid JSON: " + what);
  } catch (const nlohmann::json::exception& e) {
    // e.g. out_of_range for numbers such as 1e999
    return absl::InvalidArgumentError(std::string(source) + ": invalid JSON: " + e.what());
  }
}

StatusOr<nlohmann::json> ReadJsonFile(const std::string& path) {
  SH_ASSIGN_OR_RETURN(std::string text, ReadFile(path));
  return ParseJson(text, path);
}

Status CheckKeys(const nlohmann::json& obj, const std::vector<std::string>& allowed,
                 std::string_view where) {
  if (!obj.is_object()) {
    return absl::InvalidArgumentError(std::string(where) + ": expected a JSON object, got " +
                                      obj.type_name());
  }
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool ok = false;
    for (const auto& a : allowed) ok |= (a == it.key());
    if (!ok) {
      return absl::InvalidArgumentError(std::string(where) + ": unknown key '" + it.key() +
                                        "'; valid keys are: " + JoinNames(allowed));
    }
  }
  return absl::OkStatus();
}

StatusOr<double> GetNumber(const nlohmann::json& obj, const std::string& key,
                           std::string_view where) {
  std::string loc = std::string(where) + "/" + key;
  if (!obj.contains(key)) return absl::InvalidArgumentError(loc + ": missing required number");
  const auto& v = obj.at(key);
  if (!v.is_number()) {
    return absl::InvalidArgumentError(loc + ": expected a number, got " +
                                      std::string(v.type_name()));
  }
  double d = v.get<double>();
  if (!std::isfinite(d)) return absl::InvalidArgumentError(loc + ": number is not finite");
  return d;
}

StatusOr<std::string> GetString(const nlohmann::json& obj, const std::string& key,
                                std::string_view where) {
  std::string loc = std::string(where) + "/" + key;
  if (!obj.contains(key)) return absl::InvalidArgumentError(loc + ": missing required string");
  const auto& v = obj.at(key);
  if (!v.is_string()) {
    return absl::InvalidArgumentError(loc + ": expected a string, got " +
                                      std::string(v.type_name()));
  }
  return v.get<std::string>();
}

}  // namespace simhuman::core
