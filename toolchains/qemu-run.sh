#!/bin/sh
# CMAKE_CROSSCOMPILING_EMULATOR for the cross builds: runs one ARM program under qemu-user.
# usage: qemu-run.sh QEMU TRIPLE [-E VAR=VALUE]... PROGRAM [ARGS...]
# The loader is pointed at the cross libc (/usr/TRIPLE/lib) before Debian's multiarch
# libraries: without it, programs linked against the multiarch libraries spin forever at
# start-up. A test's own library path goes in front instead of replacing that one:
# LD_LIBRARY_PATH from the environment (as on the host, e.g. /usr/lib/TRIPLE/fakenect for
# the fakenect replay library) and any leading `-E LD_LIBRARY_PATH=...`.
# CUETRACK_EMULATED=1 tells a test it runs under emulation (10-50x slower than native),
# so a long end-to-end test can run fewer frames there instead of being skipped.
qemu=$1 triple=$2
shift 2
front=${LD_LIBRARY_PATH:-}
env_args=""
while [ "$#" -ge 2 ] && [ "$1" = "-E" ]; do
  case "$2" in
    LD_LIBRARY_PATH=*) front="${2#LD_LIBRARY_PATH=}${front:+:$front}" ;;
    *) env_args="$env_args $2" ;;  # VAR=VALUE without spaces
  esac
  shift 2
done
set -- -L "/usr/$triple" -E CUETRACK_EMULATED=1 \
  -E "LD_LIBRARY_PATH=${front:+$front:}/usr/$triple/lib:/usr/lib/$triple" \
  $(for kv in $env_args; do printf -- '-E %s ' "$kv"; done) "$@"
exec "$qemu" "$@"
