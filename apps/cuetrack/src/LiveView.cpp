// View.hpp on OpenCV's highgui. Every highgui call of the live window happens on its own
// thread; the tracker's thread only copies pixels into the mailbox.
#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>
#include <opencv2/core.hpp>
#include <opencv2/highgui.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <thread>
#include <vector>

#include "LatestMailbox.hpp"
#include "View.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::app {
namespace {

constexpr const char* kWindow = "cuetrack";
constexpr float kDepthFarMm = 5000.f;  // colour map range: the Kinect v1's useful depth
constexpr int kStripPx = 44;           // status text under the image
// No toolbar (Qt's zoom buttons): the image starts at the window's corner, 1:1.
constexpr int kWindowFlags = cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL;

cv::Mat toBgr(const RgbView& rgb) {
  cv::Mat bgr(rgb.height, rgb.width, CV_8UC3);
  for (int y = 0; y < rgb.height; ++y) {
    const Rgb8* s = rgb.row(y);
    uint8_t* d = bgr.ptr<uint8_t>(y);
    for (int x = 0; x < rgb.width; ++x) {
      d[3 * x] = s[x].b;
      d[3 * x + 1] = s[x].g;
      d[3 * x + 2] = s[x].r;
    }
  }
  return bgr;
}

cv::Scalar stateColour(uint8_t state) {
  switch (state) {
    case CTP_STATE_TRACKING:
      return {0, 220, 0};
    case CTP_STATE_LOST:
      return {0, 0, 255};
    default:
      return {0, 200, 255};  // searching, idle
  }
}

// cv::selectROI prints its instructions on stdout, which carries the track lines: they
// go to stderr instead.
cv::Rect selectRoi(const char* window, const cv::Mat& image) {
  std::fflush(stdout);
  const int saved = dup(STDOUT_FILENO);
  if (saved >= 0) dup2(STDERR_FILENO, STDOUT_FILENO);
  const cv::Rect r = cv::selectROI(window, image, true, false);
  std::cout.flush();
  std::fflush(stdout);
  if (saved >= 0) {
    dup2(saved, STDOUT_FILENO);
    close(saved);
  }
  return r;
}

cv::Rect toRect(const Box& b) {
  return cv::Rect(cvRound(b.x), cvRound(b.y), cvRound(b.w), cvRound(b.h));
}

// The frame with the track drawn, the depth colour-mapped beside it (when given), and two
// lines of text in a strip under them: the window's and the video's picture.
cv::Mat overlay(const cv::Mat& bgr, const cv::Mat& depth16, const ViewTrack& track,
                const char* line1, const char* line2) {
  cv::Mat colour = bgr.clone();
  const cv::Scalar c = stateColour(track.state);
  const bool hasBox = track.state != CTP_STATE_IDLE && track.box.w > 0.f;
  if (hasBox) cv::rectangle(colour, toRect(track.box), c, 2);
  cv::Mat image = colour;
  if (!depth16.empty()) {
    cv::Mat d8, depthColour;
    depth16.convertTo(d8, CV_8U, 255.0 / kDepthFarMm);
    cv::applyColorMap(d8, depthColour, cv::COLORMAP_JET);
    depthColour.setTo(cv::Scalar(0, 0, 0), depth16 == 0);  // no measurement: black
    if (hasBox) cv::rectangle(depthColour, toRect(track.box), cv::Scalar(255, 255, 255), 2);
    cv::hconcat(colour, depthColour, image);
  }
  cv::Mat canvas(image.rows + kStripPx, image.cols, CV_8UC3, cv::Scalar(32, 32, 32));
  image.copyTo(canvas(cv::Rect(0, 0, image.cols, image.rows)));
  cv::putText(canvas, line1, {6, image.rows + 17}, cv::FONT_HERSHEY_SIMPLEX, 0.5, c, 1,
              cv::LINE_AA);
  cv::putText(canvas, line2, {6, image.rows + 37}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(200, 200, 200), 1, cv::LINE_AA);
  return canvas;
}

}  // namespace

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

namespace {
// The picker's window and drag, on the thread that owns highgui.
bool pickOn(const cv::Mat& bgr, Box* out, char* err, size_t errLen) {
  constexpr const char* kPickWindow = "cuetrack: drag a box around the target, Enter to accept";
  cv::namedWindow(kPickWindow, kWindowFlags);
  const cv::Rect r = selectRoi(kPickWindow, bgr);
  cv::destroyWindow(kPickWindow);
  cv::waitKey(1);  // lets the window close before the run goes on
  if (r.width <= 0 || r.height <= 0) {
    std::snprintf(err, errLen, "--select: no box was drawn (cancelled)");
    return false;
  }
  *out = Box{static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.width),
             static_cast<float>(r.height)};
  return true;
}
}  // namespace

bool pickBox(const Frame& frame, Box* out, char* err, size_t errLen) {
  return pickOn(toBgr(frame.rgb), out, err, errLen);
}

bool writeSnapshot(const Frame& frame, const char* path, char* err, size_t errLen) {
  cv::Mat img = toBgr(frame.rgb);
  const cv::Scalar line(0, 255, 255), text(255, 255, 255), shadow(0, 0, 0);
  auto label = [&](const char* s, cv::Point at) {
    cv::putText(img, s, at, cv::FONT_HERSHEY_PLAIN, 0.8, shadow, 2, cv::LINE_AA);
    cv::putText(img, s, at, cv::FONT_HERSHEY_PLAIN, 0.8, text, 1, cv::LINE_AA);
  };
  char s[16];
  for (int x = kSnapshotGridPx; x < img.cols; x += kSnapshotGridPx) {
    cv::line(img, {x, 0}, {x, img.rows - 1}, line, 1);
    std::snprintf(s, sizeof s, "%d", x);
    label(s, {x + 2, 10});
  }
  for (int y = kSnapshotGridPx; y < img.rows; y += kSnapshotGridPx) {
    cv::line(img, {0, y}, {img.cols - 1, y}, line, 1);
    std::snprintf(s, sizeof s, "%d", y);
    label(s, {2, y - 2});
  }
  bool ok = false;
  try {
    ok = cv::imwrite(path, img);
  } catch (const cv::Exception& e) {
    std::snprintf(err, errLen, "--snapshot %s: %s", path, e.what());
    return false;
  }
  if (!ok) {
    std::snprintf(err, errLen,
                  "--snapshot %s: cannot write (folder missing, no space, or not .png)", path);
    return false;
  }
  return true;
}

// One frame for the window, copied out of the tracker's slot.
struct ViewFrame {
  std::vector<Rgb8> rgb;
  std::vector<uint16_t> depthMm;  // empty: no depth
  int width = 0, height = 0;
  ViewTrack track;
  std::chrono::steady_clock::time_point pushedAt;
};

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
  bool pickRequested = false, pickFinished = false, pickOk = false;
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
                  "frame %u  %s  confidence %.2f  %.1f fps  display dropped %llu",
                  f.track.frameIndex, ctp_state_name(f.track.state), f.track.confidence, fps,
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
    const bool ok = pickOn(image, &box, e, sizeof e);
    {
      std::lock_guard<std::mutex> lock(mutex);
      pickOk = ok;
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
        const cv::Rect r = selectRoi(kWindow, lastBgr);
        if (r.width > 0 && r.height > 0) {
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

bool LiveView::start(char* err, size_t errLen) {
  if (!displayAvailable(err, errLen)) return false;
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

bool LiveView::pick(const Frame& frame, Box* out, char* err, size_t errLen) {
  if (!_impl->thread.joinable()) return pickBox(frame, out, err, errLen);
  std::unique_lock<std::mutex> lock(_impl->mutex);
  _impl->pickImage = toBgr(frame.rgb);
  _impl->pickFinished = false;
  _impl->pickRequested = true;
  _impl->pickDone.wait(lock, [&] { return _impl->pickFinished || _impl->quit.load(); });
  if (!_impl->pickFinished) {
    std::snprintf(err, errLen, "--select: the window was closed");
    return false;
  }
  if (!_impl->pickOk) std::snprintf(err, errLen, "%s", _impl->pickError);
  *out = _impl->pickResult;
  return _impl->pickOk;
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

struct VideoOut::Impl {
  cv::VideoWriter writer;
  std::string path;
  int width = 0, height = 0;  // of the frames (the video is taller: the text strip)
  bool depth = false;
  double fps = 30.0;
};

VideoOut::VideoOut() : _impl(std::make_unique<Impl>()) {}
VideoOut::~VideoOut() = default;

bool VideoOut::open(const char* path, double fps, char* err, size_t errLen) {
  const size_t n = std::strlen(path);
  if (n < 5 || std::strcmp(path + n - 4, ".avi") != 0) {
    std::snprintf(err, errLen, "--video %s: expected a .avi file (Motion JPEG)", path);
    return false;
  }
  // Found out now, before the run: the writer itself only says "cannot open" (after
  // trying GStreamer), and opens on the first frame, whose size it needs.
  FILE* f = std::fopen(path, "wb");
  if (!f) {
    std::snprintf(err, errLen, "--video %s: cannot write: %s", path, std::strerror(errno));
    return false;
  }
  std::fclose(f);
  _impl->path = path;
  _impl->fps = fps > 0.0 ? fps : 30.0;
  return true;
}

bool VideoOut::write(const Frame& frame, const ViewTrack& track, char* err, size_t errLen) {
  Impl& v = *_impl;
  const cv::Mat bgr = toBgr(frame.rgb);
  cv::Mat depth;
  if (frame.hasDepth() && frame.depthMm.width == frame.rgb.width &&
      frame.depthMm.height == frame.rgb.height) {
    depth = cv::Mat(frame.depthMm.height, frame.depthMm.width, CV_16UC1,
                    const_cast<uint16_t*>(frame.depthMm.data),
                    static_cast<size_t>(frame.depthMm.stride) * sizeof(uint16_t));
  }
  if (!v.writer.isOpened()) {
    v.width = frame.rgb.width;
    v.height = frame.rgb.height;
    v.depth = !depth.empty();
    const cv::Size size((v.depth ? 2 : 1) * v.width, v.height + kStripPx);
    // OpenCV's own Motion JPEG writer: no GStreamer or FFmpeg needed.
    if (!v.writer.open(v.path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                       v.fps, size)) {
      std::snprintf(err, errLen, "--video %s: cannot write (folder missing or not writable)",
                    v.path.c_str());
      return false;
    }
  }
  if (frame.rgb.width != v.width || frame.rgb.height != v.height) {
    std::snprintf(err, errLen, "--video %s: frame %u is %dx%d, the video is %dx%d", v.path.c_str(),
                  track.frameIndex, frame.rgb.width, frame.rgb.height, v.width, v.height);
    return false;
  }
  // A frame without depth in a video with depth (or the reverse) keeps the video's layout.
  if (v.depth && depth.empty()) depth = cv::Mat(v.height, v.width, CV_16UC1, cv::Scalar(0));
  if (!v.depth) depth = cv::Mat();
  char line1[160];
  std::snprintf(line1, sizeof line1, "frame %u  %s  confidence %.2f", track.frameIndex,
                ctp_state_name(track.state), track.confidence);
  v.writer.write(
      overlay(bgr, depth, track, line1,
              v.depth ? "cuetrack   depth: near blue, far red, none black" : "cuetrack"));
  ++_frames;
  return true;
}

bool VideoOut::close(char* err, size_t errLen) {
  if (!_impl->writer.isOpened()) return true;
  _impl->writer.release();
  // VideoWriter reports no write error (a full disk, a file size limit): read the video
  // back, as cuetrack-synth does, and count the frames in it.
  cv::VideoCapture cap;
  uint32_t n = 0;
  if (cap.open(_impl->path, cv::CAP_OPENCV_MJPEG) && cap.isOpened())
    while (n < _frames && cap.grab()) ++n;
  if (n != _frames) {
    std::snprintf(err, errLen,
                  "--video %s: only %u of %u frames written could be read back (disk full or "
                  "write error)",
                  _impl->path.c_str(), static_cast<unsigned>(n), static_cast<unsigned>(_frames));
    return false;
  }
  return true;
}

}  // namespace cuetrack::app
