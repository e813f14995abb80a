#include "cuetrack/drivers/KinectPairer.hpp"

#include <chrono>

namespace cuetrack::kinect {

namespace {
constexpr int kColour = static_cast<int>(Stream::Colour);
constexpr int kDepth = static_cast<int>(Stream::Depth);
}  // namespace

void Pairer::reset(const PairerConfig& config) {
  std::lock_guard<std::mutex> lock(_mutex);
  _config = config;
  if (_config.rateDivisor < 1) _config.rateDivisor = 1;
  _externalStop = config.externalStop;
  for (int s = 0; s < 2; ++s) {
    for (int b = 0; b < kBuffersPerStream; ++b) {
      _state[s][b] = State::Free;
      _ticks[s][b] = 0;
    }
    _state[s][0] = State::Filling;
    _filling[s] = 0;
    _pending[s] = -1;
  }
  _ready = Pair{};
  _end = EndKind::None;
  _stop.store(false, std::memory_order_relaxed);
  _haveTime = false;
  _lastRaw = 0;
  _last64 = 0;
  _pairsFormed = 0;
  _counters = PairerCounters{};
}

uint64_t Pairer::unwrap(uint32_t rawTicks) {
  // One timeline for both streams (same camera clock). The signed 32-bit step
  // tolerates a frame slightly older than the last one seen from the other stream;
  // the 2^32 start offset keeps such steps from going below zero.
  if (!_haveTime) {
    _haveTime = true;
    _last64 = (1ull << 32) + rawTicks;
  } else {
    const int32_t step = static_cast<int32_t>(rawTicks - _lastRaw);
    _last64 = static_cast<uint64_t>(static_cast<int64_t>(_last64) + step);
  }
  _lastRaw = rawTicks;
  return _last64;
}

int Pairer::findFree(int s) const {
  for (int b = 0; b < kBuffersPerStream; ++b)
    if (_state[s][b] == State::Free) return b;
  return -1;
}

void Pairer::discardPair(Pair& p) {
  if (!p.valid) return;
  freeBuffer(kColour, p.colour);
  freeBuffer(kDepth, p.depth);
  p = Pair{};
}

void Pairer::deliver(std::unique_lock<std::mutex>& lock, int colour, int depth, uint64_t t) {
  if ((_pairsFormed++ % static_cast<uint64_t>(_config.rateDivisor)) != 0) {
    freeBuffer(kColour, colour);
    freeBuffer(kDepth, depth);
    ++_counters.skippedByRate;
    return;
  }
  if (_ready.valid) {
    if (_config.policy == DropPolicy::Latest) {
      discardPair(_ready);
      ++_counters.dropped;
    } else {
      // Lossless: the consumer must take the older pair first.
      while (_ready.valid && !stopRequested())
        _changed.wait_for(lock, std::chrono::milliseconds(kPollMs));
      if (stopRequested()) {
        freeBuffer(kColour, colour);
        freeBuffer(kDepth, depth);
        return;
      }
    }
  }
  if (colour >= 0) _state[kColour][colour] = State::Ready;
  if (depth >= 0) _state[kDepth][depth] = State::Ready;
  _ready.valid = true;
  _ready.colour = colour;
  _ready.depth = depth;
  _ready.timeTicks = t;
  _changed.notify_all();
}

int Pairer::frameDone(Stream stream, uint32_t rawTicks) {
  std::unique_lock<std::mutex> lock(_mutex);
  const int s = static_cast<int>(stream);
  const int o = 1 - s;
  const int b = _filling[s];
  const uint64_t t = unwrap(rawTicks);
  _ticks[s][b] = t;
  if (s == kColour)
    ++_counters.colourFrames;
  else
    ++_counters.depthFrames;

  if (stopRequested()) return b;  // keep writing into the same buffer; nobody reads it now
  if ((s == kColour && !_config.useColour) || (s == kDepth && !_config.useDepth)) return b;

  const bool single = !(_config.useColour && _config.useDepth);
  if (single) {
    _state[s][b] = State::Pending;  // owned by us until deliver() decides
    deliver(lock, s == kColour ? b : -1, s == kDepth ? b : -1, t);
  } else if (_pending[o] >= 0) {
    const int p = _pending[o];
    const int64_t dt = static_cast<int64_t>(t - _ticks[o][p]);
    const uint64_t gap = static_cast<uint64_t>(dt < 0 ? -dt : dt);
    if (gap <= _config.toleranceTicks) {
      _pending[o] = -1;
      _state[s][b] = State::Pending;
      const int colour = s == kColour ? b : p;
      const int depth = s == kDepth ? b : p;
      // A pair is stamped with its colour frame: the tracker's image.
      deliver(lock, colour, depth, s == kColour ? t : _ticks[o][p]);
    } else if (dt > 0) {
      // The other stream's frame is too old to ever find a partner.
      freeBuffer(o, p);
      _pending[o] = -1;
      ++_counters.unpaired;
      _state[s][b] = State::Pending;
      _pending[s] = b;
    } else {
      // This frame is older than the other stream's newest one: no partner will come.
      _state[s][b] = State::Free;
      ++_counters.unpaired;
    }
  } else {
    if (_pending[s] >= 0) {
      // Two frames of one stream in a row: keep the newer.
      freeBuffer(s, _pending[s]);
      ++_counters.unpaired;
    }
    _state[s][b] = State::Pending;
    _pending[s] = b;
  }

  // Choose the next buffer for the library.
  int next = findFree(s);
  while (next < 0) {
    if (stopRequested()) {
      // Nobody will read any more: reuse this frame's buffer.
      if (_pending[s] == b) _pending[s] = -1;
      if (_ready.valid &&
          ((s == kColour && _ready.colour == b) || (s == kDepth && _ready.depth == b)))
        discardPair(_ready);
      next = b;
      break;
    }
    if (_config.policy == DropPolicy::Latest && _ready.valid) {
      discardPair(_ready);
      ++_counters.dropped;
    } else {
      _changed.wait_for(lock, std::chrono::milliseconds(kPollMs));
    }
    next = findFree(s);
  }
  _state[s][next] = State::Filling;
  _filling[s] = next;
  return next;
}

void Pairer::finish(EndKind why) {
  std::lock_guard<std::mutex> lock(_mutex);
  if (_end == EndKind::None) _end = why;
  _changed.notify_all();
}

Taken Pairer::take(uint32_t timeoutMs) {
  std::unique_lock<std::mutex> lock(_mutex);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
  Taken out;
  bool waited = false;
  for (;;) {
    if (stopRequested()) {
      out.status = Taken::Status::End;
      out.end = EndKind::Stopped;
      return out;
    }
    if (_ready.valid) {
      out.status = Taken::Status::Ok;
      out.colour = _ready.colour;
      out.depth = _ready.depth;
      out.timeTicks = _ready.timeTicks;
      if (out.colour >= 0) _state[kColour][out.colour] = State::Consuming;
      if (out.depth >= 0) _state[kDepth][out.depth] = State::Consuming;
      _ready = Pair{};
      ++_counters.delivered;
      _changed.notify_all();
      return out;
    }
    if (_end != EndKind::None) {
      out.status = Taken::Status::End;
      out.end = _end;
      return out;
    }
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) {
      out.status = Taken::Status::Timeout;
      return out;
    }
    if (!waited) ++_counters.consumerWaits;
    waited = true;
    const auto poll = now + std::chrono::milliseconds(kPollMs);
    _changed.wait_until(lock, poll < deadline ? poll : deadline);
  }
}

void Pairer::release(const Taken& taken) {
  if (taken.status != Taken::Status::Ok) return;
  std::lock_guard<std::mutex> lock(_mutex);
  if (taken.colour >= 0 && _state[kColour][taken.colour] == State::Consuming)
    _state[kColour][taken.colour] = State::Free;
  if (taken.depth >= 0 && _state[kDepth][taken.depth] == State::Consuming)
    _state[kDepth][taken.depth] = State::Free;
  _changed.notify_all();
}

PairerCounters Pairer::counters() const {
  std::lock_guard<std::mutex> lock(_mutex);
  return _counters;
}

}  // namespace cuetrack::kinect
