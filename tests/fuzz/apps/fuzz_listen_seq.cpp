// cuetrack-listen's sequence bookkeeping: any series of seq numbers (4 bytes each, the
// first optionally a resumed "last seq"). The losses add up, first/last are the ones fed.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "SeqCounter.hpp"

using cuetrack::listen::SeqCounter;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  SeqCounter c;
  const bool resume = data[0] & 1;
  size_t pos = 1;
  uint32_t v = 0;
  if (resume && size >= pos + 4) {
    std::memcpy(&v, data + pos, 4);
    pos += 4;
    c.resumeAfter(v);
    if (!c.hasLast() || c.last() != v || c.any()) __builtin_trap();
  }
  uint64_t lost = 0;
  bool first = true;
  uint32_t firstSeq = 0, prev = v;
  bool havePrev = resume;
  for (; pos + 4 <= size; pos += 4) {
    uint32_t seq;
    std::memcpy(&seq, data + pos, 4);
    const uint32_t restartsBefore = c.restarts();
    const uint32_t missing = c.see(seq);
    // What the counter must say: the numbers skipped, or after a restart those before it.
    const uint32_t want = !havePrev ? 0u : seq > prev ? seq - prev - 1 : seq;
    if (missing != want) __builtin_trap();
    if ((havePrev && seq <= prev) != (c.restarts() == restartsBefore + 1)) __builtin_trap();
    lost += missing;
    if (first) firstSeq = seq;
    first = false;
    prev = seq;
    havePrev = true;
    if (c.last() != seq || c.first() != firstSeq || c.lost() != lost || !c.any()) __builtin_trap();
  }
  return 0;
}
