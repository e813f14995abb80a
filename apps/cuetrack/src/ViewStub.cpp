// View.hpp for builds without OpenCV (the boards): every call says so.
#include <cstdio>

#include "View.hpp"

namespace cuetrack::app {
namespace {
constexpr const char* kNoView =
    "not built with OpenCV (host builds only; on a board use the "
    "host's cuetrack on a recording)";
bool fail(char* err, size_t errLen) {
  std::snprintf(err, errLen, "%s", kNoView);
  return false;
}
}  // namespace

struct LiveView::Impl {};

bool viewBuilt() {
  return false;
}
bool displayAvailable(char* err, size_t errLen) {
  return fail(err, errLen);
}
PickResult pickBox(const Frame&, bool (*)(), Box*, char* err, size_t errLen) {
  fail(err, errLen);
  return PickResult::Cancelled;
}
bool writeSnapshot(const Frame&, const char*, char* err, size_t errLen, float, float) {
  return fail(err, errLen);
}
struct VideoOut::Impl {};
VideoOut::VideoOut() = default;
VideoOut::~VideoOut() = default;
bool VideoOut::open(const char*, double, char* err, size_t errLen) {
  return fail(err, errLen);
}
bool VideoOut::write(const Frame&, const ViewTrack&, char* err, size_t errLen) {
  return fail(err, errLen);
}
bool VideoOut::close(char*, size_t) {
  return true;
}

LiveView::LiveView() = default;
LiveView::~LiveView() = default;
bool LiveView::start(bool (*)(), char* err, size_t errLen) {
  return fail(err, errLen);
}
PickResult LiveView::pick(const Frame&, bool (*)(), Box*, char* err, size_t errLen) {
  fail(err, errLen);
  return PickResult::Cancelled;
}
void LiveView::push(const Frame&, const ViewTrack&) {}
void LiveView::waitWhilePaused(bool (*)()) {}
bool LiveView::takeReselect(Box*) {
  return false;
}
bool LiveView::quitRequested() const {
  return false;
}
uint64_t LiveView::droppedFrames() const {
  return 0;
}
void LiveView::close() {}

}  // namespace cuetrack::app
