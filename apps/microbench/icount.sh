#!/usr/bin/env bash
# Exact instructions per 640x480 frame of each integral-image kernel on ARM, counted
# by the qemu-icount plugin (/work/shared/tools/qemu-icount or $CUETRACK_ICOUNT_DIR).
# usage: apps/microbench/icount.sh [BUILD_DIR] [FRAMES]
#   BUILD_DIR: an aarch64 or armhf build tree with cuetrack-microbench (default build/aarch64)
# Per frame = (count at FRAMES frames - count at 0 frames) / FRAMES, so start-up and the
# test-image fill cancel out.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build/aarch64}
frames=${2:-4}
tools=${CUETRACK_ICOUNT_DIR:-$(pwd)/../shared/tools/qemu-icount}
bin="$build/bin/cuetrack-microbench"
[ -x "$bin" ] || { echo "icount.sh: $bin not built (cmake --build $build --target cuetrack-microbench)" >&2; exit 2; }
plugin="$(pwd)/build/icount/libicount.so"
[ -f "$plugin" ] || sh "$tools/build.sh" "$(dirname "$plugin")" >/dev/null

case "$(sed -n 's/^CMAKE_TOOLCHAIN_FILE:[A-Z]*=//p' "$build/CMakeCache.txt")" in
  *aarch64*) qemu=qemu-aarch64 triple=aarch64-linux-gnu ;;
  *arm-linux*) qemu=qemu-arm triple=arm-linux-gnueabihf ;;
  *) echo "icount.sh: $build is not an aarch64/armhf build tree" >&2; exit 2 ;;
esac
count() {  # count ISA KERNEL FRAMES -> instructions
  local log; log=$(mktemp)
  "$qemu" -L "/usr/$triple" -E "LD_LIBRARY_PATH=/usr/$triple/lib:/usr/lib/$triple" \
    -plugin "$plugin" -d plugin -D "$log" "$bin" --icount "$3" --isa "$1" --kernel "$2" >/dev/null
  sed -n 's/^insns: //p' "$log"; rm -f "$log"
}
printf '%-6s %-7s %16s %12s\n' kernel isa "insns/frame" "vs scalar"
for k in rgb depth gray; do
  ref=0
  for isa in scalar neon; do
    n=$(( ($(count "$isa" "$k" "$frames") - $(count "$isa" "$k" 0)) / frames ))
    [ "$isa" = scalar ] && ref=$n
    printf '%-6s %-7s %16d %11.2fx\n' "$k" "$isa" "$n" "$(awk -v a="$ref" -v b="$n" 'BEGIN { print a / b }')"
  done
done
