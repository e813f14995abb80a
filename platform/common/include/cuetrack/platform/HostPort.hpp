// "HOST:PORT" as typed on a command line (--mavlink-udp): a name or IPv4 address, or
// [IPv6]:PORT. Checked when the options are read, resolved when the socket opens.
#pragma once

#include <cstddef>

namespace cuetrack::platform {

// Splits text into host (NUL-terminated, at most hostCap bytes with the NUL) and port
// 1..65535; false when malformed.
bool splitHostPort(const char* text, char* host, size_t hostCap, unsigned* port);

}  // namespace cuetrack::platform
