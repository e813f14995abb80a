# Shared by the cross toolchain files: compilers from CUETRACK_TRIPLE, Debian multiarch
# libraries, qemu-user as the emulator so plain ctest runs the ARM tests.
find_program(CUETRACK_CROSS_CC ${CUETRACK_TRIPLE}-gcc)
find_program(CUETRACK_CROSS_CXX ${CUETRACK_TRIPLE}-g++)
if(NOT CUETRACK_CROSS_CC OR NOT CUETRACK_CROSS_CXX)
  message(FATAL_ERROR "${CUETRACK_TRIPLE}-gcc/g++ not found: run scripts/setup.sh (or install g++-${CUETRACK_TRIPLE})")
endif()
set(CMAKE_C_COMPILER ${CUETRACK_CROSS_CC})
set(CMAKE_CXX_COMPILER ${CUETRACK_CROSS_CXX})
set(CMAKE_LIBRARY_ARCHITECTURE ${CUETRACK_TRIPLE})

# Debian multiarch: the target's libraries live in /usr/lib/<triple> (and its libc in
# /usr/<triple>), beside the build machine's. There is no separate sysroot: the Debian
# cross compiler's is /, and CMAKE_SYSROOT=/ would make all of / a find root, the
# build machine's /usr/lib and /usr/local included. So the find roots are exactly the
# target's own folders and every find_library/find_path/find_package searches only
# there (ONLY): a library of the build machine cannot be found. Programs (pkg-config,
# qemu) are the build machine's (NEVER). pkg-config reads only the target's .pc files
# (and the architecture-independent ones); its -L/usr/lib/<triple> lies inside a root.
# Headers in /usr/include are shared by all architectures but lie outside the roots
# (find_path would not see them): the compiler searches /usr/include itself, libraries
# give their include folders through pkg-config, and header-only packages are found
# through their config folders (Catch2_DIR, Eigen3_DIR in CMakePresets.json).
set(CMAKE_FIND_ROOT_PATH /usr/${CUETRACK_TRIPLE} /usr/lib/${CUETRACK_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/${CUETRACK_TRIPLE}/pkgconfig:/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "")

if(CUETRACK_ARCH_FLAGS)
  set(CMAKE_C_FLAGS_INIT "${CUETRACK_ARCH_FLAGS}")
  set(CMAKE_CXX_FLAGS_INIT "${CUETRACK_ARCH_FLAGS}")
endif()
if(CUETRACK_BOARD)
  include(${CMAKE_CURRENT_LIST_DIR}/boards/${CUETRACK_BOARD}.cmake)
endif()

# binfmt_misc is not assumed: call qemu explicitly, through qemu-run.sh, which points the
# loader at the cross libc first (the multiarch libc and the cross loader differ: without
# it, programs linked against multiarch libraries spin forever at start-up) and keeps a
# test's own LD_LIBRARY_PATH (fakenect) in front.
if(CUETRACK_TRIPLE MATCHES "^aarch64")
  set(_qemu qemu-aarch64)
else()
  set(_qemu qemu-arm)
endif()
find_program(CUETRACK_QEMU NAMES ${_qemu} ${_qemu}-static)
if(CUETRACK_QEMU)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/qemu-run.sh ${CUETRACK_QEMU}
      ${CUETRACK_TRIPLE})
else()
  message(WARNING "${_qemu} not found: ARM tests cannot run (install qemu-user: scripts/setup.sh)")
endif()
