# Cross toolchain: 64-bit ARM Linux boards (Raspberry Pi 3/4/5 with a 64-bit OS, Jetson, RK3588...).
# Only the triple, compilers, find-root modes and the emulator live here;
# CPU flags are in boards/*.cmake (pass -DCUETRACK_BOARD=rpi4).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CUETRACK_TRIPLE aarch64-linux-gnu)
include(${CMAKE_CURRENT_LIST_DIR}/cross-common.cmake)
