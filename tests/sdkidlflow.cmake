# SPDX-License-Identifier: MIT
# The SDK's IDL set and IDL wrapper flow: every wrapper header of the prefix's rtm/idl compiled as C++11
# in one file, rtm-skelwrapper's outputs and options, and projects in the IDL layouts of OpenRTP 1.2
# (idl/ with rtm-config and rtm-skelwrapper) and 2.0 (idl/ sub-project), a hand-written one using
# --include-dir and --output-dir, and one on the camera and manipulator extension types, configured,
# built and run against the build tree's prefix and against an installed copy.
rtstudio_add_test(tst_sdkidlflow SOURCES tst_sdkidlflow.cpp LIBS Qt6::Core rtstudio_sdkproject)
target_compile_definitions(tst_sdkidlflow PRIVATE
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    RTSTUDIO_CMAKE_COMMAND="${CMAKE_COMMAND}"
    RTSTUDIO_CMAKE_GENERATOR="${CMAKE_GENERATOR}"
    RTSTUDIO_CMAKE_MAKE_PROGRAM="${CMAKE_MAKE_PROGRAM}"
    RTSTUDIO_CXX_COMPILER="${CMAKE_CXX_COMPILER}")
add_dependencies(tst_sdkidlflow rtsdk rtsdk_stage)
set_tests_properties(tst_sdkidlflow PROPERTIES LABELS sdk TIMEOUT 900)
