#include <cmath>
#include <cstdio>
#include <cstring>

#include "cuetrack/drivers/FakenectReader.hpp"
#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

namespace cuetrack {

namespace {
std::string baseName(const std::string& path) {
  std::string p = path;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  const size_t slash = p.find_last_of('/');
  return slash == std::string::npos ? p : p.substr(slash + 1);
}

// Reads INDEX.txt and calls onEntry(lineNo, line, len, entry) for every non-blank line
// (false from it stops the walk); a line that is not an entry is "INDEX:line: why".
template <typename OnEntry>
bool walkIndex(const std::string& indexPath, char* err, size_t errLen, OnEntry&& onEntry) {
  std::vector<uint8_t> text;
  if (!rec::readFile(indexPath.c_str(), text, err, errLen)) return false;
  const char* t = reinterpret_cast<const char*>(text.data());
  size_t pos = 0;
  const char* line = nullptr;
  size_t len = 0;
  int lineNo = 0;
  char why[200];
  while (rec::nextLine(t, text.size(), &pos, &line, &len)) {
    ++lineNo;
    if (rec::blankLine(line, len)) continue;
    rec::IndexEntry e;
    if (!rec::parseIndexLine(line, len, &e, why, sizeof why)) {
      std::snprintf(err, errLen, "%s:%d: %s", indexPath.c_str(), lineNo, why);
      return false;
    }
    if (!onEntry(lineNo, line, len, e)) return false;
  }
  return true;
}
}  // namespace

bool FakenectReader::open(const char* dir, const SourceOptions& opt) {
  _dir = dir;
  while (_dir.size() > 1 && _dir.back() == '/') _dir.pop_back();
  restart(opt);
  _name = baseName(_dir);
  _files.clear();
  _seconds.clear();
  _frames.clear();

  const std::string indexPath = _dir + "/INDEX.txt";
  int lastDepth = -1;
  std::vector<int> waitingForDepth;  // colour entries seen before any depth entry
  int prevLine = 0;
  const bool indexOk = walkIndex(
      indexPath, _error, sizeof _error,
      [&](int lineNo, const char* line, size_t len, const rec::IndexEntry& e) {
        // Capture order: a time going back (a reordered INDEX, a clock step) would give
        // frames times out of order; refuse it rather than guess.
        if (!_seconds.empty() && e.seconds < _seconds.back()) {
          std::snprintf(_error, sizeof _error,
                        "%s:%d: time %.6f s goes back from %.6f s on line %d (entries must be in "
                        "capture order)",
                        indexPath.c_str(), lineNo, e.seconds, _seconds.back(), prevLine);
          return false;
        }
        prevLine = lineNo;
        const int entry = static_cast<int>(_files.size());
        _files.emplace_back(line, len);
        _seconds.push_back(e.seconds);
        if (e.kind == 'd') {
          lastDepth = entry;
          for (int f : waitingForDepth) _frames[static_cast<size_t>(f)].depthEntry = entry;
          waitingForDepth.clear();
        } else if (e.kind == 'r') {
          if (lastDepth < 0) waitingForDepth.push_back(static_cast<int>(_frames.size()));
          _frames.push_back({entry, lastDepth});
        }
        return true;
      });
  if (!indexOk) return false;
  if (_frames.empty()) {
    std::snprintf(_error, sizeof _error, "%s: no colour (r-*.ppm) entries", indexPath.c_str());
    return false;
  }
  _t0 = _seconds.front();
  // Rounded to 1/1000 frame/s: the %f times carry microseconds only.
  const double span = _seconds[static_cast<size_t>(_frames.back().rgbEntry)] -
                      _seconds[static_cast<size_t>(_frames.front().rgbEntry)];
  _fps = _frames.size() > 1 && span > 0.0
             ? std::round(static_cast<double>(_frames.size() - 1) / span * 1000.0) / 1000.0
             : 0.0;

  return loadGroundTruth(_dir + "/groundtruth.txt", GtFormat::Bobot,
                         static_cast<int>(_frames.size()), "frames");
}

bool checkFakenectReplayable(const char* dir, char* err, size_t errLen) {
  const std::string index = std::string(dir) + "/INDEX.txt";
  int frames = 0;
  const bool ok = walkIndex(
      index, err, errLen, [&](int lineNo, const char* line, size_t len, const rec::IndexEntry& e) {
        const std::string path = std::string(dir) + "/" + std::string(line, len);
        if (!rec::isFile(path.c_str())) {
          std::snprintf(err, errLen, "%s:%d: %s is missing or not a regular file", index.c_str(),
                        lineNo, path.c_str());
          return false;
        }
        if (e.kind == 'a') return true;
        uint8_t head[64];
        long fileBytes = -1;
        size_t n = 0;
        if (FILE* f = std::fopen(path.c_str(), "rb")) {
          n = std::fread(head, 1, sizeof head, f);
          if (std::fseek(f, 0, SEEK_END) == 0) fileBytes = std::ftell(f);
          std::fclose(f);
        }
        rec::PnmHeader h;
        char why[200];
        if (!rec::parsePnmHeaderPrefix(head, n, &h, why, sizeof why)) {
          std::snprintf(err, errLen, "%s: %s", path.c_str(), why);
          return false;
        }
        if (fileBytes < 0 || static_cast<size_t>(fileBytes) < h.dataOffset + h.dataBytes()) {
          std::snprintf(err, errLen, "%s: truncated: %ld of %zu bytes", path.c_str(), fileBytes,
                        h.dataOffset + h.dataBytes());
          return false;
        }
        const bool colour = e.kind == 'r';
        if (h.width != 640 || h.height != 480 || h.type != (colour ? '6' : '5') ||
            h.maxval != (colour ? 255 : 65535)) {
          std::snprintf(err, errLen,
                        "%s: %dx%d P%c maxval %d; fakenect replays only 640x480 %s (read the "
                        "folder with --source DIR instead)",
                        path.c_str(), h.width, h.height, h.type, h.maxval,
                        colour ? "P6 maxval 255" : "P5 maxval 65535");
          return false;
        }
        frames += colour;
        return true;
      });
  if (!ok) return false;
  if (frames == 0) {
    std::snprintf(err, errLen, "%s: no colour (r-*.ppm) entries", index.c_str());
    return false;
  }
  return true;
}

void FakenectReader::entryPath(int entry, char* path, size_t len) const {
  std::snprintf(path, len, "%s/%s", _dir.c_str(), _files[static_cast<size_t>(entry)].c_str());
}

bool FakenectReader::readPair(const Frame& f, FrameSlot& out) {
  char path[1024];
  char why[200];
  rec::PnmHeader h;
  entryPath(f.rgbEntry, path, sizeof path);
  if (!rec::readFile(path, _buf, _error, sizeof _error)) return false;
  if (!rec::parsePnmHeader(_buf.data(), _buf.size(), &h, why, sizeof why)) {
    std::snprintf(_error, sizeof _error, "%s: %s", path, why);
    return false;
  }
  if (_width > 0 && (h.width != _width || h.height != _height)) {
    std::snprintf(_error, sizeof _error, "%s: %dx%d, the sequence is %dx%d", path, h.width,
                  h.height, _width, _height);
    return false;
  }
  if (!out.rgb.resize(h.width, h.height) ||
      !rec::decodePnmRgb(_buf.data(), _buf.size(), h, out.rgb.data(), why, sizeof why)) {
    std::snprintf(_error, sizeof _error, "%s: %s", path, why);
    return false;
  }
  out.hasDepth = false;
  if (f.depthEntry >= 0) {
    entryPath(f.depthEntry, path, sizeof path);
    if (!rec::readFile(path, _buf, _error, sizeof _error)) return false;
    if (!rec::parsePnmHeader(_buf.data(), _buf.size(), &h, why, sizeof why) ||
        !rec::decodePnm16(_buf.data(), _buf.size(), h, rec::Endian::Little, out.depthMm.data(), why,
                          sizeof why)) {
      std::snprintf(_error, sizeof _error, "%s: %s", path, why);
      return false;
    }
    if (h.width != out.rgb.width() || h.height != out.rgb.height()) {
      std::snprintf(_error, sizeof _error, "%s: depth %dx%d does not match colour %dx%d", path,
                    h.width, h.height, out.rgb.width(), out.rgb.height());
      return false;
    }
    out.depthMm.resize(h.width, h.height);
    uint16_t* d = out.depthMm.data();
    const int n = h.width * h.height;
    for (int i = 0; i < n; ++i) d[i] = _rawToMm(d[i]);
    out.hasDepth = true;
  }
  return true;
}

RecordedReader::FrameRead FakenectReader::readFrame(int i, FrameSlot& out) {
  if (i >= static_cast<int>(_frames.size())) return FrameRead::End;
  return readPair(_frames[static_cast<size_t>(i)], out) ? FrameRead::Ok : FrameRead::Bad;
}

uint64_t FakenectReader::frameTimeUs(int i) const {
  // open() made the times non-decreasing and at most kMaxIndexSeconds: 0..1e16 us.
  const Frame& f = _frames[static_cast<size_t>(i)];
  return static_cast<uint64_t>(
      std::llround((_seconds[static_cast<size_t>(f.rgbEntry)] - _t0) * 1e6));
}

// ---------------------------------------------------------------------------

FakenectWriter::~FakenectWriter() {
  if (_index) std::fclose(_index);
}

bool FakenectWriter::open(const char* dir, const char* sequenceName) {
  char* err = _error;
  const size_t errLen = sizeof _error;
  _error[0] = '\0';
  if (_index) std::fclose(_index);
  _index = nullptr;
  if (rec::holdsRecording(dir, err, errLen)) return false;
  if (!rec::makeDirectories(dir, err, errLen)) return false;
  _dir = dir;
  _name = sequenceName ? sequenceName : baseName(_dir);
  const std::string indexPath = _dir + "/INDEX.txt";
  _index = std::fopen(indexPath.c_str(), "wb");
  if (!_index) {
    std::snprintf(err, errLen, "%s: cannot create", indexPath.c_str());
    return false;
  }
  _count = 0;
  _gt.start(_dir, _name);
  if (!_tableReady) {
    for (int mm = 0; mm <= kMaxDepthMm; ++mm)
      _mmToRaw[mm] = kinect::mmToRaw(static_cast<uint16_t>(mm));
    _tableReady = true;
  }
  return true;
}

bool FakenectWriter::write(const FrameSlot& frame) {
  char* err = _error;
  const size_t errLen = sizeof _error;
  if (!_index) {
    std::snprintf(err, errLen, "%s: writer not open", _dir.c_str());
    return false;
  }
  const int w = frame.rgb.width(), h = frame.rgb.height();
  // 1 s offset: fakenect treats a recorded time of 0 as "no previous frame".
  const double seconds = 1.0 + static_cast<double>(frame.timeUs) * 1e-6;
  // Camera timestamp in Kinect v1 clock ticks (60 MHz, wrapping), as fakenect-record
  // writes it: fakenect hands it to the live driver's callbacks (KinectSource).
  const uint32_t ts = static_cast<uint32_t>(frame.timeUs * 60u);
  char file[128], path[1024], header[64];

  // Accelerometer: freenect_raw_tilt_state (3 x int16 accel, int8 tilt, pad, int32 status),
  // level sensor at rest: 1 g = 819 counts on y.
  uint8_t accel[12] = {0};
  accel[2] = 819 & 0xFF;
  accel[3] = 819 >> 8;
  std::snprintf(file, sizeof file, "a-%.6f-%u.dump", seconds, ts);
  std::snprintf(path, sizeof path, "%s/%s", _dir.c_str(), file);
  if (!rec::writeFile(path, accel, sizeof accel, err, errLen)) return false;
  std::fprintf(_index, "%s\n", file);

  // Depth before colour: the reader pairs a colour frame with the depth before it.
  if (frame.hasDepth) {
    const int dw = frame.depthMm.width(), dh = frame.depthMm.height();
    _buf.resize(static_cast<size_t>(dw) * static_cast<size_t>(dh) * 2);
    const uint16_t* d = frame.depthMm.data();
    for (int i = 0; i < dw * dh; ++i) {
      const uint16_t raw = d[i] <= kMaxDepthMm ? _mmToRaw[d[i]] : kinect::kRawNoDepth;
      _buf[2 * static_cast<size_t>(i)] = static_cast<uint8_t>(raw & 0xFF);
      _buf[2 * static_cast<size_t>(i) + 1] = static_cast<uint8_t>(raw >> 8);
    }
    const int hl = std::snprintf(header, sizeof header, "P5 %d %d 65535\n", dw, dh);
    std::snprintf(file, sizeof file, "d-%.6f-%u.pgm", seconds, ts);
    std::snprintf(path, sizeof path, "%s/%s", _dir.c_str(), file);
    if (!rec::writeFile2(path, header, static_cast<size_t>(hl), _buf.data(), _buf.size(), err,
                         errLen))
      return false;
    std::fprintf(_index, "%s\n", file);
  }
  if (w > 0 && h > 0) {  // depth-only frames (a depth-only Kinect stream) have no colour
    const int hl = std::snprintf(header, sizeof header, "P6 %d %d 255\n", w, h);
    std::snprintf(file, sizeof file, "r-%.6f-%u.ppm", seconds, ts);
    std::snprintf(path, sizeof path, "%s/%s", _dir.c_str(), file);
    if (!rec::writeFile2(path, header, static_cast<size_t>(hl), frame.rgb.data(),
                         static_cast<size_t>(w) * static_cast<size_t>(h) * 3, err, errLen))
      return false;
    std::fprintf(_index, "%s\n", file);
  }

  if (!_gt.write(frame, _count, err, errLen)) return false;
  ++_count;
  return true;
}

bool FakenectWriter::close() {
  char* err = _error;
  const size_t errLen = sizeof _error;
  bool ok = true;
  if (_index && std::fclose(_index) != 0) {
    std::snprintf(err, errLen, "%s/INDEX.txt: write failed", _dir.c_str());
    ok = false;
  }
  _index = nullptr;
  if (!_gt.close(err, errLen)) ok = false;
  return ok;
}

}  // namespace cuetrack
