#pragma once
/// Always-on invariant checks for programming errors (not for untrusted input).

#include <cstdio>
#include <cstdlib>

/// Aborts with file:line and the message when `cond` is false. Enabled in every build type.
#define SH_CHECK(cond, msg)                                                                    \
  do {                                                                                         \
    if (!(cond)) {                                                                             \
      std::fprintf(stderr, "%s:%d: check failed: %s: %s\n", __FILE__, __LINE__, #cond, (msg)); \
      std::abort();                                                                            \
    }                                                                                          \
  } while (0)
