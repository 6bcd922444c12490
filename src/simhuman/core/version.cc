#include "simhuman/core/version.h"

#include "simhuman/git_rev.h"  // generated at build time by cmake/git_rev.cmake

namespace simhuman::core {

std::string_view GitRevision() { return SIMHUMAN_GIT_REV; }

}  // namespace simhuman::core
