// What cuetrack shows, with the real binary: the banner and summary lines, --snapshot's
// PNG, --show without a display, and under Xvfb the real window (a screenshot of it shows
// the box the CSV says) and the picker (a synthetic mouse drag gives the box dragged, in a
// 1280x720 video's own pixels though the picker shows it at 640x360).
// Every wait polls an observable condition with a bound; no sleep synchronises.
#include <catch2/catch.hpp>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "MovingRectVideo.hpp"
#include "Process.hpp"
#include "Skip.hpp"
#include "TempDir.hpp"
#include "TestPrograms.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;
using namespace cuetrack::test;

namespace {

constexpr int kAppTimeoutMs = 120000;  // generous: 2 cores shared by many builds

bool contains(const std::string& s, const char* part) {
  return s.find(part) != std::string::npos;
}

// Runs argv to completion; its exit status (-1 when it did not end in time).
int run(std::vector<const char*> argv, const std::string& out, const std::string& err,
        int timeoutMs = kAppTimeoutMs) {
  argv.push_back(nullptr);
  const int status = runToEnd(argv.data(), out.c_str(), err.c_str(), timeoutMs);
  REQUIRE(status != kRunNotStarted);
  return status;
}

// The tool's path, or "" when it is not installed.
std::string onPath(const char* tool) {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"}) {
    const std::string path = std::string(dir) + "/" + tool;
    if (access(path.c_str(), X_OK) == 0) return path;
  }
  return "";
}

// The first frame of a generated scene, as cuetrack sees it.
cv::Mat sceneFrame(const char* scene) {
  SceneSpec spec;
  REQUIRE(makeScene(scene, &spec));
  auto source = std::make_unique<SyntheticSource>(spec, 1);
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(source->next(*slot) == ReadStatus::Ok);
  cv::Mat bgr(slot->rgb.height(), slot->rgb.width(), CV_8UC3);
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const Rgb8 p = slot->rgb.view().at(x, y);
      bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(p.b, p.g, p.r);
    }
  return bgr;
}

// An X virtual frame buffer on a free display; -displayfd names it once it is ready.
class Xvfb {
 public:
  explicit Xvfb(const TempDir& tmp) : _log(tmp.file("xvfb.out")) {}
  ~Xvfb() {
    if (_server.running()) {
      _server.signal(SIGTERM);
      int status = 0;
      _server.wait(10000, &status);
    }
  }
  bool start(const char* xvfb) {
    // -noreset: a server that resets when its last client leaves (cuetrack's display
    // probe) refused the window that followed now and then (scripts/docs-images.sh).
    const char* argv[] = {xvfb,          "-displayfd", "1",   "-screen",  "0",
                          "1280x800x24", "-nolisten",  "tcp", "-noreset", nullptr};
    if (!_server.start(argv, _log.c_str(), nullptr)) return false;
    // The display number, followed by a newline, once the server accepts clients.
    if (!waitFor([&] { return contains(slurp(_log), "\n") || !_server.running(); }, 30000))
      return false;
    const std::string n = slurp(_log);
    if (n.empty() || n.back() != '\n') return false;
    _display = ":" + n.substr(0, n.size() - 1);
    setenv("DISPLAY", _display.c_str(), 1);
    return true;
  }

 private:
  std::string _log;
  std::string _display;
  ChildProcess _server;
};

// An X window dump (xwd, ZPixmap, 24 or 32 bits per pixel, LSB first) as BGR.
cv::Mat readXwd(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {};
  std::vector<uint8_t> d;
  uint8_t buf[65536];
  size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) d.insert(d.end(), buf, buf + n);
  std::fclose(f);
  if (d.size() < 100) return {};
  auto be = [&](size_t at) {
    return (uint32_t{d[at]} << 24) | (uint32_t{d[at + 1]} << 16) | (uint32_t{d[at + 2]} << 8) |
           d[at + 3];
  };
  const uint32_t headerSize = be(0), width = be(16), height = be(20), byteOrder = be(28);
  const uint32_t bitsPerPixel = be(44), bytesPerLine = be(48), colours = be(76);
  const size_t start = headerSize + static_cast<size_t>(colours) * 12;
  if ((bitsPerPixel != 24 && bitsPerPixel != 32) || byteOrder != 0 ||
      d.size() < start + static_cast<size_t>(bytesPerLine) * height)
    return {};
  cv::Mat out(static_cast<int>(height), static_cast<int>(width), CV_8UC3);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const uint8_t* p = &d[start + y * bytesPerLine + x * (bitsPerPixel / 8)];
      out.at<cv::Vec3b>(static_cast<int>(y), static_cast<int>(x)) = cv::Vec3b(p[0], p[1], p[2]);
    }
  return out;
}

// The bounding rectangle of the pixels of exactly `colour` inside `area`.
cv::Rect pixelsOf(const cv::Mat& img, cv::Vec3b colour, cv::Rect area) {
  int x0 = INT32_MAX, y0 = INT32_MAX, x1 = -1, y1 = -1;
  area &= cv::Rect(0, 0, img.cols, img.rows);
  for (int y = area.y; y < area.y + area.height; ++y)
    for (int x = area.x; x < area.x + area.width; ++x)
      if (img.at<cv::Vec3b>(y, x) == colour) {
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x);
        y1 = std::max(y1, y);
      }
  return x1 < 0 ? cv::Rect() : cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
}

// The last CSV row's box (x, y, w, h) and its row count.
bool lastCsvBox(const std::string& csv, cv::Rect* box, size_t* rows) {
  std::vector<std::string> ls = lines(slurp(csv));
  while (!ls.empty() && ls.back().empty()) ls.pop_back();
  if (ls.size() < 2) return false;
  *rows = ls.size() - 1;
  int seq = 0, x = 0, y = 0, w = 0, h = 0;
  unsigned long long t = 0;
  char state[32];
  if (std::sscanf(ls.back().c_str(), "%d,%llu,%31[^,],%d,%d,%d,%d", &seq, &t, state, &x, &y, &w,
                  &h) != 7)
    return false;
  *box = cv::Rect(x, y, w, h);
  return true;
}

// Runs an X tool to completion; true when it exited 0.
bool xtool(std::vector<const char*> argv, const TempDir& tmp) {
  return run(std::move(argv), tmp.file("xtool.out"), tmp.file("xtool.err"), 30000) == 0;
}

// Waits for the picker's window, drags the mouse from (x0, y0) through the middle to
// (x1, y1) in it, and accepts with Return. The key goes to the focused window through
// XTEST: naming the window would race with its closing.
bool dragInPicker(const char* xdotool, const TempDir& tmp, int x0, int y0, int x1, int y1) {
  if (!xtool({xdotool, "search", "--sync", "--onlyvisible", "--name", "drag a box"}, tmp))
    return false;
  const std::vector<std::string> found = lines(slurp(tmp.file("xtool.out")));
  if (found.empty()) return false;
  const std::string id = found[0];
  const std::string p[6] = {std::to_string(x0),
                            std::to_string(y0),
                            std::to_string((x0 + x1) / 2),
                            std::to_string((y0 + y1) / 2),
                            std::to_string(x1),
                            std::to_string(y1)};
  const char* w = id.c_str();
  return xtool({xdotool, "windowfocus", "--sync", w}, tmp) &&
         xtool({xdotool,      "mousemove",  "--window",   w,           "--sync",   p[0].c_str(),
                p[1].c_str(), "mousedown",  "1",          "mousemove", "--window", w,
                "--sync",     p[2].c_str(), p[3].c_str(), "mousemove", "--window", w,
                "--sync",     p[4].c_str(), p[5].c_str(), "mouseup",   "1"},
               tmp) &&
         xtool({xdotool, "key", "Return"}, tmp);
}

}  // namespace

TEST_CASE("a run prints a banner (source and why, target) and a summary with next steps") {
  TempDir tmp;
  const std::string out = tmp.file("out.txt"), err = tmp.file("err.txt");
  REQUIRE(run({CUETRACK_APP_BIN, "--source", "synth:moving", "--frames", "20"}, out, err) == 0);
  const std::vector<std::string> e = lines(slurp(err));
  REQUIRE(e.size() >= 4);
  CHECK(contains(e[0], "cuetrack: source synth:moving"));
  CHECK(contains(e[0], "target: ground truth"));
  CHECK(contains(slurp(err), "summary: 20 frames in "));
  CHECK(contains(slurp(err), "tracked 20/20 (100%)"));
  CHECK(contains(slurp(err), "ground-truth mean overlap"));
  CHECK(contains(slurp(err), "next: "));
  CHECK(lines(slurp(out)).size() == 20);  // stdout is a file, not a terminal: every frame

  // The default source says why it was chosen; a box from --box is named as such.
  REQUIRE(run({CUETRACK_APP_BIN, "--frames", "5", "--box", "291,266,30,52"}, out, err) == 0);
  CHECK(contains(slurp(err), "a generated scene ("));
  CHECK(contains(slurp(err), "target: --box 291,266,30,52"));
}

TEST_CASE("a box on the floor is warned about in one line; the true target is not") {
  TempDir tmp;
  const std::string out = tmp.file("out.txt"), err = tmp.file("err.txt");
  REQUIRE(
      run({CUETRACK_APP_BIN, "--source", "synth:moving", "--frames", "3", "--box", "400,420,40,40"},
          out, err) == 0);
  CHECK(contains(slurp(err), "cuetrack: --box 400,420,40,40: poor target: "));
  CHECK(contains(slurp(err), "looks like its surroundings"));
  REQUIRE(
      run({CUETRACK_APP_BIN, "--source", "synth:moving", "--frames", "3", "--box", "291,266,30,52"},
          out, err) == 0);
  CHECK_FALSE(contains(slurp(err), "poor target"));

  // A box on the untextured scene's plain wall: flagged, and reported lost within the lost
  // detector's 4 misses (PeakContrast: it does not stand out from the windows beside it).
  REQUIRE(run({CUETRACK_APP_BIN, "--source", "synth:untextured", "--frames", "30", "--box",
               "100,300,40,40"},
              out, err) == 0);
  CHECK(contains(slurp(err), "--box 100,300,40,40: poor target"));
  const std::vector<std::string> track = lines(slurp(out));
  REQUIRE(track.size() == 30);
  int firstLost = -1, trackingAfter = 0;
  for (size_t i = 0; i < track.size(); ++i) {
    const bool lost = contains(track[i], " lost ");
    if (lost && firstLost < 0) firstLost = static_cast<int>(i);
    if (firstLost >= 0 && contains(track[i], " tracking ")) ++trackingAfter;
  }
  INFO("first lost line " << firstLost << ", tracking lines after it " << trackingAfter);
  CHECK(firstLost >= 1);
  CHECK(firstLost <= 5);
  CHECK(trackingAfter <= 2);
}

TEST_CASE("--snapshot writes the first frame with a 40 px grid, at the frame's size") {
  TempDir tmp;
  const std::string png = tmp.file("snap.png"), out = tmp.file("out.txt"),
                    err = tmp.file("err.txt");
  const int rc =
      run({CUETRACK_APP_BIN, "--source", "synth:moving", "--snapshot", png.c_str()}, out, err);
  if (rc == 3 && contains(slurp(err), "not built with OpenCV")) CUETRACK_SKIP("no OpenCV");
  REQUIRE(rc == 0);
  CHECK(contains(slurp(err), "grid every 40 px"));
  CHECK(slurp(out).empty());  // no tracking ran
  const cv::Mat snap = cv::imread(png, cv::IMREAD_COLOR);
  const cv::Mat frame = sceneFrame("moving");
  REQUIRE(!snap.empty());
  REQUIRE(snap.size() == frame.size());
  const cv::Vec3b gridColour(0, 255, 255);
  // Every grid line is drawn over the whole frame (labels cover a few pixels of it).
  for (int x = 40; x < snap.cols; x += 40) {
    int onLine = 0;
    for (int y = 0; y < snap.rows; ++y) onLine += snap.at<cv::Vec3b>(y, x) == gridColour;
    CHECK(onLine > snap.rows * 9 / 10);
  }
  for (int y = 40; y < snap.rows; y += 40) {
    int onLine = 0;
    for (int x = 0; x < snap.cols; ++x) onLine += snap.at<cv::Vec3b>(y, x) == gridColour;
    CHECK(onLine > snap.cols * 9 / 10);
  }
  // Between the lines and away from the labels it is the frame itself, pixel for pixel.
  int differ = 0, looked = 0;
  for (int y = 20; y < snap.rows; ++y)
    for (int x = 40; x < snap.cols; ++x) {
      if (x % 40 == 0 || y % 40 == 0 || (x % 40) < 30 && (y % 40) < 12) continue;
      ++looked;
      differ += snap.at<cv::Vec3b>(y, x) != frame.at<cv::Vec3b>(y, x);
    }
  CHECK(differ < looked / 100);  // antialiased label edges at most

  // --snapshot tracks nothing: it needs no way to a target (--no-gt, or a live camera).
  REQUIRE(run({CUETRACK_APP_BIN, "--source", "synth:moving", "--no-gt", "--snapshot", png.c_str()},
              out, err) == 0);

  // A path that cannot be written: one line naming it, exit 3.
  REQUIRE(run({CUETRACK_APP_BIN, "--source", "synth:moving", "--snapshot", "/nonexistent/x.png"},
              out, err) == 3);
  const std::string e = slurp(err);
  CHECK(std::count(e.begin(), e.end(), '\n') == 1);
  CHECK(contains(slurp(err), "/nonexistent/x.png"));
}

TEST_CASE("--video writes every frame with its track drawn; OpenCV reads it back") {
  TempDir tmp;
  const std::string avi = tmp.file("run.avi"), csv = tmp.file("t.csv"), err = tmp.file("err.txt");
  const int rc = run({CUETRACK_APP_BIN, "--source", "synth:occlusion", "--frames", "40", "--video",
                      avi.c_str(), "--out", csv.c_str()},
                     tmp.file("out.txt"), err);
  if (rc == 3 && contains(slurp(err), "not built with OpenCV")) CUETRACK_SKIP("no OpenCV");
  REQUIRE(rc == 0);
  CHECK(contains(slurp(err), ("wrote " + avi + ": 40 frames").c_str()));
  const std::vector<std::string> rows = lines(slurp(csv));
  REQUIRE(rows.size() >= 41);
  cv::VideoCapture video(avi);
  REQUIRE(video.isOpened());
  cv::Mat frame;
  int n = 0;
  while (video.read(frame)) {
    // Colour and depth side by side, a text strip under them.
    CHECK(frame.cols == 2 * 640);
    CHECK(frame.rows > 480);
    if (n == 30) {  // the box drawn is the box sent (JPEG: near-green, not exact)
      int seq = 0, x = 0, y = 0, w = 0, h = 0;
      unsigned long long t = 0;
      char state[32];
      REQUIRE(std::sscanf(rows[31].c_str(), "%d,%llu,%31[^,],%d,%d,%d,%d", &seq, &t, state, &x, &y,
                          &w, &h) == 7);
      REQUIRE(std::string(state) == "tracking");
      int x0 = 9999, y0 = 9999, x1 = -1, y1 = -1;
      for (int py = 0; py < 480; ++py)
        for (int px = 0; px < 640; ++px) {
          const cv::Vec3b p = frame.at<cv::Vec3b>(py, px);
          if (p[1] > 170 && p[0] < 90 && p[2] < 90) {
            x0 = std::min(x0, px);
            y0 = std::min(y0, py);
            x1 = std::max(x1, px);
            y1 = std::max(y1, py);
          }
        }
      INFO("drawn " << x0 << "," << y0 << " to " << x1 << "," << y1 << "; sent " << x << "," << y
                    << "," << w << "," << h);
      CHECK(std::abs(x0 - (x - 1)) <= 2);
      CHECK(std::abs(y0 - (y - 1)) <= 2);
      CHECK(std::abs(x1 - (x + w)) <= 2);
      CHECK(std::abs(y1 - (y + h)) <= 2);
    }
    ++n;
  }
  CHECK(n == 40);

  // A file that cannot be written: one line naming it, before any tracking, exit 3.
  REQUIRE(run({CUETRACK_APP_BIN, "--frames", "5", "--video", "/nonexistent/x.avi"},
              tmp.file("out.txt"), err) == 3);
  const std::string e = slurp(err);
  CHECK(e == "cuetrack: --video /nonexistent/x.avi: cannot write: No such file or directory\n");
}

TEST_CASE("--show and --select without a display fail in one line, exit 2 (usage)") {
  TempDir tmp;
  const std::string out = tmp.file("out.txt"), err = tmp.file("err.txt");
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  unsetenv("DISPLAY");
  for (const char* opt : {"--show", "--select"}) {
    INFO(opt);
    CHECK(run({CUETRACK_APP_BIN, "--source", "synth:moving", "--frames", "5", opt}, out, err) == 2);
    const std::string e = slurp(err);
    CHECK(std::count(e.begin(), e.end(), '\n') == 1);
    CHECK(contains(e, opt));
    CHECK((contains(e, "DISPLAY") || contains(e, "not built with OpenCV")));
    CHECK(slurp(out).empty());
  }
  // A display named but not there: Qt would abort the process; we say so in one line.
  setenv("DISPLAY", ":4093", 1);
  CHECK(run({CUETRACK_APP_BIN, "--source", "synth:moving", "--frames", "5", "--show"}, out, err) ==
        2);
  const std::string e = slurp(err);
  CHECK(std::count(e.begin(), e.end(), '\n') == 1);
  CHECK((contains(e, "cannot connect to display :4093") || contains(e, "not built with OpenCV")));
  if (saved.empty()) {
    unsetenv("DISPLAY");
  } else {
    setenv("DISPLAY", saved.c_str(), 1);
  }
}

TEST_CASE("under Xvfb: --show draws the box the CSV reports; space pauses, q quits") {
  const std::string xvfbPath = onPath("Xvfb"), xdotoolPath = onPath("xdotool"),
                    xwdPath = onPath("xwd");
  const char *xvfb = xvfbPath.c_str(), *xdotool = xdotoolPath.c_str(), *xwd = xwdPath.c_str();
  if (!*xvfb || !*xdotool || !*xwd)
    CUETRACK_SKIP("Xvfb, xdotool or xwd missing (scripts/setup.sh)");
  TempDir tmp;
  Xvfb x(tmp);
  REQUIRE(x.start(xvfb));
  const std::string csv = tmp.file("t.csv"), err = tmp.file("err.txt");
  const char* argv[] = {CUETRACK_APP_BIN, "--source", "synth:moving", "--frames",  "100000",
                        "--realtime",     "--show",   "--out",        csv.c_str(), nullptr};
  ChildProcess app;
  REQUIRE(app.start(argv, nullptr, err.c_str()));
  REQUIRE(xtool({xdotool, "search", "--sync", "--onlyvisible", "--name", "^cuetrack$"}, tmp));
  const std::string id = lines(slurp(tmp.file("xtool.out")))[0];
  REQUIRE(xtool({xdotool, "windowfocus", "--sync", id.c_str()}, tmp));
  REQUIRE(xtool({xdotool, "key", "space"}, tmp));

  // Paused: the CSV stops growing and the window shows its last row's box.
  const std::string dump = tmp.file("win.xwd");
  cv::Rect drawn, reported;
  size_t rows = 0;
  const bool shown = waitFor(
      [&] {
        size_t before = 0;
        cv::Rect box;
        if (!lastCsvBox(csv, &box, &before)) return false;
        if (!xtool({xwd, "-silent", "-id", id.c_str(), "-out", dump.c_str()}, tmp)) return false;
        const cv::Mat win = readXwd(dump);
        if (!lastCsvBox(csv, &reported, &rows) || rows != before || reported != box) return false;
        if (win.cols < 640 || win.rows < 480) return false;
        // The tracking box is drawn 2 px wide in pure green over the colour image.
        drawn = pixelsOf(win, cv::Vec3b(0, 220, 0), cv::Rect(0, 0, 640, 480));
        return std::abs(drawn.x - (reported.x - 1)) <= 2 &&
               std::abs(drawn.y - (reported.y - 1)) <= 2 &&
               std::abs(drawn.width - (reported.width + 1)) <= 3 &&
               std::abs(drawn.height - (reported.height + 1)) <= 3;
      },
      60000);
  INFO("drawn " << drawn << " reported " << reported << " after " << rows << " rows");
  CHECK(shown);
  CHECK(app.running());  // paused, not ended

  // r: drag a new box (here: around the box reported, 4 px larger); the run resumes and
  // starts again on it, with full confidence.
  const cv::Rect pick(reported.x - 4, reported.y - 4, reported.width + 8, reported.height + 8);
  const std::string x0 = std::to_string(pick.x), y0 = std::to_string(pick.y);
  const std::string x1 = std::to_string(pick.x + pick.width),
                    y1 = std::to_string(pick.y + pick.height);
  REQUIRE(xtool({xdotool, "key", "r"}, tmp));
  REQUIRE(xtool(
      {xdotool, "mousemove", "--window", id.c_str(), "--sync", x0.c_str(), y0.c_str(), "mousedown",
       "1", "mousemove", "--window", id.c_str(), "--sync", x1.c_str(), y1.c_str(), "mouseup", "1"},
      tmp));
  REQUIRE(xtool({xdotool, "key", "Return"}, tmp));
  char row[96];
  std::snprintf(row, sizeof row, ",tracking,%d,%d,%d,%d,", pick.x, pick.y, pick.width, pick.height);
  CHECK(waitFor([&] { return contains(slurp(csv), row); }, 60000));
  char line[96];
  std::snprintf(line, sizeof line, "re-selected --box %d,%d,%d,%d", pick.x, pick.y, pick.width,
                pick.height);
  CHECK(contains(slurp(err), line));
  REQUIRE(xtool({xdotool, "key", "q"}, tmp));
  int status = -1;
  REQUIRE(app.wait(kAppTimeoutMs, &status));
  CHECK(status == 0);
  CHECK(contains(slurp(err), "(window closed)"));
  CHECK(contains(slurp(err), "summary: "));
}

TEST_CASE("under Xvfb: --select takes the box a mouse drag draws, with and without --show") {
  const std::string xvfbPath = onPath("Xvfb"), xdotoolPath = onPath("xdotool");
  const char *xvfb = xvfbPath.c_str(), *xdotool = xdotoolPath.c_str();
  if (!*xvfb || !*xdotool) CUETRACK_SKIP("Xvfb or xdotool missing (scripts/setup.sh)");
  TempDir tmp;
  Xvfb x(tmp);
  REQUIRE(x.start(xvfb));
  // With --show, the picker runs on the window's thread (one highgui thread per process).
  for (const bool show : {false, true}) {
    INFO("--show " << show);
    const std::string csv = tmp.file(show ? "show.csv" : "t.csv"), err = tmp.file("err.txt");
    const char* argv[] = {CUETRACK_APP_BIN, "--source",  "synth:moving",
                          "--frames",       "5",         "--select",
                          "--out",          csv.c_str(), show ? "--show" : nullptr,
                          nullptr};
    ChildProcess app;
    REQUIRE(app.start(argv, nullptr, err.c_str()));
    // The target of synth:moving's first frame is at about 291,266,30,52.
    REQUIRE(dragInPicker(xdotool, tmp, 290, 265, 322, 319));
    int status = -1;
    REQUIRE(app.wait(kAppTimeoutMs, &status));
    CHECK(status == 0);
    const std::string e = slurp(err);
    CHECK(contains(e, "cuetrack: picked --box 290,265,32,54"));
    CHECK(contains(e, "target: the box dragged with --select"));
    CHECK_FALSE(contains(e, "poor target"));
    const std::vector<std::string> rows = lines(slurp(csv));
    REQUIRE(rows.size() >= 2);
    CHECK(contains(rows[1], ",tracking,290,265,32,54,"));  // the first frame is the picked one
  }
}

TEST_CASE("under Xvfb: Ctrl-C while the picker is open stops cleanly, with its final line") {
  const std::string xvfbPath = onPath("Xvfb"), xdotoolPath = onPath("xdotool");
  const char *xvfb = xvfbPath.c_str(), *xdotool = xdotoolPath.c_str();
  if (!*xvfb || !*xdotool) CUETRACK_SKIP("Xvfb or xdotool missing (scripts/setup.sh)");
  TempDir tmp;
  Xvfb x(tmp);
  REQUIRE(x.start(xvfb));
  for (const bool show : {false, true}) {
    INFO("--show " << show);
    const std::string err = tmp.file("err.txt");
    const char* argv[] = {CUETRACK_APP_BIN,          "--source", "synth:moving", "--select",
                          show ? "--show" : nullptr, nullptr};
    ChildProcess app;
    REQUIRE(app.start(argv, tmp.file("out.txt").c_str(), err.c_str()));
    REQUIRE(xtool({xdotool, "search", "--sync", "--onlyvisible", "--name", "drag a box"}, tmp));
    app.signal(SIGINT);
    int status = -1;
    REQUIRE(app.wait(30000, &status));  // the picker polls the signal flag: no key needed
    CHECK(status == 0);
    CHECK(slurp(err).find("stopped after 0 frames (signal, while --select was open)") !=
          std::string::npos);
  }
}

TEST_CASE("a target that leaves: the CSV holds the last confirmed box, the video draws none") {
  TempDir tmp;
  const std::string avi = tmp.file("run.avi"), csv = tmp.file("t.csv");
  REQUIRE(run({CUETRACK_APP_BIN, "--source", "synth:leave-return", "--frames", "60", "--video",
               avi.c_str(), "--out", csv.c_str()},
              tmp.file("out.txt"), tmp.file("err.txt")) == 0);
  const std::vector<std::string> rows = lines(slurp(csv));
  REQUIRE(rows.size() >= 61);
  int firstLost = -1;
  cv::Rect confirmed;
  for (size_t i = 1; i <= 60; ++i) {
    const std::string& row = rows[i];
    char state[32];
    int seq = 0, x = 0, y = 0, w = 0, h = 0;
    unsigned long long t = 0;
    REQUIRE(std::sscanf(row.c_str(), "%d,%llu,%31[^,],%d,%d,%d,%d", &seq, &t, state, &x, &y, &w,
                        &h) == 7);
    const size_t last = row.rfind(','), occludedAt = row.rfind(',', last - 1) + 1;
    const bool occluded = row[occludedAt] == '1';  // ...,occluded,depth_predicted
    if (std::string(state) == "tracking" && !occluded) confirmed = cv::Rect(x, y, w, h);
    if (std::string(state) == "lost" || std::string(state) == "searching") {
      if (firstLost < 0) firstLost = static_cast<int>(i) - 1;
      INFO("row " << i << ": " << row);
      CHECK(cv::Rect(x, y, w, h) == confirmed);  // never the search's box
    }
  }
  REQUIRE(firstLost > 0);  // the scene loses it within 60 frames
  // The video's frame there: no box where the CSV's box is, "target lost" in red on the image.
  cv::VideoCapture video(avi);
  REQUIRE(video.isOpened());
  // The label's corner: red pixels (JPEG-blurred text) there while lost, none before.
  auto redInCorner = [](const cv::Mat& f) {
    int n = 0;
    for (int py = 0; py < 28; ++py)
      for (int px = 0; px < 120; ++px) {
        const cv::Vec3b p = f.at<cv::Vec3b>(py, px);
        n += p[2] > 180 && p[1] < 80 && p[0] < 80;
      }
    return n;
  };
  cv::Mat frame;
  REQUIRE(video.read(frame));
  CHECK(redInCorner(frame) == 0);
  for (int i = 1; i <= firstLost; ++i) REQUIRE(video.read(frame));
  int green = 0;
  for (int py = confirmed.y - 2; py <= confirmed.y + confirmed.height + 2; ++py)
    for (int px : {confirmed.x - 1, confirmed.x + confirmed.width}) {
      const cv::Vec3b p = frame.at<cv::Vec3b>(py, px);
      green += p[1] > 170 && p[0] < 90 && p[2] < 90;
    }
  CHECK(green == 0);
  CHECK(redInCorner(frame) > 10);
}

TEST_CASE("under Xvfb: --select on a 1280x720 video picks a box in the video's pixels") {
  const std::string xvfbPath = onPath("Xvfb"), xdotoolPath = onPath("xdotool");
  const char *xvfb = xvfbPath.c_str(), *xdotool = xdotoolPath.c_str();
  if (!*xvfb || !*xdotool) CUETRACK_SKIP("Xvfb or xdotool missing (scripts/setup.sh)");
  TempDir tmp;
  const std::string avi = tmp.file("hd.avi"), csv = tmp.file("t.csv"), err = tmp.file("err.txt");
  REQUIRE(writeMovingRectVideo(avi, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 1280, 720, 3));
  Xvfb x(tmp);
  REQUIRE(x.start(xvfb));
  const char* argv[] = {CUETRACK_APP_BIN, "--source",  avi.c_str(), "--select",
                        "--out",          csv.c_str(), nullptr};
  ChildProcess app;
  REQUIRE(app.start(argv, nullptr, err.c_str()));
  // The picker shows the frame as the tracker sees it, 640x360: a drag over 360,110 to
  // 420,200 there is 720,220 to 840,400 in the video (the rectangle is at 704,216,213,180).
  REQUIRE(dragInPicker(xdotool, tmp, 360, 110, 420, 200));
  int status = -1;
  REQUIRE(app.wait(kAppTimeoutMs, &status));
  CHECK(status == 0);
  const std::string e = slurp(err);
  INFO(e);
  CHECK(contains(e, "cuetrack: picked --box 720,220,120,180"));
  const std::vector<std::string> rows = lines(slurp(csv));
  REQUIRE(rows.size() >= 2);
  CHECK(contains(rows[1], ",tracking,720,220,120,180,"));
}
