# Raspberry Pi 4 (BCM2711, Cortex-A72). Use with either toolchain.
if(CMAKE_SYSTEM_PROCESSOR STREQUAL "aarch64")
  string(APPEND CMAKE_C_FLAGS_INIT " -mcpu=cortex-a72")
  string(APPEND CMAKE_CXX_FLAGS_INIT " -mcpu=cortex-a72")
else()
  set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-a72 -mfpu=neon-fp-armv8 -mfloat-abi=hard")
  set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-a72 -mfpu=neon-fp-armv8 -mfloat-abi=hard")
endif()
