#!/usr/bin/env bash
# usage: check_core_purity.sh DIR
# core/ must include no OS, driver, OpenCV, I/O or allocating-container header and
# must not allocate (new-expressions, malloc & co., make_unique/make_shared).
# Placement new (`new (buffer) T`) is allowed; // comments are ignored.
set -u
dir=$1
[ -d "$dir" ] || { echo "check_core_purity: $dir: no such folder" >&2; exit 2; }
banned_include='^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"](opencv2?/|libfreenect|libusb|unistd\.h|fcntl\.h|termios\.h|poll\.h|signal\.h|csignal>|sys/|pthread\.h|dirent\.h|thread>|mutex>|condition_variable>|future>|chrono>|ctime>|time\.h|fstream>|iostream>|sstream>|istream>|ostream>|cstdio>|stdio\.h|filesystem>|vector>|string>|map>|unordered_map>|set>|unordered_set>|list>|forward_list>|deque>|queue>|stack>|functional>|memory>|regex>|any>)'
allocation='(^|[^[:alnum:]_])(new[[:space:]]+[[:alpha:]_:]|(malloc|calloc|realloc|aligned_alloc|posix_memalign|strdup|make_unique|make_shared)[[:space:]]*[(<])'
includes=0 allocs=0
while IFS= read -r -d '' f; do
  # Strip // comments (keeps line numbers), then look.
  code=$(sed -e 's://.*$::' "$f")
  while IFS= read -r hit; do
    [ -n "$hit" ] || continue
    echo "$f:${hit%%:*}: banned include: ${hit#*:}"
    includes=$((includes + 1))
  done < <(grep -nE "$banned_include" <<<"$code")
  while IFS= read -r hit; do
    [ -n "$hit" ] || continue
    echo "$f:${hit%%:*}: allocation: ${hit#*:}"
    allocs=$((allocs + 1))
  done < <(grep -nE "$allocation" <<<"$code")
done < <(find "$dir" -type f \( -name '*.hpp' -o -name '*.h' -o -name '*.cpp' -o -name '*.c' -o -name '*.inl' \) -print0 | sort -z)
echo "check_core_purity: $dir: purity: $includes banned include(s), $allocs allocation(s)"
[ $((includes + allocs)) -eq 0 ]
