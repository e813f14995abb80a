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

# Debian multiarch: target libraries live in /usr/lib/<triple>, headers in /usr/include.
set(CMAKE_FIND_ROOT_PATH /usr/${CUETRACK_TRIPLE} /usr/lib/${CUETRACK_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/${CUETRACK_TRIPLE}/pkgconfig:/usr/share/pkgconfig")
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
