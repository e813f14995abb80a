#include "cuetrack/platform/QueuedPort.hpp"

#include <cstdio>
#include <cstring>

namespace cuetrack::platform {

QueuedPort::QueuedPort(ByteStream& port, const Clock& clock, Reporter& reporter)
    : _port(port), _clock(clock), _reporter(reporter) {
  _connected = _port.isOpen();
  _lastTxUs = _clock.nowUs();
}

void QueuedPort::lost(const char* why) {
  if (!_connected) return;
  _connected = false;
  ++_stats.disconnects;
  // The queued messages are lost with the line: count them.
  _stats.txDropped += _stats.queued;
  _stats.queued = 0;
  _txHead = _txSize = 0;
  _lenHead = _lenCount = 0;
  _headSentBytes = 0;
  _lastRetryUs = _clock.nowUs();
  char line[512];
  std::snprintf(line, sizeof line, "%s; tracking continues, retrying every %u ms", why,
                static_cast<unsigned>(kRetryPeriodUs / 1000));
  _reporter.report(line);
  _port.close();
}

bool QueuedPort::service() {
  bool reconnected = false;
  if (!_connected) {
    const uint64_t now = _clock.nowUs();
    if (now - _lastRetryUs < kRetryPeriodUs) return false;
    _lastRetryUs = now;
    if (!_port.reopen()) return false;
    _connected = true;
    reconnected = true;
    ++_stats.reconnects;
    char line[320];
    std::snprintf(line, sizeof line, "%s: reconnected", _port.name());
    _reporter.report(line);
  }
  flush();
  return reconnected;
}

bool QueuedPort::drain(int maxMs) {
  // Bounded by iterations, not by the clock: a fake clock in tests does not move.
  for (int waitedMs = 0; _connected && _txSize > 0 && waitedMs < maxMs; waitedMs += 10) {
    if (_port.waitWritable(10)) flush();
  }
  return _txSize == 0;
}

void QueuedPort::flush() {
  while (_connected && _lenCount > 0) {
    // The rest of the oldest message, in one piece even where it wraps round the ring.
    const size_t rest = _lens[_lenHead] - _headSentBytes;
    uint8_t joined[kMaxMessageBytes];
    const uint8_t* bytes = _tx + _txHead;
    if (_txHead + rest > kTxQueueBytes) {
      const size_t first = kTxQueueBytes - _txHead;
      std::memcpy(joined, _tx + _txHead, first);
      std::memcpy(joined + first, _tx, rest - first);
      bytes = joined;
    }
    const IoResult r = _port.write(bytes, rest);
    if (r.status == IoStatus::Closed || r.status == IoStatus::Error) {
      lost(_port.error());
      return;
    }
    if (r.status == IoStatus::WouldBlock || r.bytes == 0) return;
    _txHead = (_txHead + r.bytes) % kTxQueueBytes;
    _txSize -= r.bytes;
    _headSentBytes += r.bytes;
    if (_headSentBytes < _lens[_lenHead]) return;  // a short write: the line is full
    if (_headCounted[_lenHead]) {                  // whole on the line
      ++_stats.sent;
      --_stats.queued;
    }
    _headSentBytes = 0;
    _lenHead = (_lenHead + 1) % kMaxQueuedMessages;
    --_lenCount;
  }
}

bool QueuedPort::send(const uint8_t* bytes, size_t n, bool counted) {
  const bool fits = _connected && n > 0 && n <= kMaxMessageBytes && kTxQueueBytes - _txSize >= n &&
                    _lenCount < kMaxQueuedMessages;
  if (!fits) {
    if (counted) ++_stats.txDropped;
    return false;
  }
  for (size_t i = 0; i < n; ++i) _tx[(_txHead + _txSize + i) % kTxQueueBytes] = bytes[i];
  _txSize += n;
  const size_t slot = (_lenHead + _lenCount) % kMaxQueuedMessages;
  _lens[slot] = static_cast<uint16_t>(n);
  _headCounted[slot] = counted;
  ++_lenCount;
  if (counted) ++_stats.queued;
  _lastTxUs = _clock.nowUs();
  flush();
  return true;
}

size_t QueuedPort::read(uint8_t* buf, size_t cap) {
  if (!_connected) return 0;
  const IoResult r = _port.read(buf, cap, 0);
  _stats.rxErrors += _port.takeRxDropped();
  if (r.status == IoStatus::Closed || r.status == IoStatus::Error) {
    lost(_port.error());
    return 0;
  }
  return r.bytes;
}

}  // namespace cuetrack::platform
