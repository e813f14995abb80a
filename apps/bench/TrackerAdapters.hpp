// The BenchTracker adapters: cuetrack (one Tracker, allocated once, reconfigured per
// run) and the OpenCV peers (a fresh instance per run, OpenCV's RNG seeded per run).
#pragma once

#include <memory>
#include <string>

#include "Runner.hpp"

namespace cuetrack::bench {

// OpenCV peer `name` (see Peers.hpp); nullptr with *err for an unknown name.
std::unique_ptr<BenchTracker> makePeerBench(const std::string& name, std::string* err);
// cuetrack with preset `config` ("1.1" ... "best") or an ablation of one ("best-nolost",
// "best-fixedsize": that beyond-the-paper switch off); nullptr with *err for an unknown one.
std::unique_ptr<BenchTracker> makeCuetrackBench(const std::string& config, std::string* err);
bool isCuetrackConfig(const std::string& config);

}  // namespace cuetrack::bench
