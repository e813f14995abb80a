// SHA-256 (FIPS 180-4), our own, for MAVLink 2 signing (a frame's signature is the first
// 48 bits of SHA-256 over the key and the frame). No allocation, no OS.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cuetrack::platform::mavlink {

class Sha256 {
 public:
  Sha256();
  void update(const uint8_t* data, size_t n);
  void final(uint8_t digest[32]);  // the object is spent afterwards

 private:
  void block(const uint8_t* p);
  uint32_t _h[8];
  uint8_t _buf[64]{};
  size_t _used{0};
  uint64_t _bytes{0};
};

}  // namespace cuetrack::platform::mavlink
