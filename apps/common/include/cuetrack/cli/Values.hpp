// The values several tools take, checked one way: each returns "" when `text` is one
// (and fills `out`), else why not, as a phrase for the error line ("expected ...").
// Every number is a plain decimal (platform/common DecimalText.hpp, the rule of the text
// commands too): an optional sign, digits, a point and digits where a fraction is
// allowed; no blanks, hex ("0x10"), exponents ("1e3"), inf or nan.
#pragma once

#include <cstdint>
#include <string>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::cli {

// A whole decimal number in [lo, hi]: digits with an optional leading '-', nothing else.
std::string wholeNumber(const std::string& text, long lo, long hi, long* out);
// A plain decimal number in [lo, hi] ("-2.5", ".5", "1."; the whole of text).
std::string decimal(const std::string& text, double lo, double hi, double* out);
// A seed: plain digits, 0 .. 2^64-1 ("-1" is not 2^64-1).
std::string seed(const std::string& text, uint64_t* out);
// An image size WxH, each side in [minSide, maxW] and [minSide, maxH].
std::string imageSize(const std::string& text, int minSide, int maxW, int maxH, int* w, int* h);
// A target box X,Y,W,H in pixels: finite, |v| <= 100000 (catches 1e30 and typos), W, H > 0.
std::string box(const std::string& text, Box* out);
// n plain decimal numbers "A,B,...", each within +-limit.
std::string numbers(const std::string& text, int n, float limit, float* out);
// A serial line rate termios has on Linux (9600 .. 921600).
std::string baudRate(const std::string& text, int* out);
// HOST:PORT, a name or IPv4 address, or [IPv6]:PORT; port 1..65535 (resolved later).
std::string hostPort(const std::string& text);
// A path to read: it exists and is not a folder.
std::string existingFile(const std::string& text);
// One of `choices` ("a|b|c"); the index in *out.
std::string oneOf(const std::string& text, const char* choices, int* out);

}  // namespace cuetrack::cli
