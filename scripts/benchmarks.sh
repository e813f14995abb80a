#!/usr/bin/env bash
# Regenerates the cuetrack-bench block of docs/benchmarks.md (and docs/img/bench-*.png)
# with one command: builds cuetrack-bench (host preset), then runs the paper's protocol
#   - BoBoT C, E, H (../shared/data/bobot): cuetrack 1.1-1.4 and best (2D there), 10 runs,
#     beside the paper's Table 1, and every OpenCV peer on the same frames;
#   - synthetic RGB-D scenes (the cuetrack-synth generator, in process): cuetrack
#     2.1-2.5 and best, beside the paper's Table 3 (on its own, other sequences),
#     and every OpenCV peer on the same frames;
#   - real Kinect depth (../shared/data/kinect-stills): ten targets of the NYU and TUM
#     stills, each panned by the pan: source, cuetrack 2.1, 2.4, 2.5, best and best
#     with each switch off, and KCF / CSRT;
#   - BoBoT again as a slower camera (every 2nd frame) and a lossy link (10% of the
#     frames dropped): best, best-nofastmotion, 1.1, KCF and CSRT; the synthetic
#     scenes at 10 fps (every 3rd frame): best, best-nofastmotion, 2.1, KCF and CSRT;
#   - BoBoT from other starts and backwards (OTB's temporal robustness, --from / --to /
#     --reverse): 1.1, best, KCF, CSRT and MedianFlow.
# Environment: CUETRACK_SHARED_DIR (default ../shared), BUILD (build tree, default
# build/benchmarks), RUNS (BoBoT runs, 10), SYN_RUNS (synthetic runs, 5),
# PEER_RUNS (OpenCV peer runs, 1: TLD, CSRT and MIL take 100-200 ms a frame), FRAMES (cut every sequence, default whole),
# DRY=1 (print the block instead of writing docs/benchmarks.md).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SHARED=${CUETRACK_SHARED_DIR:-$ROOT/../shared}
BOBOT="$SHARED/data/bobot"
BUILD=${BUILD:-build/benchmarks}
RUNS=${RUNS:-10}
SYN_RUNS=${SYN_RUNS:-5}
PEER_RUNS=${PEER_RUNS:-1}
FRAMES=${FRAMES:-}
SCENES=(twin-crossing occlusion untextured lighting approach turn)
DOC=docs/benchmarks.md
IMG=docs/img
OUT=$BUILD/benchmarks-out

start=$(date +%s)
stamp() { echo "== [$(( $(date +%s) - start ))s] $*" >&2; }

# What the binary is built from, taken before the build (others may commit meanwhile).
commit=$(git rev-parse --short HEAD)
dirty=$(git status --porcelain -- core apps drivers platform | grep -q . && echo " (plus uncommitted changes in the working tree)" || true)

stamp "build cuetrack-bench in $BUILD"
mkdir -p "$BUILD"
cmake --preset host -B "$BUILD" -DCUETRACK_BUILD_TESTS=OFF > "$BUILD/benchmarks-build.log" 2>&1 &&
  cmake --build "$BUILD" --target cuetrack-bench -j2 >> "$BUILD/benchmarks-build.log" 2>&1 ||
  { tail -30 "$BUILD/benchmarks-build.log" >&2; echo "benchmarks.sh: build failed" >&2; exit 1; }
BENCH="$BUILD/bin/cuetrack-bench"

rm -rf "$OUT"
mkdir -p "$OUT" "$IMG"
frames_opt=()
[ -n "$FRAMES" ] && frames_opt=(--frames "$FRAMES")
status=0

# The commands as the doc shows them (paths relative to the repository).
bobot_seqs=("$BOBOT/Vid_C_juice.avi" "$BOBOT/Vid_E_person_partially_occluded.avi"
            "$BOBOT/Vid_H_panda.avi")
bobot_cmd=("$BENCH" "${bobot_seqs[@]}" --tracker cuetrack,opencv-all --config 1.1,1.2,1.3,1.4,best,best-noanchorcloud
           --runs "$RUNS" --peer-runs "$PEER_RUNS" "${frames_opt[@]}" --paper table1
           --markdown "$OUT/bobot.md" --json "$OUT/bobot.json" --plots "$OUT/plots"
           --csv "$OUT/csv" --results "$OUT/results")
syn_seqs=()
for s in "${SCENES[@]}"; do syn_seqs+=("synth:$s"); done
syn_cmd=("$BENCH" "${syn_seqs[@]}" --tracker cuetrack,opencv-all
         --config 2.1,2.2,2.3,2.4,2.5,best,best-norefine --runs "$SYN_RUNS" --peer-runs "$PEER_RUNS"
         "${frames_opt[@]}" --paper table3 --markdown "$OUT/synth.md" --json "$OUT/synth.json"
         --plots "$OUT/plots" --csv "$OUT/csv")
# Real depth: the stills' targets (box in px) and intrinsics, as the data README gives them.
STILLS="$SHARED/data/kinect-stills"
NYU="$STILLS/nyu-joinmap"
TUM="$STILLS/tum-fr1"
nyu_k=518,519,325.5,253.5
tum_k=517.3,516.5,318.6,255.3,0.2  # freiburg1; depth value / 5 = mm
pan_seqs=("pan:$NYU/color/5.png,$NYU/depth/5.pgm,302,102,186,240,$nyu_k"
          "pan:$NYU/color/3.png,$NYU/depth/3.pgm,324,132,138,193,$nyu_k"
          "pan:$NYU/color/1.png,$NYU/depth/1.pgm,116,142,96,148,$nyu_k"
          "pan:$TUM/1.png,$TUM/1_depth.png,238,95,156,158,$tum_k"
          "pan:$TUM/1.png,$TUM/1_depth.png,425,217,85,74,$tum_k"
          "pan:$TUM/1.png,$TUM/1_depth.png,443,293,46,59,$tum_k"
          "pan:$TUM/1.png,$TUM/1_depth.png,298,62,60,40,$tum_k"
          "pan:$TUM/1.png,$TUM/1_depth.png,418,128,22,43,$tum_k"
          "pan:$TUM/1.png,$TUM/1_depth.png,202,257,184,50,$tum_k"
          "pan:$TUM/1.png,$TUM/1_depth.png,98,171,50,68,$tum_k")
pan_cmd=("$BENCH" "${pan_seqs[@]}" --tracker cuetrack,opencv-kcf,opencv-csrt
         --config 2.1,2.4,2.5,best,best-fixedsize,best-nolost,best-nomodeguard --runs "$SYN_RUNS"
         --peer-runs "$PEER_RUNS" "${frames_opt[@]}" --markdown "$OUT/pan.md"
         --json "$OUT/pan.json" --csv "$OUT/csv")
slow_cmd=("$BENCH" "${bobot_seqs[@]}" --tracker cuetrack,opencv-kcf,opencv-csrt
          --config best,best-nofastmotion,1.1 --runs "$RUNS" --peer-runs "$PEER_RUNS"
          "${frames_opt[@]}" --stride 2 --markdown "$OUT/slow.md" --json "$OUT/slow.json")
lossy_cmd=("$BENCH" "${bobot_seqs[@]}" --tracker cuetrack,opencv-kcf,opencv-csrt
           --config best,best-nofastmotion,1.1 --runs "$RUNS" --peer-runs "$PEER_RUNS"
           "${frames_opt[@]}" --drop-frames 10 --markdown "$OUT/lossy.md" --json "$OUT/lossy.json")
slowsyn_cmd=("$BENCH" "${syn_seqs[@]}" --tracker cuetrack,opencv-kcf,opencv-csrt
             --config best,best-nofastmotion,2.1 --runs "$SYN_RUNS" --peer-runs "$PEER_RUNS"
             "${frames_opt[@]}" --stride 3 --markdown "$OUT/slowsyn.md" --json "$OUT/slowsyn.json")
# Temporal robustness: each video from frames 0, 100, 200 forward and from its end, 200,
# 100 backward, one bench run per video (its table's Averages are over the six starts).
tre_cmd() {  # sets the array TRE for the video $1
  local f=$1
  TRE=("$BENCH" "$f" --from 100 "$f" --from 200 "$f" --reverse "$f" --to 200 --reverse "$f"
       --to 100 --reverse "$f" --tracker cuetrack,opencv-kcf,opencv-csrt,opencv-medianflow
       --config 1.1,best --runs "$RUNS" --peer-runs "$PEER_RUNS" "${frames_opt[@]}")
}
show() { local s="$*"; s=${s//$ROOT\//}; s=${s//$SHARED/..\/shared}; echo "$s"; }

if [ -d "$BOBOT" ]; then
  stamp "BoBoT: ${bobot_cmd[*]}"
  "${bobot_cmd[@]}" > "$OUT/bobot.txt" || status=1
  stamp "BoBoT, every 2nd frame: ${slow_cmd[*]}"
  "${slow_cmd[@]}" > "$OUT/slow.txt" || status=1
  stamp "BoBoT, 10% dropped: ${lossy_cmd[*]}"
  "${lossy_cmd[@]}" > "$OUT/lossy.txt" || status=1
  for f in "${bobot_seqs[@]}"; do
    [ -n "$FRAMES" ] && break  # FRAMES would cut the videos before their later starts
    n=$(basename "$f" .avi)
    tre_cmd "$f"
    stamp "BoBoT from other starts: ${TRE[*]}"
    "${TRE[@]}" --markdown "$OUT/tre-$n.md" --json "$OUT/tre-$n.json" > "$OUT/tre-$n.txt" || status=1
  done
else
  echo "benchmarks.sh: $BOBOT not found: the BoBoT part is left out" >&2
  status=1
fi
stamp "synthetic: ${syn_cmd[*]}"
"${syn_cmd[@]}" > "$OUT/synth.txt" || status=1
stamp "synthetic, every 3rd frame: ${slowsyn_cmd[*]}"
"${slowsyn_cmd[@]}" > "$OUT/slowsyn.txt" || status=1
if [ -d "$NYU" ] && [ -d "$TUM" ]; then
  stamp "real depth: ${pan_cmd[*]}"
  "${pan_cmd[@]}" > "$OUT/pan.txt" || status=1
else
  echo "benchmarks.sh: $STILLS not found: the real-depth part is left out" >&2
  status=1
fi
stamp "runs done (exit status $status)"

# Plots into docs/img (small PNGs, referenced from the doc); DRY=1 leaves docs/ alone.
if [ "${DRY:-0}" != 1 ]; then
  rm -f "$IMG"/bench-*.png
  for p in "$OUT"/plots/*.png; do
    [ -e "$p" ] && cp "$p" "$IMG/bench-$(basename "$p" .overlap.png).png"
  done
fi

cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
os=$(. /etc/os-release && echo "$PRETTY_NAME")
elapsed=$(( $(date +%s) - start ))

block="$OUT/block.md"
{
  echo "Generated by \`scripts/benchmarks.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'), built from"
  echo "commit \`$commit\`$dirty, in ${elapsed} s. Machine: $cpu, $(nproc) cores, $os;"
  echo "build: the \`host\` preset (RelWithDebInfo, -O2). The machine was shared with other"
  echo "jobs, so times are indicative; ratios come from the same run. The OpenCV trackers use"
  echo "OpenCV's default thread pool, cuetrack a single thread. Protocol (cuetrack-bench,"
  echo "see docs/bench-json.md): initialise at the first ground-truth box, score every later"
  echo "frame with a ground-truth line (an invisible target counts with overlap 0); hit ="
  echo "overlap > 1/3, PASCAL = overlap > 0.5; centre distance over frames where both boxes"
  echo "exist; ms per frame = the tracker's update call only (decoding excluded); allocs = heap"
  echo "allocations inside update calls per run; all figures are means over runs (seeds)."
  echo
  echo "### BoBoT (RGB): tests 1.1-1.4, best and the OpenCV trackers"
  echo
  if [ -f "$OUT/bobot.md" ]; then
    echo "cuetrack: $RUNS runs per configuration; OpenCV peers: $PEER_RUNS runs. Rows in *italics*"
    echo "are the paper's Table 1 (Xeon W3565 @ 3.2 GHz; its cpu column is its own machine; its"
    echo "1.4 row for H is not legible in our copy). Command:"
    echo
    echo '```'
    show "${bobot_cmd[*]}"
    echo '```'
    echo
    cat "$OUT/bobot.md"
    echo
    for s in Vid_C_juice Vid_E_person_partially_occluded Vid_H_panda; do
      [ -e "$IMG/bench-$s.png" ] && echo "![overlap over time, $s](img/bench-$s.png)"
    done
  else
    echo "(not run: $BOBOT missing or failed; see the script's messages)"
  fi
  echo
  echo "### Synthetic RGB-D: tests 2.1-2.5, best and the OpenCV trackers"
  echo
  echo "Scenes of the cuetrack-synth generator (640x480, 150 frames, exact ground truth,"
  echo "Kinect-like depth): ${SCENES[*]}. The paper's Table 3 figures are on its own"
  echo "BoBoT-D Kinect sequences, not on these, so they are listed apart, for the layout and"
  echo "the order of magnitude only. cuetrack: $SYN_RUNS runs per configuration; OpenCV peers:"
  echo "$PEER_RUNS runs. Command:"
  echo
  echo '```'
  show "${syn_cmd[*]}"
  echo '```'
  echo
  cat "$OUT/synth.md"
  echo
  for s in "${SCENES[@]}"; do
    [ -e "$IMG/bench-$s.png" ] && echo "![overlap over time, $s](img/bench-$s.png)"
  done
  echo
  echo "### Real Kinect depth: panned stills, tests 2.1, 2.4, 2.5, best and its ablations"
  echo
  if [ -f "$OUT/pan.md" ]; then
    echo "Ten targets of the real Kinect stills in ../shared/data/kinect-stills (three chairs of"
    echo "the NYU frames; of the TUM desk a monitor, a telephone, a mug, the teddy bear half"
    echo "behind the monitor, a can, the keyboard and a tape roll on its stand), each made into 150"
    echo "frames by the \`pan:\` source: crops sweeping 1/16 of the frame (a camera panning and"
    echo "tilting a few degrees), fresh colour noise per frame, the real depth with its holes."
    echo "Boxes drawn by hand around the whole object (chairs with their legs). cuetrack:"
    echo "$SYN_RUNS runs per configuration; KCF and CSRT: $PEER_RUNS runs. Command:"
    echo
    echo '```'
    show "${pan_cmd[*]}"
    echo '```'
    echo
    cat "$OUT/pan.md"
  else
    echo "(not run: $STILLS missing or failed; see the script's messages)"
  fi
  echo
  echo "### BoBoT from a slower camera and over a lossy link: best's fast-motion particles"
  echo
  if [ -f "$OUT/slow.md" ] && [ -f "$OUT/lossy.md" ]; then
    echo "The same three videos, thinned after the first box: every 2nd frame (12.5 fps: a board"
    echo "that tracks every other Kinect frame; C's carton then moves up to 0.6 of its width per"
    echo "frame), and 10% of the frames dropped at random (the same ones for every tracker and"
    echo "run). Frames left out are neither tracked nor scored. best-nofastmotion is best without"
    echo "its 2D fast-motion particles (docs/algorithm.md). cuetrack: $RUNS runs; KCF and CSRT:"
    echo "$PEER_RUNS runs. Commands:"
    echo
    echo '```'
    show "${slow_cmd[*]}"
    show "${lossy_cmd[*]}"
    echo '```'
    echo
    echo "Every 2nd frame:"
    echo
    cat "$OUT/slow.md"
    echo
    echo "10% of the frames dropped:"
    echo
    cat "$OUT/lossy.md"
  else
    echo "(not run: $BOBOT missing or failed; see the script's messages)"
  fi
  echo
  echo "### BoBoT from other starts and backwards: temporal robustness"
  echo
  if [ -n "$FRAMES" ]; then
    echo "(not run: FRAMES=$FRAMES cuts the videos before their later starts)"
  elif [ -f "$OUT/tre-Vid_H_panda.md" ]; then
    echo "Each video started at frames 0, 100 and 200 and played forward, and started at its"
    echo "end, at 200 and at 100 and played backward (\`--from\`, \`--to\`, \`--reverse\`;"
    echo "docs/bench-json.md): the temporal robustness evaluation of the OTB benchmark, plus"
    echo "a target that moves the other way. Each run initialises at its first frame's"
    echo "ground-truth box; Averages are over the six starts. Where E starts inside the"
    echo "occlusion (\`.from200\`, \`.to200.rev\`), the first box holds half the person and every"
    echo "tracker keeps that half, so every one scores 60-70 there. cuetrack: $RUNS runs; KCF,"
    echo "CSRT and MedianFlow: $PEER_RUNS runs. Commands:"
    echo
    echo '```'
    for f in "${bobot_seqs[@]}"; do
      tre_cmd "$f"
      show "${TRE[*]}"
    done
    echo '```'
    for f in "${bobot_seqs[@]}"; do
      echo
      cat "$OUT/tre-$(basename "$f" .avi).md"
    done
  else
    echo "(not run: $BOBOT missing or failed; see the script's messages)"
  fi
  echo
  echo "### Synthetic RGB-D at 10 fps: best's fast-motion particles in 3D"
  echo
  echo "The synthetic scenes above, every 3rd frame (10 fps instead of 30: a board that"
  echo "tracks every third Kinect frame). cuetrack: $SYN_RUNS runs; KCF and CSRT: $PEER_RUNS"
  echo "runs. Command:"
  echo
  echo '```'
  show "${slowsyn_cmd[*]}"
  echo '```'
  echo
  cat "$OUT/slowsyn.md"
  true
} > "$block"

if [ "${DRY:-0}" = 1 ]; then
  cat "$block"
else
  # Replace what lies between the markers; everything else in the doc stays as it is.
  awk -v block="$block" '
    /<!-- BEGIN cuetrack-bench/ { print; while ((getline line < block) > 0) print line; skip = 1; next }
    /<!-- END cuetrack-bench/ { skip = 0 }
    !skip { print }' "$DOC" > "$OUT/benchmarks.md"
  grep -q "<!-- END cuetrack-bench" "$OUT/benchmarks.md" || { echo "benchmarks.sh: markers missing in $DOC" >&2; exit 1; }
  cp "$OUT/benchmarks.md" "$DOC"
  stamp "wrote $DOC and $IMG/bench-*.png"
fi
exit $status
