// The length of a test's statistical loop, and whether the statistics it measures are asserted.
#pragma once

namespace sftest {

// The sanitizer tree (sf_estimation/scripts/sanitizer_checks.py) compiles the tests with
// SF_ESTIMATION_SANITIZED_TESTS. ASan and UBSan look for memory errors and undefined
// behaviour, which the first steps of a long Monte-Carlo or convergence loop reach on the same
// code paths as the rest, at -O0 and under the sanitizers 30-100 times slower than the regular
// build. There such a loop runs a short count and its test skips the statistics that need the
// full one; the regular (GCC) build of the same test runs the full count and asserts them all
// (doc/reliability.md, "Test order").
#ifdef SF_ESTIMATION_SANITIZED_TESTS
inline constexpr bool kStatisticsAsserted = false;
#else
inline constexpr bool kStatisticsAsserted = true;
#endif

/// `full` in the regular build, `sanitized` in the sanitizer tree.
constexpr int statisticalSteps(int full, int sanitized) {
  return kStatisticsAsserted ? full : sanitized;
}

}  // namespace sftest
