// The runner on in-memory sequences: protocol (init at the first ground-truth box,
// scoring of later frames), bad input (broken sequence, no ground truth, a tracker
// that cannot run), the output files, and an OpenCV peer on real pixels.
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>

#include "Outputs.hpp"
#include "PeerCache.hpp"
#include "Report.hpp"
#include "Runner.hpp"
#include "TrackerAdapters.hpp"

using namespace cuetrack;
using namespace cuetrack::bench;

namespace {

// A 160x120 textured background with a checkered 24x24 target moving 2 px per frame
// to the right; ground truth is exact. Frame `errorAt` (if >= 0) fails to read. With
// `truthMm`, the source also knows the target's 3D centre: 2 m ahead, 10 mm per frame right.
// From frame `hiddenFrom` (if >= 0) on, the target is not visible.
class MovingSquareSource final : public FrameSource {
 public:
  MovingSquareSource(int frames, int errorAt, bool gtVisible = true, bool truthMm = false,
                     int hiddenFrom = -1)
      : _frames(frames),
        _errorAt(errorAt),
        _hiddenFrom(hiddenFrom),
        _gtVisible(gtVisible),
        _truthMm(truthMm) {}
  ReadStatus next(FrameSlot& out) override {
    if (_next == _errorAt) {
      std::snprintf(_error, sizeof _error, "square/%06d.png: truncated PNG", _next);
      return ReadStatus::Error;
    }
    if (_next >= _frames) return ReadStatus::End;
    const int w = 160, h = 120, size = 24;
    const int x0 = 20 + 2 * _next, y0 = 40;
    out.rgb.resize(w, h);
    out.hasDepth = false;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint8_t bg = static_cast<uint8_t>(((x * 37) ^ (y * 91)) & 0x3f) + 60;
        Rgb8 p{bg, bg, bg};
        if (x >= x0 && x < x0 + size && y >= y0 && y < y0 + size)
          p = (((x - x0) / 6 + (y - y0) / 6) % 2) ? Rgb8{230, 30, 30} : Rgb8{20, 20, 200};
        out.rgb.data()[y * w + x] = p;
      }
    out.index = _next;
    out.timeUs = static_cast<uint64_t>(_next) * 33333u;
    out.hasGroundTruth = true;
    const bool visible = _gtVisible && (_hiddenFrom < 0 || _next < _hiddenFrom);
    out.groundTruth = visible ? Box{float(x0), float(y0), float(size), float(size)} : Box{};
    if (_truthMm) {
      out.hasTruthMm = true;
      out.truthCentreMm[0] = 10.f * static_cast<float>(_next);
      out.truthCentreMm[1] = -100.f;
      out.truthCentreMm[2] = 2000.f;
    }
    ++_next;
    return ReadStatus::Ok;
  }
  const char* error() const override { return _error; }
  const char* name() const override { return "square"; }

 private:
  int _frames, _errorAt, _hiddenFrom, _next = 0;
  bool _gtVisible, _truthMm;
  char _error[128] = "";
};

// Reports a scripted box per frame: the ground truth shifted by `shiftPx` in x.
class ShiftTracker final : public BenchTracker {
 public:
  explicit ShiftTracker(float shiftPx, bool refuse = false, std::vector<uint64_t>* seeds = nullptr)
      : _shift(shiftPx), _refuse(refuse), _seeds(seeds) {}
  bool init(const CachedFrame&, const Box&, uint64_t seed, std::string* err) override {
    if (_seeds) _seeds->push_back(seed);
    if (_refuse) *err = "cannot run: needs depth";
    return !_refuse;
  }
  Box update(const CachedFrame& f, double* stageUs) override {
    stageUs[4] = 1000;  // 1 ms total
    Box b = f.groundTruth;
    b.x += _shift;
    for (int a = 0; a < 3; ++a) _positionMm[a] = f.truthCentreMm[a] + _offsetMm[a];
    return b;
  }
  // Reports the frame's 3D truth plus this offset [mm] (a 3D tracker's estimate).
  void reportPositionMm(float dx, float dy, float dz) {
    _has3d = true;
    _offsetMm[0] = dx;
    _offsetMm[1] = dy;
    _offsetMm[2] = dz;
  }
  bool lastPositionMm(float out[3]) const override {
    for (int a = 0; a < 3; ++a) out[a] = _positionMm[a];
    return _has3d;
  }

 private:
  bool _has3d = false;
  float _offsetMm[3] = {0, 0, 0}, _positionMm[3] = {0, 0, 0};
  float _shift;
  bool _refuse;
  std::vector<uint64_t>* _seeds;
};

Sequence load(FrameSource& src) {
  Sequence seq;
  std::string err;
  REQUIRE(loadSequence(src, 0, size_t(1) << 30, &seq, &err));
  return seq;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("a broken sequence gives one line naming the file, not a partial result") {
  MovingSquareSource src(10, 4);
  Sequence seq;
  std::string err;
  CHECK_FALSE(loadSequence(src, 0, size_t(1) << 30, &seq, &err));
  CHECK(err == "square/000004.png: truncated PNG");

  MovingSquareSource empty(0, -1);
  CHECK_FALSE(loadSequence(empty, 0, size_t(1) << 30, &seq, &err));
  CHECK(err == "square: no frames");

  MovingSquareSource big(10, -1);
  CHECK_FALSE(loadSequence(big, 0, 100000, &seq, &err));  // 100 kB limit
  CHECK(err.find("--frames") != std::string::npos);
}

TEST_CASE("--frames cuts the sequence; frames are decoded once with BGR copies for peers") {
  MovingSquareSource src(10, 8);  // the error at frame 8 is never reached
  Sequence seq;
  std::string err;
  REQUIRE(loadSequence(src, 5, size_t(1) << 30, &seq, &err));
  REQUIRE(seq.frames.size() == 5);
  const CachedFrame& f = seq.frames[2];
  CHECK(f.bgr.cols == 160);
  const cv::Vec3b px = f.bgr.at<cv::Vec3b>(40, 24);  // inside the target: RGB(20,20,200)
  CHECK(int(px[0]) == 200);                          // B first
  CHECK(int(f.rgb[40 * 160 + 24].b) == 200);
}

TEST_CASE("protocol: init at the first box, later frames scored, runs get consecutive seeds") {
  MovingSquareSource src(11, -1);
  const Sequence seq = load(src);
  std::vector<uint64_t> seeds;
  TrackerFactory factory = [&](const EntrySpec&, std::string*) {
    // A 24 px box shifted by half its width: IoU exactly 1/3.
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(12.f, false, &seeds));
  };
  RunOptions options;
  options.seed = 7;
  Progress quiet(false);
  const SequenceResult r = runEntry({"fake", "default", 3}, seq, factory, options, quiet);
  REQUIRE(r.ran);
  CHECK(r.figures.frames == 10);  // 11 frames, the first initialises
  CHECK(r.figures.overlap == Approx(100.0 / 3.0));
  CHECK(r.figures.hit == 0.0);  // exactly 1/3 is not a hit
  CHECK(r.figures.pascal == 0.0);
  CHECK(r.figures.centerPx == Approx(12.0));
  CHECK(r.figures.stageMs[4] == Approx(1.0));
  CHECK(seeds == std::vector<uint64_t>{7, 8, 9});
  REQUIRE(r.frameIndex.size() == 10);
  CHECK(r.frameIndex.front() == 1);
  CHECK(r.meanOverlap.front() == Approx(1.0 / 3.0));
}

TEST_CASE("3D centre error: scored where the source knows the 3D centre and the target shows") {
  Progress quiet(false);
  auto runWith = [&](FrameSource& src, bool report3d) {
    const Sequence seq = load(src);
    TrackerFactory factory = [&](const EntrySpec&, std::string*) {
      auto t = std::make_unique<ShiftTracker>(0.f);
      if (report3d) t->reportPositionMm(3.f, -4.f, 12.f);  // 13 mm off, 12 of them in z
      return std::unique_ptr<BenchTracker>(std::move(t));
    };
    return runEntry({"fake", "default", 2}, seq, factory, RunOptions{}, quiet);
  };
  MovingSquareSource withTruth(6, -1, true, true);
  SequenceResult r = runWith(withTruth, true);
  REQUIRE(r.ran);
  CHECK(r.figures.centerMm == Approx(13.0));
  CHECK(r.figures.centerZMm == Approx(12.0));
  CHECK(r.figures.centerPx == Approx(0.0));
  // A 2D tracker (no 3D position), a source without 3D truth, a hidden target: no figure.
  MovingSquareSource again(6, -1, true, true);
  CHECK(std::isnan(runWith(again, false).figures.centerMm));
  MovingSquareSource noTruth(6, -1, true, false);
  CHECK(std::isnan(runWith(noTruth, true).figures.centerMm));
  MovingSquareSource hidden(6, -1, true, true, 1);  // visible at the first frame only
  r = runWith(hidden, true);
  REQUIRE(r.ran);
  CHECK(std::isnan(r.figures.centerMm));
}

TEST_CASE("thinning: every K-th frame after the first box, random drops the same for all") {
  MovingSquareSource src(21, -1);
  Sequence strided = load(src);
  thinSequence(&strided, 3, 0, 1);
  std::vector<int> kept;
  for (const CachedFrame& f : strided.frames) kept.push_back(f.index);
  CHECK(kept == std::vector<int>{0, 3, 6, 9, 12, 15, 18});
  CHECK(strided.droppedFrames == 14);
  CHECK(strided.frames[1].timeUs == 3u * 33333u);  // timestamps kept: the tracker sees the gap

  MovingSquareSource a(200, -1), b(200, -1), c(200, -1);
  Sequence sa = load(a), sb = load(b), sc = load(c);
  thinSequence(&sa, 1, 30, 7);
  thinSequence(&sb, 1, 30, 7);
  thinSequence(&sc, 1, 30, 8);
  CHECK(sa.frames.front().index == 0);  // the first box's frame always stays
  CHECK(sa.droppedFrames > 40);         // ~30% of 199
  CHECK(sa.droppedFrames < 80);
  CHECK(sa.droppedFrames == sb.droppedFrames);
  bool same = sa.frames.size() == sc.frames.size();
  for (size_t i = 0; same && i < sa.frames.size(); ++i)
    same = sa.frames[i].index == sc.frames[i].index;
  CHECK_FALSE(same);  // another seed drops other frames

  MovingSquareSource d(9, -1);
  Sequence untouched = load(d);
  thinSequence(&untouched, 1, 0, 1);
  CHECK(untouched.frames.size() == 9);
  CHECK(untouched.droppedFrames == 0);
}

struct Played {
  SequenceResult result;
  int initIndex = -1;
  Box initBox{};
  std::vector<int> indices;
  std::vector<uint64_t> timesUs;
};

// Writes where it was started and which frames it was then given, in order, into a
// Played that outlives it (the runner destroys its trackers).
class RecordingTracker final : public BenchTracker {
 public:
  explicit RecordingTracker(Played* out) : _out(out) {}
  bool init(const CachedFrame& f, const Box& box, uint64_t, std::string*) override {
    _out->initIndex = f.index;
    _out->initBox = box;
    return true;
  }
  Box update(const CachedFrame& f, double* stageUs) override {
    stageUs[4] = 1000;
    _out->indices.push_back(f.index);
    _out->timesUs.push_back(f.timeUs);
    return f.groundTruth;
  }

 private:
  Played* _out;
};

Played play(const Sequence& seq) {
  Played played;
  TrackerFactory factory = [&played](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<RecordingTracker>(&played));
  };
  Progress quiet(false);
  played.result = runEntry({"fake", "default", 1}, seq, factory, RunOptions{}, quiet);
  return played;
}

TEST_CASE("slicing: another start, another end, backwards; timestamps still increase") {
  MovingSquareSource src(21, -1);
  Sequence whole = load(src);
  const Played control = play(whole);  // unsliced: starts at frame 0 and plays 1..20
  CHECK(control.initIndex == 0);
  CHECK(control.indices.size() == 20);

  Sequence part = whole;
  std::string err;
  REQUIRE(sliceSequence(&part, 5, 12, false, &err));
  CHECK(part.name == "square.from5.to12");
  Played p = play(part);
  CHECK(p.initIndex == 5);
  CHECK(p.initBox.x == 30.f);  // the square's box at frame 5: x = 20 + 2 * 5
  CHECK(p.indices == std::vector<int>{6, 7, 8, 9, 10, 11, 12});
  CHECK(p.result.frameIndex == p.indices);

  Sequence back = whole;
  REQUIRE(sliceSequence(&back, -1, -1, true, &err));
  CHECK(back.name == "square.rev");
  p = play(back);
  CHECK(p.initIndex == 20);  // the last ground-truth box
  CHECK(p.initBox.x == 60.f);
  REQUIRE(p.indices.size() == 20);
  CHECK(p.indices.front() == 19);
  CHECK(p.indices.back() == 0);
  for (size_t i = 0; i < p.timesUs.size(); ++i)  // mirrored: same 33 ms gaps, increasing
    CHECK(p.timesUs[i] == static_cast<uint64_t>(i + 1) * 33333u);
  REQUIRE(p.result.ran);
  CHECK(p.result.figures.overlap == Approx(100.0));  // [%]: each frame kept its own truth

  Sequence backPart = whole;
  REQUIRE(sliceSequence(&backPart, 3, 9, true, &err));
  CHECK(backPart.name == "square.from3.to9.rev");
  p = play(backPart);
  CHECK(p.initIndex == 9);
  CHECK(p.indices == std::vector<int>{8, 7, 6, 5, 4, 3});

  // A long name loses its middle in the text table, never the slice that tells runs apart.
  EntryResult e{"fake", "default", 1, {}};
  for (const char* name : {"Vid_E_person_partially_occluded.from200.rev", "Vid_C_juice.to100.rev",
                           "Vid_E_person_partially_occluded"}) {
    e.sequences.push_back(p.result);
    e.sequences.back().name = name;
  }
  const std::string text = textReport({e});
  CHECK(text.find(" Vi~.from200.rev") != std::string::npos);
  CHECK(text.find(" Vid_~.to100.rev") != std::string::npos);
  CHECK(text.find("Vid_E_person_p~") != std::string::npos);  // no slice: the end goes

  Sequence none = whole;
  CHECK_FALSE(sliceSequence(&none, 30, -1, false, &err));
  CHECK(err == "square: no frame has an index in 30..end (of 21 frames)");
  CHECK(none.name == "square.from30");  // the table names the slice that failed
  Sequence untouched = whole;
  REQUIRE(sliceSequence(&untouched, -1, -1, false, &err));
  CHECK(untouched.name == "square");
  CHECK(untouched.frames.size() == 21);
}

TEST_CASE("invisible targets count with overlap 0; no box at all means nothing to start from") {
  MovingSquareSource hidden(5, -1, false);
  const Sequence seq = load(hidden);
  TrackerFactory factory = [](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(0.f));
  };
  Progress quiet(false);
  const SequenceResult r = runEntry({"fake", "default", 1}, seq, factory, RunOptions{}, quiet);
  CHECK_FALSE(r.ran);
  CHECK(r.error.rfind("no ground-truth box to initialise from (", 0) == 0);
}

TEST_CASE("frames that change size after the initialisation frame fail the sequence") {
  MovingSquareSource src(8, -1);
  Sequence seq = load(src);
  TrackerFactory factory = [](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(0.f));
  };
  Progress quiet(false);
  SequenceResult r = runEntry({"fake", "default", 1}, seq, factory, RunOptions{}, quiet);
  REQUIRE(r.ran);  // control: same sizes throughout
  CachedFrame& odd = seq.frames[5];
  odd.width = 80;
  odd.height = 60;
  odd.rgb.resize(80 * 60);
  r = runEntry({"fake", "default", 1}, seq, factory, RunOptions{}, quiet);
  CHECK_FALSE(r.ran);
  CHECK(r.error == "frame 5 is 80x60, the track began at 160x120");
}

TEST_CASE("a --results folder that cannot be written is reported once and marked") {
  MovingSquareSource src(5, -1);
  const Sequence seq = load(src);
  TrackerFactory factory = [](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(0.f));
  };
  RunOptions options;
  options.resultsDir = "/proc/cuetrack-nope";
  Progress quiet(false);
  const SequenceResult r = runEntry({"fake", "default", 3}, seq, factory, options, quiet);
  CHECK(r.ran);  // the figures are still good
  CHECK(r.outputError.find("/proc/cuetrack-nope") == 0);
}

TEST_CASE("a tracker that cannot run is reported with its reason, in every report") {
  MovingSquareSource src(4, -1);
  const Sequence seq = load(src);
  TrackerFactory refuse = [](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(0.f, true));
  };
  TrackerFactory fine = [](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(0.f));
  };
  Progress quiet(false);
  EntryResult a{"cuetrack", "2.1", 1, {}};
  a.sequences.push_back(runEntry({"cuetrack", "2.1", 1}, seq, refuse, RunOptions{}, quiet));
  EntryResult b{"opencv-kcf", "default", 1, {}};
  b.sequences.push_back(runEntry({"opencv-kcf", "default", 1}, seq, fine, RunOptions{}, quiet));
  REQUIRE_FALSE(a.sequences[0].ran);
  CHECK(a.sequences[0].error == "cannot run: needs depth");
  REQUIRE(b.sequences[0].ran);
  CHECK(b.sequences[0].figures.overlap == Approx(100.0));

  const std::string text = textReport({a, b});
  CHECK(text.find("cuetrack 2.1 on square: cannot run: needs depth") != std::string::npos);
  CHECK(text.find("Over.") != std::string::npos);
  // dist. says what it leaves out: the one tracker that ran had both boxes in every frame.
  CHECK(text.find("dist. covers only frames where both boxes exist; frames covered: "
                  "opencv-kcf 100%") != std::string::npos);
  const std::string md = markdownReport({a, b}, PaperReference::Table3);
  CHECK(md.find("frames covered: opencv-kcf 100%") != std::string::npos);
  CHECK(md.find("- cuetrack 2.1 on square: cannot run: needs depth") != std::string::npos);
  CHECK(md.find("paper 2.1 | 73.47 | 96.77") != std::string::npos);

  // Unknown trackers and configurations are refused by the factories.
  std::string err;
  CHECK_FALSE(makePeerBench("opencv-nope", &err));
  CHECK(err == "unknown tracker 'opencv-nope'");
}

TEST_CASE("output files: BoBoT result format, per-frame CSV, overlap plot") {
  MovingSquareSource src(6, -1);
  Sequence seq = load(src);
  seq.gtHeader = "./square.avi";
  TrackerFactory factory = [](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(0.f));
  };
  RunOptions options;
  options.resultsDir = "bench_runner_out/results";
  Progress quiet(false);
  EntryResult e{"fake", "1.1", 2, {}};
  e.sequences.push_back(runEntry({"fake", "1.1", 2}, seq, factory, options, quiet));
  REQUIRE(e.sequences[0].ran);

  const std::string bobot = readAll("bench_runner_out/results/square/fake-1.1.run2.txt");
  std::istringstream lines(bobot);
  std::string header, first, second;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  CHECK(header == "./square.avi");
  CHECK(first == "0 0.125000 0.333333 0.150000 0.200000");   // 20/160 40/120 24/160 24/120
  CHECK(second == "1 0.137500 0.333333 0.150000 0.200000");  // moved 2 px

  std::string err;
  REQUIRE(writeOverlapCsv("bench_runner_out/square.csv", {e}, 0, &err));
  const std::string csv = readAll("bench_runner_out/square.csv");
  CHECK(csv.rfind("frame,fake 1.1\n1,1.0000\n2,1.0000\n", 0) == 0);

  REQUIRE(writeOverlapPlot("bench_runner_out/square.png", {e}, 0, &err));
  const cv::Mat png = cv::imread("bench_runner_out/square.png");
  CHECK(png.cols == 900);
  CHECK(png.rows == 340);

  CHECK_FALSE(writeOverlapPlot("/nonexistent-dir/p.png", {e}, 0, &err));
  CHECK(err.find("/nonexistent-dir/p.png") == 0);

  // The overlay video: every frame, the frame's width, a legend under it (frame number +
  // one row per entry); the entry's box drawn in its colour at its first-run box.
  REQUIRE(writeOverlayVideo("bench_runner_out/square.avi", seq, {e}, 0, 30.0, &err));
  cv::VideoCapture video("bench_runner_out/square.avi");
  REQUIRE(video.isOpened());
  cv::Mat frame;
  int n = 0;
  while (video.read(frame)) {
    CHECK(frame.cols == 160);
    CHECK(frame.rows > 120 + 2 * 16);
    ++n;
  }
  CHECK(n == static_cast<int>(seq.frames.size()));
  CHECK_FALSE(writeOverlayVideo("/nonexistent-dir/v.avi", seq, {e}, 0, 30.0, &err));
  CHECK(err.find("/nonexistent-dir/v.avi: cannot write") == 0);
}

TEST_CASE("OpenCV KCF follows a clearly visible moving target on the same frames") {
  MovingSquareSource src(30, -1);
  const Sequence seq = load(src);
  TrackerFactory factory = [](const EntrySpec& s, std::string* err) {
    return makePeerBench(s.tracker, err);
  };
  Progress quiet(false);
  const SequenceResult r =
      runEntry({"opencv-kcf", "default", 1}, seq, factory, RunOptions{}, quiet);
  REQUIRE(r.ran);
  CHECK(r.figures.frames == 29);
  CHECK(r.figures.overlap > 60.0);
  CHECK(r.figures.hit > 90.0);
}

TEST_CASE("peer cache: a result comes back as it was; another sequence, seed or file misses") {
  MovingSquareSource src(11, -1);
  const Sequence seq = load(src);
  TrackerFactory factory = [&](const EntrySpec&, std::string*) {
    return std::unique_ptr<BenchTracker>(std::make_unique<ShiftTracker>(12.f));
  };
  RunOptions options;
  Progress quiet(false);
  const EntrySpec spec{"opencv-kcf", "default", 2};
  const SequenceResult r = runEntry(spec, seq, factory, options, quiet);
  REQUIRE(r.ran);
  char dir[] = "/tmp/cuetrack-peer-cache-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  const std::string path = peerCachePath(dir, spec, seq, 1);
  std::string err;
  REQUIRE(savePeerResult(path, r, &err));
  SequenceResult back;
  back.name = seq.name;
  REQUIRE(loadPeerResult(path, &back));
  CHECK(back.ran);
  CHECK(back.figures.overlap == r.figures.overlap);  // bit for bit (%.17g)
  CHECK(back.figures.centerPx == r.figures.centerPx);
  CHECK(r.figures.centerPct > 0.0);  // the share of frames centerPx covers, kept too
  CHECK(back.figures.centerPct == r.figures.centerPct);
  CHECK(back.figures.auc == r.figures.auc);
  CHECK(back.figures.runOverlap == r.figures.runOverlap);
  CHECK(back.frameIndex == r.frameIndex);
  CHECK(back.meanOverlap == r.meanOverlap);
  CHECK(back.firstRunBoxes.size() == r.firstRunBoxes.size());
  CHECK(std::equal(std::begin(r.figures.precision), std::end(r.figures.precision),
                   std::begin(back.figures.precision)));
  // Another seed, or other frames, give another key.
  CHECK(peerCachePath(dir, spec, seq, 2) != path);
  Sequence shorter = seq;
  shorter.frames.pop_back();
  CHECK(peerCachePath(dir, spec, shorter, 1) != path);
  Sequence repainted = seq;
  repainted.frames[3].rgb[0].r ^= 0xff;
  CHECK(peerCachePath(dir, spec, repainted, 1) != path);
  // A damaged file is a miss, not a result.
  {
    std::ofstream damaged(path);
    damaged << "cuetrack-peer-cache 1\nframes 10 figures 1 2\n";
  }
  SequenceResult none;
  CHECK_FALSE(loadPeerResult(path, &none));
  CHECK_FALSE(loadPeerResult(std::string(dir) + "/absent.txt", &none));
  std::remove(path.c_str());
}
