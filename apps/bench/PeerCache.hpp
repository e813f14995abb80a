// The OpenCV peers are deterministic on the same frames (a seeded cv::theRNG for those
// that sample), so a development-set run need not re-run them: --peer-cache DIR keeps
// each peer's result for each sequence, keyed by the peer, OpenCV's version, the runs,
// the first seed, the scoring rule and the decoded sequence itself. A changed video, ground truth,
// slice, stride or OpenCV gives a new key, so a stale result is never read. The timings in a cached
// result are those of the run that made it.
#pragma once

#include <cstdint>
#include <string>

#include "Results.hpp"
#include "Runner.hpp"

namespace cuetrack::bench {

// DIR/<peer>/<sequence>-<16 hex digits>.txt
std::string peerCachePath(const std::string& dir, const EntrySpec& spec, const Sequence& seq,
                          uint64_t seed);
// False when the file is absent, from another format, or damaged (then the peer runs).
bool loadPeerResult(const std::string& path, SequenceResult* out);
// Writes path.tmp, then renames it into place: a reader never sees half a file.
bool savePeerResult(const std::string& path, const SequenceResult& result, std::string* err);

}  // namespace cuetrack::bench
