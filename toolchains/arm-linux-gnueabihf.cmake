# Cross toolchain: 32-bit ARM Linux boards, hard float with NEON (Raspberry Pi OS 32-bit, BeagleBone...).
# Only the triple, compilers, find-root modes and the emulator live here;
# CPU flags are in boards/*.cmake (pass -DCUETRACK_BOARD=rpi3).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR armv7l)
set(CUETRACK_TRIPLE arm-linux-gnueabihf)
# NEON is not implied by the armhf ABI (ARMv7 + VFPv3-D16): ask for it, unless a board file sets -mfpu.
set(CUETRACK_ARCH_FLAGS "-march=armv7-a -mfpu=neon-vfpv4 -mfloat-abi=hard")
include(${CMAKE_CURRENT_LIST_DIR}/cross-common.cmake)
