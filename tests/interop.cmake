# SPDX-License-Identifier: MIT
# Interoperability with a real OpenRTM-aist 2.x (ctest label "interop"): the project rtctl
# generates for the SdkGreeter fixture is built against OpenRTM-aist's CMake package and run by
# it. OpenRTM-aist is not a dependency of RT Studio: without a prefix the test skips itself.
# The prefix comes from the cache or, at the first configure, from the OPENRTM_ROOT environment variable.
set(RTSTUDIO_OPENRTM_PREFIX "$ENV{OPENRTM_ROOT}" CACHE PATH "OpenRTM-aist 2.x prefix for the interop tests (optional)")

rtstudio_add_test(tst_interopbuild SOURCES tst_interopbuild.cpp common/sdkgreeteredits.h
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs)
target_compile_definitions(tst_interopbuild PRIVATE
    RTSTUDIO_OPENRTM_PREFIX="${RTSTUDIO_OPENRTM_PREFIX}"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    CMAKE_COMMAND="${CMAKE_COMMAND}")
add_dependencies(tst_interopbuild rtmanager rtctl)
set_tests_properties(tst_interopbuild PROPERTIES LABELS interop TIMEOUT 900)

# rtctl print / inject against OpenRTM-aist's example components.
rtstudio_add_test(tst_interopdata SOURCES tst_interopdata.cpp LIBS rtstudio_livetest rtstudio_rtctlrunner)
target_compile_definitions(tst_interopdata PRIVATE RTSTUDIO_OPENRTM_PREFIX="${RTSTUDIO_OPENRTM_PREFIX}")
add_dependencies(tst_interopdata rtctl)
set_tests_properties(tst_interopdata PROPERTIES LABELS interop)

# One name server with OpenRTM-aist's example programs, an rtcd2 master and rtmanager: every rtctl
# command against OpenRTM-aist, data of every basic type both ways, configuration, service calls
# and a mixed system saved and restored.
rtstudio_add_test(tst_interopsystem SOURCES tst_interopsystem.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtcorba_stubs)
target_compile_definitions(tst_interopsystem PRIVATE
    RTSTUDIO_OPENRTM_PREFIX="${RTSTUDIO_OPENRTM_PREFIX}"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>")
add_dependencies(tst_interopsystem rtmanager rtctl)
set_tests_properties(tst_interopsystem PROPERTIES LABELS interop)

# The online System Editor's Name Service view against the same kind of mixed system.
rtstudio_add_test(tst_interoponline SOURCES tst_interoponline.cpp
    LIBS rtsystemeditor rtstudio_livetest rtstudio_rtctlrunner)
target_compile_definitions(tst_interoponline PRIVATE
    RTSTUDIO_OPENRTM_PREFIX="${RTSTUDIO_OPENRTM_PREFIX}"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>")
add_dependencies(tst_interoponline rtmanager rtctl)
set_tests_properties(tst_interoponline PROPERTIES LABELS interop)
