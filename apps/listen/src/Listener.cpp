#include "Listener.hpp"

#include <cstdio>
#include <cstring>

#include "cuetrack/platform/TrackText.hpp"

namespace cuetrack::listen {

using platform::IoResult;
using platform::IoStatus;

Listener::Listener(platform::ByteStream& port, platform::TrackSink& tracks,
                   platform::Reporter& messages, platform::Reporter& problems)
    : _port(port), _tracks(tracks), _messages(messages), _problems(problems) {
  ctp_decoder_init(&_decoder);
}

bool Listener::send(const ctp_command_t& command) {
  uint8_t wire[CTP_MAX_WIRE + 1];
  wire[0] = 0;  // ends any half frame the device holds
  const size_t n = ctp_encode_command(&command, wire + 1, sizeof wire - 1);
  if (n == 0) return false;
  size_t done = 0;
  // A command is small; a full tty buffer is retried briefly (bounded), never forever.
  for (int tries = 0; done < n + 1 && tries < 200; ++tries) {
    const IoResult r = _port.write(wire + done, n + 1 - done);
    if (r.status == IoStatus::Closed || r.status == IoStatus::Error) return false;
    done += r.bytes;
    if (done < n + 1) {
      uint8_t scratch[1];
      _port.read(scratch, 0, 5);  // waits ~5 ms without consuming input
    }
  }
  return done == n + 1;
}

PollResult Listener::poll(int timeoutMs, bool* received) {
  *received = false;
  uint8_t buf[512];
  const IoResult r = _port.read(buf, sizeof buf, timeoutMs);
  if (r.status == IoStatus::Closed || r.status == IoStatus::Error) return PollResult::Closed;
  if (r.bytes > 0) *received = true;
  for (size_t i = 0; i < r.bytes; ++i) {
    ctp_frame_t f;
    int err = 0;
    const int res = ctp_decoder_push(&_decoder, buf[i], &f, &err);
    if (res == CTP_PUSH_ERROR) {
      ++_stats.rejected;
    } else if (res == CTP_PUSH_FRAME && !handle(f)) {
      return PollResult::OutputFailed;
    }
  }
  return PollResult::Ok;
}

bool Listener::handle(const ctp_frame_t& frame) {
  ctp_message_t m;
  const int err = ctp_parse_message(&frame, &m);
  char line[256];
  if (err != CTP_OK) {
    ++_stats.rejected;
    std::snprintf(line, sizeof line, "rejected frame type 0x%02x: %s", frame.type,
                  ctp_error_name(err));
    _problems.report(line);
    return true;
  }
  // Every device message starts with seq; the union members share that layout.
  const uint32_t seq = m.type == CTP_MSG_TRACK       ? m.u.track.seq
                       : m.type == CTP_MSG_HEARTBEAT ? m.u.heartbeat.seq
                       : m.type == CTP_MSG_ACK       ? m.u.ack.seq
                                                     : m.u.error.seq;
  const bool hadLast = _seq.hasLast();
  const uint32_t before = _seq.last(), restarts = _seq.restarts();
  const uint32_t missing = _seq.see(seq);
  _stats.seqGaps = static_cast<uint32_t>(_seq.lost());
  if (_reportNextGap && hadLast) {
    // Across a restart of ours or a reconnect: said at once, not only in the totals.
    std::snprintf(line, sizeof line, "seq %u after %u: %u messages lost%s", seq, before, missing,
                  _seq.restarts() != restarts ? " (the device restarted)" : "");
    _problems.report(line);
  }
  _reportNextGap = false;
  switch (m.type) {
    case CTP_MSG_TRACK:
      ++_stats.tracks;
      if (!_tracks.write(m.u.track)) {
        _problems.report(_tracks.error());
        return false;
      }
      return true;
    case CTP_MSG_HEARTBEAT:
      ++_stats.heartbeats;
      break;
    case CTP_MSG_ACK:
      ++_stats.acks;
      break;
    case CTP_MSG_ERROR:
      ++_stats.errors;
      break;
    default:
      break;
  }
  const size_t n = platform::formatMessageLine(m, line, sizeof line);
  if (n > 0 && line[n - 1] == '\n') line[n - 1] = '\0';
  _messages.report(line);
  return true;
}

}  // namespace cuetrack::listen
