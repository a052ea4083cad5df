# SPDX-License-Identifier: MIT
# bench_python: data-port latency and throughput of Python components beside C++ ones, as modules
# of rtmanager (bench/pythonflow), in one process and between two.
if(NOT TARGET rtpymodules OR NOT TARGET rtstudio_livetest)
    return()
endif()
foreach(module FlowSource FlowSink)
    string(TOLOWER ${module} source)
    add_library(bench${source} MODULE pythonflow/${source}.cpp pythonflow/flowprotocol.h)
    target_link_libraries(bench${source} PRIVATE rtsdk)
    set_target_properties(bench${source} PROPERTIES PREFIX "" OUTPUT_NAME ${module} AUTOMOC OFF
        LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/pythonflow)
endforeach()
add_executable(bench_python bench_python.cpp)
target_link_libraries(bench_python PRIVATE rtstudio_livetest rtstudio_rtctlrunner)
target_compile_definitions(bench_python PRIVATE
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    RTSTUDIO_BENCH_FLOW_SOURCE_DIR="${CMAKE_CURRENT_SOURCE_DIR}/pythonflow"
    RTSTUDIO_BENCH_FLOW_BUILD_DIR="${CMAKE_CURRENT_BINARY_DIR}/pythonflow")
add_dependencies(bench_python rtmanager rtctl rtpython rtpymodules benchflowsource benchflowsink)
