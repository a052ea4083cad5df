# SPDX-License-Identifier: MIT
# Interoperability with a real OpenRTM-aist 2.x (ctest label "interop"): the project rtctl
# generates for the SdkGreeter fixture is built against OpenRTM-aist's CMake package and run by
# it. OpenRTM-aist is not a dependency of RT Studio: without a prefix the test skips itself.
# The prefix comes from the cache or, at the first configure, from the OPENRTM_ROOT environment variable.
set(RTSTUDIO_OPENRTM_PREFIX "$ENV{OPENRTM_ROOT}" CACHE PATH "OpenRTM-aist 2.x prefix for the interop tests (optional)")

# One interop test: the prefix and rtmanager's path compiled in, rtmanager and rtctl built first.
function(rtstudio_add_interop_test name)
    cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBS;DEFINITIONS" ${ARGN})
    rtstudio_add_test(${name} SOURCES ${ARG_SOURCES} LIBS ${ARG_LIBS})
    target_compile_definitions(${name} PRIVATE
        RTSTUDIO_OPENRTM_PREFIX="${RTSTUDIO_OPENRTM_PREFIX}"
        RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
        ${ARG_DEFINITIONS})
    add_dependencies(${name} rtmanager rtctl)
    set_tests_properties(${name} PROPERTIES LABELS interop)
    if(ARG_TIMEOUT)
        set_tests_properties(${name} PROPERTIES TIMEOUT ${ARG_TIMEOUT})
    endif()
endfunction()

rtstudio_add_interop_test(tst_interopbuild SOURCES tst_interopbuild.cpp common/sdkgreeteredits.h
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs
    DEFINITIONS CMAKE_COMMAND="${CMAKE_COMMAND}" TIMEOUT 900)

# rtctl print / inject against OpenRTM-aist's example components.
rtstudio_add_interop_test(tst_interopdata SOURCES tst_interopdata.cpp LIBS rtstudio_livetest rtstudio_rtctlrunner)

# One name server with OpenRTM-aist's example programs, an rtcd2 master and rtmanager: every rtctl
# command against OpenRTM-aist, data of every basic type both ways, configuration, service calls
# and a mixed system saved and restored.
rtstudio_add_interop_test(tst_interopsystem SOURCES tst_interopsystem.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtcorba_stubs)

# The online System Editor's Name Service view and Manager view against the same kind of mixed system.
rtstudio_add_interop_test(tst_interoponline SOURCES tst_interoponline.cpp
    LIBS rtsystemeditor rtstudio_livetest rtstudio_rtctlrunner)

# OpenRTM-aist built with SSL_ENABLE and RT Studio on one certificate authority and one rtc.conf.
rtstudio_add_interop_test(tst_interoptls SOURCES tst_interoptls.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtcorba_tls_loaded rtcorba_stubs)
