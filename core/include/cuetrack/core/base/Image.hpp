// Non-owning, typed, stride-aware image views, and fixed-capacity owning images.
// Strides are in elements (pixels of T), not bytes.
#pragma once

#include <cstdint>

#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

struct Rgb8 {
  uint8_t r, g, b;
};
static_assert(sizeof(Rgb8) == 3, "Rgb8 must be packed: it maps interleaved RGB888 buffers");

template <typename T>
struct ImageView {
  T* data = nullptr;
  int width = 0;   // [px]
  int height = 0;  // [px]
  int stride = 0;  // elements between row starts, >= width

  bool empty() const { return data == nullptr || width <= 0 || height <= 0; }
  T* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
  T& at(int x, int y) const { return row(y)[x]; }
  // A view of the same pixels as const.
  ImageView<const T> asConst() const { return {data, width, height, stride}; }
};

using RgbView = ImageView<const Rgb8>;
using GrayView = ImageView<const uint8_t>;
using DepthView = ImageView<const uint16_t>;  // [mm], 0 = no measurement

// Owning image with compile-time capacity and a runtime size. Lives wherever its
// owner lives (static storage or inside another fixed object): never allocates.
template <typename T, int MaxW, int MaxH>
class FixedImage {
 public:
  static constexpr int kMaxWidth = MaxW;
  static constexpr int kMaxHeight = MaxH;

  // Returns false (and keeps the old size) when the size exceeds the capacity.
  bool resize(int width, int height) {
    if (width < 0 || height < 0 || width > MaxW || height > MaxH) return false;
    _width = width;
    _height = height;
    return true;
  }
  int width() const { return _width; }
  int height() const { return _height; }
  int stride() const { return _width; }  // dense rows
  T* data() { return _pixels; }
  const T* data() const { return _pixels; }
  ImageView<T> view() { return {_pixels, _width, _height, _width}; }
  ImageView<const T> view() const { return {_pixels, _width, _height, _width}; }

 private:
  T _pixels[MaxW * MaxH]{};
  int _width{0};
  int _height{0};
};

}  // namespace cuetrack
