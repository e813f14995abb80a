// A view of n contiguous elements (C++20's std::span, which C++17 lacks): one value in
// place of a (pointer, count) pair. Never owns, never allocates.
#pragma once

namespace cuetrack {

template <typename T>
class Span {
 public:
  constexpr Span() = default;
  constexpr Span(T* data, int size) : _data(data), _size(size < 0 ? 0 : size) {}
  template <int N>
  constexpr Span(T (&array)[N]) : _data(array), _size(N) {}  // NOLINT: implicit by design
  // A view of non-const elements is a view of const ones.
  constexpr operator Span<const T>() const { return Span<const T>(_data, _size); }  // NOLINT

  constexpr T* data() const { return _data; }
  constexpr int size() const { return _size; }
  constexpr bool empty() const { return _size == 0; }
  constexpr T& operator[](int i) const { return _data[i]; }
  constexpr T* begin() const { return _data; }
  constexpr T* end() const { return _data + _size; }
  // The first n elements (all of them when n >= size()).
  constexpr Span first(int n) const { return Span(_data, n < _size ? n : _size); }

 private:
  T* _data = nullptr;
  int _size = 0;
};

}  // namespace cuetrack
