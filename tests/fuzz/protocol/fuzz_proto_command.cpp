// Any bytes through the device's command path: decoder -> ctp_parse_command ->
// CommandHandler -> a recording AppControl. Every frame gets exactly one reply (or,
// for START, one deferred request), accepted commands carry in-range values and
// round-trip through the encoder. The input is also fed to the text command parser.
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "CommandHandler.hpp"
#include "cuetrack/platform/CommandText.hpp"
#include "cuetrack_proto.h"

namespace {

struct Recorder final : cuetrack::app::AppControl {
  int starts = 0, resets = 0, stops = 0, rates = 0;
  void requestStart(const cuetrack::Box& b, uint16_t) override {
    if (!(b.w > 0.f) || !(b.h > 0.f)) abort();
    ++starts;
  }
  void requestReset() override { ++resets; }
  void requestStop() override { ++stops; }
  void setRateHz(uint16_t hz) override {
    if (hz > 1000) abort();
    ++rates;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  cuetrack::app::CommandHandler handler;
  Recorder app;
  int events = 0, replies = 0;
  for (size_t i = 0; i < size; ++i) {
    ctp_frame_t f{};
    int err = 0;
    const int r = ctp_decoder_push(&d, data[i], &f, &err);
    if (r == CTP_PUSH_NONE) continue;
    ++events;
    const int startsBefore = app.starts;
    const cuetrack::app::Reply reply = handler.handle(r == CTP_PUSH_FRAME ? CTP_OK : err, f, app);
    if (reply.kind == cuetrack::app::Reply::Kind::None) {
      if (app.starts != startsBefore + 1) abort();  // only START defers its reply
    } else {
      ++replies;
    }
    if (r == CTP_PUSH_FRAME) {
      ctp_command_t c;
      if (ctp_parse_command(&f, &c) == CTP_OK) {
        uint8_t w[CTP_MAX_WIRE];
        const size_t n = ctp_encode_command(&c, w, sizeof w);
        ctp_decoder_t d2;
        ctp_decoder_init(&d2);
        ctp_frame_t f2{};
        int got = CTP_PUSH_NONE;
        for (size_t k = 0; k < n; ++k) got = ctp_decoder_push(&d2, w[k], &f2, nullptr);
        if (got != CTP_PUSH_FRAME || f2.len != f.len ||
            std::memcmp(f2.payload, f.payload, f.len) != 0)
          abort();
      }
    }
  }
  if (replies + app.starts != events) abort();
  if (handler.accepted() + handler.rejected() != static_cast<uint32_t>(events)) abort();

  // The same bytes as command text (NUL-terminated copy, bounded).
  char text[128];
  const size_t n = size < sizeof text - 1 ? size : sizeof text - 1;
  std::memcpy(text, data, n);
  text[n] = '\0';
  ctp_command_t c;
  char err[256];
  if (cuetrack::platform::parseCommandText(text, 1, &c, err, sizeof err)) {
    if (c.type == CTP_CMD_START && (c.box_px[2] <= 0 || c.box_px[3] <= 0)) abort();
    if (c.type == CTP_CMD_SET_RATE && c.rate_hz > 1000) abort();
    char back[64];
    if (cuetrack::platform::formatCommandText(c, back, sizeof back) == 0) abort();
  }
  return 0;
}
