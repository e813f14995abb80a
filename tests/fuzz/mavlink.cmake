# Fuzz target of the MAVLink parser and link (area: platform/mavlink).
#   fuzz_mavlink_parser: any byte stream through our MAVLink 2 parser (every accepted
#                        message re-encodes and parses back the same), the same bytes cut
#                        into datagrams through the datagram parser and MavlinkLink over a
#                        datagram stream (nothing carries from one datagram to the next),
#                        then through MavlinkLink over an in-memory cable (commands in range,
#                        at most one ACK per command, never a crash).
# The code under test is compiled into the target so that it carries coverage.
set(_mav ${CMAKE_SOURCE_DIR}/platform/mavlink/src)
cuetrack_add_fuzzer(mavlink_parser SOURCES ${CMAKE_CURRENT_LIST_DIR}/mavlink/fuzz_mavlink_parser.cpp
  ${_mav}/MavlinkCodec.cpp ${_mav}/MavlinkMessages.cpp ${_mav}/CameraMount.cpp ${_mav}/MavlinkLink.cpp
  ${_mav}/Sha256.cpp ${_mav}/Signing.cpp
  ${CMAKE_SOURCE_DIR}/platform/common/src/QueuedPort.cpp
  ${CMAKE_SOURCE_DIR}/platform/fake/src/FakeSerial.cpp)
target_include_directories(fuzz_mavlink_parser PRIVATE ${CMAKE_SOURCE_DIR}/platform/mavlink/include
  ${CMAKE_SOURCE_DIR}/platform/common/include ${CMAKE_SOURCE_DIR}/platform/fake/include
  ${CMAKE_SOURCE_DIR}/platform/protocol)
target_link_libraries(fuzz_mavlink_parser PRIVATE cuetrack::core_headers)
#   fuzz_mavlink_resync: any bytes followed by a valid command; the oracle is that the
#                        command is decoded on a byte stream and in a datagram, and every
#                        byte is accounted for (issue 56).
cuetrack_add_fuzzer(mavlink_resync SOURCES ${CMAKE_CURRENT_LIST_DIR}/mavlink/fuzz_mavlink_resync.cpp
  ${_mav}/MavlinkCodec.cpp ${_mav}/MavlinkMessages.cpp)
target_include_directories(fuzz_mavlink_resync PRIVATE ${CMAKE_SOURCE_DIR}/platform/mavlink/include
  ${CMAKE_SOURCE_DIR}/platform/common/include ${CMAKE_SOURCE_DIR}/platform/protocol)
target_link_libraries(fuzz_mavlink_resync PRIVATE cuetrack::core_headers)
