#!/bin/sh
# The compiler launcher of every preset (CMakeLists.txt sets it when ccache is installed):
# ccache with the project's settings, so that every clone on a machine shares one cache.
# - The cache lives outside the clone: $CUETRACK_CCACHE_DIR, else $CCACHE_DIR, else
#   ~/.cache/cuetrack/ccache (capped by scripts/test.sh on first use).
# - Paths under the clone are hashed relative to it (base dir) and the working folder is
#   left out of the hash: a clone in another folder hits the same entries.
# Usage (by CMake): scripts/ccache.sh COMPILER ARGS...
CCACHE_DIR=${CUETRACK_CCACHE_DIR:-${CCACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/cuetrack/ccache}}
CCACHE_BASEDIR=${0%/scripts/ccache.sh}  # the clone (CMake passes this file's absolute path)
CCACHE_NOHASHDIR=1
# The tests' precompiled header (tests/CMakeLists.txt) is cacheable only with these: the
# header is made in the same build, just before the files that use it.
CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:+$CCACHE_SLOPPINESS,}pch_defines,time_macros,include_file_mtime,include_file_ctime
export CCACHE_DIR CCACHE_BASEDIR CCACHE_NOHASHDIR CCACHE_SLOPPINESS
exec ccache "$@"
