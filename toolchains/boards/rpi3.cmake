# Raspberry Pi 3 (BCM2837, Cortex-A53). Use with either toolchain.
if(CMAKE_SYSTEM_PROCESSOR STREQUAL "aarch64")
  string(APPEND CMAKE_C_FLAGS_INIT " -mcpu=cortex-a53")
  string(APPEND CMAKE_CXX_FLAGS_INIT " -mcpu=cortex-a53")
else()
  set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-a53 -mfpu=neon-fp-armv8 -mfloat-abi=hard")
  set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-a53 -mfpu=neon-fp-armv8 -mfloat-abi=hard")
endif()
