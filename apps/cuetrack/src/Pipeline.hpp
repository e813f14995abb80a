// One frame at a time: source -> tracker -> sinks and the serial link (either protocol,
// behind platform::TrackLink), with commands from the link applied between frames. The
// tracker works in the slot's pixels; boxes in (--box, START) and out (sinks, link,
// lastTrack) are in the source's own (FrameSlot::scale maps them, FrameScale.hpp). Owns no big
// buffer: the frame slot, the tracker and the sources live in static storage in main().
#pragma once

#include <cstdint>

#include "ConfirmedBox.hpp"
#include "TrackerPort.hpp"
#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack/platform/TrackLink.hpp"
#include "cuetrack/platform/TrackSink.hpp"

namespace cuetrack::app {

struct PipelineOptions {
  int maxFrames = -1;           // stop after this many frames (-1: until the source ends)
  bool hasBox = false;          // --box: the target in the first frame
  Box box{};                    // [px] of the source's own frame
  bool useGroundTruth = true;   // else wait for --box or a serial START
  uint64_t statusPeriodUs = 0;  // status line period; 0 = no status line
  // Frames the source lost (for the status line); nullptr: FrameSource::skippedFrames().
  uint64_t (*droppedFrames)(const FrameSource&) = nullptr;
  // For messages: the source as the user named it (nullptr: FrameSource::name()), and
  // where its ground truth comes from, e.g. "rec/groundtruth.txt" (nullptr: "ground truth").
  const char* sourceName = nullptr;
  const char* groundTruthName = nullptr;
  // The link as the status line names it: "serial" (--serial), "udp" (--mavlink-udp).
  const char* linkName = "serial";
  // Warn in one line when a box the user gave (--box, a START) is a poor target
  // (TargetCheck.hpp) or reads as corners (BoxFit.hpp); ground-truth boxes are taken as
  // they are.
  bool warnPoorTarget = false;
  // Say once, at the first frame a source scales down, from what size to what.
  bool sayScaling = false;
};

enum class StepResult : uint8_t {
  Continue,
  Done,         // source ended or --frames reached
  Stopped,      // STOP command
  SourceError,  // reported; also a frame of another size than the track's first (reported)
  BoxRejected,  // --box or the ground-truth box refused by the tracker (reported)
  OutputsGone,  // every output failed and there is no serial link: nothing left to feed
};

class Pipeline final : public platform::LinkControl {
 public:
  static constexpr int kMaxSinks = 3;

  // Hooks into the source's waits (FrameSource::setIdleHook) until destroyed.
  Pipeline(FrameSource& source, FrameSlot& slot, TrackerPort& tracker, const Clock& clock,
           platform::Reporter& reporter, const PipelineOptions& options);
  ~Pipeline() override { _source.setIdleHook(nullptr, nullptr); }
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  bool addSink(platform::TrackSink* sink);
  void attachLink(platform::TrackLink* link) { _link = link; }

  StepResult step();
  // The run is over (end of source, --frames, a signal, an error): a START still waiting
  // for its frame is answered ERROR busy, so every command has had its one reply.
  void finish() { dropPendingStart(); }

  // Serial-side work without a frame (also done by step()): commands, heartbeats.
  void serviceLink();

  // LinkControl
  void requestStart(const platform::StartRequest& request) override;
  void requestReset() override;
  void requestStop() override;

  uint32_t frames() const { return _frames; }
  uint8_t state() const { return _state; }
  // The last frame's track as sent out (seq 0), for the window and the run summary; while
  // lost its box is the last confirmed one (ConfirmedBox.hpp).
  const ctp_track_t& lastTrack() const { return _lastTrack; }
  bool outputFailed() const { return _outputFailed; }

 private:
  // While the source waits for a frame: the link's work; a STOP ends the wait.
  static bool onSourceIdle(void* self);
  StepResult stopped();  // after a STOP: its ACK drained onto the line
  void dropPendingStart();
  // Initialise the tracker from a serial START / from --box or ground truth; true when
  // tracking starts on this frame (*initBox: the box given).
  bool startFromCommand(const Frame& frame, Box* initBox);
  bool startFromOptions(const Frame& frame, Box* initBox, bool* rejected);
  // True (reported) when frame is not of the size the track began on.
  bool sizeChanged(const Frame& frame);
  void emit(const ctp_track_t& msg, const Frame& frame);
  void statusLine();
  void warnIfPoorTarget(const Frame& frame, const Box& box, const char* origin);
  // A box that reads as X0,Y0,X1,Y1 corners (BoxFit.hpp): one line with its X,Y,W,H.
  void warnIfCorners(const Frame& frame, const Box& box, const char* origin);
  void sayScaling();

  FrameSource& _source;
  FrameSlot& _slot;
  TrackerPort& _tracker;
  const Clock& _clock;
  platform::Reporter& _reporter;
  PipelineOptions _options;
  platform::TrackLink* _link{nullptr};

  platform::TrackSink* _sinks[kMaxSinks]{};
  bool _sinkOk[kMaxSinks]{};
  uint32_t _sinkSeq[kMaxSinks]{};
  int _numSinks{0};
  bool _outputFailed{false};

  bool _targetActive{false};
  int _trackWidth{0}, _trackHeight{0};  // [px] of the frame the track began on
  bool _autoTargetTried{false};         // --box / ground truth is used once, at the start
  bool _scalingSaid{false};
  bool _startPending{false};
  platform::StartRequest _start{};
  bool _stopRequested{false};
  uint8_t _state{CTP_STATE_IDLE};
  ConfirmedBox _confirmed;  // what a lost frame reports as its box
  uint32_t _frames{0};
  ctp_track_t _lastTrack{};

  uint64_t _statusLastUs{0};
  uint32_t _statusLastFrames{0};
};

}  // namespace cuetrack::app
