#!/usr/bin/env bash
# usage: check_no_fma.sh OBJDUMP FILE...
# Fails when a function of namespace cuetrack contains a fused multiply-add (aarch64
# fmadd/fmsub/fnmadd/fnmsub, vector fmla/fmls; x86 vfmadd & co.; ARM vfma/vfms). Core is
# built with -ffp-contract=off, and so must be every copy of its header templates that a
# consumer instantiates (the linker keeps one of them): a fused copy rounds differently,
# and the same seed would no longer give the same track on every ISA.
set -u
objdump_tool=$1
shift
total=0
for f in "$@"; do
  if [ ! -f "$f" ]; then echo "check_no_fma: $f: no such file" >&2; exit 2; fi
  listing=$("$objdump_tool" -d -C --no-show-raw-insn "$f") ||
    { echo "check_no_fma: $objdump_tool failed on $f" >&2; exit 2; }
  hits=$(awk '
    /^[0-9a-f]+ <.*>:$/ { fn = $0; sub(/^[0-9a-f]+ </, "", fn); sub(/>:$/, "", fn); next }
    fn ~ /cuetrack::/ && $2 ~ /^(fn?m(add|sub)|fml[as]|vfn?m(add|sub)[0-9a-z]*|vfn?m[as](\.f(32|64))?)$/ {
      n[fn]++
    }
    END { for (k in n) printf "%d %s\n", n[k], k }' <<<"$listing" | sort -rn)
  if [ -n "$hits" ]; then
    count=$(awk '{ s += $1 } END { print s }' <<<"$hits")
    total=$((total + count))
    echo "check_no_fma: $(basename "$f"): $count fused multiply-add(s) in cuetrack code:"
    head -n 8 <<<"$hits" | sed 's/^/  /'
  fi
done
if [ "$total" -gt 0 ]; then exit 1; fi
echo "check_no_fma: no fused multiply-add in cuetrack code of $# file(s)"
