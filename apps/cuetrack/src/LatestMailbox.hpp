// A single-slot "latest item" mailbox between a producer that must never wait (the
// tracker's loop) and a slow consumer (a window). Triple buffered: the producer fills its
// own buffer without a lock, then swaps it with the middle one; the consumer swaps the
// middle one for its own. The lock guards only those swaps, never a copy or a render, so
// a consumer stuck drawing cannot hold the producer up. An item the consumer never took
// before a newer one came is dropped and counted.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <utility>

namespace cuetrack::app {

template <typename T>
class LatestMailbox {
 public:
  // fill(T&) writes the new item into the producer's buffer (which holds an older item,
  // so buffers can be reused without allocating). Never waits for the consumer.
  template <typename Fill>
  void push(Fill&& fill) {
    fill(*_write);
    {
      std::lock_guard<std::mutex> lock(_mutex);
      if (_fresh) ++_dropped;
      std::swap(_write, _middle);
      _fresh = true;
      ++_pushed;
    }
    _ready.notify_one();
  }

  // The newest item not taken yet, or nullptr when none came within timeout (or close()d).
  // Valid until the next take() on this (the one consumer) thread.
  const T* take(std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(_mutex);
    if (!_ready.wait_for(lock, timeout, [this] { return _fresh || _closed; })) return nullptr;
    if (!_fresh) return nullptr;
    std::swap(_read, _middle);
    _fresh = false;
    return _read;
  }

  // Wakes a consumer waiting in take().
  void close() {
    {
      std::lock_guard<std::mutex> lock(_mutex);
      _closed = true;
    }
    _ready.notify_all();
  }

  uint64_t dropped() const {
    std::lock_guard<std::mutex> lock(_mutex);
    return _dropped;
  }
  uint64_t pushed() const {
    std::lock_guard<std::mutex> lock(_mutex);
    return _pushed;
  }

 private:
  T _items[3]{};
  T* _write = &_items[0];
  T* _middle = &_items[1];
  T* _read = &_items[2];
  bool _fresh = false;  // _middle holds an item the consumer has not taken
  bool _closed = false;
  uint64_t _dropped = 0;
  uint64_t _pushed = 0;
  mutable std::mutex _mutex;
  std::condition_variable _ready;
};

}  // namespace cuetrack::app
