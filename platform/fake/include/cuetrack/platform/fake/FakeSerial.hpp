// Two in-memory byte streams joined back to back, like a null-modem cable:
// what end a() writes, end b() reads, and the reverse. Each direction is a fixed
// ring; a full ring gives short writes / WouldBlock like a real tty. The cable
// can be unplugged (both ends see Closed) and plugged back in (reopen works).
#pragma once

#include <cstddef>

#include "cuetrack/platform/ByteStream.hpp"

namespace cuetrack::platform {

class FakeSerialCable {
 public:
  static constexpr size_t kRingBytes = 4096;

  class End final : public ByteStream {
   public:
    IoResult read(uint8_t* buf, size_t cap, int timeoutMs) override;  // never waits
    IoResult write(const uint8_t* data, size_t len) override;
    bool waitWritable(int timeoutMs) override;  // never waits: true when there is room
    bool isOpen() const override { return _open; }
    bool reopen() override;
    void close() override { _open = false; }
    const char* error() const override { return _error; }
    const char* name() const override { return _name; }

   private:
    friend class FakeSerialCable;
    struct Ring {
      uint8_t bytes[kRingBytes]{};
      size_t head{0}, size{0};
    };
    FakeSerialCable* _cable{nullptr};
    Ring* _in{nullptr};
    Ring* _out{nullptr};
    bool _open{true};
    char _name[8]{};
    char _error[64]{};
  };

  FakeSerialCable();
  FakeSerialCable(const FakeSerialCable&) = delete;
  FakeSerialCable& operator=(const FakeSerialCable&) = delete;

  End& a() { return _a; }
  End& b() { return _b; }
  // Unplugged: both ends read/write Closed and cannot reopen; buffered bytes are lost.
  void setPlugged(bool plugged);
  bool plugged() const { return _plugged; }
  // Free space of the ring that end a() writes into (to simulate a stalled peer).
  void setCapacityAtoB(size_t bytes) { _capAtoB = bytes; }

 private:
  End::Ring _aToB, _bToA;
  End _a, _b;
  bool _plugged{true};
  size_t _capAtoB{kRingBytes};
};

}  // namespace cuetrack::platform
