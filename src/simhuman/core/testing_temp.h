#pragma once
/// For tests only: temporary file paths that no other test process uses (ctest runs tests in
/// parallel, one process each).

#include <unistd.h>

#include <filesystem>
#include <string>

namespace simhuman::core::testing {

/// `<system temp dir>/simhuman_<pid>_<name>`. Nothing is created or removed.
inline std::string UniqueTempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("simhuman_" + std::to_string(getpid()) + "_" + name))
      .string();
}

}  // namespace simhuman::core::testing
