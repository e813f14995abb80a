// The app's pipeline with fakes all round: a tiny frame source, a stand-in tracker,
// a settable clock, memory sinks and an in-memory serial cable. Covers target
// selection, the commands and their replies, rate limit, heartbeats, rejected input,
// a stalled or vanished peer and failing outputs.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "AllocCounter.hpp"
#include "PacedSource.hpp"
#include "Pipeline.hpp"
#include "SerialLink.hpp"
#include "WaitingSource.hpp"
#include "cuetrack/platform/TrackText.hpp"
#include "cuetrack/platform/fake/FakeClock.hpp"
#include "cuetrack/platform/fake/FakeSerial.hpp"
#include "cuetrack/platform/fake/MemoryReporter.hpp"
#include "cuetrack/platform/fake/MemorySink.hpp"
#include "cuetrack/platform/mavlink/MavlinkLink.hpp"
#include "fc_link.h"

using namespace cuetrack;
using namespace cuetrack::app;
using namespace cuetrack::platform;

namespace {

// 64x48 grey frames, 30 fps timestamps, optional ground truth in every frame.
constexpr int kTinyW = 64, kTinyH = 48;
class TinySource final : public FrameSource {
 public:
  TinySource(int frames, bool withTruth) : _frames(frames), _withTruth(withTruth) {}
  ReadStatus next(FrameSlot& out) override {
    if (_failAt == _index) return ReadStatus::Error;
    if (_stallAt == _index) {
      // A device that delivers nothing for a while: the wait passes in idle slices.
      _stallAt = -1;
      for (int i = 0; i < _stallSlices; ++i) {
        _stallClock->advanceUs(FrameSource::kIdleSliceMs * 1000u);
        if (_onSlice) _onSlice(i, _onSliceCtx);
        if (idle()) return ReadStatus::End;
      }
    }
    if (_index >= _frames) return ReadStatus::End;
    if (_index >= _resizeFrom)
      out.rgb.resize(_resizeW, _resizeH);
    else
      out.rgb.resize(kTinyW, kTinyH);
    out.hasDepth = false;
    out.scale = _scale;
    out.timeUs = static_cast<uint64_t>(_index) * 33333u + (_index >= _gapFrom ? _gapUs : 0u);
    out.index = _index;
    out.hasGroundTruth = _withTruth;
    out.groundTruth = _index >= _visibleFrom ? Box{_truthX, 12.f, 20.f, 16.f} : Box{};
    ++_index;
    return ReadStatus::Ok;
  }
  const char* error() const override { return "tiny.seq: frame 3: truncated"; }
  const char* name() const override { return "tiny"; }
  void failAt(int i) { _failAt = i; }
  void gapBefore(int i, uint64_t us) {  // timestamps from frame i on are us later
    _gapFrom = i;
    _gapUs = us;
  }
  // Before frame i the source waits `slices` idle slices, advancing `clock` through each
  // and calling onSlice(slice, ctx) (the peer's doings meanwhile) before the idle hook.
  void stallAt(int i, int slices, FakeClock* clock, void (*onSlice)(int, void*) = nullptr,
               void* ctx = nullptr) {
    _stallAt = i;
    _stallSlices = slices;
    _stallClock = clock;
    _onSlice = onSlice;
    _onSliceCtx = ctx;
  }
  // Frames scaled down from a w x h source (twice 64x48: 128x96), as a large video's are.
  void scaledFrom(int w, int h) { _scale = FrameScale{w, h, 64, 48}; }
  void visibleFrom(int i) { _visibleFrom = i; }  // ground truth empty before frame i
  void truthX(float x) { _truthX = x; }
  void resizeFrom(int i, int w, int h) {  // frames i... are w x h
    _resizeFrom = i;
    _resizeW = w;
    _resizeH = h;
  }

 private:
  int _frames;
  bool _withTruth;
  int _index = 0;
  int _failAt = -1;
  int _stallAt = -1, _stallSlices = 0;
  int _gapFrom = 1 << 30;
  uint64_t _gapUs = 0;
  FakeClock* _stallClock = nullptr;
  void (*_onSlice)(int, void*) = nullptr;
  void* _onSliceCtx = nullptr;
  int _visibleFrom = 0;
  float _truthX = 10.f;
  int _resizeFrom = 1 << 30, _resizeW = 0, _resizeH = 0;
  FrameScale _scale{};
};

// Moves the box 1 px right per update; refuses boxes with x < 0.
class StubTracker final : public TrackerPort {
 public:
  bool configure(const char*, uint64_t, const Clock*) override { return true; }
  int init(const Frame&, const Box& box, const char** why) override {
    if (box.x < 0.f) {
      *why = "BoxOutsideImage";
      return 2;
    }
    _box = _init = box;
    ++inits;
    return 0;
  }
  TrackResult update(const Frame&) override {
    ++updates;
    _box.x += 1.f;
    TrackResult r;
    r.state = lost ? TrackState::Lost : TrackState::Tracking;
    r.box = _box;
    r.confidence = 0.75f;
    if (with3d) {  // a centre 2 m ahead that moves with the box
      r.hasPosition3d = true;
      r.positionMm[0] = 10.f * _box.x;
      r.positionMm[2] = 2000.f;
    }
    return r;
  }
  void reset() override { ++resets; }
  Box lastInit() const { return _init; }
  int inits = 0, updates = 0, resets = 0;
  bool lost = false;
  bool with3d = false;

 private:
  Box _box{}, _init{};
};

// The host end of the cable: sends commands, decodes what the app sent.
struct Host {
  explicit Host(ByteStream& s) : stream(s) { ctp_decoder_init(&dec); }
  void send(const ctp_command_t& c) {
    uint8_t w[CTP_MAX_WIRE];
    const size_t n = ctp_encode_command(&c, w, sizeof w);
    REQUIRE(stream.write(w, n).bytes == n);
  }
  void sendRaw(const std::vector<uint8_t>& bytes) {
    REQUIRE(stream.write(bytes.data(), bytes.size()).bytes == bytes.size());
  }
  // Decodes everything that arrived since the last call.
  std::vector<ctp_message_t> drain() {
    std::vector<ctp_message_t> out;
    uint8_t buf[512];
    for (;;) {
      const IoResult r = stream.read(buf, sizeof buf, 0);
      if (r.bytes == 0) break;
      for (size_t i = 0; i < r.bytes; ++i) {
        ctp_frame_t f;
        if (ctp_decoder_push(&dec, buf[i], &f, nullptr) == CTP_PUSH_FRAME) {
          ctp_message_t m;
          REQUIRE(ctp_parse_message(&f, &m) == CTP_OK);
          out.push_back(m);
        }
      }
    }
    return out;
  }
  ByteStream& stream;
  ctp_decoder_t dec;
};

ctp_command_t command(uint8_t type, uint16_t id) {
  ctp_command_t c{};
  c.type = type;
  c.id = id;
  return c;
}

ctp_command_t startCommand(uint16_t id, int16_t x, int16_t y, int16_t w, int16_t h) {
  ctp_command_t c = command(CTP_CMD_START, id);
  c.box_px[0] = x;
  c.box_px[1] = y;
  c.box_px[2] = w;
  c.box_px[3] = h;
  return c;
}

int countType(const std::vector<ctp_message_t>& ms, uint8_t type) {
  int n = 0;
  for (const auto& m : ms) n += m.type == type;
  return n;
}

// Everything a test needs, in static storage once (FrameSlot is 1.5 MiB).
struct Rig {
  Rig(int frames, bool truth, const PipelineOptions& o = {})
      : source(frames, truth),
        link(cable.a(), clock, reporter),
        pipeline(source, slot(), tracker, clock, reporter, o),
        host(cable.b()) {
    pipeline.addSink(&sink);
    pipeline.attachLink(&link);
  }
  static FrameSlot& slot() {
    static FrameSlot s;
    return s;
  }
  StepResult step() {
    clock.advanceUs(33333);
    return pipeline.step();
  }
  // Before frame `frame` the camera delivers nothing for `slices` idle slices of 100 ms;
  // the host sends `c` 0.5 s into that silence.
  void stallThenSend(int frame, int slices, const ctp_command_t& c) {
    midStall = c;
    source.stallAt(
        frame, slices, &clock,
        [](int slice, void* self) {
          Rig& r = *static_cast<Rig*>(self);
          if (slice == 4) r.host.send(r.midStall);
        },
        this);
  }
  FakeClock clock{1000};
  FakeSerialCable cable;
  MemoryReporter reporter;
  MemorySink sink;
  TinySource source;
  StubTracker tracker;
  SerialLink link;
  Pipeline pipeline;
  Host host;
  ctp_command_t midStall{};
};

}  // namespace

TEST_CASE("ground truth starts tracking; every frame reaches the sink and the link") {
  static Rig rig(5, true);
  for (int i = 0; i < 5; ++i) REQUIRE(rig.step() == StepResult::Continue);
  REQUIRE(rig.step() == StepResult::Done);
  REQUIRE(rig.sink.size() == 5);
  CHECK(rig.sink.at(0).state == CTP_STATE_TRACKING);
  CHECK(rig.sink.at(0).box_px[0] == 10);  // the init frame reports the given box
  CHECK(rig.sink.at(0).confidence == 65535);
  CHECK(rig.sink.at(4).box_px[0] == 14);  // 4 updates, 1 px each
  CHECK(rig.sink.at(4).seq == 4);
  CHECK(rig.sink.at(3).time_us == 99999);
  CHECK(rig.tracker.inits == 1);
  const auto msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_TRACK) == 5);
  CHECK(msgs.back().u.track.box_px[0] == 14);
  CHECK(msgs.back().u.track.seq == 4);
}

TEST_CASE("--box wins over ground truth; a refused --box ends the run with BoxRejected") {
  PipelineOptions o;
  o.hasBox = true;
  o.box = Box{30.f, 5.f, 8.f, 8.f};
  static Rig good(3, true, o);
  REQUIRE(good.step() == StepResult::Continue);
  CHECK(good.sink.at(0).box_px[0] == 30);
  o.box.x = -50.f;
  static Rig bad(3, true, o);
  REQUIRE(bad.step() == StepResult::BoxRejected);
  // The line says the image's size: what the box had to fit.
  CHECK(bad.reporter.countContaining(
            "--box -50,5,8,8 refused by the tracker: BoxOutsideImage (the image is 64x48)") == 1);
}

TEST_CASE("a --box or START that reads as corners X0,Y0,X1,Y1 is named, with its X,Y,W,H") {
  PipelineOptions o;
  o.warnPoorTarget = true;  // user boxes are checked
  o.hasBox = true;
  o.box = Box{20.f, 10.f, 50.f, 40.f};  // runs past 64x48 as X,Y,W,H; fits as corners
  static Rig rig(3, true, o);
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.reporter.countContaining("--box 20,10,50,40 runs past the 64x48 image as X,Y,W,H; if "
                                     "50,40 is the bottom-right corner, the box is 20,10,30,30") ==
        1);
  rig.host.send(startCommand(3, 4, 6, 60, 46));
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.reporter.countContaining("START 4,6,60,46 runs past the 64x48 image") == 1);
  rig.host.send(startCommand(4, 30, 5, 20, 20));  // inside: nothing said
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.reporter.countContaining("runs past") == 2);
}

TEST_CASE("a scaled-down source: --box, START and every track out are in its own pixels") {
  PipelineOptions o;
  o.hasBox = true;
  o.box = Box{40.f, 20.f, 16.f, 16.f};  // in the 128x96 source
  static Rig rig(10, false, o);
  rig.source.scaledFrom(128, 96);
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.tracker.lastInit().x == 20.f);  // the tracker sees the 64x48 frame
  CHECK(rig.tracker.lastInit().w == 8.f);
  CHECK(rig.sink.at(0).box_px[0] == 40);
  CHECK(rig.sink.at(0).box_px[2] == 16);
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.at(1).box_px[0] == 42);  // 1 px of the frame is 2 of the source
  rig.host.send(startCommand(9, 60, 30, 20, 20));
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.tracker.lastInit().x == 30.f);
  CHECK(rig.tracker.lastInit().h == 10.f);
  CHECK(rig.sink.at(2).box_px[0] == 60);
  CHECK(rig.sink.at(2).box_px[3] == 20);
  const auto msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_TRACK) == 3);
  CHECK(msgs.back().u.track.box_px[0] == 60);
}

TEST_CASE("a poor target from START or --box is warned about in one line, and still tracked") {
  // TinySource's frames are one flat colour: any box there has no texture and looks like
  // its surroundings (a plain wall).
  PipelineOptions o;
  o.useGroundTruth = false;
  o.warnPoorTarget = true;
  static Rig rig(10, true, o);
  REQUIRE(rig.step() == StepResult::Continue);
  rig.host.send(startCommand(7, 20, 10, 16, 16));
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.at(1).state == CTP_STATE_TRACKING);
  CHECK(rig.reporter.countContaining("START 20,10,16,16: poor target: almost no texture") == 1);
  CHECK(rig.reporter.countContaining("plain wall") == 1);

  o.hasBox = true;
  o.box = Box{30.f, 5.f, 8.f, 8.f};
  static Rig boxRig(3, true, o);
  REQUIRE(boxRig.step() == StepResult::Continue);
  CHECK(boxRig.reporter.countContaining("--box 30,5,8,8: poor target") == 1);

  // Off (the default, and the tests above): nothing said.
  o.warnPoorTarget = false;
  static Rig quiet(3, true, o);
  REQUIRE(quiet.step() == StepResult::Continue);
  CHECK(quiet.reporter.countContaining("poor target") == 0);
}

TEST_CASE("START, RESET and STOP over the serial link, each answered") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(100, true, o);
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.at(0).state == CTP_STATE_IDLE);  // no target until told

  ctp_command_t start = startCommand(41, 5, 6, 7, 8);
  rig.host.send(start);
  REQUIRE(rig.step() == StepResult::Continue);
  auto msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_ACK) == 1);
  for (const auto& m : msgs) {
    if (m.type == CTP_MSG_ACK) {
      CHECK(m.u.ack.cmd_type == CTP_CMD_START);
      CHECK(m.u.ack.cmd_id == 41);
    }
  }
  CHECK(msgs.back().type == CTP_MSG_TRACK);
  CHECK(msgs.back().u.track.state == CTP_STATE_TRACKING);
  CHECK(msgs.back().u.track.box_px[0] == 5);
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.at(2).box_px[0] == 6);

  rig.host.send(command(CTP_CMD_RESET, 42));
  REQUIRE(rig.step() == StepResult::Continue);
  msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_ACK) == 1);
  CHECK(rig.tracker.resets == 1);
  CHECK(msgs.back().u.track.state == CTP_STATE_IDLE);

  rig.host.send(command(CTP_CMD_STOP, 43));
  REQUIRE(rig.step() == StepResult::Stopped);
  msgs = rig.host.drain();
  REQUIRE(msgs.size() == 1);
  CHECK(msgs[0].type == CTP_MSG_ACK);
  CHECK(msgs[0].u.ack.cmd_id == 43);
  // seq runs across all message types without gaps
  CHECK(msgs[0].u.ack.seq == rig.link.stats().sent - 1);
}

TEST_CASE("a START that a RESET or STOP overtakes before the next frame is answered busy") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(10, false, o);
  ctp_command_t start = startCommand(50, 5, 6, 7, 8);
  rig.host.send(start);
  rig.host.send(command(CTP_CMD_RESET, 51));
  REQUIRE(rig.step() == StepResult::Continue);
  auto msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_ERROR) == 1);
  REQUIRE(countType(msgs, CTP_MSG_ACK) == 1);
  CHECK(msgs[0].type == CTP_MSG_ERROR);  // the START's answer comes first
  CHECK(msgs[0].u.error.cmd_type == CTP_CMD_START);
  CHECK(msgs[0].u.error.cmd_id == 50);
  CHECK(msgs[0].u.error.code == CTP_E_BUSY);
  CHECK(msgs[1].type == CTP_MSG_ACK);
  CHECK(msgs[1].u.ack.cmd_id == 51);
  CHECK(msgs.back().u.track.state == CTP_STATE_IDLE);  // the START was not applied

  start.id = 60;
  rig.host.send(start);
  rig.host.send(command(CTP_CMD_STOP, 61));
  REQUIRE(rig.step() == StepResult::Stopped);
  msgs = rig.host.drain();
  REQUIRE(msgs.size() == 2);
  CHECK(msgs[0].type == CTP_MSG_ERROR);
  CHECK(msgs[0].u.error.cmd_id == 60);
  CHECK(msgs[0].u.error.code == CTP_E_BUSY);
  CHECK(msgs[1].type == CTP_MSG_ACK);
  CHECK(msgs[1].u.ack.cmd_id == 61);
}

TEST_CASE("a START still waiting for its frame when the run ends is answered busy") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(1, false, o);  // one frame, then the end of the source
  REQUIRE(rig.step() == StepResult::Continue);
  rig.host.send(startCommand(80, 5, 6, 20, 16));
  REQUIRE(rig.step() == StepResult::Done);
  CHECK(countType(rig.host.drain(), CTP_MSG_ERROR) == 0);  // not yet: the app decides at exit
  rig.pipeline.finish();                                   // as App does after the loop
  const auto msgs = rig.host.drain();
  REQUIRE(msgs.size() == 1);
  CHECK(msgs[0].type == CTP_MSG_ERROR);
  CHECK(msgs[0].u.error.cmd_id == 80);
  CHECK(msgs[0].u.error.code == CTP_E_BUSY);
  rig.pipeline.finish();
  CHECK(rig.host.drain().empty());  // one reply, not two
}

TEST_CASE("a START reaching past the image reports the part inside on its first frame") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(5, false, o);
  rig.host.send(startCommand(70, 50, 40, 100, 100));  // the frames are 64x48
  REQUIRE(rig.step() == StepResult::Continue);
  const ctp_track_t& t = rig.sink.at(0);
  CHECK(t.state == CTP_STATE_TRACKING);
  CHECK(t.box_px[0] == 50);
  CHECK(t.box_px[1] == 40);
  CHECK(t.box_px[2] == 14);
  CHECK(t.box_px[3] == 8);
}

TEST_CASE("a START the tracker refuses gets ERROR rejected and leaves the app idle") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(10, false, o);
  ctp_command_t start = startCommand(9, -3, 0, 4, 4);
  rig.host.send(start);
  REQUIRE(rig.step() == StepResult::Continue);
  const auto msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_ERROR) == 1);
  CHECK(msgs[0].u.error.code == CTP_E_REJECTED);
  CHECK(msgs[0].u.error.cmd_id == 9);
  CHECK(msgs.back().u.track.state == CTP_STATE_IDLE);
  CHECK(rig.reporter.countContaining("refused") == 1);
}

TEST_CASE("garbage, corrupt and malformed inbound frames are answered with ERROR and counted") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(10, false, o);
  std::vector<uint8_t> junk = {0x12, 0x34, 0x56, 0x00};  // invalid frame -> framing or CRC
  rig.host.sendRaw(junk);
  uint8_t w[CTP_MAX_WIRE];
  ctp_command_t reset = command(CTP_CMD_RESET, 77);
  size_t n = ctp_encode_command(&reset, w, sizeof w);
  w[2] ^= 0x01;  // corrupt one bit -> CRC error
  rig.host.sendRaw(std::vector<uint8_t>(w, w + n));
  ctp_command_t badRate = command(CTP_CMD_SET_RATE, 78);
  badRate.rate_hz = 5000;  // out of range
  rig.host.send(badRate);
  const uint8_t notACommand[3] = {1, 2, 3};
  n = ctp_encode_frame(CTP_MSG_TRACK, notACommand, sizeof notACommand, w, sizeof w);
  rig.host.sendRaw(std::vector<uint8_t>(w, w + n));
  rig.host.send(command(CTP_CMD_RESET, 79));  // a good one after all that
  REQUIRE(rig.step() == StepResult::Continue);
  const auto msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_ERROR) == 4);
  REQUIRE(countType(msgs, CTP_MSG_ACK) == 1);
  std::vector<int> codes;
  for (const auto& m : msgs)
    if (m.type == CTP_MSG_ERROR) codes.push_back(m.u.error.code);
  CHECK((codes[0] == CTP_E_CRC || codes[0] == CTP_E_FRAMING));
  CHECK(codes[1] == CTP_E_CRC);
  CHECK(codes[2] == CTP_E_VALUE);
  CHECK(codes[3] == CTP_E_TYPE);
  CHECK(rig.link.stats().rxErrors == 4);
  CHECK(rig.link.commands().accepted() == 1);
}

TEST_CASE("SET_RATE thins the serial stream but not the other outputs; 0 restores every frame") {
  static Rig rig(61, true);
  ctp_command_t rate = command(CTP_CMD_SET_RATE, 5);
  rate.rate_hz = 10;  // 30 fps frames -> every 3rd
  rig.host.send(rate);
  for (int i = 0; i < 31; ++i) REQUIRE(rig.step() == StepResult::Continue);
  const auto msgs = rig.host.drain();
  CHECK(countType(msgs, CTP_MSG_ACK) == 1);
  CHECK(countType(msgs, CTP_MSG_TRACK) == 11);  // frames 0, 3, ..., 30
  CHECK(rig.sink.size() == 31);
  rate.rate_hz = 0;  // "every frame" (serial-protocol.md, SET_RATE)
  rate.id = 6;
  rig.host.send(rate);
  for (int i = 0; i < 30; ++i) REQUIRE(rig.step() == StepResult::Continue);
  const auto after = rig.host.drain();
  CHECK(countType(after, CTP_MSG_ACK) == 1);
  CHECK(countType(after, CTP_MSG_TRACK) == 30);  // frames 31..60, none thinned
  CHECK(rig.sink.size() == 61);
}

TEST_CASE("a heartbeat goes out after 1 s without any message") {
  static Rig rig(0, false);  // no frames at all
  rig.host.drain();
  rig.pipeline.serviceLink();
  CHECK(rig.host.drain().empty());
  rig.clock.advanceUs(1000001);
  rig.pipeline.serviceLink();
  const auto msgs = rig.host.drain();
  REQUIRE(msgs.size() == 1);
  REQUIRE(msgs[0].type == CTP_MSG_HEARTBEAT);
  CHECK(msgs[0].u.heartbeat.state == CTP_STATE_IDLE);
  CHECK(msgs[0].u.heartbeat.time_us == rig.clock.nowUs());
  rig.pipeline.serviceLink();
  CHECK(rig.host.drain().empty());  // not again until another second passes
}

TEST_CASE("on a congested line a heartbeat is tried once a second, and every loss is counted") {
  static Rig rig(150, true);     // 5 s at 30 fps
  rig.cable.setCapacityAtoB(0);  // the peer stopped reading: nothing leaves the queue
  for (int i = 0; i < 150; ++i) REQUIRE(rig.step() == StepResult::Continue);
  const platform::LinkStats& s = rig.link.stats();
  // Every frame sent a TRACK (queued or dropped); the rest are heartbeats. The last
  // successful write never moves, so only the clock may pace them: 1, 2, 3, 4 s.
  const uint32_t heartbeats = s.sent + s.txDropped + s.queued - 150;
  CHECK(heartbeats >= 3);
  CHECK(heartbeats <= 5);
  CHECK(s.txDropped > 100);  // most tracks lost, each counted once
}

TEST_CASE("while the camera stalls, heartbeats still go out and commands are answered") {
  static Rig rig(10, true);
  REQUIRE(rig.step() == StepResult::Continue);
  rig.host.drain();
  // 2.5 s without a frame before frame 1 (the live Kinect waits up to its stall timeout);
  // a RESET comes 0.5 s into it.
  rig.stallThenSend(1, 25, command(CTP_CMD_RESET, 60));
  REQUIRE(rig.step() == StepResult::Continue);
  const auto msgs = rig.host.drain();
  CHECK(countType(msgs, CTP_MSG_HEARTBEAT) == 2);  // at 1 s and 2 s of silence
  CHECK(countType(msgs, CTP_MSG_ACK) == 1);        // the RESET, answered mid-stall
  CHECK(rig.tracker.resets == 1);
  REQUIRE_FALSE(msgs.empty());
  CHECK(msgs.back().type == CTP_MSG_TRACK);  // then the frame that came
}

TEST_CASE("a STOP that arrives while the camera stalls ends the wait and the run") {
  static Rig rig(10, true);
  REQUIRE(rig.step() == StepResult::Continue);
  rig.host.drain();
  // 100 s without a frame; a STOP comes 0.5 s into it.
  rig.stallThenSend(1, 1000, command(CTP_CMD_STOP, 61));
  CHECK(rig.step() == StepResult::Stopped);
  const auto msgs = rig.host.drain();
  REQUIRE(msgs.size() == 1);
  CHECK(msgs[0].type == CTP_MSG_ACK);
  CHECK(msgs[0].u.ack.cmd_id == 61);
  CHECK(rig.clock.nowUs() == 1000u + 2 * 33333u + 5 * 100000u);  // the STOP's own slice
}

TEST_CASE("a vanished serial peer is reported, tracking continues, the link comes back") {
  static Rig rig(50, true);
  REQUIRE(rig.step() == StepResult::Continue);
  rig.cable.setPlugged(false);
  for (int i = 0; i < 5; ++i) REQUIRE(rig.step() == StepResult::Continue);
  CHECK_FALSE(rig.link.connected());
  CHECK(rig.reporter.countContaining("peer gone; tracking continues") == 1);
  CHECK(rig.sink.size() == 6);  // other outputs carried on
  rig.cable.setPlugged(true);
  for (int i = 0; i < 20; ++i) REQUIRE(rig.step() == StepResult::Continue);  // > 0.5 s retry
  CHECK(rig.link.connected());
  CHECK(rig.reporter.countContaining("reconnected") == 1);
  CHECK(rig.link.stats().reconnects == 1);
  const auto msgs = rig.host.drain();
  REQUIRE(countType(msgs, CTP_MSG_TRACK) > 0);
  CHECK(msgs.back().u.track.state == CTP_STATE_TRACKING);
  // The messages of the outage were dropped and counted; seq shows them as a gap.
  CHECK(rig.link.stats().txDropped >= 5);
  CHECK(msgs.back().u.track.seq ==
        rig.link.stats().sent + rig.link.stats().txDropped + rig.link.stats().queued - 1);
}

TEST_CASE("a stalled peer never blocks: messages that do not fit are dropped and counted") {
  static Rig rig(201, true);
  rig.cable.setCapacityAtoB(100);  // the peer stops reading after 100 bytes
  for (int i = 0; i < 200; ++i) REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.size() == 200);
  CHECK(rig.link.stats().txDropped > 100);
  CHECK(rig.link.stats().sent + rig.link.stats().txDropped + rig.link.stats().queued >= 200);
  // The host sees every dropped message as a gap in seq (section 3 of the protocol).
  rig.cable.setCapacityAtoB(1 << 20);
  rig.host.drain();  // what got through before the stall
  REQUIRE(rig.step() == StepResult::Continue);
  const auto msgs = rig.host.drain();
  REQUIRE_FALSE(msgs.empty());
  const ctp_message_t& last = msgs.back();
  REQUIRE(last.type == CTP_MSG_TRACK);
  CHECK(last.u.track.seq ==
        rig.link.stats().sent + rig.link.stats().txDropped + rig.link.stats().queued - 1);
  CHECK(last.u.track.seq > rig.link.stats().sent);  // the drops left a gap
}

TEST_CASE("a failing output is reported once, the rest goes on, the run is marked") {
  static Rig rig(5, true);
  rig.sink.setFailing(true);
  for (int i = 0; i < 5; ++i) REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.reporter.countContaining("memory: write failed (simulated); output stopped") == 1);
  CHECK(rig.pipeline.outputFailed());
  CHECK(countType(rig.host.drain(), CTP_MSG_TRACK) == 5);
}

TEST_CASE("a source error is reported with the source's line and ends the run") {
  static Rig rig(10, true);
  rig.source.failAt(2);
  REQUIRE(rig.step() == StepResult::Continue);
  REQUIRE(rig.step() == StepResult::Continue);
  REQUIRE(rig.step() == StepResult::SourceError);
  CHECK(rig.reporter.countContaining("tiny.seq: frame 3: truncated") == 1);
}

TEST_CASE("lost then still lost goes out as LOST then SEARCHING") {
  static Rig rig(5, true);
  REQUIRE(rig.step() == StepResult::Continue);
  rig.tracker.lost = true;
  REQUIRE(rig.step() == StepResult::Continue);
  REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.at(1).state == CTP_STATE_LOST);
  CHECK(rig.sink.at(2).state == CTP_STATE_SEARCHING);
}

TEST_CASE("the status line reports frames, fps, dropped frames, state and the link") {
  PipelineOptions o;
  o.statusPeriodUs = 1000000;
  o.droppedFrames = [](const FrameSource&) -> uint64_t { return 7; };
  static Rig rig(40, true, o);
  for (int i = 0; i < 40; ++i) REQUIRE(rig.step() == StepResult::Continue);
  // 33333 us per frame on the fake clock: the first full second ends after frame 31.
  REQUIRE(rig.reporter.countContaining("fps") == 1);
  CHECK(rig.reporter.countContaining(
            "frame 31 fps 30.0 dropped 7 state tracking | serial up sent 31 ") == 1);
}

TEST_CASE("without a serial link, the run ends once every output has failed") {
  static FakeClock clock;
  static MemoryReporter reporter;
  static MemorySink sink;
  static TinySource source(10, true);
  static StubTracker tracker;
  static Pipeline pipeline(source, Rig::slot(), tracker, clock, reporter, PipelineOptions{});
  pipeline.addSink(&sink);
  REQUIRE(pipeline.step() == StepResult::Continue);
  sink.setFailing(true);
  REQUIRE(pipeline.step() == StepResult::OutputsGone);
  CHECK(pipeline.outputFailed());
}

TEST_CASE("steady-state frames, commands and replies allocate nothing") {
  PipelineOptions o;
  o.statusPeriodUs = 1000000;
  static Rig rig(400, true, o);
  REQUIRE(rig.step() == StepResult::Continue);  // first frame: target set up
  ctp_command_t rate = command(CTP_CMD_SET_RATE, 1);
  rate.rate_hz = 15;
  uint8_t wire[CTP_MAX_WIRE];
  const size_t n = ctp_encode_command(&rate, wire, sizeof wire);
  uint8_t drained[4096];
  cuetrack::test::AllocScope scope;
  for (int i = 0; i < 300; ++i) {
    if (i % 50 == 0) rig.cable.b().write(wire, n);
    REQUIRE(rig.step() == StepResult::Continue);
    rig.cable.b().read(drained, sizeof drained, 0);  // the host keeps up
  }
  CHECK(scope.allocations() == 0);
  CHECK(rig.link.stats().rxFrames == 6);
  cuetrack::test::AllocScope control;  // positive control: the counter sees allocations
  std::vector<int> v(10);
  CHECK(control.allocations() >= 1);
}

TEST_CASE(
    "every message is counted once, sent or dropped, the queue included: the far end agrees") {
  static Rig rig(60, true);
  rig.cable.setCapacityAtoB(600);  // the peer reads 600 bytes, then stops: some stay queued
  for (int i = 0; i < 60; ++i) REQUIRE(rig.step() == StepResult::Continue);
  rig.link.drain(20);  // at exit: what cannot leave stays queued
  const platform::LinkStats& s = rig.link.stats();
  const auto got = rig.host.drain();
  CHECK(s.queued > 0);
  CHECK(s.txDropped > 0);
  CHECK(got.size() == s.sent);  // "sent" is what the peer could read, no more
  // Each message took a seq: the last one read, plus what never left, is the total.
  REQUIRE(!got.empty());
  const uint32_t lastSeq = got.back().u.track.seq;
  CHECK(s.sent + s.txDropped + s.queued >= lastSeq + 1);
  CHECK(s.sent + s.txDropped + s.queued >= 60);  // a TRACK a frame, and heartbeats
}

TEST_CASE("drain waits for room and puts queued messages on the line, bounded") {
  static Rig rig(50, true);
  rig.cable.setCapacityAtoB(0);  // the peer reads nothing
  for (int i = 0; i < 10; ++i) REQUIRE(rig.step() == StepResult::Continue);
  REQUIRE_FALSE(rig.link.drain(50));  // gives up instead of hanging
  rig.cable.setCapacityAtoB(FakeSerialCable::kRingBytes);
  REQUIRE(rig.link.drain(50));
  CHECK(countType(rig.host.drain(), CTP_MSG_TRACK) == 10);
}

TEST_CASE("ground truth starts tracking at the first frame where the target is visible") {
  static Rig rig(6, true);
  rig.source.visibleFrom(3);
  for (int i = 0; i < 6; ++i) REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.at(2).state == CTP_STATE_IDLE);
  CHECK(rig.sink.at(3).state == CTP_STATE_TRACKING);
  CHECK(rig.sink.at(3).box_px[0] == 10);
  CHECK(rig.tracker.inits == 1);
}

TEST_CASE("a frame of another size mid-track ends the run with one line naming the source") {
  PipelineOptions o;
  o.sourceName = "rec/";
  static Rig rig(6, true, o);
  rig.source.resizeFrom(3, 32, 24);
  for (int i = 0; i < 3; ++i) REQUIRE(rig.step() == StepResult::Continue);
  REQUIRE(rig.step() == StepResult::SourceError);
  CHECK(rig.reporter.countContaining("rec/: frame 3 is 32x24, the track began at 64x48") == 1);
  CHECK(rig.sink.size() == 3);  // no track was made up for the odd frame
  CHECK(rig.tracker.updates == 2);
}

TEST_CASE("frames may change size while no target is tracked; a START takes the new size") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(6, true, o);
  rig.source.resizeFrom(2, 32, 24);
  for (int i = 0; i < 3; ++i) REQUIRE(rig.step() == StepResult::Continue);
  ctp_command_t start = startCommand(3, 2, 0, 8, 8);
  rig.host.send(start);
  for (int i = 0; i < 3; ++i) REQUIRE(rig.step() == StepResult::Continue);
  CHECK(rig.sink.at(5).state == CTP_STATE_TRACKING);
  CHECK(rig.reporter.countContaining("the track began at") == 0);
}

TEST_CASE("a refused ground-truth box ends the run, naming the ground-truth file and frame") {
  PipelineOptions o;
  o.groundTruthName = "rec/groundtruth.txt";
  static Rig rig(5, true, o);
  rig.source.visibleFrom(2);
  rig.source.truthX(-4.f);
  REQUIRE(rig.step() == StepResult::Continue);  // target not visible yet: idle
  REQUIRE(rig.step() == StepResult::Continue);
  REQUIRE(rig.step() == StepResult::BoxRejected);
  CHECK(rig.reporter.countContaining(
            "rec/groundtruth.txt: frame 2: box -4,12,20,16 refused by the tracker: "
            "BoxOutsideImage") == 1);
  CHECK(rig.tracker.inits == 0);
}

TEST_CASE("--realtime: frames come at the recording's own times, the link served meanwhile") {
  FakeClock clock(5000);
  FakeSleeper sleeper(clock);
  TinySource tiny(10, false);  // 30 fps timestamps
  PacedSource paced(tiny, clock, sleeper);
  static FrameSlot slot;
  REQUIRE(paced.next(slot) == ReadStatus::Ok);  // the first at once
  CHECK(clock.nowUs() == 5000);
  REQUIRE(paced.next(slot) == ReadStatus::Ok);
  CHECK(clock.nowUs() == 5000 + 33333);  // due one frame period after the first
  clock.advanceUs(50000);                // a tracker slower than the camera: no wait
  const int calls = sleeper.calls;
  REQUIRE(paced.next(slot) == ReadStatus::Ok);
  CHECK(sleeper.calls == calls);
  for (int i = 3; i < 10; ++i) REQUIRE(paced.next(slot) == ReadStatus::Ok);
  CHECK(clock.nowUs() == 5000 + 9 * 33333);  // back on the recording's schedule
  CHECK(paced.next(slot) == ReadStatus::End);
  CHECK(std::string(paced.name()) == "tiny");

  // A recording with a 1 s gap before frame 2: the idle hook runs after every slice of
  // the wait (100 ms at most), and a hook that asks to stop ends it.
  TinySource gap(5, false);
  gap.gapBefore(2, 1000000);
  PacedSource gapPaced(gap, clock, sleeper);
  struct Hook {
    int calls = 0;
    static bool fn(void* self) { return ++static_cast<Hook*>(self)->calls == 3; }
  } hook;
  gapPaced.setIdleHook(&Hook::fn, &hook);
  const uint64_t t0 = clock.nowUs();
  REQUIRE(gapPaced.next(slot) == ReadStatus::Ok);
  REQUIRE(gapPaced.next(slot) == ReadStatus::Ok);  // 33 ms: one short slice
  CHECK(hook.calls == 1);
  CHECK(gapPaced.next(slot) == ReadStatus::End);  // stopped 200 ms into the gap
  CHECK(hook.calls == 3);
  CHECK(clock.nowUs() == t0 + 33333 + 200000);
}

namespace {
// A camera that is plugged in at a given time: the opener fails ("no Kinect found on USB",
// then "no permission" once it is on the bus) until the clock reaches `plugInUs`.
struct LateCamera {
  FakeClock* clock = nullptr;
  uint64_t busUs = 0, plugInUs = 0;
  FrameSource* camera = nullptr;
  int opens = 0;
  void (*onOpen)(int attempt, void* ctx) = nullptr;  // the peer's doings meanwhile
  void* onOpenCtx = nullptr;
  static FrameSource* open(void* self, char* err, size_t n) {
    LateCamera& c = *static_cast<LateCamera*>(self);
    ++c.opens;
    if (c.onOpen) c.onOpen(c.opens, c.onOpenCtx);
    if (c.clock->nowUs() >= c.plugInUs) return c.camera;
    std::snprintf(
        err, n, "%s",
        c.clock->nowUs() >= c.busUs ? "kinect#0: no permission" : "no Kinect found on USB");
    return nullptr;
  }
};
}  // namespace

TEST_CASE("--wait-camera: a camera plugged in later is looked for every second, then used") {
  FakeClock clock(1000);
  FakeSleeper sleeper(clock);
  MemoryReporter reporter;
  TinySource tiny(3, false);
  LateCamera late;
  late.clock = &clock;
  late.busUs = 1000 + 2000000;  // on the bus after 2 s, readable after 3.5 s
  late.plugInUs = 1000 + 3500000;
  late.camera = &tiny;
  WaitingSource waiting(&LateCamera::open, &late, clock, sleeper, reporter);
  CHECK_FALSE(waiting.tryOpen());
  CHECK(waiting.awaitingDevice());
  CHECK(std::string(waiting.error()) == "no Kinect found on USB");
  static FrameSlot slot;
  REQUIRE(waiting.next(slot) == ReadStatus::Ok);  // frames flow once it opens
  CHECK_FALSE(waiting.awaitingDevice());
  CHECK(late.opens == 5);  // at 0, 1, 2, 3 and 4 s
  CHECK(clock.nowUs() == 1000 + 4000000);
  CHECK(sleeper.calls == 40);  // in 100 ms slices
  // One line per distinct reason, and one when it comes.
  CHECK(reporter.count() == 3);
  CHECK(reporter.countContaining("no Kinect found on USB; waiting for it (--wait-camera)") == 1);
  CHECK(reporter.countContaining("kinect#0: no permission; waiting for it") == 1);
  CHECK(reporter.countContaining("tiny: found after 5 attempts") == 1);
  REQUIRE(waiting.next(slot) == ReadStatus::Ok);
  REQUIRE(waiting.next(slot) == ReadStatus::Ok);
  CHECK(waiting.next(slot) == ReadStatus::End);
  CHECK(late.opens == 5);

  // A camera that is there at once: no report, no wait.
  TinySource there(1, false);
  LateCamera now;
  now.clock = &clock;
  now.camera = &there;
  MemoryReporter quiet;
  WaitingSource direct(&LateCamera::open, &now, clock, sleeper, quiet);
  REQUIRE(direct.next(slot) == ReadStatus::Ok);
  CHECK(quiet.count() == 0);
  CHECK(now.opens == 1);
}

TEST_CASE("--wait-camera with a serial link: flagged heartbeats, an early START, a STOP ends it") {
  static FakeClock clock(1000);
  static FakeSleeper sleeper(clock);
  static MemoryReporter reporter;
  static FakeSerialCable cable;
  static SerialLink link(cable.a(), clock, reporter);
  static Host host(cable.b());
  static StubTracker tracker;
  static FrameSlot slot;
  static TinySource tiny(10, false);
  static LateCamera late;
  late.clock = &clock;
  late.busUs = late.plugInUs = 1000 + 2500000;
  late.camera = &tiny;
  late.onOpen = [](int attempt, void* h) {  // the flight controller starts early
    if (attempt == 2) static_cast<Host*>(h)->send(startCommand(70, 10, 12, 20, 16));
  };
  late.onOpenCtx = &host;
  static WaitingSource waiting(&LateCamera::open, &late, clock, sleeper, reporter);
  PipelineOptions o;
  o.useGroundTruth = false;
  static Pipeline pipeline(waiting, slot, tracker, clock, reporter, o);
  pipeline.attachLink(&link);
  REQUIRE_FALSE(waiting.tryOpen());
  REQUIRE(pipeline.step() == StepResult::Continue);  // waits 3 s, then the first frame
  const auto msgs = host.drain();
  // While it waited: a heartbeat a second (at 1, 2 and 3 s), each flagged no-camera.
  REQUIRE(countType(msgs, CTP_MSG_HEARTBEAT) == 3);
  for (const auto& m : msgs)
    if (m.type == CTP_MSG_HEARTBEAT) {
      CHECK((m.u.heartbeat.flags & CTP_HB_NO_CAMERA) != 0);
      CHECK(m.u.heartbeat.state == CTP_STATE_IDLE);
    }
  // The START, sent before there was a camera, is answered and applied on the first frame.
  CHECK(countType(msgs, CTP_MSG_ACK) == 1);
  REQUIRE_FALSE(msgs.empty());
  REQUIRE(msgs.back().type == CTP_MSG_TRACK);
  CHECK(msgs.back().u.track.state == CTP_STATE_TRACKING);
  CHECK(tracker.inits == 1);
  // With the camera there, a silent second gives a heartbeat without the flag.
  clock.advanceUs(1000001);
  pipeline.serviceLink();
  const auto later = host.drain();
  REQUIRE(countType(later, CTP_MSG_HEARTBEAT) == 1);
  CHECK(later[0].u.heartbeat.flags == 0);

  // A STOP while no camera is there ends the wait and the run.
  static TinySource never(1, false);
  static LateCamera absent;
  absent.clock = &clock;
  absent.busUs = absent.plugInUs = UINT64_MAX;
  absent.camera = &never;
  absent.onOpen = [](int attempt, void* h) {
    if (attempt == 3) static_cast<Host*>(h)->send(command(CTP_CMD_STOP, 71));
  };
  absent.onOpenCtx = &host;
  static SerialLink link2(cable.a(), clock, reporter);
  static WaitingSource waiting2(&LateCamera::open, &absent, clock, sleeper, reporter);
  static Pipeline pipeline2(waiting2, slot, tracker, clock, reporter, o);
  pipeline2.attachLink(&link2);
  REQUIRE_FALSE(waiting2.tryOpen());
  CHECK(pipeline2.step() == StepResult::Stopped);
  const auto end = host.drain();
  REQUIRE(countType(end, CTP_MSG_ACK) == 1);
  CHECK(absent.opens == 3);
}

TEST_CASE("the flight controller's example, on the other end of the cable, steers by the tracks") {
  PipelineOptions o;
  o.useGroundTruth = false;
  static Rig rig(40, false, o);
  rig.tracker.with3d = true;
  static fc_link_t fc;
  fc_link_init(&fc);
  // The controller's loop: read what came (the clock in ms), then act.
  auto pump = [] {
    const uint32_t nowMs = static_cast<uint32_t>(rig.clock.nowUs() / 1000u);
    uint8_t buf[256];
    for (;;) {
      const IoResult r = rig.host.stream.read(buf, sizeof buf, 0);
      if (r.bytes == 0) break;
      for (size_t i = 0; i < r.bytes; ++i) fc_link_on_byte(&fc, buf[i], nowMs);
    }
    return nowMs;
  };
  int32_t c[3];
  REQUIRE(rig.step() == StepResult::Continue);  // idle: no target yet
  uint32_t now = pump();
  CHECK(fc_link_alive(&fc, now));
  CHECK_FALSE(fc_link_target(&fc, now, c));
  uint8_t w[CTP_MAX_WIRE];
  const size_t n = fc_link_start(&fc, 10, 12, 20, 16, w, sizeof w);
  REQUIRE(rig.host.stream.write(w, n).bytes == n);
  for (int i = 0; i < 10; ++i) REQUIRE(rig.step() == StepResult::Continue);
  now = pump();
  CHECK(fc.acks == 1);
  REQUIRE(fc_link_target(&fc, now, c));
  CHECK(c[2] == 2000);
  CHECK(c[0] == static_cast<int32_t>(10.f * (10.f + 9.f)));  // the 10th frame's box x
  CHECK(fc.lost == 0);
  rig.tracker.lost = true;  // the tracker loses it: no more steering
  REQUIRE(rig.step() == StepResult::Continue);
  now = pump();
  CHECK_FALSE(fc_link_target(&fc, now, c));
  // STOP from the controller: acknowledged, the run ends.
  const size_t m = fc_link_stop(&fc, w, sizeof w);
  REQUIRE(rig.host.stream.write(w, m).bytes == m);
  CHECK(rig.step() == StepResult::Stopped);
  pump();
  CHECK(fc.acks == 2);
  CHECK(fc.errors == 0);
}

namespace {

// A tracker that plays a script of results, one per update: the target seen, then behind
// something (occluded), then lost with the lost search's box jumping about, as the core's
// does (a corner, partly off the image).
class ScriptTracker final : public TrackerPort {
 public:
  static constexpr int kSteps = 5;
  bool configure(const char*, uint64_t, const Clock*) override { return true; }
  int init(const Frame&, const Box&, const char**) override { return 0; }
  TrackResult update(const Frame&) override {
    TrackResult r;
    r.confidence = 0.5f;
    r.hasPosition3d = true;
    r.positionMm[2] = 2000.f;
    switch (_step++) {
      case 0:  // seen: the last confirmed box
        r.state = TrackState::Tracking;
        r.box = Box{11.f, 12.f, 20.f, 16.f};
        r.positionMm[0] = 110.f;
        break;
      case 1:  // behind something: where it went, not seen
        r.state = TrackState::Tracking;
        r.occluded = true;
        r.box = Box{14.f, 12.f, 20.f, 16.f};
        r.positionMm[0] = 140.f;
        break;
      case 2:
      case 3:  // lost: the search's boxes
        r.state = TrackState::Lost;
        r.box = _step == 3 ? Box{43.f, -9.f, 30.f, 30.f} : Box{-20.f, 40.f, 30.f, 30.f};
        r.positionMm[0] = -900.f;
        break;
      default:  // found again
        r.state = TrackState::Tracking;
        r.box = Box{30.f, 20.f, 20.f, 16.f};
        r.positionMm[0] = 300.f;
        break;
    }
    return r;
  }
  void reset() override {}

 private:
  int _step = 0;
};

// The frames' states as sent: tracking (init), tracking, occluded, lost, searching, tracking.
constexpr int kScriptFrames = 1 + ScriptTracker::kSteps;

}  // namespace

TEST_CASE("while lost, every output carries the last confirmed box with the lost state") {
  // stdout and CSV (the sink), and the serial link, decoded by the protocol's decoder.
  {
    static FakeClock clock{1000};
    static MemoryReporter reporter;
    static TinySource source(kScriptFrames, true);
    static ScriptTracker script;
    static FakeSerialCable cable;
    static SerialLink link(cable.a(), clock, reporter);
    static Host host(cable.b());
    static Pipeline pipeline(source, Rig::slot(), script, clock, reporter, {});
    static MemorySink sink;
    pipeline.addSink(&sink);
    pipeline.attachLink(&link);
    for (int i = 0; i < kScriptFrames; ++i) {
      clock.advanceUs(33333);
      REQUIRE(pipeline.step() == StepResult::Continue);
    }
    std::vector<ctp_track_t> sent;
    for (const ctp_message_t& m : host.drain())
      if (m.type == CTP_MSG_TRACK) sent.push_back(m.u.track);
    REQUIRE(sent.size() == kScriptFrames);
    REQUIRE(sink.size() == kScriptFrames);
    const uint8_t states[kScriptFrames] = {CTP_STATE_TRACKING,  CTP_STATE_TRACKING,
                                           CTP_STATE_TRACKING,  CTP_STATE_LOST,
                                           CTP_STATE_SEARCHING, CTP_STATE_TRACKING};
    for (int i = 0; i < kScriptFrames; ++i) {
      INFO("frame " << i);
      for (const ctp_track_t& t : {sink.at(static_cast<size_t>(i)), sent[static_cast<size_t>(i)]}) {
        CHECK(t.state == states[i]);
        CHECK(((t.flags & CTP_FLAG_OCCLUDED) != 0) == (i == 2));
        if (i == 3 || i == 4) {  // frame 1's box and centre, never the search's
          CHECK(t.box_px[0] == 11);
          CHECK(t.box_px[1] == 12);
          CHECK(t.box_px[2] == 20);
          CHECK(t.box_px[3] == 16);
          CHECK(t.centre_mm[0] == 110);
          CHECK((t.flags & CTP_FLAG_HAS_3D) != 0);
        }
      }
    }
    CHECK(sent[5].box_px[0] == 30);  // found again: the new box
    // The text forms (stdout's line, the CSV row) of a lost frame.
    char line[256];
    REQUIRE(formatTrackLine(sink.at(3), line, sizeof line) > 0);
    CHECK(std::string(line).find(" lost box=11,12,20,16 ") != std::string::npos);
    REQUIRE(formatTrackCsvRow(sink.at(4), line, sizeof line) > 0);
    CHECK(std::string(line).find(",searching,11,12,20,16,") != std::string::npos);
  }
  // MAVLink: lost is ERROR with the last confirmed box, and no LANDING_TARGET.
  {
    static FakeClock clock{1000};
    static MemoryReporter reporter;
    static TinySource source(kScriptFrames, true);
    static ScriptTracker script;
    static FakeSerialCable cable;
    static mavlink::MavlinkLink link(cable.a(), clock, reporter, mavlink::LinkConfig{});
    static Pipeline pipeline(source, Rig::slot(), script, clock, reporter, {});
    pipeline.attachLink(&link);
    Rig::slot().intrinsics = kKinectV1Intrinsics;  // LANDING_TARGET needs them; kept by TinySource
    static mavlink::Parser parser;
    std::vector<mavlink::CameraTrackingImageStatus> status;
    std::vector<int> landingFrames;
    for (int i = 0; i < kScriptFrames; ++i) {
      clock.advanceUs(33333);
      REQUIRE(pipeline.step() == StepResult::Continue);
      uint8_t buf[512];
      mavlink::Message m;
      for (IoResult r; (r = cable.b().read(buf, sizeof buf, 0)).bytes > 0;) {
        for (size_t k = 0; k < r.bytes; ++k) {
          if (!parser.push(buf[k], &m)) continue;
          if (m.header.msgId == mavlink::kMsgCameraTrackingImageStatus)
            status.push_back(mavlink::unpackCameraTrackingImageStatus(m.payload));
          if (m.header.msgId == mavlink::kMsgLandingTarget) landingFrames.push_back(i);
        }
      }
    }
    REQUIRE(status.size() == kScriptFrames);
    for (int i : {3, 4}) {
      INFO("frame " << i);
      CHECK(status[static_cast<size_t>(i)].trackingStatus == mavlink::kTrackingStatusError);
      // The last confirmed box (11,12,20,16), as on every other output.
      const mavlink::CameraTrackingImageStatus& s = status[static_cast<size_t>(i)];
      CHECK(s.recTopX == Approx(11.f / static_cast<float>(kTinyW)));
      CHECK(s.recTopY == Approx(12.f / static_cast<float>(kTinyH)));
      CHECK(s.recBottomX == Approx(31.f / static_cast<float>(kTinyW)));
      CHECK(s.recBottomY == Approx(28.f / static_cast<float>(kTinyH)));
    }
    CHECK(status[5].trackingStatus == mavlink::kTrackingStatusActive);
    REQUIRE(!landingFrames.empty());  // sent while tracking in 3D...
    CHECK(landingFrames.front() == 1);
    for (int i : landingFrames) CHECK((i != 3 && i != 4));  // ...never while lost
  }
}
