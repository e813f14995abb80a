// A UDP peer as a ByteStream, for MAVLink to a companion computer's router
// (--mavlink-udp HOST:PORT): a connected datagram socket, non-blocking. Each write is one
// datagram (QueuedPort writes one whole message at a time); reads return what the
// datagrams from that peer carried. UDP loses what nobody receives: a write while the
// peer is not listening counts as sent, as the datagram would be lost on a network too.
#pragma once

#include "cuetrack/platform/ByteStream.hpp"

namespace cuetrack::platform {

class UdpSocket final : public ByteStream {
 public:
  UdpSocket() = default;
  ~UdpSocket() override;
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  // "HOST:PORT" (a name, an IPv4 address, or [IPv6]:PORT). False with error() set.
  bool open(const char* hostPort);

  IoResult read(uint8_t* buf, size_t cap, int timeoutMs) override;
  IoResult write(const uint8_t* data, size_t len) override;
  bool waitWritable(int timeoutMs) override;
  bool isOpen() const override { return _fd >= 0; }
  bool reopen() override { return _fd >= 0; }
  void close() override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name; }

 private:
  int _fd{-1};
  char _name[300]{};
  char _error[400]{};
};

}  // namespace cuetrack::platform
