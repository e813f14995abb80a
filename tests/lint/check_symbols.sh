#!/usr/bin/env bash
# usage: check_symbols.sh NM LIBRARY.a
# Fails when the library's object code calls an allocator or throws: operator
# new/new[] (any overload), malloc & co., __cxa_throw/__cxa_allocate_exception or
# std::__throw_* (what -fno-exceptions code reaches through e.g. std::array::at).
set -u
nm_tool=$1 lib=$2
if [ ! -f "$lib" ]; then echo "check_symbols: $lib: no such library" >&2; exit 2; fi
undefined=$("$nm_tool" -u "$lib") || { echo "check_symbols: $nm_tool failed on $lib" >&2; exit 2; }
# Mangled names, so both 64-bit (_Znwm) and 32-bit ARM (_Znwj) operator new match.
banned=$(awk 'NF { print $NF }' <<<"$undefined" | sort -u | grep -E \
  '^(_Zn[wa][jmy].*|malloc|calloc|realloc|aligned_alloc|posix_memalign|memalign|valloc|strdup|__cxa_throw|__cxa_allocate_exception|_ZSt[0-9]+__throw_.*)$')
if [ -n "$banned" ]; then
  echo "check_symbols: $(basename "$lib") banned symbols: $(tr '\n' ' ' <<<"$banned")"
  while read -r s; do
    echo "  $s = $(c++filt "$s" 2>/dev/null || echo "$s")"
  done <<<"$banned"
  exit 1
fi
echo "check_symbols: $(basename "$lib"): no allocator or throw among $(grep -c ' U ' <<<"$undefined") undefined symbols"
