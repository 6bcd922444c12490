#include "simhuman/app/common.h"

#include <cctype>
#include <filesystem>
#include <initializer_list>

#include "absl/strings/match.h"
#include "simhuman/core/json_io.h"

namespace simhuman::app {
namespace {

bool WordChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '"';
}

// true if one of `words` occurs in `text` outside a longer word or a string's quotes
bool HasBareWord(const std::string& text, std::initializer_list<const char*> words) {
  for (const char* w : words) {
    const std::string word(w);
    for (size_t pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1)) {
      bool before = pos > 0 && WordChar(text[pos - 1]);
      size_t end = pos + word.size();
      bool after = end < text.size() && WordChar(text[end]);
      if (!before && !after) return true;
    }
  }
  return false;
}

}  // namespace

int ExitCodeFor(const absl::Status& status) {
  switch (status.code()) {
    case absl::StatusCode::kOk:
      return kExitOk;
    case absl::StatusCode::kInvalidArgument:
    case absl::StatusCode::kNotFound:
    case absl::StatusCode::kOutOfRange:
    case absl::StatusCode::kAlreadyExists:
    case absl::StatusCode::kPermissionDenied:
      return kExitBadInput;
    default:
      return kExitInternal;
  }
}

int ReportError(std::ostream& err, const std::string& command, const absl::Status& status) {
  std::string msg(status.message());
  for (char& c : msg) {
    if (c == '\n') c = ' ';
  }
  err << "simhuman " << command << ": error: " << msg << std::endl;
  return ExitCodeFor(status);
}

core::StatusOr<control::MpcConfig> ResolveConfig(const std::string& preset, bool preset_given,
                                                 const std::string& config_path) {
  if (config_path.empty()) {
    core::StatusOr<control::MpcConfig> c = control::MpcConfig::Preset(preset);
    if (!c.ok()) return core::Annotate(c.status(), "--preset");
    return c;
  }
  SH_ASSIGN_OR_RETURN(std::string text, core::ReadFile(config_path));
  // core::ParseJson reports syntax errors and overflows (e.g. 1e999) as statuses
  core::StatusOr<nlohmann::json> j = core::ParseJson(text, config_path);
  if (!j.ok()) {
    std::string msg(j.status().message());
    if (HasBareWord(text, {"NaN", "nan", "Infinity", "inf"})) {
      msg += " (JSON has no NaN or Infinity: every number must be finite)";
    }
    return absl::InvalidArgumentError(msg);
  }
  if (!j->is_object()) {
    return absl::InvalidArgumentError(config_path +
                                      ": expected a JSON object of MPC settings, got " +
                                      std::string(j->type_name()));
  }
  if (!j->contains("preset")) {
    (*j)["preset"] = preset;
  } else if (preset_given && (*j)["preset"] != preset) {
    return absl::InvalidArgumentError(config_path + ": /preset: " + (*j)["preset"].dump() +
                                      " conflicts with --preset " + preset + "; pass one of them");
  }
  core::StatusOr<control::MpcConfig> c = absl::InternalError("unparsed");
  try {
    c = control::MpcConfig::FromJson(*j, config_path);
  } catch (const nlohmann::json::exception& e) {
    c = absl::InvalidArgumentError(config_path + ": " + e.what());
  }
  if (!c.ok() && !absl::StartsWith(c.status().message(), config_path)) {
    return core::Annotate(c.status(), config_path);
  }
  return c;
}

absl::Status MakeOutputDir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    return absl::PermissionDeniedError("cannot create output directory '" + dir +
                                       "': " + (ec ? ec.message() : "not a directory"));
  }
  return absl::OkStatus();
}

}  // namespace simhuman::app
