# SPDX-License-Identifier: MIT
# The SDK's prefix (sdk/package/): layout, CMake package, pkg-config files, rtm-config and the skeleton
# wrapper, and projects in five consumption styles built and run against the build tree's prefix and
# against an installed copy (cmake --install --component sdk into a temporary folder).
rtstudio_add_test(tst_sdkpackage SOURCES tst_sdkpackage.cpp LIBS Qt6::Core rtstudio_sdkproject)
target_compile_definitions(tst_sdkpackage PRIVATE
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    RTSTUDIO_CMAKE_COMMAND="${CMAKE_COMMAND}"
    RTSTUDIO_CMAKE_GENERATOR="${CMAKE_GENERATOR}"
    RTSTUDIO_CMAKE_MAKE_PROGRAM="${CMAKE_MAKE_PROGRAM}"
    RTSTUDIO_CXX_COMPILER="${CMAKE_CXX_COMPILER}"
    RTSDK_LINK_FLAGS="${RTSDK_LINK_FLAGS_SPACED}")
add_dependencies(tst_sdkpackage rtsdk rtsdk_stage)
set_tests_properties(tst_sdkpackage PROPERTIES LABELS sdk TIMEOUT 600)
