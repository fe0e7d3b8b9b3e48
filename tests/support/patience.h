// How long a test waits for an event (a reload, a file change, a line of output) before it
// gives up: a limit generous enough that a loaded machine cannot miss it, times
// FXKIT_TEST_SLOWDOWN (tests/CMakeLists.txt: 10 in sanitizer builds). Tests wait for the
// event itself; the limit only ends a test that would otherwise hang.
#pragma once
#include <chrono>

#ifndef FXKIT_TEST_SLOWDOWN
#define FXKIT_TEST_SLOWDOWN 1
#endif

namespace fx::testing {

// `limit` (a minute unless said otherwise) scaled for the build.
inline constexpr std::chrono::milliseconds patience(std::chrono::milliseconds limit = std::chrono::seconds(60)) {
  return limit * FXKIT_TEST_SLOWDOWN;
}

}  // namespace fx::testing
