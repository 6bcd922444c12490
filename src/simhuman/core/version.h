#pragma once
/// Build provenance: the git revision this binary was built from.

#include <string_view>

namespace simhuman::core {

/// `git describe --always --dirty` of the source tree at build time (e.g. "76ff671a2b3c" or
/// "76ff671a2b3c-dirty"); "unknown" outside a git checkout. Refreshed on every build.
std::string_view GitRevision();

}  // namespace simhuman::core
