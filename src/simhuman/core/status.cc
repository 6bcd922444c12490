#include "simhuman/core/status.h"

namespace simhuman::core {

std::string JoinNames(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i) out += ", ";
    out += names[i];
  }
  return out;
}

Status Annotate(const Status& status, std::string_view where) {
  if (status.ok()) return status;
  return Status(status.code(), std::string(where) + ": " + std::string(status.message()));
}

}  // namespace simhuman::core
