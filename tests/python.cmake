# SPDX-License-Identifier: MIT
# Python components (python/): OpenRTM-aist-Python's SimpleIO example unchanged (shared corpus), a
# component of ours exchanging data with rtmanager's built-ins, callback exceptions, the IDL types.
if(NOT TARGET rtpython)
    return()
endif()

rtstudio_add_test(tst_python SOURCES tst_python.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtcorba_stubs)
target_compile_definitions(tst_python PRIVATE
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    RTSTUDIO_PYTHON_PATH="${RTSTUDIO_PYTHON_STAGE}"
    RTSTUDIO_PYTHON_EXECUTABLE="${RTSTUDIO_PYTHON_EXECUTABLE}"
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    CMAKE_COMMAND="${CMAKE_COMMAND}")
add_dependencies(tst_python rtmanager rtctl rtpython rtsdk)
set_tests_properties(tst_python PROPERTIES LABELS python TIMEOUT 600)
