#!/usr/bin/env bash
# The development set in one command: cuetrack-bench over every sequence of
# ../shared/data/otb (the real videos), ../shared/data/bobot (BoBoT C, E, H), the 50
# randomised synthetic RGB-D scenes rand:1..50 over the real Kinect stills (a group with
# its own average), every hand-made synthetic scene of cuetrack-synth --list and, when
# ../shared/data/kinect-stills is there, the hand-made scenes in real Kinect stills of
# scripts/still_seqs.sh (still:),
# CONFIG... (default: best 1.1) with 5 seeds each, beside OpenCV's CSRT, KCF and
# MedianFlow (deterministic: run once, cached). It prints how many sequences it ran.
#
#   scripts/devset.sh [CONFIG...]        e.g. scripts/devset.sh best best-nolost 1.1
#   SET=real scripts/devset.sh best      the real videos alone (otb + BoBoT C, E, H)
#   SET=rand scripts/devset.sh best      the randomised RGB-D group alone
#
# Prints first the real videos' average (overlap with its seed spread, hit rate) for each
# tracker: the figure that counts; then the randomised group's. Then one row per sequence and the averages with their seed-to-seed spread, AUC and
# precision at 20 px; writes OTB success and precision plots. The rule for a tracking
# change (docs/algorithm.md): keep it only if the average overlap rises by more than the
# spread and no sequence falls by more than it.
# Environment: CUETRACK_SHARED_DIR (default ../shared), BUILD (default build/host),
# OUT (default build/devset), PEER_CACHE (default $OUT/peer-cache), RUNS (5), PEERS (opencv-csrt,opencv-kcf,opencv-medianflow;
# empty for none), FRAMES (cut every sequence; quick checks only), SET (all; real: the
# real videos only, the figure that counts; rand: the randomised group only), RGB_ONLY=1
# (drop depth: the 2D path, for the 3D-against-colour comparison).
# Exit: 0 done; 1 a sequence or output failed; 77 no ../shared (skipped, with a message).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SHARED=${CUETRACK_SHARED_DIR:-$ROOT/../shared}
BUILD=${BUILD:-build/host}
OUT=${OUT:-build/devset}
RUNS=${RUNS:-5}
PEERS=${PEERS-opencv-csrt,opencv-kcf,opencv-medianflow}
FRAMES=${FRAMES:-}
SET=${SET:-all}
case "$SET" in all|real|rand) ;; *) echo "devset.sh: SET must be all, real or rand, not '$SET'" >&2; exit 2 ;; esac
NRAND=50  # the randomised group: rand:1..50 (docs/synthetic.md)
configs=("$@")
[ ${#configs[@]} -eq 0 ] && configs=(best 1.1)

if [ ! -d "$SHARED/data/otb" ] || [ ! -d "$SHARED/data/bobot" ]; then
  echo "devset.sh: skipped: no development set at $SHARED/data/{otb,bobot} (set CUETRACK_SHARED_DIR)" >&2
  exit 77
fi

BENCH="$BUILD/bin/cuetrack-bench"
SYNTH="$BUILD/bin/cuetrack-synth"
if [ ! -x "$BENCH" ] || [ ! -x "$SYNTH" ] ||
   [ -n "$(find core apps drivers platform -newer "$BENCH" -name '*.[ch]pp' -print -quit)" ]; then
  echo "devset.sh: building cuetrack-bench and cuetrack-synth in $BUILD" >&2
  { [ -f "$BUILD/CMakeCache.txt" ] || cmake --preset host -B "$BUILD" >/dev/null; } &&
    cmake --build "$BUILD" --target cuetrack-bench cuetrack-synth -j"$(nproc)" >/dev/null ||
    { echo "devset.sh: the build of cuetrack-bench failed (run: cmake --build $BUILD --target cuetrack-bench cuetrack-synth)" >&2; exit 1; }
fi
# Every synthetic scene the generator has (cuetrack-synth --list).
mapfile -t SCENES < <("$SYNTH" --list)
[ ${#SCENES[@]} -gt 0 ] || { echo "devset.sh: $SYNTH --list named no scene" >&2; exit 1; }

seqs=()
groups=()
if [ "$SET" != rand ]; then
  for d in "$SHARED"/data/otb/*/; do [ -f "$d/groundtruth_rect.txt" ] && seqs+=("${d%/}"); done
  for v in "$SHARED"/data/bobot/*.avi; do seqs+=("$v"); done
  groups+=(--group "real videos:0:${#seqs[@]}")  # first: the figure that counts
fi
if [ "$SET" != real ]; then
  if [ -d "$SHARED/data/kinect-stills" ]; then
    first=${#seqs[@]}
    for i in $(seq 1 $NRAND); do seqs+=("rand:$i:$SHARED/data"); done
    groups+=(--group "randomised RGB-D:$first:$NRAND")
  else
    echo "devset.sh: no $SHARED/data/kinect-stills: the randomised group is left out" >&2
  fi
fi
if [ "$SET" = all ]; then
  for s in "${SCENES[@]}"; do seqs+=("synth:$s"); done
  source scripts/still_seqs.sh  # still_seqs: empty without the stills
  seqs+=("${still_seqs[@]}")
fi

mkdir -p "$OUT"
trackers=cuetrack
[ -n "$PEERS" ] && trackers="cuetrack,$PEERS"
frames_opt=()
[ -n "$FRAMES" ] && frames_opt=(--frames "$FRAMES")
[ "${RGB_ONLY:-0}" = 1 ] && frames_opt+=(--rgb-only)
cmd=("$BENCH" --quiet --tracker "$trackers" --config "$(IFS=,; echo "${configs[*]}")"
     --runs "$RUNS" --peer-runs 1 --peer-cache "${PEER_CACHE:-$OUT/peer-cache}" "${frames_opt[@]}"
     --json "$OUT/devset.json" --markdown "$OUT/devset-bench.md" --plots "$OUT/plots"
     "${seqs[@]}")
start=$(date +%s)
status=0
"${cmd[@]}" > "$OUT/devset-bench.txt" || status=$?
python3 scripts/devset_table.py "${groups[@]}" "$OUT/devset.json" "$OUT/devset.md"
echo
echo "${#seqs[@]} sequences, $RUNS seeds, $(( $(date +%s) - start )) s. Plots: $OUT/plots/success.png," \
     "$OUT/plots/precision.png (and one per sequence); Markdown: $OUT/devset.md; JSON: $OUT/devset.json"
exit $status
