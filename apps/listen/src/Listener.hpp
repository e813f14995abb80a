// The host side of the protocol: decodes what arrives on a byte stream, writes each
// TRACK to a sink (lines or CSV) and every other message as a line, sends commands.
#pragma once

#include <cstdint>

#include "SeqCounter.hpp"
#include "cuetrack/platform/ByteStream.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack/platform/TrackSink.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::listen {

struct ListenStats {
  uint32_t tracks = 0;
  uint32_t heartbeats = 0;
  uint32_t acks = 0;
  uint32_t errors = 0;    // ERROR replies from the device
  uint32_t rejected = 0;  // frames we refused: framing, CRC, version, malformed
  uint32_t seqGaps = 0;   // messages missing according to seq (SeqCounter::lost)
};

enum class PollResult : uint8_t { Ok, Closed, OutputFailed };

class Listener {
 public:
  Listener(platform::ByteStream& port, platform::TrackSink& tracks, platform::Reporter& messages,
           platform::Reporter& problems);

  // Waits up to timeoutMs for bytes and handles all that came. *received tells
  // whether any byte arrived.
  PollResult poll(int timeoutMs, bool* received);
  bool send(const ctp_command_t& command);

  // The messages before this run (a state file) or before a reconnect ended at seq
  // `lastSeq`: the first seq after it is checked, and a gap reported in one line.
  void resumeAfter(uint32_t lastSeq) {
    _seq.resumeAfter(lastSeq);
    _reportNextGap = true;
  }
  // The port went away and came back: report the gap the first message shows.
  void noteReconnect() { _reportNextGap = true; }

  const ListenStats& stats() const { return _stats; }
  const SeqCounter& seq() const { return _seq; }
  const ctp_stats_t& decoderStats() const { return _decoder.stats; }

 private:
  bool handle(const ctp_frame_t& frame);

  platform::ByteStream& _port;
  platform::TrackSink& _tracks;
  platform::Reporter& _messages;
  platform::Reporter& _problems;
  ctp_decoder_t _decoder{};
  ListenStats _stats{};
  SeqCounter _seq;
  bool _reportNextGap{false};
};

}  // namespace cuetrack::listen
