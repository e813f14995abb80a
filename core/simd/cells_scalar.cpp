// Reference cell coder (CellKernels.hpp): WeakClassifier::cellOf of each window's response.
#include "cuetrack/core/model/CellKernels.hpp"
#include "cuetrack/core/model/WeakClassifier.hpp"

namespace cuetrack::cellk::scalar {

namespace {
template <FeatureKind K>
void code(const Feature& f, const FrameTables& t, const Box* wins, const uint8_t* valid, int n,
          uint16_t* cells, const uint16_t* order) {
  for (int k = 0; k < n; ++k) {
    const int i = order != nullptr ? order[k] : k;
    cells[i] = static_cast<uint16_t>(
        valid[i] ? WeakClassifier::cellOf(evaluateKind<K>(f, wins[i], t), K) : kLutCells);
  }
}
}  // namespace

int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins,
              const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order) {
  switch (kind) {
    case FeatureKind::Gray:
      code<FeatureKind::Gray>(f, t, wins, valid, n, cells, order);
      break;
    case FeatureKind::Depth:
      code<FeatureKind::Depth>(f, t, wins, valid, n, cells, order);
      break;
    case FeatureKind::Colour:
      code<FeatureKind::Colour>(f, t, wins, valid, n, cells, order);
      break;
  }
  return n;
}

}  // namespace cuetrack::cellk::scalar
