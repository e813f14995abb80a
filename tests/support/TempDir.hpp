// A fresh temporary folder per test, removed afterwards (tests write recordings and
// logs), the small text-file helpers, and damageAviFrame (a video whose container stays
// whole while one frame's picture is damaged).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <catch2/catch.hpp>

namespace cuetrack::test {

class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/cuetrack-test-XXXXXX";
    const char* p = mkdtemp(tmpl);
    REQUIRE(p != nullptr);
    _path = p;
  }
  ~TempDir() {
    const std::string cmd = "rm -rf '" + _path + "'";
    if (std::system(cmd.c_str()) != 0) WARN("could not remove " << _path);
  }
  const std::string& path() const { return _path; }
  std::string operator/(const std::string& name) const { return _path + "/" + name; }
  std::string file(const char* name) const { return _path + "/" + name; }

 private:
  std::string _path;
};

inline void writeText(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "wb");
  REQUIRE(f != nullptr);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
}

inline std::string readText(const std::string& path) {
  std::string s;
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return s;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  std::fclose(f);
  return s;
}

// Flips bits in the middle of the JPEG data of video frame `frame` (the frame-th "00dc"
// chunk of the AVI's movi list): the container stays whole, the picture is damaged.
inline void damageAviFrame(const std::string& avi, int frame) {
  std::string data = readText(avi);
  size_t at = data.find("movi");
  REQUIRE(at != std::string::npos);
  for (int k = 0; k <= frame; ++k) {
    at = data.find("00dc", at + 4);
    REQUIRE(at != std::string::npos);
  }
  uint32_t size = 0;
  std::memcpy(&size, data.data() + at + 4, 4);
  REQUIRE(size > 2000);
  for (uint32_t i = size / 2; i < size / 2 + 600; i += 7) data[at + 8 + i] ^= 0x5a;
  writeText(avi, data);
}

}  // namespace cuetrack::test
