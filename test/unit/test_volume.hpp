// How much of a randomised or brute-force test to run. The release pass runs
// all of it; the sanitizer pass (TOOLKIT_SANITIZED=1) builds the tests' own
// code, oracles included, at -O0 under ASan, where they run about ten times
// slower, so there it runs a share that still reaches every branch the test
// is about, and the release pass keeps the volume.
#pragma once

#include <cstdlib>

inline int test_volume(int release, int sanitized) {
  return std::getenv("TOOLKIT_SANITIZED") != nullptr ? sanitized : release;
}
