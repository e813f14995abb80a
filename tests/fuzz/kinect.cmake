# Fuzz target of the Kinect pairer (drivers/kinect; no libfreenect needed: the pairer
# only tracks buffer states and times).
cuetrack_add_fuzzer(kinect_pairer SOURCES ${CMAKE_CURRENT_LIST_DIR}/kinect/fuzz_kinect_pairer.cpp
  ${CMAKE_SOURCE_DIR}/drivers/kinect/src/KinectPairer.cpp)
target_include_directories(fuzz_kinect_pairer PRIVATE ${CMAKE_SOURCE_DIR}/drivers/kinect/include)
find_package(Threads REQUIRED)
target_link_libraries(fuzz_kinect_pairer PRIVATE Threads::Threads)
