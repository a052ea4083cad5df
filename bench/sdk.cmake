# SPDX-License-Identifier: MIT
# Benchmarks of the component SDK (sdk/): data-port latency and throughput as OpenRTM-aist's
# Throughput example measures them, and the time from Generate to a running instance.
add_executable(bench_sdkflow bench_sdkflow.cpp openrtmthroughput.h openrtmthroughput.cpp)
target_link_libraries(bench_sdkflow PRIVATE rtsdk)
target_compile_definitions(bench_sdkflow PRIVATE RTCTL_PATH="$<TARGET_FILE:rtctl>")
add_dependencies(bench_sdkflow rtctl)

add_executable(bench_sdkgenerate bench_sdkgenerate.cpp)
target_link_libraries(bench_sdkgenerate PRIVATE Qt6::Core)
target_compile_definitions(bench_sdkgenerate PRIVATE
    RTCTL_PATH="$<TARGET_FILE:rtctl>"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    RTSTUDIO_BENCH_DATA_DIR="${CMAKE_CURRENT_SOURCE_DIR}/data"
    CMAKE_COMMAND="${CMAKE_COMMAND}")
add_dependencies(bench_sdkgenerate rtctl rtmanager rtsdk)
if(TARGET rtsdk_stage)
    add_dependencies(bench_sdkgenerate rtsdk_stage)
endif()
