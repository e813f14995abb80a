// A fakenect recording as a whole: the input is a little archive (INDEX.txt and the
// files it names, each length-prefixed), written to a private folder and read with
// FakenectReader: pairing, timestamp order, paths, size changes, damaged frames, the
// replay check. Every frame read is sane; every failure is one line.
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "cuetrack/drivers/FakenectReader.hpp"

using namespace cuetrack;

namespace {

std::string gDir;
std::string gWritten[80];  // the files of the last input, removed before the next
int gWrittenCount = 0;

// Two bytes of length (little-endian, at most 4096), then that many bytes.
bool take(const uint8_t*& p, const uint8_t* end, std::string* out) {
  if (end - p < 2) return false;
  size_t n = static_cast<size_t>(p[0]) | (static_cast<size_t>(p[1] & 0x0f) << 8);
  p += 2;
  if (n > static_cast<size_t>(end - p)) n = static_cast<size_t>(end - p);
  out->assign(reinterpret_cast<const char*>(p), n);
  p += n;
  return true;
}

void writeFile(const std::string& name, const std::string& data) {
  if (gWrittenCount == 80) return;
  gWritten[gWrittenCount++] = gDir + "/" + name;
  FILE* f = std::fopen(gWritten[gWrittenCount - 1].c_str(), "wb");
  if (!f) return;
  std::fwrite(data.data(), 1, data.size(), f);
  std::fclose(f);
}

bool plainName(const std::string& s) {  // written only inside our folder
  if (s.empty() || s.size() > 64 || s[0] == '.') return false;
  for (char c : s)
    if (c == '/' || c == '\0' || c == '\n' || c == '\r') return false;
  return true;
}

void removeAll() {
  for (int i = 0; i < gWrittenCount; ++i) unlink(gWritten[i].c_str());
  gWrittenCount = 0;
}

bool oneLine(const char* s) {
  return s[0] != '\0' && !std::strchr(s, '\n');
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static FrameSlot slot;
  if (gDir.empty()) {
    char tmpl[] = "/tmp/cuetrack-fuzz-fakenect-XXXXXX";
    if (!mkdtemp(tmpl)) return 0;
    gDir = tmpl;
    std::atexit([] {  // leave nothing in /tmp
      removeAll();
      rmdir(gDir.c_str());
    });
  }
  removeAll();
  const uint8_t* p = data;
  const uint8_t* end = data + size;
  std::string index;
  if (!take(p, end, &index)) return 0;
  writeFile("INDEX.txt", index);
  // The files INDEX names, in its order, each with the next piece of the input.
  size_t start = 0;
  while (start < index.size()) {
    size_t nl = index.find('\n', start);
    if (nl == std::string::npos) nl = index.size();
    std::string line = index.substr(start, nl - start);
    start = nl + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string content;
    if (!plainName(line) || !take(p, end, &content)) continue;
    writeFile(line, content);
  }
  std::string gt;
  if (take(p, end, &gt)) writeFile("groundtruth.txt", gt);

  char err[512] = "";
  if (!checkFakenectReplayable(gDir.c_str(), err, sizeof err) && !oneLine(err)) __builtin_trap();

  SourceOptions opt;
  opt.skipBadFrames = (size & 1) != 0;
  FakenectReader r;
  if (!r.open(gDir.c_str(), opt)) {
    if (!oneLine(r.error())) __builtin_trap();
    return 0;
  }
  uint64_t lastUs = 0;
  for (int i = 0; i < 64; ++i) {
    const ReadStatus st = r.next(slot);
    if (st == ReadStatus::End) break;
    if (st == ReadStatus::Error) {
      if (!oneLine(r.error())) __builtin_trap();
      break;
    }
    const int w = slot.rgb.width(), h = slot.rgb.height();
    if (w <= 0 || h <= 0 || w > kMaxImageWidth || h > kMaxImageHeight) __builtin_trap();
    if (slot.hasDepth && (slot.depthMm.width() != w || slot.depthMm.height() != h))
      __builtin_trap();
    if (i > 0 && slot.timeUs < lastUs) __builtin_trap();  // time runs forwards
    lastUs = slot.timeUs;
  }
  if (r.skippedFrames() < 0) __builtin_trap();
  return 0;
}
