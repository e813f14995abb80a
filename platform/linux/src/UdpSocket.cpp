#include "cuetrack/platform/linux/UdpSocket.hpp"

#include "cuetrack/platform/HostPort.hpp"

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cuetrack::platform {

UdpSocket::~UdpSocket() {
  close();
}

bool UdpSocket::open(const char* hostPort) {
  close();
  _kernelDrops = _reportedDrops = _cutDatagrams = 0;  // a new socket counts from 0
  std::snprintf(_name, sizeof _name, "udp:%s", hostPort);
  char host[256];
  unsigned port = 0;
  if (!splitHostPort(hostPort, host, sizeof host, &port)) {
    std::snprintf(_error, sizeof _error, "%s: expected HOST:PORT", _name);
    return false;
  }
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_DGRAM;
  char service[8];
  std::snprintf(service, sizeof service, "%u", port);
  addrinfo* found = nullptr;
  const int rc = ::getaddrinfo(host, service, &hints, &found);
  if (rc != 0) {
    std::snprintf(_error, sizeof _error, "%s: cannot resolve the host: %s", _name,
                  ::gai_strerror(rc));
    return false;
  }
  int err = 0;
  for (addrinfo* a = found; a != nullptr && _fd < 0; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0) {
      err = errno;
      continue;
    }
    // The kernel's count of the datagrams it dropped for this socket, with each datagram.
    const int on = 1;
    _countsDrops = ::setsockopt(fd, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on) == 0;
    if (::connect(fd, a->ai_addr, a->ai_addrlen) != 0) {
      err = errno;
      ::close(fd);
      continue;
    }
    _fd = fd;
  }
  ::freeaddrinfo(found);
  if (_fd < 0) {
    std::snprintf(_error, sizeof _error, "%s: cannot connect: %s", _name, std::strerror(err));
    return false;
  }
  _error[0] = '\0';
  return true;
}

void UdpSocket::close() {
  if (_fd >= 0) ::close(_fd);
  _fd = -1;
}

IoResult UdpSocket::read(uint8_t* buf, size_t cap, int timeoutMs) {
  if (_fd < 0) return {IoStatus::Closed, 0};
  pollfd p{_fd, POLLIN, 0};
  if (::poll(&p, 1, timeoutMs) <= 0) return {IoStatus::Ok, 0};
  // Empty or cut datagrams are skipped here (a cut one counted), bounded so that a flood
  // of them cannot hold the caller.
  for (int tries = 0; tries < 64; ++tries) {
    iovec iov{buf, cap};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(uint32_t))];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    const ssize_t n = ::recvmsg(_fd, &msg, MSG_DONTWAIT);
    if (n < 0) {
      // Nobody listening at the peer yet (ICMP port unreachable), or nothing there: not an
      // error.
      if (errno == EAGAIN || errno == EINTR || errno == ECONNREFUSED) return {IoStatus::Ok, 0};
      std::snprintf(_error, sizeof _error, "%s: receive failed: %s", _name, std::strerror(errno));
      return {IoStatus::Error, 0};
    }
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c)) {
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SO_RXQ_OVFL &&
          c->cmsg_len >= CMSG_LEN(sizeof(uint32_t)))
        std::memcpy(&_kernelDrops, CMSG_DATA(c), sizeof _kernelDrops);
    }
    if ((msg.msg_flags & MSG_TRUNC) != 0) {
      ++_cutDatagrams;
      continue;
    }
    if (n > 0) return {IoStatus::Ok, static_cast<size_t>(n)};
  }
  return {IoStatus::Ok, 0};
}

uint32_t UdpSocket::takeRxDropped() {
  // The kernel's counter runs on (and wraps) on its own: hand out what is new.
  const uint32_t total = _kernelDrops + _cutDatagrams;
  const uint32_t fresh = total - _reportedDrops;
  _reportedDrops = total;
  return fresh;
}

IoResult UdpSocket::write(const uint8_t* data, size_t len) {
  if (_fd < 0) return {IoStatus::Closed, 0};
  for (;;) {
    const ssize_t n = ::send(_fd, data, len, 0);
    if (n >= 0) return {IoStatus::Ok, static_cast<size_t>(n)};
    if (errno == EINTR) continue;
    if (errno == EAGAIN) return {IoStatus::WouldBlock, 0};
    // The peer is not listening (yet): the datagram is lost, as on any network.
    if (errno == ECONNREFUSED) return {IoStatus::Ok, len};
    std::snprintf(_error, sizeof _error, "%s: send failed: %s", _name, std::strerror(errno));
    return {IoStatus::Error, 0};
  }
}

bool UdpSocket::waitWritable(int timeoutMs) {
  if (_fd < 0) return false;
  pollfd p{_fd, POLLOUT, 0};
  return ::poll(&p, 1, timeoutMs) > 0 && (p.revents & POLLOUT) != 0;
}

}  // namespace cuetrack::platform
