# Raspberry Pi 5 (BCM2712, Cortex-A76). Use with either toolchain.
if(CMAKE_SYSTEM_PROCESSOR STREQUAL "aarch64")
  string(APPEND CMAKE_C_FLAGS_INIT " -mcpu=cortex-a76")
  string(APPEND CMAKE_CXX_FLAGS_INIT " -mcpu=cortex-a76")
else()
  set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-a76 -mfpu=neon-fp-armv8 -mfloat-abi=hard")
  set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-a76 -mfpu=neon-fp-armv8 -mfloat-abi=hard")
endif()
