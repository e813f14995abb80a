#include "Pipeline.hpp"

#include <cstdio>

#include "BoxFit.hpp"
#include "StartBox.hpp"
#include "TargetCheck.hpp"
#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/platform/TrackText.hpp"

namespace cuetrack::app {
namespace {
using fmath::clampf;

Box clipToImage(const Box& b, int width, int height) {
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  const float x0 = clampf(b.x, 0.f, w), y0 = clampf(b.y, 0.f, h);
  const float x1 = clampf(b.x + b.w, 0.f, w), y1 = clampf(b.y + b.h, 0.f, h);
  return Box{x0, y0, x1 - x0, y1 - y0};
}
}  // namespace

Pipeline::Pipeline(FrameSource& source, FrameSlot& slot, TrackerPort& tracker, const Clock& clock,
                   platform::Reporter& reporter, const PipelineOptions& options)
    : _source(source),
      _slot(slot),
      _tracker(tracker),
      _clock(clock),
      _reporter(reporter),
      _options(options) {
  _statusLastUs = _clock.nowUs();
  _source.setIdleHook(&Pipeline::onSourceIdle, this);
}

bool Pipeline::onSourceIdle(void* self) {
  Pipeline& p = *static_cast<Pipeline*>(self);
  p.serviceLink();
  return p._stopRequested;
}

bool Pipeline::addSink(platform::TrackSink* sink) {
  if (_numSinks >= kMaxSinks) return false;
  _sinks[_numSinks] = sink;
  _sinkOk[_numSinks] = true;
  ++_numSinks;
  return true;
}

// A start waits for the next frame. One that a newer start, a reset or a stop supersedes
// before then is answered Superseded: every command gets exactly one reply.
void Pipeline::dropPendingStart() {
  if (_startPending && _link) _link->answerStart(_start.token, platform::StartOutcome::Superseded);
  _startPending = false;
}

void Pipeline::requestStart(const platform::StartRequest& request) {
  dropPendingStart();
  _startPending = true;
  _start = request;
}

void Pipeline::requestStop() {
  dropPendingStart();
  _stopRequested = true;
}

void Pipeline::requestReset() {
  dropPendingStart();
  _tracker.reset();
  _targetActive = false;
  _autoTargetTried = true;  // a reset target stays reset: no silent re-init from ground truth
  _state = CTP_STATE_IDLE;
}

void Pipeline::serviceLink() {
  if (!_link) return;
  platform::LinkStatus status;
  status.state = _state;
  status.frames = _frames;
  status.noCamera = _source.awaitingDevice();
  _link->poll(*this, status);
}

bool Pipeline::startFromCommand(const Frame& frame, Box* initBox) {
  _startPending = false;
  _autoTargetTried = true;
  const char* why = "";
  // A box in pixels comes in the source's own pixels; the frame may be scaled down.
  platform::StartRequest start = _start;
  if (start.kind == platform::StartRequest::Kind::BoxPx) start.box = _slot.scale.toSlot(start.box);
  const Box box = startBoxPx(start, frame);
  if (_tracker.init(frame, box, &why) == 0) {
    *initBox = box;
    if (_start.kind == platform::StartRequest::Kind::BoxPx) warnIfCorners(frame, box, "START");
    warnIfPoorTarget(frame, box, "START");
    if (_link) _link->answerStart(_start.token, platform::StartOutcome::Started);
    return true;
  }
  char line[200];
  const Box said = _slot.scale.toSource(box);  // as the sender gave it
  std::snprintf(line, sizeof line, "%s START %g,%g,%g,%g refused: %s (the image is %dx%d)",
                _options.linkName, said.x, said.y, said.w, said.h, why,
                _slot.scale.sourceWidth(frame.rgb.width),
                _slot.scale.sourceHeight(frame.rgb.height));
  _reporter.report(line);
  _tracker.reset();
  _targetActive = false;
  _state = CTP_STATE_IDLE;
  if (_link) _link->answerStart(_start.token, platform::StartOutcome::Refused);
  return false;
}

bool Pipeline::startFromOptions(const Frame& frame, Box* initBox, bool* rejected) {
  // --box applies to the first frame; ground truth to the first frame where the
  // target is visible. Either is tried once.
  Box box{};
  if (_options.hasBox) {
    box = _slot.scale.toSlot(_options.box);  // --box is in the source's own pixels
  } else if (_options.useGroundTruth && _slot.hasGroundTruth && !_slot.groundTruth.empty()) {
    box = _slot.groundTruth;
  } else {
    return false;
  }
  _autoTargetTried = true;
  const char* why = "";
  if (_tracker.init(frame, box, &why) == 0) {
    *initBox = box;
    if (_options.hasBox) {
      warnIfCorners(frame, box, "--box");
      warnIfPoorTarget(frame, box, "--box");
    }
    return true;
  }
  // Either ends the run: without it nothing would be tracked, ever.
  char line[640];
  const Box said = _slot.scale.toSource(box);  // as the user or the file gave it
  // A frame scaled down for the tracker scales the box too: say what the tracker saw.
  const int sourceW = _slot.scale.sourceWidth(frame.rgb.width);
  const int sourceH = _slot.scale.sourceHeight(frame.rgb.height);
  char image[160];
  if (sourceW != frame.rgb.width)
    std::snprintf(image, sizeof image,
                  "the image is %dx%d, scaled down to %dx%d for the tracker, where the box is "
                  "%.1fx%.1f px; give a larger box",
                  sourceW, sourceH, frame.rgb.width, frame.rgb.height, static_cast<double>(box.w),
                  static_cast<double>(box.h));
  else
    std::snprintf(image, sizeof image, "the image is %dx%d", sourceW, sourceH);
  if (_options.hasBox) {
    std::snprintf(line, sizeof line, "--box %g,%g,%g,%g refused by the tracker: %s (%s)", said.x,
                  said.y, said.w, said.h, why, image);
  } else {
    std::snprintf(line, sizeof line,
                  "%s: frame %d: box %g,%g,%g,%g refused by the tracker: %s (%s)",
                  _options.groundTruthName ? _options.groundTruthName : "ground truth", _slot.index,
                  said.x, said.y, said.w, said.h, why, image);
  }
  _reporter.report(line);
  *rejected = true;
  return false;
}

void Pipeline::warnIfPoorTarget(const Frame& frame, const Box& box, const char* origin) {
  if (!_options.warnPoorTarget) return;
  const TargetCheck check = checkTarget(frame, box);
  if (check.issues == 0) return;
  char issues[320];
  describeTargetIssues(check, issues, sizeof issues);
  char line[512];
  const Box said = _slot.scale.toSource(box);
  std::snprintf(line, sizeof line,
                "%s %g,%g,%g,%g: poor target: %s (the track may follow nothing; --select or "
                "--snapshot FILE.png to pick another)",
                origin, said.x, said.y, said.w, said.h, issues);
  _reporter.report(line);
}

void Pipeline::sayScaling() {
  if (!_options.sayScaling || _scalingSaid || !_slot.scale.scaled()) return;
  _scalingSaid = true;
  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %dx%d frames scaled down to %dx%d for the tracker; boxes in and out are in "
                "the %dx%d pixels",
                _options.sourceName ? _options.sourceName : _source.name(),
                _slot.scale.sourceWidthPx, _slot.scale.sourceHeightPx, _slot.scale.widthPx,
                _slot.scale.heightPx, _slot.scale.sourceWidthPx, _slot.scale.sourceHeightPx);
  _reporter.report(line);
}

void Pipeline::warnIfCorners(const Frame& frame, const Box& slotBox, const char* origin) {
  // Judged and said in the source's own pixels, as the box was given.
  const Box box = _slot.scale.toSource(slotBox);
  const int w = _slot.scale.sourceWidth(frame.rgb.width);
  const int h = _slot.scale.sourceHeight(frame.rgb.height);
  Box xywh{};
  if (!_options.warnPoorTarget || !looksLikeCorners(box, w, h, &xywh)) return;
  char line[320];
  std::snprintf(line, sizeof line,
                "%s %g,%g,%g,%g runs past the %dx%d image as X,Y,W,H; if %g,%g is the bottom-right "
                "corner, the box is %g,%g,%g,%g (X,Y,W,H)",
                origin, box.x, box.y, box.w, box.h, w, h, box.w, box.h, xywh.x, xywh.y, xywh.w,
                xywh.h);
  _reporter.report(line);
}

bool Pipeline::sizeChanged(const Frame& frame) {
  if (frame.rgb.width == _trackWidth && frame.rgb.height == _trackHeight) return false;
  // The tracker would skip such a frame and still say "tracking".
  char line[512];
  std::snprintf(line, sizeof line, "%s: frame %d is %dx%d, the track began at %dx%d",
                _options.sourceName ? _options.sourceName : _source.name(), _slot.index,
                frame.rgb.width, frame.rgb.height, _trackWidth, _trackHeight);
  _reporter.report(line);
  return true;
}

StepResult Pipeline::stopped() {
  if (_link) _link->drain(1000);  // the ACK goes out before we do
  return StepResult::Stopped;
}

StepResult Pipeline::step() {
  serviceLink();
  if (_stopRequested) return stopped();
  if (_options.maxFrames >= 0 && static_cast<int64_t>(_frames) >= _options.maxFrames) {
    return StepResult::Done;
  }
  const ReadStatus rs = _source.next(_slot);
  // End with a STOP pending: it came while the source waited (onSourceIdle).
  if (rs == ReadStatus::End) return _stopRequested ? stopped() : StepResult::Done;
  if (rs == ReadStatus::Error) {
    _reporter.report(_source.error());
    return StepResult::SourceError;
  }
  sayScaling();
  const Frame frame = _slot.frame();
  if (_targetActive && !_startPending && sizeChanged(frame)) return StepResult::SourceError;
  const uint64_t t0 = _clock.nowUs();

  TrackResult result;
  Box initBox{};
  bool initialised = false;
  if (_startPending) {
    initialised = startFromCommand(frame, &initBox);
  } else if (!_targetActive && !_autoTargetTried) {
    bool rejected = false;
    initialised = startFromOptions(frame, &initBox, &rejected);
    if (rejected) return StepResult::BoxRejected;
  }

  if (initialised) {
    // The init frame reports the box the tracker was given, with full confidence, cut to
    // the image as the tracker cuts it (a box reaching past the edge tracks what is inside).
    _targetActive = true;
    _trackWidth = frame.rgb.width;
    _trackHeight = frame.rgb.height;
    result.state = TrackState::Tracking;
    result.box = clipToImage(initBox, frame.rgb.width, frame.rgb.height);
    result.confidence = 1.f;
  } else if (_targetActive) {
    result = _tracker.update(frame);
  }
  const uint64_t procUs = _clock.nowUs() - t0;
  result.box = _slot.scale.toSource(result.box);  // every output speaks the source's pixels
  ctp_track_t msg = platform::toTrackMessage(
      result, frame.timeUs, static_cast<uint32_t>(procUs > 0xFFFFFFFFu ? 0xFFFFFFFFu : procUs),
      _state);
  _confirmed.apply(msg);  // lost: the last confirmed box, never the search's
  _state = msg.state;
  _lastTrack = msg;
  ++_frames;
  emit(msg, frame);
  statusLine();
  if (!_link && _numSinks > 0) {
    bool anyOk = false;
    for (int i = 0; i < _numSinks; ++i) anyOk = anyOk || _sinkOk[i];
    if (!anyOk) return StepResult::OutputsGone;
  }
  return StepResult::Continue;
}

void Pipeline::emit(const ctp_track_t& msg, const Frame& frame) {
  for (int i = 0; i < _numSinks; ++i) {
    if (!_sinkOk[i]) continue;
    ctp_track_t m = msg;
    m.seq = _sinkSeq[i]++;
    if (!_sinks[i]->write(m)) {
      char line[448];
      std::snprintf(line, sizeof line, "%s; output stopped, tracking continues",
                    _sinks[i]->error());
      _reporter.report(line);
      _sinkOk[i] = false;
      _outputFailed = true;
    }
  }
  if (_link) {
    platform::FrameReport report;
    report.track = msg;
    report.widthPx = _slot.scale.sourceWidth(frame.rgb.width);
    report.heightPx = _slot.scale.sourceHeight(frame.rgb.height);
    report.intrinsics = _slot.scale.toSource(frame.intrinsics);
    _link->sendFrame(report);
  }
}

void Pipeline::statusLine() {
  if (_options.statusPeriodUs == 0) return;
  const uint64_t now = _clock.nowUs();
  const uint64_t dt = now - _statusLastUs;
  if (dt < _options.statusPeriodUs) return;
  const double fps =
      static_cast<double>(_frames - _statusLastFrames) * 1e6 / static_cast<double>(dt);
  char line[256];
  const uint64_t dropped = _options.droppedFrames ? _options.droppedFrames(_source)
                                                  : static_cast<uint64_t>(_source.skippedFrames());
  int n = std::snprintf(line, sizeof line, "frame %u fps %.1f dropped %llu state %s",
                        static_cast<unsigned>(_frames), fps,
                        static_cast<unsigned long long>(dropped), ctp_state_name(_state));
  if (_link && n > 0 && static_cast<size_t>(n) < sizeof line) {
    const platform::LinkStats& s = _link->stats();
    std::snprintf(line + n, sizeof line - static_cast<size_t>(n),
                  " | %s %s sent %u tx-dropped %u rx-errors %u refused %u", _options.linkName,
                  _link->connected() ? "up" : "down", static_cast<unsigned>(s.sent),
                  static_cast<unsigned>(s.txDropped), static_cast<unsigned>(s.rxErrors),
                  static_cast<unsigned>(s.rxRefused));
  }
  _reporter.report(line);
  _statusLastUs = now;
  _statusLastFrames = _frames;
}

}  // namespace cuetrack::app
