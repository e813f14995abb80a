#!/usr/bin/env bash
# usage: check_format.sh CLANG_FORMAT SOURCE_DIR
# The project's C/C++ files follow .clang-format (clang-format 14, --dry-run -Werror).
set -u
cf=$1 src=$2
cd "$src" || exit 2
mapfile -d '' files < <(find core platform drivers apps tests -type f \
  \( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.hpp' \) -print0 | sort -z)
out=$("$cf" --dry-run -Werror "${files[@]}" 2>&1)
rc=$?
if [ $rc -ne 0 ]; then
  grep -E 'error:' <<<"$out" | cut -d: -f1 | sort | uniq -c | sed 's/^/  needs clang-format: /'
  echo "check_format: run: clang-format -i <file> (repo .clang-format)"
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
