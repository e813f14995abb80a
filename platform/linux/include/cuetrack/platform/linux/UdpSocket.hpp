// A UDP peer as a ByteStream, for MAVLink to a companion computer's router
// (--mavlink-udp HOST:PORT): a connected datagram socket, non-blocking. Each write is one
// datagram (QueuedPort writes one whole message at a time); each read returns one whole
// datagram from that peer (datagrams() is true), so give it kMaxDatagramBytes. UDP loses
// what nobody receives: a write while the peer is not listening counts as sent, as the
// datagram would be lost on a network too. What the kernel drops on the way in (the
// receive buffer full) is counted through SO_RXQ_OVFL and handed out by takeRxDropped().
#pragma once

#include "cuetrack/platform/ByteStream.hpp"

namespace cuetrack::platform {

class UdpSocket final : public ByteStream {
 public:
  static constexpr size_t kMaxDatagramBytes = 65535;  // UDP's length field: none is larger

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
  bool datagrams() const override { return true; }
  uint32_t takeRxDropped() override;
  // False when this kernel (or emulator) cannot report its drops (SO_RXQ_OVFL refused).
  bool countsDrops() const { return _countsDrops; }
  int fd() const { return _fd; }  // for a caller's poll(); -1 when closed

 private:
  int _fd{-1};
  bool _countsDrops{false};
  uint32_t _kernelDrops{0};    // the socket's drop counter as the last datagram carried it
  uint32_t _reportedDrops{0};  // of which takeRxDropped() has handed out
  uint32_t _cutDatagrams{0};   // longer than the caller's buffer: dropped here, counted
  char _name[300]{};
  char _error[400]{};
};

}  // namespace cuetrack::platform
