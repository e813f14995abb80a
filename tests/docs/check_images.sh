#!/usr/bin/env bash
# The docs' pictures: every picture README.md or docs/*.md shows is in docs/img and is
# made by a script of scripts/ (named there: docs-images.sh, benchmarks.sh), and every
# file of docs/img is shown by a doc (none left behind by a tool that no longer makes it).
#   check_images.sh ROOT      (ROOT: the clone; exit 0 all good, 1 a picture at fault)
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: check_images.sh ROOT" >&2; exit 2; }
root=$1
bad=0
shown=$(cd "$root" && grep -ohE '!\[[^]]*\]\((docs/)?img/[^)]+\)' README.md docs/*.md |
  sed -E 's/.*\((docs\/)?img\/([^)]+)\)/\2/' | sort -u)
for f in $shown; do
  if [ ! -f "$root/docs/img/$f" ]; then
    echo "check_images: docs show img/$f, which is not in docs/img"; bad=1
  elif ! grep -qF -- "$f" "$root"/scripts/*; then
    echo "check_images: no script of scripts/ makes img/$f"; bad=1
  fi
done
for p in "$root"/docs/img/*; do
  [ -e "$p" ] || continue
  f=$(basename "$p")
  grep -qxF -- "$f" <<<"$shown" || { echo "check_images: docs/img/$f is shown by no doc"; bad=1; }
done
[ "$bad" = 0 ] && echo "check_images: $(wc -w <<<"$shown") pictures, each made by a script"
exit "$bad"
