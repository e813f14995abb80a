// The live Kinect v1 as a FrameSource, through libfreenect's asynchronous API.
//
//   static KinectSource kinect;             // ~4.5 MiB of frame buffers: never on the stack
//   if (!kinect.open(options)) { fprintf(stderr, "%s\n", kinect.error()); return 2; }
//   static FrameSlot slot;
//   while (kinect.next(slot) == ReadStatus::Ok) tracker.update(slot.frame());
//
// freenect_process_events runs on a thread of its own. The library writes straight
// into our buffers (freenect_set_video_buffer / freenect_set_depth_buffer), three per
// stream, rotated by kinect::Pairer; colour and depth are paired by their camera
// timestamps. After open() nothing allocates per frame. next() copies a pair into the
// caller's FrameSlot: colour RGB888 640x480, depth in mm registered to colour
// (FREENECT_DEPTH_REGISTERED on a device; raw 11-bit converted in software with the
// project's one formula, cuetrack/drivers/KinectDepth.hpp, under fakenect or on request).
//
// Every wait is bounded: no frame within the stall timeout, an unplugged device or a
// stream that stops gives Error (one line naming the device), a requested stop gives
// End, and the end of a fakenect recording gives End.
//
// fakenect: with LD_LIBRARY_PATH=/usr/lib/<triple>/fakenect and FAKENECT_PATH=<recording>
// the same code replays a recording. It is detected at run time (it lacks
// freenect_set_flag); it serves raw depth only and delivers every frame (Lossless).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>

#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/KinectPairer.hpp"

// libfreenect's opaque types, so that only drivers/kinect/src includes <libfreenect.h>.
struct _freenect_context;
struct _freenect_device;

namespace cuetrack {

enum class KinectStreams : uint8_t { Both, DepthOnly, ColourOnly };
enum class KinectDepthMode : uint8_t {
  Auto,        // Registered on a device, Raw under fakenect
  Registered,  // FREENECT_DEPTH_REGISTERED: mm, registered to colour by the library
  Raw,         // FREENECT_DEPTH_11BIT + software raw->mm (not registered to colour)
};
enum class KinectDelivery : uint8_t {
  Auto,      // Latest on a device, Lossless under fakenect
  Latest,    // a slow consumer gets the newest pair; older ones are dropped (counted)
  Lossless,  // the event loop waits for the consumer (replay; loses USB packets live)
};
enum class KinectLed : uint8_t { Unchanged, Off, Green, Red, Yellow, BlinkGreen, BlinkRedYellow };

struct KinectOptions {
  int deviceIndex = 0;           // 0-based, in libfreenect's enumeration order
  const char* serial = nullptr;  // camera serial; when set, overrides deviceIndex
  KinectStreams streams = KinectStreams::Both;
  KinectDepthMode depthMode = KinectDepthMode::Auto;
  KinectDelivery delivery = KinectDelivery::Auto;
  int rateDivisor = 1;  // deliver every Nth pair (saves CPU, not USB bandwidth)
  bool setTilt = false;
  float tiltDeg = 0.f;  // [deg], -27..27, when setTilt
  KinectLed led = KinectLed::Unchanged;
  uint32_t pairToleranceUs = 16000;  // max colour/depth time difference of a pair [us]
  uint32_t startTimeoutMs = 5000;    // first frame
  uint32_t stallTimeoutMs = 2000;    // any later frame
  // Polled every ~20 ms while waiting (e.g. platform::stopRequested for SIGINT/SIGTERM):
  // when it returns true, next() returns End.
  bool (*stopRequested)() = nullptr;
};

// Parsers for command lines; false on an unknown name.
bool parseKinectStreams(const char* name, KinectStreams* out);      // both, depth, colour
bool parseKinectDepthMode(const char* name, KinectDepthMode* out);  // auto, registered, raw
bool parseKinectLed(const char* name,
                    KinectLed* out);  // off green red yellow blink-green blink-red-yellow
const char* toString(KinectStreams s);

// USB isochronous load of the chosen streams at 640x480, 30 Hz [MB/s]: colour (8-bit
// Bayer) 9.2, depth (11-bit packed) 12.7, both 21.9. Pi-class boards carry ~15-20.
double kinectUsbLoadMBps(KinectStreams streams);

struct KinectStats {
  uint64_t colourFrames = 0;  // frames received from the library
  uint64_t depthFrames = 0;
  uint64_t delivered = 0;      // frames handed out by next()
  uint64_t dropped = 0;        // pairs overwritten because the consumer was slower (Latest)
  uint64_t unpaired = 0;       // frames without a partner within the tolerance
  uint64_t skippedByRate = 0;  // pairs skipped by rateDivisor
};

// True when the libfreenect loaded into this process is fakenect's replay library.
bool kinectReplayLibraryLoaded();

// Cheap presence query (a few ms, no streaming): the number of Kinect cameras on the
// USB bus, or -1 with a one-line reason in err (libusb unusable). fakenect: always 1.
int countKinects(char* err, std::size_t errLen);

// Camera serials of the plugged-in Kinects (up to maxDevices, each NUL-terminated in
// serials[i]); returns the count, or -1 with err. Not available under fakenect.
inline constexpr int kKinectSerialLen = 32;
int listKinectSerials(char (*serials)[kKinectSerialLen], int maxDevices, char* err,
                      std::size_t errLen);

class KinectSource final : public FrameSource {
 public:
  static constexpr int kWidth = 640;   // [px] colour and depth (FREENECT_RESOLUTION_MEDIUM)
  static constexpr int kHeight = 480;  // [px]
  static constexpr std::size_t kColourBytes = kWidth * kHeight * 3;
  static constexpr std::size_t kDepthPixels = kWidth * kHeight;
  static_assert(kWidth <= kMaxImageWidth && kHeight <= kMaxImageHeight, "FrameSlot too small");

  KinectSource() = default;
  ~KinectSource() override;
  KinectSource(const KinectSource&) = delete;
  KinectSource& operator=(const KinectSource&) = delete;

  // Opens the device, starts the streams and the event thread. false + error() on failure
  // (no Kinect, permission, bad option, fakenect without a recording).
  bool open(const KinectOptions& options);
  // Stops the streams and the event thread, closes the device. Safe to call twice.
  void close();
  bool isOpen() const { return _ctx != nullptr; }

  // Async-signal-safe: the next (or a waiting) next() returns End within ~20 ms.
  void requestStop() { _pairer.requestStop(); }

  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name; }

  KinectStats stats() const;
  bool replay() const { return _replay; }  // fakenect is serving the frames
  KinectStreams streams() const { return _options.streams; }
  bool depthRegistered() const { return _registered; }

 private:
  static void onDepth(_freenect_device* dev, void* data, uint32_t timestamp);
  static void onColour(_freenect_device* dev, void* data, uint32_t timestamp);
  void eventLoop();
  // The steps of open(), each false after fail().
  bool checkOptions(const KinectOptions& options);
  bool checkReplay();
  bool openDevice(const KinectOptions& options);
  void resetPairer(const KinectOptions& options);
  bool setModes(const KinectOptions& options);
  bool startStreams();
  bool fail(const char* fmt, ...) __attribute__((format(printf, 2, 3)));
  void copyOut(const kinect::Taken& taken, FrameSlot& out);

  KinectOptions _options{};
  kinect::Pairer _pairer;
  _freenect_context* _ctx = nullptr;
  _freenect_device* _dev = nullptr;
  std::thread _thread;
  std::atomic<int> _loopResult{0};  // freenect_process_events' failure code
  bool _replay = false;
  bool _registered = false;
  bool _colourOn = false;
  bool _depthOn = false;
  bool _started = false;  // a frame was delivered
  bool _failed = false;   // sticky Error
  int _index = 0;
  uint64_t _originTicks = 0;
  char _name[48] = "kinect";
  char _error[256] = "";
  uint16_t _rawToMm[2048]{};  // raw 11-bit disparity -> mm, from KinectDepth.hpp

  // Frame buffers the library writes into (memory layout: 3 x 921,600 B colour,
  // 3 x 614,400 B depth = 4.6 MB).
  alignas(64) uint8_t _colour[kinect::kBuffersPerStream][kColourBytes];
  alignas(64) uint16_t _depth[kinect::kBuffersPerStream][kDepthPixels];
};

}  // namespace cuetrack
