# Fuzz targets of the recorded-frame parsers (area: drivers/recorded). All parsers take
# memory buffers; their sources are compiled into each target so they carry libFuzzer's
# coverage instrumentation and ASan/UBSan checks. No OpenCV here (the fuzz preset has none).
#   fuzz_recorded_pnm         PGM/PPM header + 8/16-bit decoding (fakenect, NYU stills)
#   fuzz_recorded_index       fakenect INDEX.txt lines
#   fuzz_recorded_gt          ground-truth files, BoBoT and OTB
#   fuzz_recorded_intrinsics  intrinsics.txt
#   fuzz_recorded_fakenect    a whole fakenect recording (INDEX + files), read and checked
#   fuzz_recorded_specs       the pan: and still: source specs
set(_rec ${CMAKE_SOURCE_DIR}/drivers/recorded)
set(_rec_src ${_rec}/src/RecordedParsers.cpp ${_rec}/src/StillSpecs.cpp ${_rec}/src/GroundTruth.cpp
  ${_rec}/src/FileBuffer.cpp)
foreach(name pnm index gt intrinsics specs)
  cuetrack_add_fuzzer(recorded_${name}
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/recorded/fuzz_recorded_${name}.cpp ${_rec_src})
  target_include_directories(fuzz_recorded_${name} PRIVATE ${_rec}/include)
  target_link_libraries(fuzz_recorded_${name} PRIVATE cuetrack_frame_source)
endforeach()

# The whole reader: Fakenect.cpp, its base and the Kinect depth table with the parsers.
cuetrack_add_fuzzer(recorded_fakenect
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/recorded/fuzz_recorded_fakenect.cpp ${_rec}/src/Fakenect.cpp
  ${_rec}/src/RecordedReader.cpp ${_rec_src} LIBS cuetrack_recorded)
target_include_directories(fuzz_recorded_fakenect PRIVATE ${_rec}/include
  ${CMAKE_SOURCE_DIR}/core/include ${CMAKE_SOURCE_DIR}/drivers/common/include)
