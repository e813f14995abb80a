// A vector with its capacity in the type (ETL's etl::vector; the 1-D sibling of
// FixedImage): N elements stored inline, a runtime size up to N. Lives wherever its owner
// lives (static storage or inside another fixed object): never allocates, never throws;
// growing past N is refused (false), not clamped silently.
#pragma once

#include "cuetrack/core/base/Span.hpp"

namespace cuetrack {

template <typename T, int N>
class FixedVector {
  static_assert(N > 0, "a FixedVector holds at least one element");

 public:
  static constexpr int kCapacity = N;

  // Returns false (and keeps the old size) when n exceeds the capacity or is negative.
  bool resize(int n) {
    if (n < 0 || n > N) return false;
    _size = n;
    return true;
  }
  // Returns false (and adds nothing) when full.
  bool push_back(const T& v) {
    if (_size >= N) return false;
    _data[_size++] = v;
    return true;
  }
  void clear() { _size = 0; }
  int size() const { return _size; }
  bool empty() const { return _size == 0; }
  bool full() const { return _size == N; }
  static constexpr int capacity() { return N; }

  T& operator[](int i) { return _data[i]; }
  const T& operator[](int i) const { return _data[i]; }
  T* data() { return _data; }
  const T* data() const { return _data; }
  T* begin() { return _data; }
  T* end() { return _data + _size; }
  const T* begin() const { return _data; }
  const T* end() const { return _data + _size; }
  Span<T> span() { return Span<T>(_data, _size); }
  Span<const T> span() const { return Span<const T>(_data, _size); }

 private:
  T _data[N]{};
  int _size = 0;
};

}  // namespace cuetrack
