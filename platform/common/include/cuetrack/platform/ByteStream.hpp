// A bidirectional byte stream: the serial port on the board, an in-memory loop in
// tests. Never blocks longer than the timeout given; writes never block at all, so
// a stalled peer cannot wedge the tracker.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cuetrack::platform {

enum class IoStatus : uint8_t {
  Ok,          // bytes transferred (possibly 0 for a read that timed out)
  WouldBlock,  // write: the peer's buffer is full, nothing written
  Closed,      // the peer or device went away; reopen() may bring it back
  Error,       // anything else; error() has the line
};

struct IoResult {
  IoStatus status = IoStatus::Ok;
  size_t bytes = 0;
};

class ByteStream {
 public:
  virtual ~ByteStream() = default;
  // Waits at most timeoutMs (0 = just poll) for data, then reads what is there.
  virtual IoResult read(uint8_t* buf, size_t cap, int timeoutMs) = 0;
  // Writes what fits now (a short count is possible), never waits.
  virtual IoResult write(const uint8_t* data, size_t len) = 0;
  // Waits at most timeoutMs until a write could make progress; false on timeout or
  // when the stream is not open. For bounded draining at exit, never in the frame loop.
  virtual bool waitWritable(int timeoutMs) = 0;
  virtual bool isOpen() const = 0;
  // Tries to open the same device again after Closed; false while it is absent.
  virtual bool reopen() = 0;
  virtual void close() = 0;
  // Last error as one line naming the device, e.g. "/dev/ttyUSB0: Input/output error".
  virtual const char* error() const = 0;
  virtual const char* name() const = 0;
  // True when each read returns exactly one whole datagram (UDP): a reader parses each on
  // its own, so a bad one cannot reach into the next.
  virtual bool datagrams() const { return false; }
  // Inbound units the OS dropped before we could read them (a datagram socket's receive
  // buffer overflowed) since the last call; 0 where nothing can be dropped unseen.
  virtual uint32_t takeRxDropped() { return 0; }
};

}  // namespace cuetrack::platform
