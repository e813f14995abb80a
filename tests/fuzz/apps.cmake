# Fuzz targets of the apps' own parsers (issue 34):
#   fuzz_app_options   cuetrack's command line (NUL-separated argv)
#   fuzz_listen_seq    cuetrack-listen's sequence bookkeeping (SeqCounter)
#   fuzz_listen_options cuetrack-listen's command line (NUL-separated argv)
#   fuzz_source_spec   synth:<scene>[:frames] through the shared source factory
# The parsers' sources are compiled into each target (coverage instrumentation).
set(_app ${CMAKE_SOURCE_DIR}/apps)
# Through the command-line layer (apps/common, CLI11), as fuzz_listen_options below.
cuetrack_add_fuzzer(app_options SOURCES ${CMAKE_CURRENT_LIST_DIR}/apps/fuzz_app_options.cpp
  ${_app}/cuetrack/src/Options.cpp ${CMAKE_SOURCE_DIR}/platform/common/src/HostPort.cpp
  ${_app}/common/src/Command.cpp LIBS cuetrack_cli)
target_include_directories(fuzz_app_options PRIVATE ${_app}/cuetrack/src
  ${CMAKE_SOURCE_DIR}/core/include ${CMAKE_SOURCE_DIR}/platform/common/include)

cuetrack_add_fuzzer(listen_seq SOURCES ${CMAKE_CURRENT_LIST_DIR}/apps/fuzz_listen_seq.cpp)
target_include_directories(fuzz_listen_seq PRIVATE ${_app}/listen/src)

cuetrack_add_fuzzer(source_spec SOURCES ${CMAKE_CURRENT_LIST_DIR}/apps/fuzz_source_spec.cpp
  LIBS cuetrack_open_source)

# Through the command-line layer (apps/common, CLI11): its Command.cpp is compiled in too,
# the value checks come from its library.
cuetrack_add_fuzzer(listen_options SOURCES ${CMAKE_CURRENT_LIST_DIR}/apps/fuzz_listen_options.cpp
  ${_app}/listen/src/ListenOptions.cpp ${CMAKE_SOURCE_DIR}/platform/common/src/CommandText.cpp
  ${_app}/common/src/Command.cpp
  LIBS cuetrack_proto cuetrack_cli)
target_include_directories(fuzz_listen_options PRIVATE ${_app}/listen/src
  ${CMAKE_SOURCE_DIR}/platform/common/include)
