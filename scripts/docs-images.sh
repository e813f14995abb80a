#!/usr/bin/env bash
# Regenerates the two pictures of docs/first-hour.md with the built tools:
#   docs/img/first-hour-show.jpg      the `cuetrack --show` window, paused while the target
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
# stopped changing. python3 (standard library only) writes the dump as a JPEG with the
# tables of the snapshot's JPEG (OpenCV's, quality 95), so both pictures are encoded alike.
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

# 3. A virtual display on a free number (-displayfd prints it once clients may connect).
Xvfb -displayfd 1 -screen 0 1280x800x24 -nolisten tcp >"$tmp/display" 2>"$tmp/xvfb.err" &
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

# 5. The dump as a JPEG: baseline, 4:2:0, the quantisation and Huffman tables of the
# snapshot's JPEG (OpenCV's defaults), so both pictures are encoded alike.
if ! python3 - "$tmp/b.xwd" "$tmp/snapshot.jpg" "$tmp/show.jpg" <<'PY'
import math, struct, sys

src, ref, dst = sys.argv[1:4]

# The window dump: ZPixmap, 24 or 32 bits per pixel, masks naming the channels.
d = open(src, "rb").read()
hdr = struct.unpack(">25I", d[:100])
header_size, fmt, width, height = hdr[0], hdr[2], hdr[4], hdr[5]
byte_order, bpp, bpl = hdr[7], hdr[11], hdr[12]
masks, ncolours = hdr[14:17], hdr[19]
if fmt != 2 or bpp not in (24, 32):
    sys.exit("docs-images: %s: not a 24/32-bit ZPixmap window dump" % src)
start = header_size + 12 * ncolours
shifts = [(m & -m).bit_length() - 1 for m in masks]
step = bpp // 8
order = "little" if byte_order == 0 else "big"
rgb = []  # rows of (r, g, b)
for y in range(height):
    row = d[start + y * bpl:start + y * bpl + width * step]
    px = [int.from_bytes(row[i:i + step], order) for i in range(0, width * step, step)]
    rgb.append([tuple((p & m) >> s for m, s in zip(masks, shifts)) for p in px])

# The tables: DQT and DHT segments of the reference JPEG, copied as they are.
r = open(ref, "rb").read()
segments, qt, i = [], {}, 2
while r[i + 1] != 0xDA:
    marker, length = r[i + 1], struct.unpack(">H", r[i + 2:i + 4])[0]
    body = r[i + 4:i + 2 + length]
    if marker == 0xDB:
        segments.append(r[i:i + 2 + length])
        j = 0
        while j < len(body):
            if body[j] >> 4:
                sys.exit("docs-images: %s: 16-bit quantisation tables" % ref)
            qt[body[j] & 15] = body[j + 1:j + 65]  # zigzag order
            j += 65
    elif marker == 0xC4:
        segments.append(r[i:i + 2 + length])
    i += 2 + length
huff = {}
for seg in segments:
    if seg[1] != 0xC4:
        continue
    body, j = seg[4:], 0
    while j < len(body):
        tc, bits = body[j], body[j + 1:j + 17]
        vals = body[j + 17:j + 17 + sum(bits)]
        codes, code, k = {}, 0, 0
        for n in range(16):
            for _ in range(bits[n]):
                codes[vals[k]] = (code, n + 1)
                code += 1
                k += 1
            code <<= 1
        huff[tc] = codes
        j += 17 + sum(bits)
if set(qt) != {0, 1} or set(huff) != {0x00, 0x10, 0x01, 0x11}:
    sys.exit("docs-images: %s: not one luma and one chroma table of each kind" % ref)

zigzag = sorted(range(64), key=lambda n: (n // 8 + n % 8,
                (n % 8) if (n // 8 + n % 8) % 2 == 0 else (n // 8)))
cos = [[(math.sqrt(0.5) if u == 0 else 1.0) / 2 * math.cos((2 * x + 1) * u * math.pi / 16)
        for x in range(8)] for u in range(8)]

# Colour to YCbCr (JFIF), edges repeated to whole 16x16 MCUs, chroma averaged 2x2.
W, H = (width + 15) // 16 * 16, (height + 15) // 16 * 16
Y = [[0.0] * W for _ in range(H)]
Cb = [[0.0] * W for _ in range(H)]
Cr = [[0.0] * W for _ in range(H)]
for y in range(H):
    row = rgb[min(y, height - 1)]
    Yy, Cby, Cry = Y[y], Cb[y], Cr[y]
    for x in range(W):
        R, G, B = row[min(x, width - 1)]
        Yy[x] = 0.299 * R + 0.587 * G + 0.114 * B - 128
        Cby[x] = -0.168736 * R - 0.331264 * G + 0.5 * B
        Cry[x] = 0.5 * R - 0.418688 * G - 0.081312 * B
def half(P):
    return [[(P[2 * y][2 * x] + P[2 * y][2 * x + 1] + P[2 * y + 1][2 * x] +
              P[2 * y + 1][2 * x + 1]) / 4 for x in range(W // 2)] for y in range(H // 2)]
Cb, Cr = half(Cb), half(Cr)

out = bytearray()
acc = nbits = 0
def put(code, length):
    global acc, nbits
    acc = (acc << length) | code
    nbits += length
    while nbits >= 8:
        nbits -= 8
        b = (acc >> nbits) & 0xFF
        out.append(b)
        if b == 0xFF:
            out.append(0)
    acc &= (1 << nbits) - 1

def block(P, bx, by, q, dc_table, ac_table, prev):
    rows = [P[by + k][bx:bx + 8] for k in range(8)]
    t = [[sum(c * v for c, v in zip(cu, r)) for cu in cos] for r in rows]  # t[y][u]
    coef = [0] * 64
    for k, n in enumerate(zigzag):
        v, u = divmod(n, 8)
        cv = cos[v]
        coef[k] = int(round(sum(cv[y] * t[y][u] for y in range(8)) / q[k]))
    diff = coef[0] - prev
    s = abs(diff).bit_length()
    put(*dc_table[s])
    if s:
        put(diff if diff > 0 else diff + (1 << s) - 1, s)
    run = 0
    for k in range(1, 64):
        a = coef[k]
        if a == 0:
            run += 1
            continue
        while run > 15:
            put(*ac_table[0xF0])
            run -= 16
        s = abs(a).bit_length()
        put(*ac_table[(run << 4) | s])
        put(a if a > 0 else a + (1 << s) - 1, s)
        run = 0
    if run:
        put(*ac_table[0x00])
    return coef[0]

qy, qc = qt[0], qt[1]
pred = [0, 0, 0]
for my in range(0, H, 16):
    for mx in range(0, W, 16):
        for oy, ox in ((0, 0), (0, 8), (8, 0), (8, 8)):
            pred[0] = block(Y, mx + ox, my + oy, qy, huff[0x00], huff[0x10], pred[0])
        pred[1] = block(Cb, mx // 2, my // 2, qc, huff[0x01], huff[0x11], pred[1])
        pred[2] = block(Cr, mx // 2, my // 2, qc, huff[0x01], huff[0x11], pred[2])
if nbits:
    put((1 << (8 - nbits)) - 1, 8 - nbits)  # pad with ones

sof = struct.pack(">BHHB", 8, height, width, 3) + bytes([1, 0x22, 0, 2, 0x11, 1, 3, 0x11, 1])
sos = bytes([3, 1, 0x00, 2, 0x11, 3, 0x11, 0, 63, 0])
jfif = b"JFIF\0" + bytes([1, 1, 0, 0, 1, 0, 1, 0, 0])
def seg(marker, body):
    return bytes([0xFF, marker]) + struct.pack(">H", len(body) + 2) + body
dqt = [s for s in segments if s[1] == 0xDB]
dht = [s for s in segments if s[1] == 0xC4]
with open(dst, "wb") as f:
    f.write(b"\xFF\xD8" + seg(0xE0, jfif) + b"".join(dqt) + seg(0xC0, sof) + b"".join(dht) +
            seg(0xDA, sos) + bytes(out) + b"\xFF\xD9")
PY
then
  die "python3 could not convert the window dump"
fi

mv "$tmp/show.jpg" "$outdir/first-hour-show.jpg"
mv "$tmp/snapshot.jpg" "$outdir/first-hour-snapshot.jpg"
echo "docs-images: wrote $outdir/first-hour-show.jpg (paused on frame $seq; the target" \
  "is hidden in frames $hidden_first-$hidden_last) and $outdir/first-hour-snapshot.jpg"
