// The transmit path every link shares: a small queue in front of a ByteStream so a slow
// or stalled peer never blocks the tracker (a message that does not fit is refused
// whole, the caller counts it), reads that never wait, and reconnecting every
// kRetryPeriodUs when the device went away (the messages queued then are counted lost).
// It writes one message at a time, so on a datagram stream (UDP) each is one datagram.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/platform/ByteStream.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack/platform/TrackLink.hpp"

namespace cuetrack::platform {

class QueuedPort {
 public:
  static constexpr size_t kTxQueueBytes = 2048;
  static constexpr size_t kMaxQueuedMessages = 256;  // a message is at least 8 bytes
  static constexpr size_t kMaxMessageBytes = 512;    // MAVLink's largest frame is 280
  static constexpr uint64_t kRetryPeriodUs = 500000;

  QueuedPort(ByteStream& port, const Clock& clock, Reporter& reporter);

  // Queues one whole message, or nothing (queue full or disconnected). Unless `counted`
  // is false (framing filler) it is counted once: in stats().queued until its last byte is
  // on the line, then in stats().sent; in stats().txDropped when it is refused or lost
  // with the queue.
  bool send(const uint8_t* bytes, size_t n, bool counted = true);
  // Flushes, and while disconnected retries the device every kRetryPeriodUs. True on
  // the call that reconnected (the caller resets its decoder).
  bool service();
  // Reads what arrived without waiting; 0 when nothing did or the line was lost. On a
  // datagram stream, one whole datagram; what the OS dropped before is counted in
  // stats().rxErrors.
  size_t read(uint8_t* buf, size_t cap);
  bool datagrams() const { return _port.datagrams(); }
  // At exit: waits (at most ~maxMs) until the queue is on the line. True when empty (what
  // stays in stats().queued never left: the final line counts it as dropped).
  bool drain(int maxMs);

  bool connected() const { return _connected; }
  size_t queuedBytes() const { return _txSize; }
  uint64_t lastTxUs() const { return _lastTxUs; }
  LinkStats& stats() { return _stats; }
  const LinkStats& stats() const { return _stats; }
  const char* name() const { return _port.name(); }

 private:
  void lost(const char* why);
  void flush();

  ByteStream& _port;
  const Clock& _clock;
  Reporter& _reporter;
  uint8_t _tx[kTxQueueBytes]{};
  size_t _txHead{0}, _txSize{0};
  // Lengths of the queued messages, oldest first: what a lost line takes with it.
  uint16_t _lens[kMaxQueuedMessages]{};
  size_t _lenHead{0}, _lenCount{0};
  size_t _headSentBytes{0};  // of the oldest queued message, already on the line
  bool _headCounted[kMaxQueuedMessages]{};
  uint64_t _lastTxUs{0};
  uint64_t _lastRetryUs{0};
  bool _connected{true};
  LinkStats _stats{};
};

}  // namespace cuetrack::platform
