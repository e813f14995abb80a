// The only file of the project that includes <libfreenect.h>.
//
// fakenect 0.5.3 lacks some symbols (freenect_set_flag, the registration functions,
// freenect_list_device_attributes): this code relies on lazy binding and calls them
// only when the real library is loaded. Never link it with -z now.
#include "cuetrack/drivers/KinectSource.hpp"

#include "cuetrack/drivers/FakenectReader.hpp"

#include <dlfcn.h>
#include <libfreenect.h>
#include <libusb.h>
#include <pthread.h>
#include <signal.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/drivers/KinectDepth.hpp"

namespace cuetrack {

namespace {

struct Name {
  const char* text;
  int value;
};

template <typename E, int N>
bool parseName(const Name (&names)[N], const char* name, E* out) {
  if (!name) return false;
  for (const Name& n : names) {
    if (std::strcmp(n.text, name) == 0) {
      *out = static_cast<E>(n.value);
      return true;
    }
  }
  return false;
}

const Name kStreamNames[] = {{"both", static_cast<int>(KinectStreams::Both)},
                             {"depth", static_cast<int>(KinectStreams::DepthOnly)},
                             {"colour", static_cast<int>(KinectStreams::ColourOnly)},
                             {"color", static_cast<int>(KinectStreams::ColourOnly)}};
const Name kDepthNames[] = {{"auto", static_cast<int>(KinectDepthMode::Auto)},
                            {"registered", static_cast<int>(KinectDepthMode::Registered)},
                            {"raw", static_cast<int>(KinectDepthMode::Raw)}};
const Name kLedNames[] = {{"off", static_cast<int>(KinectLed::Off)},
                          {"green", static_cast<int>(KinectLed::Green)},
                          {"red", static_cast<int>(KinectLed::Red)},
                          {"yellow", static_cast<int>(KinectLed::Yellow)},
                          {"blink-green", static_cast<int>(KinectLed::BlinkGreen)},
                          {"blink-red-yellow", static_cast<int>(KinectLed::BlinkRedYellow)}};

freenect_led_options toFreenect(KinectLed led) {
  switch (led) {
    case KinectLed::Off:
      return LED_OFF;
    case KinectLed::Green:
      return LED_GREEN;
    case KinectLed::Red:
      return LED_RED;
    case KinectLed::Yellow:
      return LED_YELLOW;
    case KinectLed::BlinkGreen:
      return LED_BLINK_GREEN;
    case KinectLed::BlinkRedYellow:
      return LED_BLINK_RED_YELLOW;
    case KinectLed::Unchanged:
      break;
  }
  return LED_GREEN;
}

// Opens a context that claims only the camera (plus the motor when asked): the
// audio subdevice is never needed.
int openContext(freenect_context** ctx, bool motor) {
  const int r = freenect_init(ctx, nullptr);
  if (r < 0) return r;
  freenect_set_log_level(*ctx, FREENECT_LOG_ERROR);
  freenect_select_subdevices(
      *ctx, static_cast<freenect_device_flags>(FREENECT_DEVICE_CAMERA |
                                               (motor ? FREENECT_DEVICE_MOTOR : 0)));
  return 0;
}

}  // namespace

bool parseKinectStreams(const char* name, KinectStreams* out) {
  return parseName(kStreamNames, name, out);
}
bool parseKinectDepthMode(const char* name, KinectDepthMode* out) {
  return parseName(kDepthNames, name, out);
}
bool parseKinectLed(const char* name, KinectLed* out) {
  return parseName(kLedNames, name, out);
}
const char* toString(KinectStreams s) {
  switch (s) {
    case KinectStreams::Both:
      return "both";
    case KinectStreams::DepthOnly:
      return "depth";
    case KinectStreams::ColourOnly:
      return "colour";
  }
  return "?";
}

double kinectUsbLoadMBps(KinectStreams streams) {
  // Wire formats at 640x480, 30 Hz: colour is 8-bit Bayer, depth 11-bit packed.
  const double colour = 640.0 * 480.0 * 1.0 * 30.0 / 1e6;        // 9.2 MB/s
  const double depth = 640.0 * 480.0 * 11.0 / 8.0 * 30.0 / 1e6;  // 12.7 MB/s
  switch (streams) {
    case KinectStreams::Both:
      return colour + depth;
    case KinectStreams::DepthOnly:
      return depth;
    case KinectStreams::ColourOnly:
      return colour;
  }
  return colour + depth;
}

bool kinectReplayLibraryLoaded() {
  // fakenect 0.5.3 does not export freenect_set_flag; the real library always has.
  return dlsym(RTLD_DEFAULT, "freenect_set_flag") == nullptr;
}

int countKinects(char* err, std::size_t errLen) {
  freenect_context* ctx = nullptr;
  const int r = openContext(&ctx, false);
  if (r < 0) {
    if (err && errLen)
      std::snprintf(err, errLen, "libfreenect: freenect_init failed (%d): USB not usable", r);
    return -1;
  }
  const int n = freenect_num_devices(ctx);
  freenect_shutdown(ctx);
  if (n < 0) {
    if (err && errLen)
      std::snprintf(err, errLen, "libfreenect: cannot enumerate USB devices (%d)", n);
    return -1;
  }
  return n;
}

int listKinectSerials(char (*serials)[kKinectSerialLen], int maxDevices, char* err,
                      std::size_t errLen) {
  if (kinectReplayLibraryLoaded()) {
    if (err && errLen) std::snprintf(err, errLen, "fakenect replay library: no device serials");
    return -1;
  }
  freenect_context* ctx = nullptr;
  if (openContext(&ctx, false) < 0) {
    if (err && errLen)
      std::snprintf(err, errLen, "libfreenect: freenect_init failed: USB not usable");
    return -1;
  }
  freenect_device_attributes* list = nullptr;
  const int n = freenect_list_device_attributes(ctx, &list);
  int count = 0;
  for (freenect_device_attributes* a = list; a && count < maxDevices; a = a->next, ++count) {
    std::snprintf(serials[count], kKinectSerialLen, "%s",
                  a->camera_serial ? a->camera_serial : "?");
  }
  freenect_free_device_attributes(list);
  freenect_shutdown(ctx);
  if (n < 0) {
    if (err && errLen) std::snprintf(err, errLen, "libfreenect: cannot list devices (%d)", n);
    return -1;
  }
  return count;
}

KinectSource::~KinectSource() {
  close();
}

bool KinectSource::fail(const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(_error, sizeof _error, fmt, args);
  va_end(args);
  close();
  return false;
}

bool KinectSource::open(const KinectOptions& options) {
  close();
  _options = options;
  _error[0] = '\0';
  _failed = false;
  _started = false;
  _index = 0;
  _originTicks = 0;
  _loopResult.store(0);
  _replay = kinectReplayLibraryLoaded();
  _colourOn = options.streams != KinectStreams::DepthOnly;
  _depthOn = options.streams != KinectStreams::ColourOnly;
  if (options.serial && options.serial[0])
    std::snprintf(_name, sizeof _name, "kinect:%s", options.serial);
  else
    std::snprintf(_name, sizeof _name, "kinect#%d", options.deviceIndex);
  if (_replay) std::snprintf(_name, sizeof _name, "fakenect");

  if (!checkOptions(options)) return false;
  if (_replay && !checkReplay()) return false;
  for (int r = 0; r < 2048; ++r) _rawToMm[r] = kinect::rawToMm(static_cast<uint16_t>(r));
  if (!openDevice(options)) return false;
  resetPairer(options);
  freenect_set_user(_dev, this);
  return setModes(options) && startStreams();
}

bool KinectSource::checkOptions(const KinectOptions& options) {
  if (options.rateDivisor < 1)
    return fail("%s: rate divisor must be >= 1 (got %d)", _name, options.rateDivisor);
  if (options.setTilt && (options.tiltDeg < -27.f || options.tiltDeg > 27.f))
    return fail("%s: tilt %.1f deg out of range -27..27", _name,
                static_cast<double>(options.tiltDeg));

  KinectDepthMode depthMode = options.depthMode;
  if (depthMode == KinectDepthMode::Auto)
    depthMode = _replay ? KinectDepthMode::Raw : KinectDepthMode::Registered;
  if (_replay && depthMode == KinectDepthMode::Registered)
    return fail("fakenect: the replay library serves raw 11-bit depth only (use raw depth)");
  _registered = depthMode == KinectDepthMode::Registered;
  return true;
}

bool KinectSource::checkReplay() {
  // fakenect calls exit(1) on these; catch them here with a clear line instead.
  const char* path = std::getenv("FAKENECT_PATH");
  if (!path || !path[0])
    return fail("fakenect: FAKENECT_PATH is not set (it names the recording to replay)");
  char index[1024];
  std::snprintf(index, sizeof index, "%s/INDEX.txt", path);
  FILE* f = std::fopen(index, "rb");
  if (!f) return fail("%s: cannot open (FAKENECT_PATH must name a fakenect recording)", index);
  std::fclose(f);
  char why[sizeof _error];
  if (!checkFakenectReplayable(path, why, sizeof why)) return fail("fakenect: %s", why);
  return true;
}

bool KinectSource::openDevice(const KinectOptions& options) {
  const bool motor = options.setTilt || options.led != KinectLed::Unchanged;
  int r = openContext(&_ctx, motor);
  if (r < 0) {
    _ctx = nullptr;
    return fail("%s: libfreenect could not initialise USB (freenect_init %d)", _name, r);
  }
  const int n = freenect_num_devices(_ctx);
  if (n <= 0)
    return fail(
        "no Kinect found on USB: plug in a Kinect v1 with its 12 V adapter (see docs/kinect.md)");
  if (options.serial && options.serial[0]) {
    r = freenect_open_device_by_camera_serial(_ctx, &_dev, options.serial);
    if (r < 0) {
      _dev = nullptr;
      return fail(
          "%s: cannot open the Kinect with this serial (%d): not plugged in, or no "
          "permission (udev rule, docs/kinect.md)",
          _name, r);
    }
    return true;
  }
  if (options.deviceIndex < 0 || options.deviceIndex >= n)
    return fail("%s: no such device (%d Kinect%s found)", _name, n, n == 1 ? "" : "s");
  r = freenect_open_device(_ctx, &_dev, options.deviceIndex);
  if (r < 0) {
    _dev = nullptr;
    return fail(
        "%s: cannot open the Kinect (%d): in use by another program, or no permission "
        "(udev rule, docs/kinect.md)",
        _name, r);
  }
  return true;
}

void KinectSource::resetPairer(const KinectOptions& options) {
  kinect::PairerConfig pc;
  pc.useColour = _colourOn;
  pc.useDepth = _depthOn;
  pc.toleranceTicks = static_cast<uint64_t>(options.pairToleranceUs) * kinect::kTicksPerUs;
  pc.rateDivisor = options.rateDivisor;
  pc.externalStop = options.stopRequested;
  const KinectDelivery delivery =
      options.delivery == KinectDelivery::Auto
          ? (_replay ? KinectDelivery::Lossless : KinectDelivery::Latest)
          : options.delivery;
  pc.policy = delivery == KinectDelivery::Lossless ? kinect::DropPolicy::Lossless
                                                   : kinect::DropPolicy::Latest;
  _pairer.reset(pc);
}

bool KinectSource::setModes(const KinectOptions& options) {
  if (_depthOn) {
    const freenect_frame_mode mode = freenect_find_depth_mode(
        FREENECT_RESOLUTION_MEDIUM, _registered ? FREENECT_DEPTH_REGISTERED : FREENECT_DEPTH_11BIT);
    if (!mode.is_valid || freenect_set_depth_mode(_dev, mode) < 0)
      return fail("%s: depth mode 640x480 %s not supported", _name,
                  _registered ? "registered" : "11-bit");
    freenect_set_depth_callback(_dev, &KinectSource::onDepth);
    freenect_set_depth_buffer(_dev, _depth[_pairer.filling(kinect::Stream::Depth)]);
  }
  if (_colourOn) {
    const freenect_frame_mode mode =
        freenect_find_video_mode(FREENECT_RESOLUTION_MEDIUM, FREENECT_VIDEO_RGB);
    if (!mode.is_valid || freenect_set_video_mode(_dev, mode) < 0)
      return fail("%s: video mode 640x480 RGB not supported", _name);
    freenect_set_video_callback(_dev, &KinectSource::onColour);
    freenect_set_video_buffer(_dev, _colour[_pairer.filling(kinect::Stream::Colour)]);
  }
  if (options.led != KinectLed::Unchanged && freenect_set_led(_dev, toFreenect(options.led)) < 0)
    std::fprintf(stderr, "%s: warning: cannot set the LED (motor subdevice missing?)\n", _name);
  if (options.setTilt && freenect_set_tilt_degs(_dev, options.tiltDeg) < 0)
    std::fprintf(stderr, "%s: warning: cannot set the tilt (motor subdevice missing?)\n", _name);
  return true;
}

bool KinectSource::startStreams() {
  int r = 0;
  if (_depthOn && (r = freenect_start_depth(_dev)) < 0)
    return fail("%s: cannot start the depth stream (%d)", _name, r);
  if (_colourOn && (r = freenect_start_video(_dev)) < 0)
    return fail("%s: cannot start the colour stream (%d)", _name, r);

  // The event thread starts with SIGINT/SIGTERM/SIGHUP blocked (it inherits this
  // thread's mask), so they reach the application's threads, not libusb's poll (EINTR).
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  sigaddset(&block, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &block, &old);
  _thread = std::thread([this] { eventLoop(); });
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return true;
}

void KinectSource::eventLoop() {
  timeval timeout{0, 100000};  // 100 ms: bounds how long a stop request waits
  while (!_pairer.stopRequested()) {
    // fakenect's _timeout variant ignores the timeout; it sleeps to the recorded timing.
    const int r = freenect_process_events_timeout(_ctx, &timeout);
    if (r == LIBUSB_ERROR_INTERRUPTED) continue;
    if (r < 0) {
      _loopResult.store(r);
      _pairer.finish(kinect::EndKind::StreamEnded);
      return;
    }
  }
  _pairer.finish(kinect::EndKind::Stopped);
}

void KinectSource::onDepth(_freenect_device* dev, void*, uint32_t timestamp) {
  auto* self = static_cast<KinectSource*>(freenect_get_user(dev));
  const int next = self->_pairer.frameDone(kinect::Stream::Depth, timestamp);
  freenect_set_depth_buffer(dev, self->_depth[next]);
}

void KinectSource::onColour(_freenect_device* dev, void*, uint32_t timestamp) {
  auto* self = static_cast<KinectSource*>(freenect_get_user(dev));
  const int next = self->_pairer.frameDone(kinect::Stream::Colour, timestamp);
  freenect_set_video_buffer(dev, self->_colour[next]);
}

void KinectSource::close() {
  // On the event thread itself: a library that exit()s inside its event processing
  // (fakenect on a file it cannot read) runs static destructors there. The process is
  // ending; joining ourselves would abort it, and libusb is mid-call: leave both alone.
  if (_thread.joinable() && _thread.get_id() == std::this_thread::get_id()) {
    _thread.detach();
    return;
  }
  if (_thread.joinable()) {
    _pairer.requestStop();
    _thread.join();
  }
  if (_dev) {
    // Stopping a stream waits inside libusb for its in-flight transfers; after a USB
    // failure or a stall (device gone) that wait may never end, so skip it then.
    const bool healthy = !_failed && _loopResult.load() == 0;
    if (healthy && _depthOn) freenect_stop_depth(_dev);
    if (healthy && _colourOn) freenect_stop_video(_dev);
    freenect_close_device(_dev);
    _dev = nullptr;
  }
  if (_ctx) {
    freenect_shutdown(_ctx);
    _ctx = nullptr;
  }
}

void KinectSource::copyOut(const kinect::Taken& taken, FrameSlot& out) {
  if (taken.colour >= 0) {
    out.rgb.resize(kWidth, kHeight);
    std::memcpy(out.rgb.data(), _colour[taken.colour], kColourBytes);
  } else {
    out.rgb.resize(0, 0);  // depth-only mode: no colour image
  }
  out.hasDepth = taken.depth >= 0;
  if (out.hasDepth) {
    out.depthMm.resize(kWidth, kHeight);
    const uint16_t* src = _depth[taken.depth];
    uint16_t* dst = out.depthMm.data();
    if (_registered) {
      for (std::size_t i = 0; i < kDepthPixels; ++i) dst[i] = src[i] <= kMaxDepthMm ? src[i] : 0;
    } else {
      for (std::size_t i = 0; i < kDepthPixels; ++i) dst[i] = _rawToMm[src[i] & 2047u];
    }
  } else {
    out.depthMm.resize(0, 0);
  }
  if (!_started) {
    _started = true;
    _originTicks = taken.timeTicks;
  }
  out.timeUs = (taken.timeTicks - _originTicks) / kinect::kTicksPerUs;
  out.intrinsics = kKinectV1Intrinsics;
  out.index = _index++;
  out.hasGroundTruth = false;
  out.groundTruth = Box{};
}

ReadStatus KinectSource::next(FrameSlot& out) {
  if (_failed) return ReadStatus::Error;
  if (!isOpen()) {
    std::snprintf(_error, sizeof _error, "%s: not open", _name);
    return ReadStatus::Error;
  }
  const uint32_t waitMs = _started ? _options.stallTimeoutMs : _options.startTimeoutMs;
  // The wait in slices, with the caller's idle hook between them (heartbeats in a stall).
  kinect::Taken taken;
  for (uint32_t waitedMs = 0;;) {
    const uint32_t left = waitMs - waitedMs;
    const uint32_t slice = left < kIdleSliceMs ? left : kIdleSliceMs;
    taken = _pairer.take(slice);
    waitedMs += slice;
    if (taken.status != kinect::Taken::Status::Timeout || waitedMs >= waitMs) break;
    if (idle()) {
      std::snprintf(_error, sizeof _error, "%s: stopped", _name);
      return ReadStatus::End;
    }
  }
  switch (taken.status) {
    case kinect::Taken::Status::Ok:
      copyOut(taken, out);
      _pairer.release(taken);
      return ReadStatus::Ok;
    case kinect::Taken::Status::Timeout: {
      const kinect::PairerCounters c = _pairer.counters();
      std::snprintf(_error, sizeof _error,
                    "%s: no %s within %.1f s (received %llu colour, %llu depth frames): unplugged, "
                    "stream stopped, or USB bandwidth too low (see docs/kinect.md)",
                    _name, _colourOn && _depthOn ? "colour+depth pair" : "frame", waitMs / 1000.0,
                    static_cast<unsigned long long>(c.colourFrames),
                    static_cast<unsigned long long>(c.depthFrames));
      _failed = true;
      return ReadStatus::Error;
    }
    case kinect::Taken::Status::End:
      break;
  }
  if (taken.end == kinect::EndKind::Stopped) {
    std::snprintf(_error, sizeof _error, "%s: stopped", _name);
    return ReadStatus::End;
  }
  if (_replay) {
    std::snprintf(_error, sizeof _error, "fakenect: end of the recording");
    return ReadStatus::End;
  }
  std::snprintf(_error, sizeof _error,
                "%s: USB event processing failed (%d: %s): Kinect unplugged or its power lost",
                _name, _loopResult.load(), libusb_error_name(_loopResult.load()));
  _failed = true;
  return ReadStatus::Error;
}

KinectStats KinectSource::stats() const {
  const kinect::PairerCounters c = _pairer.counters();
  KinectStats s;
  s.colourFrames = c.colourFrames;
  s.depthFrames = c.depthFrames;
  s.delivered = c.delivered;
  s.dropped = c.dropped;
  s.unpaired = c.unpaired;
  s.skippedByRate = c.skippedByRate;
  return s;
}

}  // namespace cuetrack
