#include "simhuman/core/json_io.h"

#include <algorithm>
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

}  // namespace simhuman::core
