# SPDX-License-Identifier: MIT
# OpenRTM-aist's C++ API as users' code meets it: every public header and the declarations code uses,
# OpenRTM-aist's own examples (the shared corpus) and components in the styles users write, built
# against the SDK and run.

# Every public header OpenRTM-aist installs compiles alone against the prefix, as C++11, and
# brings the standard headers OpenRTM-aist's brings (the list: data/openrtm/headers.txt).
rtstudio_add_test(tst_sdkheaders SOURCES tst_sdkheaders.cpp LIBS Qt6::Core)
target_compile_definitions(tst_sdkheaders PRIVATE
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    RTSTUDIO_CMAKE_COMMAND="${CMAKE_COMMAND}"
    RTSTUDIO_CXX_COMPILER="${CMAKE_CXX_COMPILER}")
add_dependencies(tst_sdkheaders rtsdk_stage)
set_tests_properties(tst_sdkheaders PROPERTIES LABELS sdk TIMEOUT 900)

# OpenRTM-aist's own C++ examples (shared conformance corpus), unchanged, built against the SDK
# from the build tree and an installed copy, and run in rtmanager and as programs.
rtstudio_add_test(tst_sdkexamples SOURCES tst_sdkexamples.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs)
rtstudio_uses_sdk_projects(tst_sdkexamples)
target_compile_definitions(tst_sdkexamples PRIVATE CMAKE_COMMAND="${CMAKE_COMMAND}")
set_tests_properties(tst_sdkexamples PROPERTIES LABELS "sdk;conformance" TIMEOUT 2400)

# Components in the styles OpenRTM users write beyond OpenRTM's examples (data/sdkstyles), built
# against the SDK and run in rtmanager and as programs.
rtstudio_add_test(tst_sdkstyles SOURCES tst_sdkstyles.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs)
rtstudio_uses_sdk_projects(tst_sdkstyles)
set_tests_properties(tst_sdkstyles PROPERTIES LABELS sdk TIMEOUT 900)
