// Counting replacements for the global allocation functions. operator new is
// replaced portably (the standard allows it); malloc & co. are interposed by
// defining them here and forwarding to glibc's __libc_* entry points, so calls from
// C code and libraries are counted too. Sanitizer builds keep their own malloc.
#include "AllocCounter.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<uint64_t> gAllocs{0};
std::atomic<uint64_t> gFrees{0};
// Initial-exec TLS in the executable: reading it never allocates.
thread_local uint64_t tAllocs = 0;
inline void countAlloc() {
  gAllocs.fetch_add(1, std::memory_order_relaxed);
  ++tAllocs;
}
}  // namespace

namespace cuetrack::test {
uint64_t allocationCount() {
  return gAllocs.load(std::memory_order_relaxed);
}
uint64_t deallocationCount() {
  return gFrees.load(std::memory_order_relaxed);
}
uint64_t threadAllocationCount() {
  return tAllocs;
}
uint64_t controlAllocations() {
  const AllocScope scope;
  int* volatile p = new int(3);  // volatile: the pair must not be optimised away
  delete p;
  void* volatile q = std::malloc(16);
  std::free(q);
  return scope.allocations();
}
}  // namespace cuetrack::test

#if defined(__SANITIZE_ADDRESS__)
#define CUETRACK_INTERPOSE_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CUETRACK_INTERPOSE_MALLOC 0
#endif
#endif
#ifndef CUETRACK_INTERPOSE_MALLOC
#define CUETRACK_INTERPOSE_MALLOC 1
#endif

#if CUETRACK_INTERPOSE_MALLOC
extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void __libc_free(void*);
void* __libc_memalign(size_t, size_t);

void* aligned_alloc(size_t a, size_t n) {
  countAlloc();
  return __libc_memalign(a, n);
}
int posix_memalign(void** out, size_t a, size_t n) {
  countAlloc();
  *out = __libc_memalign(a, n);
  return *out ? 0 : 12;  // ENOMEM
}

void* malloc(size_t n) {
  countAlloc();
  return __libc_malloc(n);
}
void* calloc(size_t n, size_t s) {
  countAlloc();
  return __libc_calloc(n, s);
}
void* realloc(void* p, size_t n) {
  countAlloc();
  return __libc_realloc(p, n);
}
void free(void* p) {
  if (p) gFrees.fetch_add(1, std::memory_order_relaxed);
  __libc_free(p);
}
}
#endif

// operator new/delete: with the C allocator interposed above they are counted there,
// once; under ASan (which owns malloc) they count here, every overload alike.
namespace {
constexpr bool kCountHere = !CUETRACK_INTERPOSE_MALLOC;
void* newBytes(size_t n) {
  if (kCountHere) countAlloc();
  void* p = std::malloc(n ? n : 1);
  if (!p) std::abort();
  return p;
}
void* newAligned(size_t n, std::align_val_t a) {
  if (kCountHere) countAlloc();
  void* p = nullptr;
  if (posix_memalign(&p, static_cast<size_t>(a), n ? n : 1) != 0) std::abort();
  return p;
}
void deleteBytes(void* p) {
  if (kCountHere && p) gFrees.fetch_add(1, std::memory_order_relaxed);
  std::free(p);
}
}  // namespace

void* operator new(size_t n) {
  return newBytes(n);
}
void* operator new[](size_t n) {
  return newBytes(n);
}
void* operator new(size_t n, const std::nothrow_t&) noexcept {
  return newBytes(n);
}
void* operator new[](size_t n, const std::nothrow_t&) noexcept {
  return newBytes(n);
}
void* operator new(size_t n, std::align_val_t a) {
  return newAligned(n, a);
}
void* operator new[](size_t n, std::align_val_t a) {
  return newAligned(n, a);
}
void operator delete(void* p) noexcept {
  deleteBytes(p);
}
void operator delete[](void* p) noexcept {
  deleteBytes(p);
}
void operator delete(void* p, size_t) noexcept {
  deleteBytes(p);
}
void operator delete[](void* p, size_t) noexcept {
  deleteBytes(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  deleteBytes(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  deleteBytes(p);
}
void operator delete(void* p, size_t, std::align_val_t) noexcept {
  deleteBytes(p);
}
void operator delete[](void* p, size_t, std::align_val_t) noexcept {
  deleteBytes(p);
}
