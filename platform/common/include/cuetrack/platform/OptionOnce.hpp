// A command-line option given twice is an error, not "the last one wins": a second
// --box appended to a service's settings would silently replace the first.
#pragma once

#include <cstddef>
#include <cstdio>
#include <cstring>

namespace cuetrack::platform {

class OptionOnce {
 public:
  // True the first time `name` comes; after that false, with "NAME given twice" in err.
  // `name` must outlive this object (argv strings do).
  bool first(const char* name, char* err, size_t errLen) {
    for (int i = 0; i < _count; ++i) {
      if (std::strcmp(_seen[i], name) == 0) {
        std::snprintf(err, errLen, "%s given twice", name);
        return false;
      }
    }
    if (_count < kMax) _seen[_count++] = name;
    return true;
  }

 private:
  static constexpr int kMax = 64;  // more distinct options than any tool has
  const char* _seen[kMax]{};
  int _count = 0;
};

}  // namespace cuetrack::platform
