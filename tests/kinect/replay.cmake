# Included by tests/kinect/CMakeLists.txt: the live code path through fakenect, and
# cuetrack-record.
# ---- How to run a program of this build, plain or under fakenect -----------------
# Host: LD_LIBRARY_PATH=<fakenect dir> in the test's environment. Cross builds run
# under qemu-user, whose emulator line sets the guest's LD_LIBRARY_PATH itself
# (toolchains/cross-common.cmake): prepend the target's fakenect dir to that -E value
# (a copy of the line; the toolchain file stays as it is).
set(_fakenect_dir /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/fakenect)
set(_run_plain "")
set(_run_fakenect "")
set(_fakenect_env "")
if(CMAKE_CROSSCOMPILING)
  set(_run_plain ${CMAKE_CROSSCOMPILING_EMULATOR})
  set(_run_fakenect ${CMAKE_CROSSCOMPILING_EMULATOR})
  set(_patched OFF)
  foreach(_arg IN LISTS CMAKE_CROSSCOMPILING_EMULATOR)
    if(_arg MATCHES "^LD_LIBRARY_PATH=")
      set(_patched ON)
    endif()
  endforeach()
  if(_patched)
    list(TRANSFORM _run_fakenect REPLACE "^LD_LIBRARY_PATH=" "LD_LIBRARY_PATH=${_fakenect_dir}:")
  else()
    list(APPEND _run_fakenect -E LD_LIBRARY_PATH=${_fakenect_dir})
  endif()
else()
  set(_fakenect_env "LD_LIBRARY_PATH=${_fakenect_dir}")
endif()

# Without a usable fakenect the replay tests are still registered, each reporting SKIPPED
# with the reason (counted, not dropped); _run_fakenect then marks the commands that need it.
set(_fakenect_missing "")
if(NOT EXISTS ${_fakenect_dir}/libfreenect.so.0.5 OR (CMAKE_CROSSCOMPILING AND NOT CMAKE_CROSSCOMPILING_EMULATOR))
  set(_fakenect_missing "fakenect not usable for ${CMAKE_LIBRARY_ARCHITECTURE} (${_fakenect_dir}): install libfreenect-bin / libfreenect0.5:<arch> (scripts/setup.sh)")
  message(STATUS "${_fakenect_missing}: Kinect replay tests report skipped")
  set(_run_fakenect CUETRACK_NO_FAKENECT)
endif()
if(NOT TARGET cuetrack_recorded OR NOT TARGET cuetrack_synth OR NOT TARGET cuetrack_platform_linux)
  message(STATUS "Kinect replay tests skipped: need cuetrack_recorded, cuetrack_synth, cuetrack_platform_linux")
  return()
endif()

# ---- Recordings, generated at test time (fixture) ----------------------------------
set(_rec ${CMAKE_CURRENT_BINARY_DIR}/recordings)
add_executable(make_fakenect_recording make_fakenect_recording.cpp)
target_link_libraries(make_fakenect_recording PRIVATE cuetrack_recorded cuetrack_synth cuetrack_warnings)
# 12 frames of a moving target; and 8 frames with a 1.5 s pause after frame 3 (a stall).
add_test(NAME test_kinect_make_recordings
         COMMAND ${CMAKE_COMMAND} -E rm -rf ${_rec})
add_test(NAME test_kinect_make_recording_moving
         COMMAND make_fakenect_recording ${_rec}/moving moving 12)
add_test(NAME test_kinect_make_recording_stall
         COMMAND make_fakenect_recording ${_rec}/stall moving 8 4 1500)
set_tests_properties(test_kinect_make_recordings PROPERTIES FIXTURES_SETUP kinect_clean LABELS kinect)
set_tests_properties(test_kinect_make_recording_moving test_kinect_make_recording_stall PROPERTIES
  FIXTURES_SETUP kinect_recordings FIXTURES_REQUIRED kinect_clean LABELS kinect TIMEOUT 300)

# ---- Replay tests: one process per case (fakenect's state is global) ----------------
add_executable(test_kinect_replay test_kinect_replay.cpp)
target_link_libraries(test_kinect_replay PRIVATE cuetrack_test_main cuetrack_kinect cuetrack_recorded
                      cuetrack::core cuetrack_platform_linux cuetrack_alloc_counter cuetrack_warnings)
cuetrack_use_test_pch(test_kinect_replay)

if(TARGET cuetrack_recorded_cv)  # RGB-D folder reader for cuetrack-record --format rgbd
  target_link_libraries(test_kinect_replay PRIVATE cuetrack_recorded_cv)
  target_compile_definitions(test_kinect_replay PRIVATE CUETRACK_TEST_HAVE_RGBD)
endif()

# kinect_replay_test(name tag recording [ENV...]): the cases of test_kinect_replay with
# that tag (-w NoTests: a tag that matches nothing fails), in a process of their own.
function(kinect_replay_test name tag recording)
  set(warn -w NoTests)
  if(name STREQUAL "test_kinect_replay_rest")
    set(warn "")  # the catch-all (below): no case left over is fine
  else()
    set_property(GLOBAL APPEND PROPERTY CUETRACK_KINECT_REPLAY_TAGS "${tag}")
  endif()
  if(_fakenect_missing)
    cuetrack_add_skipped_test(${name} "${_fakenect_missing}")
    return()
  endif()
  add_test(NAME ${name} COMMAND ${_run_fakenect} $<TARGET_FILE:test_kinect_replay> ${warn} "${tag}")
  set_tests_properties(${name} PROPERTIES
    ENVIRONMENT "FAKENECT_PATH=${recording};${_fakenect_env};${ARGN}"
    FIXTURES_REQUIRED kinect_recordings LABELS "kinect;fakenect" TIMEOUT 300
    SKIP_RETURN_CODE ${CUETRACK_SKIP_RC})
endfunction()
# The catch-all, registered once this folder is read (after every tagged run, some of them
# conditional): the cases no tag runs, so that a new case cannot go unrun.
function(kinect_replay_catch_all)
  get_property(tags GLOBAL PROPERTY CUETRACK_KINECT_REPLAY_TAGS)
  list(JOIN tags "" rest)
  string(REPLACE "[" "~[" rest "${rest}")
  kinect_replay_test(test_kinect_replay_rest "${rest}" ${_rec}/moving)
endfunction()
cmake_language(DEFER CALL kinect_replay_catch_all)

kinect_replay_test(test_kinect_replay_delivers "[delivers]" ${_rec}/moving)
kinect_replay_test(test_kinect_replay_tracks "[tracks]" ${_rec}/moving)
kinect_replay_test(test_kinect_replay_stall "[stall]" ${_rec}/stall)
kinect_replay_test(test_kinect_replay_stop "[stop]" ${_rec}/moving)
kinect_replay_test(test_kinect_replay_signal "[signal]" ${_rec}/stall)
kinect_replay_test(test_kinect_replay_depth_only "[depth-only]" ${_rec}/moving)
kinect_replay_test(test_kinect_replay_colour_only "[colour-only]" ${_rec}/moving)
kinect_replay_test(test_kinect_replay_misuse "[misuse]" ${_rec}/moving)

set(_expect ${CUETRACK_RUN_EXPECT})
function(kinect_record_test name run rc)
  if("CUETRACK_NO_FAKENECT" IN_LIST run)
    cuetrack_add_skipped_test(${name} "${_fakenect_missing}")
    return()
  endif()
  list(JOIN run "|" _cmd)
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} "-DCMD=${_cmd}" -DEXPECT_RC=${rc} ${ARGN} -P ${_expect})
  set_tests_properties(${name} PROPERTIES LABELS kinect TIMEOUT 300)
endfunction()

# ---- cuetrack on the live path: both streams (3D, a centre in mm) or colour only (2D) ---
if(TARGET cuetrack)
  set(_cuetrack $<TARGET_FILE:cuetrack>)
  set(_box 291,267,31,52)  # the recording's first ground-truth box
  kinect_record_test(test_kinect_cuetrack_both
                     "${_run_fakenect};${_cuetrack};--source;kinect;--box;${_box};--frames;6" 0
                     "-DEXPECT_OUT=track seq=5 t=[0-9]+us tracking box=[0-9,]+ mm=-?[0-9]+,")
  kinect_record_test(test_kinect_cuetrack_colour_only
                     "${_run_fakenect};${_cuetrack};--source;kinect:colour;--box;${_box};--frames;6" 0
                     "-DEXPECT_OUT=track seq=5 t=[0-9]+us tracking box=[0-9,]+ mm=- ")
  set_tests_properties(test_kinect_cuetrack_both test_kinect_cuetrack_colour_only PROPERTIES
    ENVIRONMENT "FAKENECT_PATH=${_rec}/moving;${_fakenect_env}"
    FIXTURES_REQUIRED kinect_recordings)
endif()

# ---- cuetrack-record ---------------------------------------------------------------
if(NOT TARGET cuetrack-record)
  return()
endif()
set(_record $<TARGET_FILE:cuetrack-record>)

kinect_record_test(test_kinect_record_help "${_run_plain};${_record};--help" 0
                   "-DEXPECT_OUT=usage: cuetrack-record.*Exit codes")
kinect_record_test(test_kinect_record_bad_args "${_run_plain};${_record};--out;x;--frames;zero" 2
                   -DONE_LINE_ERR=ON "-DEXPECT_ERR=--frames")
# This machine has no Kinect: one clear line and exit code 1 (skip where one is plugged in).
kinect_record_test(test_kinect_record_no_kinect
                   "${_run_plain};${_record};--frames;1;--out;${CMAKE_CURRENT_BINARY_DIR}/no-kinect" 1
                   -DONE_LINE_ERR=ON "-DEXPECT_ERR=no Kinect found|could not initialise USB")
# Record a fakenect replay with cuetrack-record, then compare the copy with the original.
kinect_record_test(test_kinect_record_replay
                   "${_run_fakenect};${_record};--out;${_rec}/copy" 0
                   "-DEXPECT_ERR=12 frames" -DCLEAN_DIR=${_rec}/copy)
set_tests_properties(test_kinect_record_replay PROPERTIES
  ENVIRONMENT "FAKENECT_PATH=${_rec}/moving;${_fakenect_env}"
  FIXTURES_REQUIRED kinect_recordings FIXTURES_SETUP kinect_copy)
kinect_replay_test(test_kinect_record_copy_matches "[copy]" ${_rec}/moving "CUETRACK_KINECT_COPY=${_rec}/copy")
set_tests_properties(test_kinect_record_copy_matches PROPERTIES FIXTURES_REQUIRED "kinect_recordings;kinect_copy")

if(TARGET cuetrack_recorded_cv)
  kinect_record_test(test_kinect_record_replay_rgbd
                     "${_run_fakenect};${_record};--format;rgbd;--frames;5;--out;${_rec}/copy-rgbd" 0
                     "-DEXPECT_ERR=5/5 frames" -DCLEAN_DIR=${_rec}/copy-rgbd)
  set_tests_properties(test_kinect_record_replay_rgbd PROPERTIES
    ENVIRONMENT "FAKENECT_PATH=${_rec}/moving;${_fakenect_env}"
    FIXTURES_REQUIRED kinect_recordings FIXTURES_SETUP kinect_copy_rgbd)
  kinect_replay_test(test_kinect_record_rgbd_matches "[copy-rgbd]" ${_rec}/moving
                     "CUETRACK_KINECT_COPY=${_rec}/copy-rgbd")
  set_tests_properties(test_kinect_record_rgbd_matches PROPERTIES
    FIXTURES_REQUIRED "kinect_recordings;kinect_copy_rgbd")
endif()
