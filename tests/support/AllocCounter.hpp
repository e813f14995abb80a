// Counts heap allocations in this process (operator new/delete and the C allocator).
// Link cuetrack_alloc_counter into a test, then:
//   AllocScope scope;            // starts counting
//   tracker.update(frame);
//   REQUIRE(scope.allocations() == 0);
// A positive control belongs in every test that relies on it (see test_lint_alloc_counter.cpp).
#pragma once

#include <cstdint>

namespace cuetrack::test {

// Totals since process start (all threads).
uint64_t allocationCount();
uint64_t deallocationCount();
// Allocations made by the calling thread only (e.g. a consumer, while a library's own
// thread allocates for itself). Same hooks as allocationCount().
uint64_t threadAllocationCount();

class AllocScope;
// The positive control for a test program that asserts zero allocations: one new and
// one malloc; returns what this program's counter saw of them (2; 1 under ASan, which
// keeps malloc to itself; 0 if the hooks are not in effect).
uint64_t controlAllocations();

class AllocScope {
 public:
  AllocScope() : _start(allocationCount()) {}
  uint64_t allocations() const { return allocationCount() - _start; }

 private:
  uint64_t _start;
};

class ThreadAllocScope {
 public:
  ThreadAllocScope() : _start(threadAllocationCount()) {}
  uint64_t allocations() const { return threadAllocationCount() - _start; }

 private:
  uint64_t _start;
};

}  // namespace cuetrack::test
