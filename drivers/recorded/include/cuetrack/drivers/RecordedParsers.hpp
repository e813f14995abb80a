// Parsers of the recorded formats, on memory buffers (so libFuzzer can drive them and
// readers can reuse one file buffer). None allocates; each returns false with a short
// reason in `err` (the caller prefixes the file name and line).
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"

namespace cuetrack::rec {

// ---- PNM (P5 grey / P6 colour), the fakenect and NYU still formats ----------
struct PnmHeader {
  char type = 0;          // '5' (grey) or '6' (RGB)
  int width = 0;          // [px]
  int height = 0;         // [px]
  int maxval = 0;         // 1..65535; > 255 means 16-bit samples
  size_t dataOffset = 0;  // first byte of the pixels
  int bytesPerSample() const { return maxval > 255 ? 2 : 1; }
  size_t dataBytes() const {
    return static_cast<size_t>(width) * static_cast<size_t>(height) * (type == '6' ? 3u : 1u) *
           static_cast<size_t>(bytesPerSample());
  }
};
bool parsePnmHeader(const uint8_t* buf, size_t len, PnmHeader* out, char* err, size_t errLen);
// The header alone, from the first bytes of a file (pixels not checked for length).
bool parsePnmHeaderPrefix(const uint8_t* buf, size_t len, PnmHeader* out, char* err, size_t errLen);

enum class Endian : uint8_t { Little, Big };  // fakenect writes little-endian, NYU big-endian

// Colour from P6 (8-bit) or P5 (8-bit grey, replicated); image must hold width x height.
bool decodePnmRgb(const uint8_t* buf, size_t len, const PnmHeader& h, Rgb8* dst, char* err,
                  size_t errLen);
// 16-bit P5 samples as they are (raw disparity or mm, depending on the file).
bool decodePnm16(const uint8_t* buf, size_t len, const PnmHeader& h, Endian endian, uint16_t* dst,
                 char* err, size_t errLen);

// ---- fakenect INDEX.txt lines: "<c>-<seconds>-<timestamp>.<ext>" -------------
struct IndexEntry {
  char kind = 0;           // 'r' colour, 'd' depth, 'a' accelerometer
  double seconds = 0.0;    // host time of capture [s]
  uint32_t timestamp = 0;  // device timestamp (opaque)
};
// line excludes the newline ('\r' allowed at its end). False for a malformed name or
// seconds outside 0..kMaxIndexSeconds (host time: Unix seconds up to the year 2286).
inline constexpr double kMaxIndexSeconds = 1e10;
bool parseIndexLine(const char* line, size_t len, IndexEntry* out, char* err, size_t errLen);

// ---- Ground truth -------------------------------------------------------------
// BoBoT line "idx x y w h" (normalised to the image size, `0 0 0 0` = not visible).
bool parseBobotLine(const char* line, size_t len, int* idx, float box[4], char* err, size_t errLen);
// OTB line "x,y,w,h" (comma and/or whitespace separated), 1-based pixels.
bool parseOtbLine(const char* line, size_t len, float box[4], char* err, size_t errLen);
// intrinsics.txt: "fx fy cx cy" [px]. fx, fy must lie in kMinFocalPx..kMaxFocalPx and
// cx, cy in 0..kMaxImageWidth/Height (the readers check them against the image as well).
inline constexpr float kMinFocalPx = 10.f;
inline constexpr float kMaxFocalPx = 100000.f;
bool parseIntrinsics(const char* text, size_t len, CameraIntrinsics* out, char* err, size_t errLen);

// The frame count of a spec's ":frames" suffix: a whole number in 1..kMaxSpecFrames.
inline constexpr long kMaxSpecFrames = 1000000;
bool parseFrameCount(const char* text, int* out);

// Splits a text buffer into lines: returns the next line start/length after *pos, and
// advances *pos; false at the end. '\r' before '\n' is dropped.
bool nextLine(const char* text, size_t len, size_t* pos, const char** line, size_t* lineLen);
// True when the line holds only whitespace.
bool blankLine(const char* line, size_t len);

}  // namespace cuetrack::rec
