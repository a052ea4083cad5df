# SPDX-License-Identifier: MIT
# rtmanager's built-in examples checked against OpenRTM-aist 2.1's C++ examples (live rtmanager).
rtstudio_add_test(tst_managerexamples SOURCES tst_managerexamples.cpp LIBS rtstudio_livetest rtcorba_stubs)
target_compile_definitions(tst_managerexamples PRIVATE RTMANAGER_PATH="$<TARGET_FILE:rtmanager>")
add_dependencies(tst_managerexamples rtmanager)
