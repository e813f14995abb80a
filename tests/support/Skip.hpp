// Honest skips for Catch2 2.13 (which has no SKIP of its own): CUETRACK_SKIP(reason)
// prints the reason, marks the run as skipped and leaves the test case. Our main
// (catch_main.cpp) then exits with kSkipReturnCode when nothing failed, and ctest,
// told that code by cuetrack_add_test (SKIP_RETURN_CODE), reports the test as skipped,
// never as passed. One ctest test is one executable: a skipped case marks the whole
// executable skipped (its other cases still ran, and any failure still fails it).
#pragma once

#include <catch2/catch.hpp>

#include <cstdio>

namespace cuetrack::test {

constexpr int kSkipReturnCode = 77;  // the autotools/ctest convention for "skipped"

// Test cases that skipped in this process; read by our main.
int& skipCount();

}  // namespace cuetrack::test

// A statement: prints "SKIPPED: <reason>" to stderr and returns from the test case.
#define CUETRACK_SKIP(reason)        \
  do {                               \
    ++::cuetrack::test::skipCount(); \
    WARN("SKIPPED: " << reason);     \
    return;                          \
  } while (false)

// A statement: a part of the test case cannot run here (e.g. kernels for an instruction
// set this CPU lacks). Prints the reason and marks the run as skipped, but does not
// return: the rest still runs, and a failed check still fails the test.
#define CUETRACK_SKIP_PART(reason)   \
  do {                               \
    ++::cuetrack::test::skipCount(); \
    WARN("SKIPPED: " << reason);     \
  } while (false)
