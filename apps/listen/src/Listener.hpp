// The host side of the protocol: decodes what arrives on a byte stream, writes each
// TRACK to a sink (lines or CSV) and every other message as a line, sends commands.
#pragma once

#include <cstdint>

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
  uint32_t seqGaps = 0;   // messages missing according to seq
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

  const ListenStats& stats() const { return _stats; }
  const ctp_stats_t& decoderStats() const { return _decoder.stats; }

 private:
  bool handle(const ctp_frame_t& frame);

  platform::ByteStream& _port;
  platform::TrackSink& _tracks;
  platform::Reporter& _messages;
  platform::Reporter& _problems;
  ctp_decoder_t _decoder{};
  ListenStats _stats{};
  bool _haveSeq{false};
  uint32_t _lastSeq{0};
};

}  // namespace cuetrack::listen
