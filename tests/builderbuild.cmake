# SPDX-License-Identifier: MIT
# Building generated projects: Codegen::ProjectBuilder, `rtctl build`, the Builder's Build action.
# Fixture projects: tests/data/projectbuild/ (plain CMake, no OpenRTM-aist or SDK needed).
rtstudio_add_test(tst_codegenprojectbuilder
    SOURCES tst_codegenprojectbuilder.cpp tst_builderbuildsupport.h LIBS rtcodegen)
rtstudio_add_test(tst_rtctlbuild
    SOURCES tst_rtctlbuild.cpp tst_builderbuildsupport.h LIBS rtstudio_rtctlrunner)
rtstudio_add_test(tst_builderbuildapp
    SOURCES tst_builderbuildapp.cpp tst_builderbuildsupport.h LIBS rtstudio_app)
# Signals the real rtctl while it builds.
target_compile_definitions(tst_rtctlbuild PRIVATE RTCTL_PATH="$<TARGET_FILE:rtctl>")
