// Buffer rotation and colour/depth pairing for the Kinect driver, kept free of
// libfreenect so it can be tested (and its allocations counted) on its own.
//
// Each stream owns kBuffersPerStream frame buffers (the pixels live in
// KinectSource; this class only tracks their state):
//
//   Filling   registered with libfreenect (freenect_set_*_buffer); written only by the
//             library, in the event thread, just before it calls our callback
//   Pending   finished, waiting for a partner frame of the other stream
//   Ready     half of the newest complete pair, waiting for the consumer
//   Consuming being copied out by the consumer (next()); nobody else touches it
//   Free      anything else
//
// The event thread calls frameDone() from the libfreenect callback and registers the
// buffer it returns; the consumer calls take() / release(). Three buffers per stream
// suffice: Filling + Ready + (Pending or Consuming); when a fourth would be needed,
// DropPolicy decides: Latest drops the older Ready pair (live device: keep latency
// low), Lossless makes the event thread wait for the consumer (replay: every recorded
// frame is delivered). Nothing allocates after construction.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace cuetrack::kinect {

inline constexpr int kBuffersPerStream = 3;
inline constexpr uint32_t kTicksPerUs = 60;  // Kinect v1 frame timestamps count a 60 MHz clock

enum class Stream : uint8_t { Colour = 0, Depth = 1 };
enum class DropPolicy : uint8_t { Latest, Lossless };

// Why frames stopped coming.
enum class EndKind : uint8_t {
  None,
  Stopped,      // requestStop()
  StreamEnded,  // freenect_process_events failed: end of a fakenect recording, or USB gone
};

struct PairerConfig {
  bool useColour = true;
  bool useDepth = true;
  DropPolicy policy = DropPolicy::Latest;
  uint64_t toleranceTicks = 16000ull * kTicksPerUs;  // max |t_colour - t_depth| of a pair
  int rateDivisor = 1;                               // deliver every Nth pair
  bool (*externalStop)() = nullptr;                  // polled by waiters too (e.g. a signal flag)
};

struct PairerCounters {
  uint64_t colourFrames = 0;  // frames the library delivered
  uint64_t depthFrames = 0;
  uint64_t delivered = 0;      // pairs handed to the consumer
  uint64_t dropped = 0;        // complete pairs overwritten before the consumer took them
  uint64_t unpaired = 0;       // frames discarded without a partner within the tolerance
  uint64_t skippedByRate = 0;  // pairs skipped by rateDivisor
  uint64_t consumerWaits = 0;  // take() calls that found nothing and waited (ahead of the camera)
};

// What take() hands the consumer.
struct Taken {
  enum class Status : uint8_t { Ok, End, Timeout };
  Status status = Status::Timeout;
  EndKind end = EndKind::None;
  int colour = -1;         // buffer index, -1 when the stream is off
  int depth = -1;          // buffer index, -1 when the stream is off
  uint64_t timeTicks = 0;  // unwrapped 60 MHz time of the pair (colour's when present)
};

class Pairer {
 public:
  Pairer() = default;
  Pairer(const Pairer&) = delete;
  Pairer& operator=(const Pairer&) = delete;

  // Back to the initial state. Only while no thread is inside the other calls.
  void reset(const PairerConfig& config);

  // The buffer the library should write first (register it before starting).
  int filling(Stream s) const { return _filling[static_cast<int>(s)]; }

  // Event thread: stream s finished a frame in its filling buffer, stamped rawTicks
  // (the camera's 32-bit counter; wraps every 71.6 s). Returns the buffer to register
  // next. May wait (Lossless) but returns promptly once stop is requested.
  int frameDone(Stream s, uint32_t rawTicks);

  // Event thread: no more frames will come. Pairs already Ready are still delivered.
  void finish(EndKind why);

  // Any thread, including a signal handler (one lock-free atomic store). Waiters
  // notice within kPollMs.
  void requestStop() { _stop.store(true, std::memory_order_relaxed); }
  bool stopRequested() const {
    return _stop.load(std::memory_order_relaxed) || (_externalStop && _externalStop());
  }

  // Consumer: waits at most timeoutMs for a pair. On Ok the buffers are Consuming
  // until release(). Stop wins over a Ready pair; a finished stream's Ready pair is
  // still delivered before End.
  Taken take(uint32_t timeoutMs);
  void release(const Taken& taken);

  PairerCounters counters() const;

  static constexpr int kPollMs = 20;  // how often waiters look at the stop flag

 private:
  enum class State : uint8_t { Free, Filling, Pending, Ready, Consuming };
  struct Pair {
    bool valid = false;
    int colour = -1;
    int depth = -1;
    uint64_t timeTicks = 0;
  };

  uint64_t unwrap(uint32_t rawTicks);
  void freeBuffer(int s, int b) {
    if (b >= 0) _state[s][b] = State::Free;
  }
  void discardPair(Pair& p);
  // Installs a complete pair as Ready (waits or drops per policy). Lock held.
  void deliver(std::unique_lock<std::mutex>& lock, int colour, int depth, uint64_t t);
  int findFree(int s) const;

  mutable std::mutex _mutex;
  std::condition_variable _changed;
  std::atomic<bool> _stop{false};

  PairerConfig _config{};
  bool (*_externalStop)() = nullptr;  // copy of _config.externalStop, read without the lock
  State _state[2][kBuffersPerStream]{};
  uint64_t _ticks[2][kBuffersPerStream]{};
  int _filling[2] = {0, 0};
  int _pending[2] = {-1, -1};
  Pair _ready{};
  EndKind _end = EndKind::None;
  bool _haveTime = false;
  uint32_t _lastRaw = 0;
  uint64_t _last64 = 0;
  uint64_t _pairsFormed = 0;
  PairerCounters _counters{};
};

}  // namespace cuetrack::kinect
