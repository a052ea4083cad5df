# SPDX-License-Identifier: MIT
# Component packages (rtctl package) and Debian repositories of them (rtctl repo) that apt-get reads.
rtstudio_add_test(tst_debnames SOURCES tst_debnames.cpp LIBS rtpackages)

rtstudio_add_test(tst_componentpackage SOURCES tst_componentpackage.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject)
target_compile_definitions(tst_componentpackage PRIVATE
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>")
add_dependencies(tst_componentpackage rtctl rtsdk rtmanager)
if(TARGET rtsdk_stage)
    add_dependencies(tst_componentpackage rtsdk_stage)
endif()
set_tests_properties(tst_componentpackage PROPERTIES LABELS package TIMEOUT 600)

rtstudio_add_test(tst_componentrepository SOURCES tst_componentrepository.cpp LIBS rtstudio_rtctlrunner rtpackages)
add_dependencies(tst_componentrepository rtctl)
set_tests_properties(tst_componentrepository PROPERTIES LABELS package)

# The Builder's Package and Publish… (a generated project built against this tree's SDK).
rtstudio_add_test(tst_builderpackage SOURCES tst_builderpackage.cpp
    LIBS rtstudio_app rtstudio_rtctlrunner rtstudio_sdkproject)
target_compile_definitions(tst_builderpackage PRIVATE RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}")
add_dependencies(tst_builderpackage rtctl rtsdk)
if(TARGET rtsdk_stage)
    add_dependencies(tst_builderpackage rtsdk_stage)
endif()
set_tests_properties(tst_builderpackage PROPERTIES LABELS package TIMEOUT 600)

# The System Editor's Repository view over a component repository.
rtstudio_add_test(tst_serepositorypackages SOURCES tst_serepositorypackages.cpp
    LIBS rtsystemeditor rtstudio_rtctlrunner)
add_dependencies(tst_serepositorypackages rtctl)
set_tests_properties(tst_serepositorypackages PROPERTIES LABELS package)

rtstudio_add_test(tst_packagestore SOURCES tst_packagestore.cpp LIBS rtpackageinstall)
set_tests_properties(tst_packagestore PROPERTIES LABELS package)

# rtctl node and rtmanager's package installer: installs without root, verified as apt does.
rtstudio_add_test(tst_managerinstall SOURCES tst_managerinstall.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba)
target_compile_definitions(tst_managerinstall PRIVATE
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>")
add_dependencies(tst_managerinstall rtctl rtsdk rtmanager)
if(TARGET rtsdk_stage)
    add_dependencies(tst_managerinstall rtsdk_stage)
endif()
set_tests_properties(tst_managerinstall PROPERTIES LABELS package TIMEOUT 600)

# rtctl deploy / undeploy: installs from a repository, restore and start as one transaction.
rtstudio_add_test(tst_deployinstall SOURCES tst_deployinstall.cpp tst_deploysupport.h
    LIBS rtstudio_app rtdeploy rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs)
target_compile_definitions(tst_deployinstall PRIVATE
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>")
add_dependencies(tst_deployinstall rtctl rtsdk rtmanager)
if(TARGET rtsdk_stage)
    add_dependencies(tst_deployinstall rtsdk_stage)
endif()
set_tests_properties(tst_deployinstall PROPERTIES LABELS package TIMEOUT 600)
