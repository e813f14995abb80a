#include "Outputs.hpp"

#include <algorithm>

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "Runner.hpp"

namespace cuetrack::bench {
namespace {

bool closeChecked(FILE* f, const std::string& path, std::string* err) {
  const bool bad = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || bad) {
    *err = path + ": write failed: " + std::strerror(errno);
    return false;
  }
  return true;
}

FILE* openForWrite(const std::string& path, std::string* err) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) *err = path + ": cannot write: " + std::strerror(errno);
  return f;
}

// Distinct colours (BGR) for up to 12 curves; cuetrack entries come first.
const cv::Scalar kPalette[] = {{40, 40, 220},  {200, 90, 30},  {40, 160, 40}, {160, 40, 160},
                               {20, 140, 220}, {140, 140, 20}, {90, 90, 90},  {200, 160, 120},
                               {120, 60, 200}, {60, 200, 200}, {30, 90, 140}, {180, 30, 100}};

}  // namespace

std::string fileLabel(const EntryResult& e) {
  return e.config == "default" || e.config.empty() ? e.tracker : e.tracker + "-" + e.config;
}

bool makeDirs(const std::string& path, std::string* err) {
  std::string partial;
  for (size_t i = 0; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/') {
      if (!partial.empty() && ::mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST) {
        *err = partial + ": cannot create folder: " + std::strerror(errno);
        return false;
      }
    }
    if (i < path.size()) partial += path[i];
  }
  return true;
}

bool writeOverlapCsv(const std::string& path, const std::vector<EntryResult>& entries,
                     size_t sequence, std::string* err) {
  FILE* f = openForWrite(path, err);
  if (!f) return false;
  // Frames: those of the first entry that ran (all entries evaluate the same frames).
  const SequenceResult* ref = nullptr;
  std::fprintf(f, "frame");
  for (const EntryResult& e : entries) {
    std::fprintf(f, ",%s", e.label().c_str());
    const SequenceResult& s = e.sequences[sequence];
    if (!ref && s.ran) ref = &s;
  }
  std::fprintf(f, "\n");
  for (size_t i = 0; ref && i < ref->frameIndex.size(); ++i) {
    std::fprintf(f, "%d", ref->frameIndex[i]);
    for (const EntryResult& e : entries) {
      const SequenceResult& s = e.sequences[sequence];
      if (s.ran && i < s.meanOverlap.size())
        std::fprintf(f, ",%.4f", s.meanOverlap[i]);
      else
        std::fprintf(f, ",");
    }
    std::fprintf(f, "\n");
  }
  return closeChecked(f, path, err);
}

bool writeOverlapPlot(const std::string& path, const std::vector<EntryResult>& entries,
                      size_t sequence, std::string* err) {
  const int width = 900, height = 340;
  const int left = 50, right = 200, top = 30, bottom = 40;  // margins [px]
  const int plotW = width - left - right, plotH = height - top - bottom;
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));

  int maxFrame = 1;
  for (const EntryResult& e : entries) {
    const SequenceResult& s = e.sequences[sequence];
    if (s.ran)  // not the last frame's index: a --reverse'd sequence ends at its smallest
      for (const int index : s.frameIndex) maxFrame = std::max(maxFrame, index);
  }
  auto px = [&](double frame, double overlapValue) {
    return cv::Point(left + static_cast<int>(frame / maxFrame * plotW),
                     top + static_cast<int>((1.0 - overlapValue) * plotH));
  };
  const cv::Scalar grid(225, 225, 225), axis(0, 0, 0);
  for (int i = 0; i <= 4; ++i) {
    const double v = i * 0.25;
    cv::line(img, px(0, v), px(maxFrame, v), grid, 1);
    char buf[16];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    cv::putText(img, buf, px(0, v) + cv::Point(-45, 4), cv::FONT_HERSHEY_SIMPLEX, 0.4, axis, 1,
                cv::LINE_AA);
  }
  for (int i = 0; i <= 5; ++i) {
    const int frame = maxFrame * i / 5;
    char buf[16];
    std::snprintf(buf, sizeof buf, "%d", frame);
    cv::putText(img, buf, px(frame, 0) + cv::Point(-10, 18), cv::FONT_HERSHEY_SIMPLEX, 0.4, axis, 1,
                cv::LINE_AA);
  }
  cv::rectangle(img, px(0, 1), px(maxFrame, 0), axis, 1);
  cv::putText(img, "frame", cv::Point(left + plotW / 2 - 20, height - 6), cv::FONT_HERSHEY_SIMPLEX,
              0.45, axis, 1, cv::LINE_AA);
  std::string title = "overlap: ";
  for (const EntryResult& e : entries)
    if (!e.sequences[sequence].name.empty()) {
      title += e.sequences[sequence].name;
      break;
    }
  cv::putText(img, title, cv::Point(left, 20), cv::FONT_HERSHEY_SIMPLEX, 0.55, axis, 1,
              cv::LINE_AA);

  int curve = 0;
  for (const EntryResult& e : entries) {
    const SequenceResult& s = e.sequences[sequence];
    const cv::Scalar colour = kPalette[curve % (sizeof kPalette / sizeof kPalette[0])];
    const int legendY = top + 14 + 16 * curve;
    ++curve;
    std::string label = e.label();
    if (!s.ran) label += " (cannot run)";
    cv::line(img, cv::Point(width - right + 10, legendY - 4),
             cv::Point(width - right + 30, legendY - 4), colour, 2);
    cv::putText(img, label, cv::Point(width - right + 35, legendY), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                axis, 1, cv::LINE_AA);
    if (!s.ran) continue;
    for (size_t i = 1; i < s.frameIndex.size(); ++i)
      cv::line(img, px(s.frameIndex[i - 1], s.meanOverlap[i - 1]),
               px(s.frameIndex[i], s.meanOverlap[i]), colour, 1, cv::LINE_AA);
  }
  try {
    if (cv::imwrite(path, img)) return true;
    *err = path + ": cannot write PNG";
  } catch (const cv::Exception& e) {
    *err = path + ": cannot write PNG: " + e.what();
  }
  return false;
}

bool writeCurvePlot(const std::string& path, const std::vector<EntryResult>& entries,
                    CurveKind kind, std::string* err) {
  const bool success = kind == CurveKind::Success;
  const int width = 640, height = 400;
  const int left = 50, right = 230, top = 30, bottom = 40;  // margins [px]
  const int plotW = width - left - right, plotH = height - top - bottom;
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const double xMax = success ? 1.0 : kPrecisionSteps - 1;
  auto px = [&](double x, double y) {
    return cv::Point(left + static_cast<int>(x / xMax * plotW),
                     top + static_cast<int>((1.0 - y) * plotH));
  };
  const cv::Scalar grid(225, 225, 225), axis(0, 0, 0);
  char buf[96];
  for (int i = 0; i <= 5; ++i) {
    const double v = i * 0.2;
    cv::line(img, px(0, v), px(xMax, v), grid, 1);
    std::snprintf(buf, sizeof buf, "%.1f", v);
    cv::putText(img, buf, px(0, v) + cv::Point(-35, 4), cv::FONT_HERSHEY_SIMPLEX, 0.4, axis, 1,
                cv::LINE_AA);
    const double x = xMax * i / 5;
    std::snprintf(buf, sizeof buf, success ? "%.1f" : "%.0f", x);
    cv::putText(img, buf, px(x, 0) + cv::Point(-8, 18), cv::FONT_HERSHEY_SIMPLEX, 0.4, axis, 1,
                cv::LINE_AA);
  }
  cv::rectangle(img, px(0, 1), px(xMax, 0), axis, 1);
  cv::putText(img, success ? "overlap threshold" : "location error threshold [px]",
              cv::Point(left + plotW / 2 - 70, height - 6), cv::FONT_HERSHEY_SIMPLEX, 0.45, axis, 1,
              cv::LINE_AA);
  int ranMin = 0;
  for (const EntryResult& e : entries) ranMin = std::max(ranMin, e.sequencesRan());
  std::snprintf(buf, sizeof buf, "%s plots of OPE, mean of %d sequences",
                success ? "Success" : "Precision", ranMin);
  cv::putText(img, buf, cv::Point(left, 20), cv::FONT_HERSHEY_SIMPLEX, 0.55, axis, 1, cv::LINE_AA);

  // Legend in the field's order: best figure first.
  std::vector<size_t> order;
  for (size_t i = 0; i < entries.size(); ++i)
    if (entries[i].sequencesRan() > 0) order.push_back(i);
  auto figure = [&](size_t i) {
    const Figures a = entries[i].average();
    return success ? a.auc : a.precision20;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return figure(a) > figure(b); });
  const size_t palette = sizeof kPalette / sizeof kPalette[0];
  for (size_t k = 0; k < order.size(); ++k) {
    const EntryResult& e = entries[order[k]];
    const Figures a = e.average();
    const cv::Scalar colour = kPalette[order[k] % palette];
    const int legendY = top + 14 + 16 * static_cast<int>(k);
    std::snprintf(buf, sizeof buf, "%s [%.1f]", e.label().c_str(), figure(order[k]));
    cv::line(img, cv::Point(width - right + 10, legendY - 4),
             cv::Point(width - right + 30, legendY - 4), colour, 2);
    cv::putText(img, buf, cv::Point(width - right + 35, legendY), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                axis, 1, cv::LINE_AA);
    const int steps = success ? kSuccessSteps : kPrecisionSteps;
    const double* y = success ? a.success : a.precision;
    for (int t = 1; t < steps; ++t) {
      const double x0 = success ? (t - 1) / double(steps - 1) : t - 1;
      const double x1 = success ? t / double(steps - 1) : t;
      cv::line(img, px(x0, y[t - 1]), px(x1, y[t]), colour, 2, cv::LINE_AA);
    }
  }
  std::snprintf(buf, sizeof buf, success ? "[AUC, %%]" : "[at %d px, %%]", kPrecisionAtPx);
  cv::putText(img, buf, cv::Point(width - right + 10, height - bottom), cv::FONT_HERSHEY_SIMPLEX,
              0.4, axis, 1, cv::LINE_AA);
  try {
    if (cv::imwrite(path, img)) return true;
    *err = path + ": cannot write PNG";
  } catch (const cv::Exception& e) {
    *err = path + ": cannot write PNG: " + e.what();
  }
  return false;
}

namespace {

constexpr int kLegendRowPx = 18;

// Frame i of the sequence with the ground truth (white) and each entry's first-run box (the
// plot's colours) drawn in, and under it a legend: the frame number, then one row per
// entry ("lost" where it had no box).
cv::Mat overlayImage(const Sequence& seq, size_t i, const std::vector<EntryResult>& entries,
                     size_t sequence) {
  const CachedFrame& f = seq.frames[i];
  const size_t palette = sizeof kPalette / sizeof kPalette[0];
  auto rect = [](const Box& b) {
    return cv::Rect(cvRound(b.x), cvRound(b.y), cvRound(b.w), cvRound(b.h));
  };
  const int rows = 1 + static_cast<int>(entries.size());
  cv::Mat img(f.bgr.rows + kLegendRowPx * rows + 4, f.bgr.cols, CV_8UC3, cv::Scalar(32, 32, 32));
  f.bgr.copyTo(img(cv::Rect(0, 0, f.bgr.cols, f.bgr.rows)));
  const bool truth = f.hasGroundTruth && !f.groundTruth.empty();
  if (truth) cv::rectangle(img, rect(f.groundTruth), cv::Scalar(255, 255, 255), 2);
  char line[256];
  std::snprintf(line, sizeof line, "frame %d   ground truth (white)%s", f.index,
                f.hasGroundTruth && !truth ? ": not visible" : "");
  int y = f.bgr.rows + kLegendRowPx - 4;
  cv::putText(img, line, {6, y}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(255, 255, 255), 1,
              cv::LINE_AA);
  for (size_t e = 0; e < entries.size(); ++e) {
    const SequenceResult& s = entries[e].sequences[sequence];
    const cv::Scalar colour = kPalette[e % palette];
    const bool hasBox = s.ran && i < s.firstRunBoxes.size() && !s.firstRunBoxes[i].empty();
    if (hasBox) cv::rectangle(img, rect(s.firstRunBoxes[i]), colour, 2);
    std::snprintf(line, sizeof line, "%s%s", entries[e].label().c_str(),
                  !s.ran   ? ": did not run"
                  : hasBox ? ""
                           : ": lost");
    y += kLegendRowPx;
    cv::line(img, {6, y - 4}, {26, y - 4}, colour, 2);
    cv::putText(img, line, {32, y}, cv::FONT_HERSHEY_SIMPLEX, 0.45, colour, 1, cv::LINE_AA);
  }
  return img;
}

}  // namespace

bool writeOverlayFrames(const std::string& dir, const Sequence& seq,
                        const std::vector<EntryResult>& entries, size_t sequence,
                        std::string* err) {
  if (!makeDirs(dir, err)) return false;
  for (size_t i = 0; i < seq.frames.size(); ++i) {
    const CachedFrame& f = seq.frames[i];
    if (f.bgr.empty()) continue;
    const cv::Mat img = overlayImage(seq, i, entries, sequence);
    char name[32];
    std::snprintf(name, sizeof name, "/%06d.jpg", f.index);
    const std::string path = dir + name;
    try {
      if (!cv::imwrite(path, img)) {
        *err = path + ": cannot write JPEG";
        return false;
      }
    } catch (const cv::Exception& ex) {
      *err = path + ": cannot write JPEG: " + ex.what();
      return false;
    }
  }
  return true;
}

bool writeOverlayVideo(const std::string& path, const Sequence& seq,
                       const std::vector<EntryResult>& entries, size_t sequence, double fps,
                       std::string* err) {
  cv::VideoWriter writer;
  cv::Size size;
  int written = 0;
  for (size_t i = 0; i < seq.frames.size(); ++i) {
    if (seq.frames[i].bgr.empty()) continue;
    const cv::Mat img = overlayImage(seq, i, entries, sequence);
    if (!writer.isOpened()) {
      FILE* probe = std::fopen(path.c_str(), "wb");  // the writer's own error says nothing
      if (!probe) {
        *err = path + ": cannot write: " + std::strerror(errno);
        return false;
      }
      std::fclose(probe);
      if (!writer.open(path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                       fps > 0.0 ? fps : 30.0, img.size())) {
        *err = path + ": cannot write Motion JPEG";
        return false;
      }
      size = img.size();
    }
    if (img.size() != size) {
      *err = path + ": the frames change size";
      return false;
    }
    writer.write(img);
    ++written;
  }
  writer.release();
  if (written == 0) {
    *err = path + ": no frame to write";
    return false;
  }
  return true;
}

bool writeBobotResult(const std::string& path, const std::string& header,
                      const std::vector<IndexedBox>& boxes, int imageWidth, int imageHeight,
                      std::string* err) {
  FILE* f = openForWrite(path, err);
  if (!f) return false;
  std::fprintf(f, "%s\n", header.c_str());
  const double sx = imageWidth > 0 ? 1.0 / imageWidth : 0.0;
  const double sy = imageHeight > 0 ? 1.0 / imageHeight : 0.0;
  for (const IndexedBox& b : boxes) {
    if (b.box.empty())
      std::fprintf(f, "%d 0 0 0 0\n", b.index);
    else
      std::fprintf(f, "%d %.6f %.6f %.6f %.6f\n", b.index, b.box.x * sx, b.box.y * sy, b.box.w * sx,
                   b.box.h * sy);
  }
  return closeChecked(f, path, err);
}

}  // namespace cuetrack::bench
