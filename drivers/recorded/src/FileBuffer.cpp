#include "cuetrack/drivers/FileBuffer.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cuetrack::rec {

bool readFile(const char* path, std::vector<uint8_t>& buf, char* err, size_t errLen) {
  // O_NONBLOCK: a FIFO (or device) in place of a file must not block open(); it is
  // refused below. Reads of a regular file ignore the flag.
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    std::snprintf(err, errLen, "%s: cannot open (%s)", path, std::strerror(errno));
    return false;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    std::snprintf(err, errLen, "%s: not a regular file", path);
    ::close(fd);
    return false;
  }
  const size_t size = static_cast<size_t>(st.st_size);
  buf.resize(size);  // keeps capacity: no allocation once the largest file was read
  size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(fd, buf.data() + got, size - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<size_t>(n);
  }
  ::close(fd);
  if (got != size) {
    std::snprintf(err, errLen, "%s: read %zu of %zu bytes", path, got, size);
    return false;
  }
  return true;
}

bool writeFile2(const char* path, const void* a, size_t aLen, const void* b, size_t bLen, char* err,
                size_t errLen) {
  const int fd = ::open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    std::snprintf(err, errLen, "%s: cannot create (%s)", path, std::strerror(errno));
    return false;
  }
  const void* parts[2] = {a, b};
  const size_t lens[2] = {aLen, bLen};
  for (int i = 0; i < 2; ++i) {
    const uint8_t* p = static_cast<const uint8_t*>(parts[i]);
    size_t left = lens[i];
    while (left > 0) {
      const ssize_t n = ::write(fd, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        std::snprintf(err, errLen, "%s: write failed (%s)", path, std::strerror(errno));
        ::close(fd);
        return false;
      }
      p += n;
      left -= static_cast<size_t>(n);
    }
  }
  if (::close(fd) != 0) {
    std::snprintf(err, errLen, "%s: close failed (%s)", path, std::strerror(errno));
    return false;
  }
  return true;
}

bool writeFile(const char* path, const void* data, size_t len, char* err, size_t errLen) {
  return writeFile2(path, data, len, nullptr, 0, err, errLen);
}

bool isDirectory(const char* path) {
  struct stat st {};
  return ::stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

bool isFile(const char* path) {
  struct stat st {};
  return ::stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

long long fileSize(const char* path) {
  struct stat st {};
  return ::stat(path, &st) == 0 ? static_cast<long long>(st.st_size) : -1;
}

bool pathTooLong(const char* path, char* err, size_t errLen) {
  const size_t n = std::strlen(path);
  if (n <= kMaxPathChars) return false;
  std::snprintf(err, errLen, "%.60s...: path longer than %zu characters (%zu)", path, kMaxPathChars,
                n);
  return true;
}

bool exists(const char* path) {
  struct stat st {};
  return ::lstat(path, &st) == 0;
}

bool makeDirectories(const char* path, char* err, size_t errLen) {
  char buf[1024];
  const size_t n = std::strlen(path);
  if (n == 0 || n >= sizeof buf) {
    std::snprintf(err, errLen, "%s: bad directory name", path);
    return false;
  }
  std::memcpy(buf, path, n + 1);
  for (size_t i = 1; i <= n; ++i) {
    if (buf[i] != '/' && buf[i] != '\0') continue;
    const char saved = buf[i];
    buf[i] = '\0';
    if (::mkdir(buf, 0755) != 0 && errno != EEXIST) {
      std::snprintf(err, errLen, "%s: cannot create directory (%s)", buf, std::strerror(errno));
      return false;
    }
    buf[i] = saved;
  }
  if (!isDirectory(path)) {
    std::snprintf(err, errLen, "%s: not a directory", path);
    return false;
  }
  return true;
}

bool holdsRecording(const char* dir, char* err, size_t errLen) {
  static const char* const kNames[] = {
      "INDEX.txt",     "rgb", "depth", "img", "groundtruth.txt", "groundtruth_rect.txt",
      "intrinsics.txt"};
  for (const char* name : kNames) {
    char path[1024];
    std::snprintf(path, sizeof path, "%s/%s", dir, name);
    struct stat st {};
    if (::lstat(path, &st) == 0) {
      std::snprintf(err, errLen,
                    "%s: already holds a recording (%s); write to a new or empty folder", dir,
                    name);
      return true;
    }
  }
  return false;
}

std::string fileStem(const std::string& path) {
  std::string p = path;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  const size_t slash = p.find_last_of('/');
  std::string base = slash == std::string::npos ? p : p.substr(slash + 1);
  const size_t dot = base.find_last_of('.');
  if (dot != std::string::npos && dot > 0) base = base.substr(0, dot);
  return base;
}

}  // namespace cuetrack::rec
