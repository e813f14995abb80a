// Deliberately allocating code: the symbol check (test_lint_symbols_control) must reject
// the library built from this file. Never linked into anything.
#include <cstdlib>

int* lintBadNew() {
  return new int(7);
}
void* lintBadMalloc(std::size_t n) {
  return std::malloc(n);
}
