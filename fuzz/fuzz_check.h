// Shared by the harnesses: what counts as a finding besides sanitizer reports.
#pragma once

#include <cstdio>
#include <cstdlib>

// A broken invariant of a reader's result: report and abort (libFuzzer records the input).
#define TRIBO_FUZZ_CHECK(cond)                                                             \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      std::fprintf(stderr, "fuzz check failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__);  \
      std::abort();                                                                        \
    }                                                                                      \
  } while (0)
