// --json FILE: the stable schema of issue 7, documented in docs/bench-json.md.
//   {"tracker", "config", "runs",
//    "sequences": [{"name", "frames", "overlap", "hit", "pascal", "center_px",
//                   "center_mm", "center_z_mm", "ms_median", "ms_mean",
//                   "allocs"}],
//    "average": {"frames", "overlap", "hit", "pascal", "center_px", "center_mm",
//                "center_z_mm", "ms_median", "ms_mean", "allocs"}}
// One entry: that object; several: an array of them. Percentages are 0-100.
// A figure that does not exist (tracker could not run, no centre distance, no 3D truth or
// no 3D position) is null. Written through nlohmann-json, indented two spaces; figures
// are rounded to the decimals the schema's page gives.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "Results.hpp"

namespace cuetrack::bench {

std::string toJson(const std::vector<EntryResult>& entries);
// Writes toJson() to `path`; on failure fills `err` with one line and returns false.
bool writeJson(const char* path, const std::vector<EntryResult>& entries, std::string* err);

}  // namespace cuetrack::bench
