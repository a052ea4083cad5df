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
if(TARGET rtpymodules)
    add_dependencies(tst_python rtpymodules)
endif()
# The sanitizer build's extension module needs the sanitizer runtimes loaded first into python3.
set(python_sanitizer_preload "")
if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=[^ ]*address")
    foreach(runtime libasan.so libubsan.so)
        execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=${runtime}
                        OUTPUT_VARIABLE runtime_path OUTPUT_STRIP_TRAILING_WHITESPACE)
        list(APPEND python_sanitizer_preload "${runtime_path}")
    endforeach()
endif()
list(JOIN python_sanitizer_preload " " python_sanitizer_preload)
target_compile_definitions(tst_python PRIVATE RTSTUDIO_SANITIZER_PRELOAD="${python_sanitizer_preload}")
set_tests_properties(tst_python PROPERTIES LABELS python TIMEOUT 600)

# Python modules inside rtmanager (python/embed): the plugin rtmanager opens on its first .py module.
if(TARGET rtpymodules)
    rtstudio_add_test(tst_pythonmanager SOURCES tst_pythonmanager.cpp
        LIBS rtstudio_livetest rtstudio_rtctlrunner rtcorba_stubs)
    target_compile_definitions(tst_pythonmanager PRIVATE
        RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
        RTSTUDIO_PYTHON_PLUGIN="$<TARGET_FILE:rtpymodules>")
    add_dependencies(tst_pythonmanager rtmanager rtctl rtpython rtpymodules rtsdk)
    set_tests_properties(tst_pythonmanager PROPERTIES LABELS python TIMEOUT 600)
endif()

# The Builder's Build and Run in Manager for a generated Python project, against a live rtmanager.
if(TARGET rtpymodules)
    rtstudio_add_test(tst_builderpython SOURCES tst_builderpython.cpp
        LIBS rtstudio_app rtstudio_livetest rtstudio_rtctlrunner rtcorba_stubs)
    target_compile_definitions(tst_builderpython PRIVATE RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
        RTSTUDIO_PYTHON_PATH="${RTSTUDIO_PYTHON_STAGE}"
        RTSTUDIO_PYTHON_EXECUTABLE="${RTSTUDIO_PYTHON_EXECUTABLE}"
        RTSTUDIO_SANITIZER_PRELOAD="${python_sanitizer_preload}")
    add_dependencies(tst_builderpython rtmanager rtctl rtpython rtpymodules rtsdk)
    set_tests_properties(tst_builderpython PROPERTIES LABELS python TIMEOUT 600)
endif()

# Service ports of Python components: rtctl idl --lang python, Python providers and consumers,
# OpenRTM-aist-Python's SimpleService example unchanged, calls both ways with rtmanager's C++ built-ins.
# OpenRTM-aist's C++ MyServiceProvider / MyServiceConsumer examples are built against the SDK for it.
rtstudio_add_test(tst_pythonservice SOURCES tst_pythonservice.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs)
rtstudio_uses_sdk_projects(tst_pythonservice)
target_compile_definitions(tst_pythonservice PRIVATE
    RTSTUDIO_PYTHON_PATH="${RTSTUDIO_PYTHON_STAGE}"
    RTSTUDIO_PYTHON_EXECUTABLE="${RTSTUDIO_PYTHON_EXECUTABLE}"
    RTSTUDIO_SANITIZER_PRELOAD="${python_sanitizer_preload}")
add_dependencies(tst_pythonservice rtmanager rtctl rtpython rtsdk)
set_tests_properties(tst_pythonservice PROPERTIES LABELS python TIMEOUT 600)
# OpenRTM-aist-Python's other examples unchanged (shared corpus) and components of ours with the same
# abilities, standalone and as modules of rtmanager.
if(TARGET rtpymodules)
    rtstudio_add_test(tst_pythonexamples SOURCES tst_pythonexamples.cpp
        LIBS rtstudio_livetest rtstudio_rtctlrunner rtcorba_stubs)
    target_compile_definitions(tst_pythonexamples PRIVATE
        RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
        RTCTL_PATH="$<TARGET_FILE:rtctl>"
        RTSTUDIO_PYTHON_PATH="${RTSTUDIO_PYTHON_STAGE}"
        RTSTUDIO_PYTHON_EXECUTABLE="${RTSTUDIO_PYTHON_EXECUTABLE}"
        RTSTUDIO_SANITIZER_PRELOAD="${python_sanitizer_preload}")
    add_dependencies(tst_pythonexamples rtmanager rtctl rtpython rtpymodules rtsdk)
    set_tests_properties(tst_pythonexamples PROPERTIES LABELS "python;conformance" TIMEOUT 600)
endif()

# Python components and OpenRTM-aist 2.x's C++ examples exchange samples and service calls (interop).
if(COMMAND rtstudio_add_interop_test)
    rtstudio_add_interop_test(tst_interoppython SOURCES tst_interoppython.cpp
        LIBS rtstudio_livetest rtstudio_rtctlrunner)
    target_compile_definitions(tst_interoppython PRIVATE
        RTSTUDIO_PYTHON_PATH="${RTSTUDIO_PYTHON_STAGE}"
        RTSTUDIO_PYTHON_EXECUTABLE="${RTSTUDIO_PYTHON_EXECUTABLE}"
        RTSTUDIO_SANITIZER_PRELOAD="${python_sanitizer_preload}")
    add_dependencies(tst_interoppython rtpython)
endif()

# A Python component over TLS (tst_tls runs the case when the Python runtime is built).
target_compile_definitions(tst_tls PRIVATE
    RTSTUDIO_PYTHON_PATH="${RTSTUDIO_PYTHON_STAGE}"
    RTSTUDIO_PYTHON_EXECUTABLE="${RTSTUDIO_PYTHON_EXECUTABLE}"
    RTSTUDIO_SANITIZER_PRELOAD="${python_sanitizer_preload}")
add_dependencies(tst_tls rtpython)
