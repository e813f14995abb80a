# Fuzz targets of the serial protocol (area: platform/protocol, apps/cuetrack).
#   fuzz_proto_decoder: any byte stream through the frame decoder and message parser;
#                       every accepted message must re-encode to the same frame.
#   fuzz_proto_command: any byte stream through the device's command path (decoder,
#                       command parser, CommandHandler), plus the text command parser.
# The code under test is compiled into each target (not linked from the libraries) so
# that it carries libFuzzer's coverage instrumentation.
set(_proto ${CMAKE_SOURCE_DIR}/platform/protocol/cuetrack_proto.c)
cuetrack_add_fuzzer(proto_decoder SOURCES ${CMAKE_CURRENT_LIST_DIR}/protocol/fuzz_proto_decoder.cpp
  ${_proto})
cuetrack_add_fuzzer(proto_command SOURCES ${CMAKE_CURRENT_LIST_DIR}/protocol/fuzz_proto_command.cpp
  ${_proto} ${CMAKE_SOURCE_DIR}/apps/cuetrack/src/CommandHandler.cpp
  ${CMAKE_SOURCE_DIR}/platform/common/src/CommandText.cpp)
foreach(t fuzz_proto_decoder fuzz_proto_command)
  target_include_directories(${t} PRIVATE ${CMAKE_SOURCE_DIR}/platform/protocol
    ${CMAKE_SOURCE_DIR}/apps/cuetrack/src ${CMAKE_SOURCE_DIR}/platform/common/include)
  target_link_libraries(${t} PRIVATE cuetrack::core_headers)
endforeach()
