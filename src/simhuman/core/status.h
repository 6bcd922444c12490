#pragma once
/// Status types for untrusted input. Everything that parses files, flags or commands returns
/// absl::Status / absl::StatusOr<T>; messages name the culprit and list valid alternatives.

#include <string>
#include <string_view>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace simhuman::core {

using absl::Status;
using absl::StatusOr;

/// Joins names as "a, b, c" for "valid are: ..." messages.
std::string JoinNames(const std::vector<std::string>& names);

/// Prefixes a status message with a location (a file, a JSON pointer): "where: message".
Status Annotate(const Status& status, std::string_view where);

}  // namespace simhuman::core

#define SH_STATUS_CONCAT_INNER(a, b) a##b
#define SH_STATUS_CONCAT(a, b) SH_STATUS_CONCAT_INNER(a, b)

/// Returns from the current function if `expr` (an absl::Status) is not OK.
#define SH_RETURN_IF_ERROR(expr)             \
  do {                                       \
    ::absl::Status sh_status_ = (expr);      \
    if (!sh_status_.ok()) return sh_status_; \
  } while (0)

/// `SH_ASSIGN_OR_RETURN(auto x, StatusOrExpr)`: unwraps or returns the error.
#define SH_ASSIGN_OR_RETURN(lhs, expr) \
  SH_ASSIGN_OR_RETURN_IMPL(SH_STATUS_CONCAT(sh_statusor_, __LINE__), lhs, expr)
#define SH_ASSIGN_OR_RETURN_IMPL(tmp, lhs, expr) \
  auto tmp = (expr);                             \
  if (!tmp.ok()) return tmp.status();            \
  lhs = std::move(tmp).value()
