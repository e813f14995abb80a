#!/usr/bin/env bash
# Regenerates docs/benchmarks.md, the current state, at one commit, with one command.
# Every table there is printed with the command that made it. Sections:
#   Development set   scripts/devset.sh best 1.1 (../shared/data/otb + BoBoT + synthetic
#                     RGB-D scenes, 5 seeds, beside CSRT, KCF and MedianFlow), with the
#                     success and precision plots;
#   BoBoT             the paper's protocol and Table 1: 1.1-1.4 and best, 10 seeds;
#   Synthetic RGB-D   2.1-2.5 and best on the cuetrack-synth scenes, beside Table 3;
#   Real Kinect depth ten real stills made into panning sequences (pan:), and four
#                     synthetic scenes' targets in real stills (still:, still_seqs.sh);
#   Speed and memory  cuetrack-trackspeed per preset (host), the integral images
#                     (cuetrack-microbench), and on aarch64 exact instructions per
#                     frame (qemu-icount) when an aarch64 build exists;
#   On-board path     on aarch64: fakenect replay through the Kinect driver, the
#                     tracker and the serial encoder, against the tracker alone.
# What was tried and dropped is in docs/experiments.md, not here.
# Environment: CUETRACK_SHARED_DIR (default ../shared), BUILD (host build tree, default
# build/host), ARM (aarch64 build tree, default build/aarch64), RUNS (BoBoT, 10),
# SYN_RUNS (synthetic and panned, 5), DRY=1 (print instead of writing the doc).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
SHARED=${CUETRACK_SHARED_DIR:-$ROOT/../shared}
BOBOT="$SHARED/data/bobot"
BUILD=${BUILD:-build/host}
ARM=${ARM:-build/aarch64}
RUNS=${RUNS:-10}
SYN_RUNS=${SYN_RUNS:-5}
DOC=docs/benchmarks.md
IMG=docs/img
OUT=$BUILD/benchmarks-out
CACHE=$BUILD/devset/peer-cache  # shared with scripts/devset.sh
PEERS=opencv-csrt,opencv-kcf,opencv-medianflow

start=$(date +%s)
stamp() { echo "== [$(( $(date +%s) - start ))s] $*" >&2; }
commit=$(git rev-parse --short HEAD)
dirty=$(git status --porcelain -- core apps drivers platform | grep -q . && echo " plus uncommitted changes" || true)

stamp "build the host tools in $BUILD"
{ [ -f "$BUILD/CMakeCache.txt" ] || cmake --preset host -B "$BUILD" >/dev/null; } &&
  cmake --build "$BUILD" -j"$(nproc)" --target cuetrack cuetrack-bench cuetrack-trackspeed \
    cuetrack-microbench cuetrack-synth >/dev/null ||
  { echo "benchmarks.sh: the host build failed (cmake --build $BUILD)" >&2; exit 1; }
BENCH="$BUILD/bin/cuetrack-bench"
mapfile -t SCENES < <("$BUILD/bin/cuetrack-synth" --list)  # every synthetic scene
[ ${#SCENES[@]} -gt 0 ] || { echo "benchmarks.sh: cuetrack-synth --list named no scene" >&2; exit 1; }
rm -rf "$OUT"
mkdir -p "$OUT" "$IMG"
status=0
show() { local s="$*"; s=${s//$ROOT\//}; s=${s//$SHARED/..\/shared}; echo "$s"; }
code() { echo '```'; show "$@"; echo '```'; }

# ---- runs ------------------------------------------------------------------------
have_shared=0
[ -d "$SHARED/data/otb" ] && [ -d "$BOBOT" ] && have_shared=1
if [ $have_shared = 1 ]; then
  stamp "development set"
  OUT="$OUT/devset-out" PEER_CACHE="$CACHE" BUILD="$BUILD" bash scripts/devset.sh best 1.1 > "$OUT/devset.txt" || status=1
fi
bobot_seqs=("$BOBOT/Vid_C_juice.avi" "$BOBOT/Vid_E_person_partially_occluded.avi" "$BOBOT/Vid_H_panda.avi")
bobot_cmd=("$BENCH" --quiet "${bobot_seqs[@]}" --tracker "cuetrack,$PEERS" --config 1.1,1.2,1.3,1.4,best
           --runs "$RUNS" --peer-runs 1 --peer-cache "$CACHE" --paper table1 --markdown "$OUT/bobot.md")
syn_seqs=()
for s in "${SCENES[@]}"; do syn_seqs+=("synth:$s"); done
syn_cmd=("$BENCH" --quiet "${syn_seqs[@]}" --tracker "cuetrack,$PEERS" --config 2.1,2.2,2.3,2.4,2.5,best
         --runs "$SYN_RUNS" --peer-runs 1 --peer-cache "$CACHE" --paper table3 --markdown "$OUT/synth.md")
syn2d_cmd=("$BENCH" --quiet "${syn_seqs[@]}" --tracker cuetrack --config best --rgb-only
           --runs "$SYN_RUNS" --markdown "$OUT/synth2d.md")
source scripts/still_seqs.sh  # STILLS, NYU, TUM, nyu_k, tum_k, still_seqs
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
pan_cmd=("$BENCH" --quiet "${pan_seqs[@]}" --tracker cuetrack,opencv-csrt,opencv-kcf
         --config 2.1,2.4,2.5,best --runs "$SYN_RUNS" --peer-runs 1 --peer-cache "$CACHE"
         --markdown "$OUT/pan.md")
# The same trackers on synthetic targets in real stills: best in 3D, 2.1, and best in 2D.
still_cmd=("$BENCH" --quiet "${still_seqs[@]}" --tracker cuetrack --config best,2.1
           --runs "$SYN_RUNS" --markdown "$OUT/still.md")
still2d_cmd=("$BENCH" --quiet "${still_seqs[@]}" --tracker cuetrack --config best --rgb-only
             --runs "$SYN_RUNS" --markdown "$OUT/still2d.md")
if [ -d "$BOBOT" ]; then
  stamp "BoBoT"
  "${bobot_cmd[@]}" > /dev/null || status=1
fi
stamp "synthetic RGB-D"
"${syn_cmd[@]}" > /dev/null || status=1
"${syn2d_cmd[@]}" > /dev/null || status=1
if [ -d "$NYU" ] && [ -d "$TUM" ]; then
  stamp "panned real stills"
  "${pan_cmd[@]}" > /dev/null || status=1
  stamp "synthetic targets in real stills"
  "${still_cmd[@]}" > /dev/null || status=1
  "${still2d_cmd[@]}" > /dev/null || status=1
fi

stamp "speed (host)"
speed_rows=""
size_line=""
# best --rgb-only: best's 2D path (an RGB camera, a video), with the correlation filter.
for p in 1.1 2.1 best "best --rgb-only"; do
  # shellcheck disable=SC2086  # "best --rgb-only" is the preset and a flag
  line=$("$BUILD/bin/cuetrack-trackspeed" --preset $p --frames 150 | tail -1)
  med=$(sed -n 's/^median update \([0-9]*\) us.*/\1/p' <<<"$line")
  stages=$(sed -n 's/.*(\(.*\)).*/\1/p' <<<"$line")
  speed_rows+="| $p | $med | $stages |"$'\n'
  size_line=$(sed -n 's/.*tracker sizeof \([0-9]*\) B.*/\1/p' <<<"$line")
done
# While lost a frame costs more (the whole image's tables, the template's scan, fresh
# windows anywhere): best's update time by state on two scenes where the target is away.
lost_rows=""
for sc in leave-return occlusion; do
  csv="$OUT/lost-$sc.csv"
  "$BUILD/bin/cuetrack" --source "synth:$sc" --config best --seed 1 --quiet --out "$csv" >/dev/null 2>&1 ||
    { echo "benchmarks.sh: cuetrack --source synth:$sc failed" >&2; status=1; continue; }
  lost_rows+=$(awk -F, 'NR > 2 { print (($3 == "lost" || $3 == "searching") ? "lost" : "tracking"), $14 }' "$csv" |
    sort -k1,1 -k2,2n | awk -v sc="$sc" '{ v[$1] = v[$1] " " $2; n[$1]++ }  # frame 0: the set-up
      END { for (k in n) { split(substr(v[k], 2), a, " ")
        printf "| %s | %s | %d | %d | %d |\n", sc, k, n[k], a[int((n[k] + 1) / 2)], a[n[k]] } }' | sort)
  lost_rows+=$'\n'
done
micro=$("$BUILD/bin/cuetrack-microbench" --runs 200 2>&1 || true)

# aarch64: exact instructions per frame under qemu-user with the icount plugin.
icount_tools=${CUETRACK_ICOUNT_DIR:-$SHARED/tools/qemu-icount}
plugin="$ROOT/build/icount/libicount.so"
arm_rows="" path_rows=""
if [ -x "$ARM/bin/cuetrack-trackspeed" ] && [ -x "$ARM/bin/cuetrack" ] && [ -d "$icount_tools" ] &&
   command -v qemu-aarch64 >/dev/null; then
  [ -f "$plugin" ] || sh "$icount_tools/build.sh" "$(dirname "$plugin")" >/dev/null
  icount() {  # icount [ENV=V ...] -- PROGRAM ARGS -> instructions
    local log envs=(); log=$(mktemp)
    while [ "$1" != -- ]; do envs+=(-E "$1"); shift; done; shift
    qemu-aarch64 -L /usr/aarch64-linux-gnu "${envs[@]}" -plugin "$plugin" -d plugin -D "$log" "$@" >/dev/null 2>&1 || true
    sed -n 's/^insns: //p' "$log"; rm -f "$log"
  }
  lib=LD_LIBRARY_PATH=/usr/aarch64-linux-gnu/lib:/usr/lib/aarch64-linux-gnu
  stamp "aarch64 instructions (qemu-icount)"
  for p in 1.1 2.1 best "best --rgb-only"; do
    # shellcheck disable=SC2086
    a=$(icount "$lib" -- "$ARM/bin/cuetrack-trackspeed" --preset $p --frames 50 --icount)
    # shellcheck disable=SC2086
    b=$(icount "$lib" -- "$ARM/bin/cuetrack-trackspeed" --preset $p --frames 0 --icount)
    arm_rows+="| $p | $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f M", (a - b) / 50 / 1e6 }') |"$'\n'
  done
  # The whole on-board path: libfreenect (fakenect replaying a recording, as the Kinect
  # would deliver it) -> our Kinect driver's conversion -> the tracker -> the serial
  # encoder writing to a pseudo-terminal. (60 frames - 20 frames) / 40.
  rec="$OUT/rec-moving"
  "$BUILD/bin/cuetrack-synth" --scene moving --frames 60 --out "$rec" >/dev/null
  # The Kinect source has no ground truth: the first box from the recording's (BoBoT
  # format: index, then x, y, w, h as fractions of 640x480).
  box=$(awk 'NR == 2 { printf "%d,%d,%d,%d", $2 * 640, $3 * 480, $4 * 640, $5 * 480 }' "$rec/groundtruth.txt")
  if command -v socat >/dev/null && [ -f /usr/lib/aarch64-linux-gnu/fakenect/libfreenect.so.0.5 ]; then
    socat PTY,raw,echo=0,link="$OUT/ttyA" PTY,raw,echo=0,link="$OUT/ttyB" & spid=$!
    for _ in $(seq 50); do [ -e "$OUT/ttyB" ] && break; sleep 0.1; done
    cat "$OUT/ttyB" > /dev/null & cpid=$!
    flib="LD_LIBRARY_PATH=/usr/lib/aarch64-linux-gnu/fakenect:/usr/aarch64-linux-gnu/lib:/usr/lib/aarch64-linux-gnu"
    for p in 2.1 best; do
      a=$(icount "$flib" "FAKENECT_PATH=$rec" -- "$ARM/bin/cuetrack" --source kinect --box "$box" --config "$p" --frames 60 --serial "$OUT/ttyA" --quiet)
      b=$(icount "$flib" "FAKENECT_PATH=$rec" -- "$ARM/bin/cuetrack" --source kinect --box "$box" --config "$p" --frames 20 --serial "$OUT/ttyA" --quiet)
      t=$(icount "$lib" -- "$ARM/bin/cuetrack-trackspeed" --preset "$p" --frames 60 --icount)
      u=$(icount "$lib" -- "$ARM/bin/cuetrack-trackspeed" --preset "$p" --frames 20 --icount)
      path_rows+="| $p | $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f M", (a - b) / 40 / 1e6 }') | $(awk -v a="$t" -v b="$u" 'BEGIN { printf "%.2f M", (a - b) / 40 / 1e6 }') |"$'\n'
    done
    kill "$cpid" "$spid" 2>/dev/null || true
  fi
fi
stamp "runs done (exit status $status)"

# ---- the page --------------------------------------------------------------------
if [ "${DRY:-0}" != 1 ] && [ -f "$OUT/devset-out/plots/success.png" ]; then
  cp "$OUT/devset-out/plots/success.png" "$IMG/devset-success.png"
  cp "$OUT/devset-out/plots/precision.png" "$IMG/devset-precision.png"
fi
cpu=$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')
os=$(. /etc/os-release && echo "$PRETTY_NAME")
page="$OUT/benchmarks.md"
{
  echo "# Benchmarks"
  echo
  echo "The current state, generated by \`scripts/benchmarks.sh\` on $(date -u '+%Y-%m-%d'), built"
  echo "from commit \`$commit\`$dirty, in $(( $(date +%s) - start )) s. Machine: $cpu, $(nproc) cores"
  echo "(shared with other jobs, so times are indicative; ratios come from the same run), $os;"
  echo "the \`host\` preset (RelWithDebInfo). Every figure is re-made by that script; each table"
  echo "gives its command. What the figures mean: docs/bench-json.md. What was tried and"
  echo "dropped: [experiments.md](experiments.md)."
  echo
  echo "## Development set"
  echo
  if [ $have_shared = 1 ]; then
    echo "Every tracking change is judged here (docs/algorithm.md): the real videos of"
    echo "\`../shared/data/otb\` (OTB, VOT, UAV123, DTB70, UAVDT), BoBoT C, E and H, the ${#SCENES[@]} synthetic"
    echo "RGB-D scenes and ${#still_seqs[@]} synthetic targets in real Kinect stills (\`still:\`); cuetrack 5"
    echo "seeds, the OpenCV trackers once (they are deterministic). Mean"
    echo "overlap [%] per sequence; the last column is best minus 1.1, \`*\` where it exceeds the"
    echo "seed-to-seed spread. A frame where the target is hidden or out of view scores 1 for a"
    echo "tracker that reports it absent (lost, or occluded) and 0 for one that reports a box"
    echo "([bench-json](bench-json.md)). Command:"
    echo
    code "scripts/devset.sh best 1.1"
    echo
    echo "The figure that counts, the real videos' average (a video a tracker cannot start"
    echo "counts 0):"
    echo
    sed -n '1p' "$OUT/devset-out/devset.md"
    echo
    sed -n '/^| sequence/,$p' "$OUT/devset-out/devset.md"
    echo
    echo "![success plot](img/devset-success.png) ![precision plot](img/devset-precision.png)"
  else
    echo "(not run: no ../shared/data/otb or bobot)"
  fi
  echo
  echo "## BoBoT: the paper's protocol"
  echo
  if [ -f "$OUT/bobot.md" ]; then
    echo "The paper's Table 1 protocol on BoBoT C, E, H: cuetrack $RUNS seeds, the OpenCV trackers"
    echo "once. Rows in *italics* are the paper's own figures (Xeon W3565; its cpu column is its"
    echo "machine). Command:"
    echo
    code "${bobot_cmd[*]}"
    echo
    cat "$OUT/bobot.md"
  else
    echo "(not run: $BOBOT missing)"
  fi
  echo
  echo "## Synthetic RGB-D"
  echo
  echo "The cuetrack-synth scenes (640x480, 150 frames, exact 2D and 3D truth, Kinect-like"
  echo "depth with holes and noise): ${SCENES[*]}. cuetrack $SYN_RUNS seeds. The paper's Table 3"
  echo "is on its own Kinect sequences, not these: listed apart, for the order of magnitude. Command:"
  echo
  code "${syn_cmd[*]}"
  echo
  cat "$OUT/synth.md"
  echo
  echo "The same scenes with their depth dropped: \`best\` in 2D (its RGB fallback), to hold"
  echo "against \`best\` in 3D above. Command:"
  echo
  code "${syn2d_cmd[*]}"
  echo
  cat "$OUT/synth2d.md"
  echo
  echo "## Real Kinect depth: panned stills"
  echo
  if [ -f "$OUT/pan.md" ]; then
    echo "Ten targets of the real Kinect stills in ../shared/data/kinect-stills (NYU chairs; a"
    echo "monitor, telephone, mug, teddy bear, can, keyboard and tape roll of the TUM desk), each made"
    echo "into 150 frames by the \`pan:\` source (crops sweeping 1/16 of the frame, fresh colour noise,"
    echo "the real depth with its holes). cuetrack $SYN_RUNS seeds. Command:"
    echo
    code "${pan_cmd[*]}"
    echo
    cat "$OUT/pan.md"
  else
    echo "(not run: $STILLS missing)"
  fi
  echo
  echo "## Real Kinect depth: synthetic targets in real stills"
  echo
  if [ -f "$OUT/still.md" ]; then
    echo "Four synthetic scenes' objects rendered into the same stills by the \`still:\` source"
    echo "(scripts/still_seqs.sh; exact truth; the target's depth through the synthetic Kinect"
    echo "model, the room's the real one): a book turning 100 mm before the TUM monitor, a cylinder"
    echo "60 mm before the NYU armchair's back with a board passing in front, a box turning before"
    echo "the NYU sideboard, a target carried with a hand over the TUM desk. cuetrack $SYN_RUNS seeds."
    echo "Command:"
    echo
    code "${still_cmd[*]}"
    echo
    cat "$OUT/still.md"
    echo
    echo "The same with their depth dropped (\`best\` in 2D). Command:"
    echo
    code "${still2d_cmd[*]}"
    echo
    cat "$OUT/still2d.md"
  else
    echo "(not run: $STILLS missing)"
  fi
  echo
  echo "## Speed and memory"
  echo
  echo "Median update time on one x86 core, 150 frames of the synthetic scene \`moving\` (640x480"
  echo "RGB-D), with the stages (µs). \`sizeof(Tracker)\` = $size_line B for every preset, allocated"
  echo "once; no heap use while tracking (counted by \`test_core_tracker\` and the bench's allocs"
  echo "column). \`best --rgb-only\` drops the depth: best's 2D path (a colour camera or a video),"
  echo "where the correlation filter searches 3 scales and learns every frame. Budget (issue 41):"
  echo "2.5 ms, 25 M aarch64 instructions. Command: \`cuetrack-trackspeed --preset P\`."
  echo
  echo "| preset | median µs / frame | stages (µs) |"
  echo "|---|---:|---|"
  printf '%s' "$speed_rows"
  echo
  echo "While lost, the integral tables cover the whole image, the correlation template (3D) searches"
  echo "3 tiles of it (each 3 x 3 sides of the last window), and half the particles are fresh"
  echo "windows anywhere; yet a lost frame costs about what a tracked one does (it learns"
  echo "nothing). best's update time by state, seed 1 (µs;"
  echo "\`cuetrack --source synth:SCENE --out F.csv\`, column proc_us):"
  echo
  echo "| scene | state | frames | median µs | max µs |"
  echo "|---|---|---:|---:|---:|"
  printf '%s' "$lost_rows"
  echo
  if [ -n "$arm_rows" ]; then
    echo "On aarch64, exact instructions per frame (qemu-user with the qemu-icount plugin; 50 frames"
    echo "minus 0 frames, divided by 50; generic \`-O2\`, no board flags). Command:"
    echo "\`qemu-aarch64 -plugin libicount.so -d plugin $ARM/bin/cuetrack-trackspeed --preset P --frames N --icount\`."
    echo
    echo "| preset | aarch64 instructions / frame |"
    echo "|---|---:|"
    printf '%s' "$arm_rows"
  else
    echo "(aarch64 instruction counts not measured: no $ARM build, qemu-aarch64 or qemu-icount.)"
  fi
  echo
  echo "The integral images, one 640x480 frame per kernel, each SIMD kernel bit-exact to the"
  echo "scalar reference (\`cuetrack-microbench --runs 200\`; on ARM \`apps/microbench/icount.sh\`):"
  echo
  echo '```'
  echo "$micro"
  echo '```'
  echo
  echo "## On-board path"
  echo
  if [ -n "$path_rows" ]; then
    echo "What a board spends per frame, in aarch64 instructions: libfreenect delivering a recorded"
    echo "Kinect stream (fakenect replaying \`cuetrack-synth --scene moving\`), the Kinect driver's"
    echo "conversion (raw 11-bit depth to mm, registration), the tracker, and the serial encoder"
    echo "writing each track to a pseudo-terminal; beside the tracker alone on the same scene"
    echo "((60 frames - 20 frames) / 40, qemu-icount). Command: \`FAKENECT_PATH=rec qemu-aarch64"
    echo "-plugin libicount.so -d plugin $ARM/bin/cuetrack --source kinect --box B --config P --frames N --serial PTY\`"
    echo "(B: the recording's first ground-truth box, as \`cuetrack-bench\` starts)."
    echo
    echo "| preset | whole path / frame | tracker alone / frame |"
    echo "|---|---:|---:|"
    printf '%s' "$path_rows"
  else
    echo "(not measured: needs an aarch64 build in $ARM with cuetrack, qemu-aarch64, socat, the"
    echo "arm64 fakenect library and qemu-icount.)"
  fi
  echo
  echo "Serial link budget (from docs/serial-protocol.md): a TRACK frame is 46 bytes on the wire,"
  echo "4.0 ms at 115200 baud (12 % of the line at 30 fps), 0.5 ms at 921600."
  # The test command's times are measured by hand (`time scripts/test.sh`, a quiet machine),
  # not by this script: the page's last section is kept as it is.
  if [ -f "$DOC" ] && grep -q '^## Test command' "$DOC"; then
    echo
    sed -n '/^## Test command/,$p' "$DOC"
  fi
} > "$page"
if [ "${DRY:-0}" = 1 ]; then cat "$page"; else cp "$page" "$DOC"; stamp "wrote $DOC ($(wc -l < "$DOC") lines)"; fi
exit $status
