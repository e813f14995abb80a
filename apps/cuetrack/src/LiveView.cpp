// The live window on OpenCV's highgui. Every highgui call of the window happens on its own
// thread; the tracker's thread only copies pixels into the mailbox. It wires the display
// probe, the overlay and the picker together.
#include "LiveView.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <opencv2/core.hpp>
#include <opencv2/highgui.hpp>
#include <thread>
#include <vector>

#include "CvImage.hpp"
#include "DisplayProbe.hpp"
#include "LatestMailbox.hpp"
#include "Overlay.hpp"
#include "Picker.hpp"
#include "PickerCv.hpp"

namespace cuetrack::app {
namespace {

constexpr const char* kWindow = "cuetrack";

// One frame for the window, copied out of the tracker's slot.
struct ViewFrame {
  std::vector<Rgb8> rgb;
  std::vector<uint16_t> depthMm;  // empty: no depth
  int width = 0, height = 0;
  ViewTrack track;
  std::chrono::steady_clock::time_point pushedAt;
};

}  // namespace

struct LiveView::Impl {
  LatestMailbox<ViewFrame> mailbox;
  std::thread thread;
  std::atomic<bool> closing{false};
  std::atomic<bool> quit{false};
  std::mutex mutex;  // paused, reselect
  std::condition_variable resumed;
  bool paused = false;
  bool hasReselect = false;
  Box reselect{};
  // A --select asked of the window thread (highgui belongs to one thread per process).
  cv::Mat pickImage;
  bool pickRequested = false, pickFinished = false;
  PickResult pickOutcome = PickResult::Cancelled;
  bool (*stop)() = nullptr;  // the signal flag: a picker open in the window polls it
  Box pickResult{};
  char pickError[160] = "";
  std::condition_variable pickDone;

  // Window thread state.
  cv::Mat lastBgr;  // the last frame without overlay (for re-selecting on it)
  double fps = 0.0;
  bool haveLast = false;
  uint32_t lastIndex = 0;
  std::chrono::steady_clock::time_point lastAt;
  bool shown = false;

  void setPaused(bool p) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      paused = p;
    }
    resumed.notify_all();
  }
  bool isPaused() {
    std::lock_guard<std::mutex> lock(mutex);
    return paused;
  }

  cv::Mat render(const ViewFrame& f) {
    const RgbView view{f.rgb.data(), f.width, f.height, f.width};
    lastBgr = toBgr(view);
    cv::Mat depth;
    if (!f.depthMm.empty())
      depth = cv::Mat(f.height, f.width, CV_16UC1, const_cast<uint16_t*>(f.depthMm.data()));
    // fps of the tracker: frames it did between two frames the window showed.
    if (haveLast && f.track.frameIndex > lastIndex) {
      const double dt = std::chrono::duration<double>(f.pushedAt - lastAt).count();
      if (dt > 0) {
        const double now = (f.track.frameIndex - lastIndex) / dt;
        fps = fps > 0 ? 0.8 * fps + 0.2 * now : now;
      }
    }
    haveLast = true;
    lastIndex = f.track.frameIndex;
    lastAt = f.pushedAt;
    char line1[256], line2[160];
    std::snprintf(line1, sizeof line1,
                  "frame %u  %s  confidence %.2f  %.1f fps  window dropped %llu",
                  f.track.frameIndex, trackLook(f.track).word, f.track.confidence, fps,
                  static_cast<unsigned long long>(mailbox.dropped()));
    std::snprintf(line2, sizeof line2, "%sspace pause  r re-select  q quit%s",
                  isPaused() ? "PAUSED  " : "",
                  depth.empty() ? "" : "   depth: near blue, far red, none black");
    return overlay(lastBgr, depth, f.track, line1, line2);
  }

  void servePick() {
    cv::Mat image;
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!pickRequested) return;
      pickRequested = false;
      image = pickImage;
    }
    Box box{};
    char e[160] = "";
    const PickResult outcome = pickOn(image, stop, &box, e, sizeof e);
    {
      std::lock_guard<std::mutex> lock(mutex);
      pickOutcome = outcome;
      pickResult = box;
      std::snprintf(pickError, sizeof pickError, "%s", e);
      pickFinished = true;
    }
    pickDone.notify_all();
  }

  void run() {
    cv::setNumThreads(1);  // drawing must not take the tracker's cores (a board has 2-4)
    cv::namedWindow(kWindow, kWindowFlags);
    ViewFrame last;  // the shown frame, to redraw on pause
    bool haveFrame = false;
    while (!closing.load()) {
      servePick();
      if (const ViewFrame* f = mailbox.take(std::chrono::milliseconds(10))) {
        last.rgb = f->rgb;
        last.depthMm = f->depthMm;
        last.width = f->width;
        last.height = f->height;
        last.track = f->track;
        last.pushedAt = f->pushedAt;
        haveFrame = true;
        cv::imshow(kWindow, render(last));
        shown = true;
      }
      const int key = cv::waitKey(5);
      if (key == ' ' && haveFrame) {
        setPaused(!isPaused());
        cv::imshow(kWindow, render(last));
      } else if (key == 'r' && haveFrame) {
        setPaused(true);
        cv::Rect r;
        if (selectRoi(kWindow, lastBgr, stop, &r) == PickResult::Picked) {
          std::lock_guard<std::mutex> lock(mutex);
          reselect = Box{static_cast<float>(r.x), static_cast<float>(r.y),
                         static_cast<float>(r.width), static_cast<float>(r.height)};
          hasReselect = true;
        }
        setPaused(false);
      } else if (key == 'q' || key == 'Q' || key == 27) {
        quit = true;
      }
      if (shown && cv::getWindowProperty(kWindow, cv::WND_PROP_VISIBLE) < 1) quit = true;
      if (quit.load()) setPaused(false);
    }
    cv::destroyAllWindows();
    cv::waitKey(1);
  }
};

LiveView::LiveView() : _impl(std::make_unique<Impl>()) {}
LiveView::~LiveView() {
  close();
}

bool LiveView::start(bool (*stop)(), char* err, size_t errLen) {
  if (!displayAvailable(err, errLen)) return false;
  _impl->stop = stop;
  _impl->thread = std::thread([this] { _impl->run(); });
  return true;
}

void LiveView::push(const Frame& frame, const ViewTrack& track) {
  if (!_impl->thread.joinable()) return;
  _impl->mailbox.push([&](ViewFrame& v) {
    const int w = frame.rgb.width, h = frame.rgb.height;
    v.width = w;
    v.height = h;
    v.rgb.resize(static_cast<size_t>(w) * static_cast<size_t>(h));  // no allocation once sized
    for (int y = 0; y < h; ++y)
      std::memcpy(&v.rgb[static_cast<size_t>(y) * w], frame.rgb.row(y), sizeof(Rgb8) * w);
    if (frame.hasDepth() && frame.depthMm.width == w && frame.depthMm.height == h) {
      v.depthMm.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
      for (int y = 0; y < h; ++y)
        std::memcpy(&v.depthMm[static_cast<size_t>(y) * w], frame.depthMm.row(y),
                    sizeof(uint16_t) * w);
    } else {
      v.depthMm.clear();
    }
    v.track = track;
    v.pushedAt = std::chrono::steady_clock::now();
  });
}

void LiveView::waitWhilePaused(bool (*stop)()) {
  std::unique_lock<std::mutex> lock(_impl->mutex);
  while (_impl->paused && !_impl->quit.load() && !(stop && stop())) {
    _impl->resumed.wait_for(lock, std::chrono::milliseconds(100));  // polls stop (a signal)
  }
}

PickResult LiveView::pick(const Frame& frame, bool (*stop)(), Box* out, char* err, size_t errLen) {
  if (!_impl->thread.joinable()) return pickBox(frame, stop, out, err, errLen);
  std::unique_lock<std::mutex> lock(_impl->mutex);
  _impl->pickImage = toBgr(frame.rgb);
  _impl->pickFinished = false;
  _impl->pickRequested = true;
  _impl->pickDone.wait(lock, [&] { return _impl->pickFinished || _impl->quit.load(); });
  if (!_impl->pickFinished) {
    std::snprintf(err, errLen, "--select: the window was closed");
    return PickResult::Cancelled;
  }
  if (_impl->pickOutcome != PickResult::Picked) std::snprintf(err, errLen, "%s", _impl->pickError);
  *out = _impl->pickResult;
  return _impl->pickOutcome;
}

bool LiveView::takeReselect(Box* box) {
  std::lock_guard<std::mutex> lock(_impl->mutex);
  if (!_impl->hasReselect) return false;
  *box = _impl->reselect;
  _impl->hasReselect = false;
  return true;
}

bool LiveView::quitRequested() const {
  return _impl->quit.load();
}
uint64_t LiveView::droppedFrames() const {
  return _impl->mailbox.dropped();
}

void LiveView::close() {
  if (!_impl || !_impl->thread.joinable()) return;
  _impl->closing = true;
  _impl->mailbox.close();
  _impl->thread.join();
}

}  // namespace cuetrack::app
