#!/usr/bin/env bash
# Regenerates the two pictures of docs/first-hour.md with the built tools:
#   docs/img/first-hour-show.png      the `cuetrack --show` window, paused while the target
#                                     of synth:occlusion is hidden behind the box
#   docs/img/first-hour-snapshot.jpg  `cuetrack --snapshot` of synth:moving (40 px grid)
#
# usage: scripts/docs-images.sh [OUTDIR]      (default OUTDIR: docs/img; about 15 s)
#
# Needs build/host/bin/cuetrack and cuetrack-synth (cmake --build build/host --target
# cuetrack cuetrack-synth), Xvfb, xdotool, xwd and python3 (scripts/setup.sh installs
# them). The window runs on a virtual display of its own and is driven the way
# tests/apps/test_app_view.cpp drives it: xdotool presses space once the --out CSV shows
# a frame that the scene's ground truth marks hidden, and xwd dumps the window once it has
# stopped changing. python3 (standard library only: zlib and struct) writes the dump as a
# PNG, lossless, so the window's text and boxes stay sharp.
# Exit: 0 done, 1 a step failed (named on stderr), 2 bad arguments, 77 a tool is missing.
set -euo pipefail

script=$(readlink -f "$0")
if [ $# -gt 1 ]; then
  sed -n '7p' "$script" | sed 's/^# //' >&2
  exit 2
fi
if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  sed -n '2,16p' "$script" | sed 's/^# \{0,1\}//'
  exit 0
fi
outdir=""
if [ $# -eq 1 ]; then
  outdir=$(cd "$1" 2>/dev/null && pwd) || { echo "docs-images: no folder $1" >&2; exit 2; }
fi
cd "$(dirname "$script")/.."
outdir="${outdir:-docs/img}"
bin=build/host/bin

die() { echo "docs-images: $*" >&2; exit 1; }
for t in cuetrack cuetrack-synth; do
  if [ ! -x "$bin/$t" ]; then
    echo "docs-images: no $bin/$t: build it with cmake --build build/host --target $t" >&2
    exit 77
  fi
done
for t in Xvfb xdotool xwd python3; do
  if ! command -v "$t" >/dev/null; then
    echo "docs-images: $t missing (scripts/setup.sh installs it)" >&2
    exit 77
  fi
done

tmp=$(mktemp -d /tmp/docs-images-XXXXXX)
xvfb_pid="" app_pid=""
cleanup() {
  if [ -n "$app_pid" ]; then  # before Xvfb: the window's end needs its display
    kill "$app_pid" 2>/dev/null || true
    for _ in {1..100}; do kill -0 "$app_pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$app_pid" 2>/dev/null || true
    wait "$app_pid" 2>/dev/null || true
  fi
  if [ -n "$xvfb_pid" ]; then
    kill "$xvfb_pid" 2>/dev/null || true
    wait "$xvfb_pid" 2>/dev/null || true
  fi
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

# Polls "$@" every 0.05 s for up to $1 seconds; false when it never held.
wait_until() {
  local end=$((SECONDS + $1)); shift
  until "$@"; do
    [ "$SECONDS" -lt "$end" ] || return 1
    sleep 0.05
  done
}

# 1. The snapshot: cuetrack writes it itself (OpenCV picks JPEG, quality 95, by the name).
"$bin/cuetrack" --source synth:moving --snapshot "$tmp/snapshot.jpg" 2>"$tmp/snapshot.err" ||
  die "cuetrack --snapshot failed: $(tail -n 1 "$tmp/snapshot.err")"

# 2. Which frames hide the target: the scene's ground truth is 0 0 0 0 there.
"$bin/cuetrack-synth" --scene occlusion --out "$tmp/occlusion" >/dev/null 2>"$tmp/synth.err" ||
  die "cuetrack-synth failed: $(tail -n 1 "$tmp/synth.err")"
read -r hidden_first hidden_last < <(awk '{ sub(/\r$/, "") }  # CRLF lines
  NF == 5 && $4 == 0 && $5 == 0 { if (f == "") f = $1; l = $1 } END { print f, l }' \
  "$tmp/occlusion/groundtruth.txt")
[ -n "${hidden_last:-}" ] || die "synth:occlusion's ground truth hides no frame"

# 3. A virtual display on a free number (-displayfd prints it once clients may connect;
# -noreset: a reset when the last client leaves, cuetrack's display probe, would refuse
# the window for a moment).
Xvfb -displayfd 1 -screen 0 1280x800x24 -nolisten tcp -noreset >"$tmp/display" 2>"$tmp/xvfb.err" &
xvfb_pid=$!
display_ready() { grep -q '^[0-9]*$' "$tmp/display" && [ "$(wc -l <"$tmp/display")" -ge 1 ]; }
wait_until 30 display_ready || die "Xvfb did not start: $(tail -n 1 "$tmp/xvfb.err")"
DISPLAY=":$(head -n 1 "$tmp/display")"
export DISPLAY

# 4. The window, at the scene's 30 frames a second, paused while the target is hidden.
# Space lands 4 to 15 frames after the frame the poll saw, with the machine's load: it is
# pressed on the third hidden frame, and a run that paused too late is done again.
pause_at=$((hidden_first + 2))
csv="$tmp/track.csv"
last_seq() { tail -n 1 "$csv" 2>/dev/null | cut -d, -f1; }
reached() {
  kill -0 "$app_pid" 2>/dev/null || die "cuetrack ended early: $(tail -n 1 "$tmp/show.err")"
  local s; s=$(last_seq)
  [[ "$s" =~ ^[0-9]+$ ]] && [ "$s" -ge "$pause_at" ]
}
# Paused: the CSV stops growing and two dumps of the window in a row are the same.
settled() {
  local rows; rows=$(wc -l <"$csv")
  xwd -silent -id "$win" -out "$tmp/a.xwd" || die "xwd could not dump the window"
  sleep 0.3
  xwd -silent -id "$win" -out "$tmp/b.xwd" || die "xwd could not dump the window"
  [ "$(wc -l <"$csv")" = "$rows" ] && cmp -s "$tmp/a.xwd" "$tmp/b.xwd"
}
app_done() { ! kill -0 "$app_pid" 2>/dev/null; }
show_once() {  # true when the window paused on a hidden frame ($seq); leaves b.xwd
  rm -f "$csv"
  "$bin/cuetrack" --source synth:occlusion --show --realtime --out "$csv" --quiet \
    2>"$tmp/show.err" &
  app_pid=$!
  win=$(timeout 60 xdotool search --sync --onlyvisible --name '^cuetrack$' | head -n 1) ||
    die "no cuetrack window: $(tail -n 1 "$tmp/show.err")"
  xdotool windowfocus --sync "$win" || die "xdotool could not focus the window"
  wait_until 60 reached || die "the run did not reach frame $pause_at"
  xdotool key space || die "xdotool could not press space"
  wait_until 30 settled || die "the window did not settle after space"
  seq=$(last_seq)
  xdotool key q || die "xdotool could not press q"
  wait_until 30 app_done || die "cuetrack did not quit on q"
  wait "$app_pid" || die "cuetrack --show exited $?: $(tail -n 1 "$tmp/show.err")"
  app_pid=""
  [ "$seq" -ge "$hidden_first" ] && [ "$seq" -le "$hidden_last" ]
}
for attempt in 1 2 3; do
  if show_once; then break; fi
  [ "$attempt" -lt 3 ] || die "paused on frame $seq, after the hidden frames" \
    "$hidden_first-$hidden_last, three times: the machine is too busy; run again later"
  echo "docs-images: paused on frame $seq, not in the hidden frames" \
    "$hidden_first-$hidden_last; once more" >&2
done

# 5. The dump as a PNG (8-bit RGB): each row filtered None, Sub or Up by the usual guess
# (the least sum of its bytes read as signed), or every row alike when that packs smaller;
# zlib at level 9.
if ! python3 - "$tmp/b.xwd" "$tmp/show.png" <<'PY'
import struct, sys, zlib

src, dst = sys.argv[1:3]

# The window dump: ZPixmap, 24 or 32 bits per pixel, 8-bit masks naming the channels.
d = open(src, "rb").read()
hdr = struct.unpack(">25I", d[:100])
header_size, fmt, width, height = hdr[0], hdr[2], hdr[4], hdr[5]
byte_order, bpp, bpl = hdr[7], hdr[11], hdr[12]
masks, ncolours = hdr[14:17], hdr[19]
shifts = [(m & -m).bit_length() - 1 for m in masks]
if fmt != 2 or bpp not in (24, 32) or any(m >> s != 255 for m, s in zip(masks, shifts)):
    sys.exit("docs-images: %s: not a 24/32-bit ZPixmap window dump" % src)
start = header_size + 12 * ncolours
step = bpp // 8
order = "little" if byte_order == 0 else "big"
ms = list(zip(masks, shifts))
rows = []  # rows of R G B bytes
for y in range(height):
    row = d[start + y * bpl:start + y * bpl + width * step]
    px = [int.from_bytes(row[i:i + step], order) for i in range(0, width * step, step)]
    rows.append(bytes((p & m) >> s for p in px for m, s in ms))

# Each row as None (0), Sub (1) and Up (2); the picked rows and the three uniform streams.
prev = bytes(3 * width)
filtered = []
for r in rows:
    filtered.append((r, bytes((a - b) & 255 for a, b in zip(r, bytes(3) + r)),
                     bytes((a - b) & 255 for a, b in zip(r, prev))))
    prev = r
def cost(f):
    return sum(b if b < 128 else 256 - b for b in f)
picked = [min(range(3), key=lambda k: cost(fs[k])) for fs in filtered]
streams = [b"".join(bytes([k]) + fs[k] for k, fs in zip(picked, filtered))]
streams += [b"".join(bytes([k]) + fs[k] for fs in filtered) for k in range(3)]
idat = min((zlib.compress(s, 9) for s in streams), key=len)

def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
with open(dst, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n" +
            chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", idat) + chunk(b"IEND", b""))
PY
then
  die "python3 could not convert the window dump"
fi

mv "$tmp/show.png" "$outdir/first-hour-show.png"
mv "$tmp/snapshot.jpg" "$outdir/first-hour-snapshot.jpg"
echo "docs-images: wrote $outdir/first-hour-show.png (paused on frame $seq; the target" \
  "is hidden in frames $hidden_first-$hidden_last) and $outdir/first-hour-snapshot.jpg"
