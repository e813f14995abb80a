#!/bin/sh
# CMAKE_CROSSCOMPILING_EMULATOR for the cross builds: runs one ARM program under qemu-user.
# usage: qemu-run.sh QEMU TRIPLE PROGRAM [ARGS...]
# The loader is pointed at the cross libc (/usr/TRIPLE/lib) before Debian's multiarch
# libraries: without it, programs linked against the multiarch libraries spin forever at
# start-up. A test's own LD_LIBRARY_PATH (e.g. the fakenect replay library in
# /usr/lib/TRIPLE/fakenect) goes first instead of being dropped by qemu's -E.
# CUETRACK_EMULATED=1 tells a test it runs under emulation (10-50x slower than native),
# so a long end-to-end test can run fewer frames there instead of being skipped.
qemu=$1 triple=$2
shift 2
exec "$qemu" -L "/usr/$triple" -E CUETRACK_EMULATED=1 \
  -E "LD_LIBRARY_PATH=${LD_LIBRARY_PATH:+$LD_LIBRARY_PATH:}/usr/$triple/lib:/usr/lib/$triple" "$@"
