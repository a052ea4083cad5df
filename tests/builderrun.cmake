# SPDX-License-Identifier: MIT
# The Builder's Run in Manager against a real rtmanager (the SDK-built test module stands in for
# a built component), and the Problems panel's source viewer. Fixtures: tests/data/builderrun/.
rtstudio_add_test(tst_builderrunmanager
    SOURCES tst_builderrunmanager.cpp LIBS rtstudio_app rtcorba rtstudio_livetest)
target_compile_definitions(tst_builderrunmanager PRIVATE
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    MANAGER_TEST_MODULE_DIR="${CMAKE_CURRENT_BINARY_DIR}/managermodules")
add_dependencies(tst_builderrunmanager rtmanager managertestmodule)
