// The display probe on OpenCV builds: $DISPLAY, then a real connection through XCB.
#include "DisplayProbe.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace cuetrack::app {

bool viewBuilt() {
  return true;
}

bool displayAvailable(char* err, size_t errLen) {
  const char* d = std::getenv("DISPLAY");
  if (d == nullptr || *d == '\0') {
    std::snprintf(err, errLen,
                  "no display ($DISPLAY is not set): run it on a desktop, with ssh -X, or use "
                  "--snapshot FILE.png");
    return false;
  }
  // Qt aborts the process when it cannot reach the display: try it first, through the
  // XCB library Qt's xcb plugin loads anyway (no build dependency of ours).
  void* xcb = dlopen("libxcb.so.1", RTLD_NOW | RTLD_LOCAL);
  if (xcb == nullptr) {
    std::snprintf(err, errLen, "cannot load libxcb.so.1 to reach display %s", d);
    return false;
  }
  using Connect = void* (*)(const char*, int*);
  using HasError = int (*)(void*);
  using Disconnect = void (*)(void*);
  const auto connect = reinterpret_cast<Connect>(dlsym(xcb, "xcb_connect"));
  const auto hasError = reinterpret_cast<HasError>(dlsym(xcb, "xcb_connection_has_error"));
  const auto disconnect = reinterpret_cast<Disconnect>(dlsym(xcb, "xcb_disconnect"));
  bool ok = false;
  if (connect && hasError && disconnect) {
    void* c = connect(d, nullptr);
    ok = c != nullptr && hasError(c) == 0;
    if (c) disconnect(c);
  }
  if (!ok) {
    std::snprintf(err, errLen,
                  "cannot connect to display %s ($DISPLAY): is the X server running, and may "
                  "this user use it?",
                  d);
    return false;
  }
  return true;
}

}  // namespace cuetrack::app
