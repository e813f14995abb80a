// Files the bench writes besides the tables: per-frame overlaps (CSV), overlap-over-time
// plots like the paper's Fig. 5 (PNG, drawn with OpenCV imgproc), and result files
// in the BoBoT evaluator's format. Each returns false with one line in *err on failure.
#pragma once

#include <string>
#include <vector>

#include "Results.hpp"
#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::bench {

// One row per evaluated frame: frame,<entry label>,... (mean overlap over runs, 0-1).
bool writeOverlapCsv(const std::string& path, const std::vector<EntryResult>& entries,
                     size_t sequence, std::string* err);

// Overlap (0-1) over frames, one curve per entry that ran, with a legend.
bool writeOverlapPlot(const std::string& path, const std::vector<EntryResult>& entries,
                      size_t sequence, std::string* err);

// OTB's one-pass-evaluation plots over all sequences (the mean curves of each entry):
// success rate against overlap threshold, the legend giving the area under the curve,
// or precision against centre-error threshold, the legend giving the value at 20 px.
enum class CurveKind { Success, Precision };
bool writeCurvePlot(const std::string& path, const std::vector<EntryResult>& entries,
                    CurveKind kind, std::string* err);

// BoBoT result file: `header` (the ground truth's first line, which the evaluator
// compares), then `idx x y w h` divided by the image size; an empty box -> 0 0 0 0.
struct IndexedBox {
  int index;
  Box box;
};
bool writeBobotResult(const std::string& path, const std::string& header,
                      const std::vector<IndexedBox>& boxes, int imageWidth, int imageHeight,
                      std::string* err);

// Overlay frames: DIR/NNNNNN.jpg, the sequence's colour with the ground truth (white)
// and each entry's first-run box (the plot's colours) drawn in, a legend under it (frame
// number, each entry's colour, "lost" where it had no box).
struct Sequence;
bool writeOverlayFrames(const std::string& dir, const Sequence& seq,
                        const std::vector<EntryResult>& entries, size_t sequence, std::string* err);
// The same frames as one Motion JPEG video (PATH.avi) at fps (0: 30).
bool writeOverlayVideo(const std::string& path, const Sequence& seq,
                       const std::vector<EntryResult>& entries, size_t sequence, double fps,
                       std::string* err);

// Makes `path` and its parents; false with *err on failure.
bool makeDirs(const std::string& path, std::string* err);
// "opencv-kcf" / "cuetrack-1.1": a label usable in file names.
std::string fileLabel(const EntryResult& e);

}  // namespace cuetrack::bench
