// A secret key file (--mavlink-key): exactly `size` raw bytes in a regular file that only
// its owner may read or write (chmod 600): a key others can read signs for them too.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cuetrack::platform {

// False with one line in err naming the file (missing, not a regular file, open to group
// or others, not exactly size bytes, one byte repeated such as all zeros). Never waits: a
// FIFO is refused at once.
bool readKeyFile(const char* path, uint8_t* out, size_t size, char* err, size_t errLen);

// Now by the wall clock, in MAVLink signing's units (10 us since 2015-01-01 UTC); 0 when the
// clock is not set (before 2015: a board without a real-time clock, before NTP).
uint64_t signingTimestampNow();

}  // namespace cuetrack::platform
