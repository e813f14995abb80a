// A fresh temporary folder per test, removed afterwards (tests write recordings).
#pragma once

#include <cstdlib>
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

}  // namespace cuetrack::test
