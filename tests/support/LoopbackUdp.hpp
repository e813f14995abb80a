// The far end of a --mavlink-udp test: a UDP socket bound to 127.0.0.1 on a free port.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cstdio>

namespace cuetrack::test {

struct LoopbackUdp {
  int fd = -1;
  char target[32] = "";  // "127.0.0.1:PORT", for UdpSocket::open / --mavlink-udp
  // roomyBuffer false: the system's default receive buffer, as an ordinary ground station.
  explicit LoopbackUdp(bool roomyBuffer = true) {
    fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    REQUIRE(fd >= 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    // Room for a burst of answers (200 ACKs at once) before the test reads them.
    const int rcvBytes = 1 << 20;
    if (roomyBuffer) ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &rcvBytes, sizeof rcvBytes);
    REQUIRE(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
    socklen_t len = sizeof addr;
    REQUIRE(::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0);
    std::snprintf(target, sizeof target, "127.0.0.1:%u",
                  static_cast<unsigned>(ntohs(addr.sin_port)));
  }
  ~LoopbackUdp() { close(); }
  void close() {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

}  // namespace cuetrack::test
