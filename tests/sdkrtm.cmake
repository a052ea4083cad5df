# SPDX-License-Identifier: MIT
# The component SDK's C++ API in one process (tst_sdkrtm), and a generated component built
# against it, loaded into rtmanager and run standalone (tst_sdkgenerated).
rtstudio_add_test(tst_sdkrtm SOURCES tst_sdkrtm.cpp LIBS rtsdk)
target_include_directories(tst_sdkrtm PRIVATE ${PROJECT_SOURCE_DIR}/manager ${PROJECT_SOURCE_DIR}/sdk/rtm)
set_tests_properties(tst_sdkrtm PROPERTIES LABELS sdk)

# Data port callbacks, the port API and component/port listeners as older OpenRTM-aist components use them.
rtstudio_add_test(tst_sdkports SOURCES tst_sdkports.cpp LIBS rtsdk)
target_include_directories(tst_sdkports PRIVATE ${PROJECT_SOURCE_DIR}/manager ${PROJECT_SOURCE_DIR}/sdk/rtm)
set_tests_properties(tst_sdkports PROPERTIES LABELS sdk)

rtstudio_add_test(tst_sdkgenerated SOURCES tst_sdkgenerated.cpp LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcorba_stubs)
rtstudio_uses_sdk_projects(tst_sdkgenerated)
target_compile_definitions(tst_sdkgenerated PRIVATE CMAKE_COMMAND="${CMAKE_COMMAND}")
set_tests_properties(tst_sdkgenerated PROPERTIES LABELS sdk TIMEOUT 900)

# Shared by the tests that build generated projects against the SDK.
add_library(rtstudio_sdkproject STATIC common/sdkproject.h common/sdkproject.cpp)
target_include_directories(rtstudio_sdkproject PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/common)
target_link_libraries(rtstudio_sdkproject PUBLIC Qt6::Core)

rtstudio_add_test(tst_sdkfixtures SOURCES tst_sdkfixtures.cpp
    LIBS rtstudio_livetest rtstudio_rtctlrunner rtstudio_sdkproject rtcodegen rtcorba_stubs)
rtstudio_uses_sdk_projects(tst_sdkfixtures)
set_tests_properties(tst_sdkfixtures PROPERTIES LABELS sdk TIMEOUT 900)

# A hand-written OpenRTM-style module that crashes on request, hosted by master and slaves.
add_library(sdkcrashprobe MODULE sdkmodules/crashprobe.cpp)
target_link_libraries(sdkcrashprobe PRIVATE rtsdk)
set_target_properties(sdkcrashprobe PROPERTIES PREFIX "" OUTPUT_NAME CrashProbe AUTOMOC OFF
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/sdkmodules)
rtstudio_add_test(tst_sdkslaves SOURCES tst_sdkslaves.cpp LIBS rtstudio_livetest rtstudio_rtctlrunner rtsystemeditor)
target_compile_definitions(tst_sdkslaves PRIVATE
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    SDK_TEST_MODULE_DIR="${CMAKE_CURRENT_BINARY_DIR}/sdkmodules")
add_dependencies(tst_sdkslaves rtmanager rtctl sdkcrashprobe)
set_tests_properties(tst_sdkslaves PROPERTIES LABELS sdk)
target_compile_definitions(tst_sdkrtm PRIVATE
    MANAGER_TEST_MODULE="${CMAKE_CURRENT_BINARY_DIR}/managermodules/ManagerTestModule.so")
add_dependencies(tst_sdkrtm managertestmodule)

# The component API's headers as C++11, the standard OpenRTP 2.0 projects build with.
add_library(sdkrtm_cxx11 OBJECT sdk/rtm_cxx11.cpp)
target_link_libraries(sdkrtm_cxx11 PRIVATE rtsdk)
set_target_properties(sdkrtm_cxx11 PROPERTIES CXX_STANDARD 11 CXX_EXTENSIONS ON AUTOMOC OFF)
add_dependencies(tst_sdkrtm sdkrtm_cxx11)

# OpenRTM-aist's utility headers (NVUtil, CORBA_SeqUtil, CORBA_RTCUtil, CorbaNaming, …) against live
# components in one process and a real omniNames.
rtstudio_add_test(tst_sdkutil SOURCES tst_sdkutil.cpp LIBS rtsdk rtstudio_livetest)
set_tests_properties(tst_sdkutil PROPERTIES LABELS sdk)

# The manager's `timer.tick` read from its configuration: defaults for unreadable values, a bound
# for huge ones; one child process per value (the manager is one per process).
rtstudio_add_test(tst_sdktimertick SOURCES tst_sdktimertick.cpp LIBS rtsdk)
set_tests_properties(tst_sdktimertick PROPERTIES LABELS sdk)

# Execution contexts (ExtTrig, OpenHRP, Simulator) and the manager's internals, in this process and
# in rtmanager.
# OpenRTM-aist's ExtTrigger example is built against the staged SDK and run.
rtstudio_add_test(tst_sdkec SOURCES tst_sdkec.cpp LIBS rtsdk rtstudio_livetest rtstudio_sdkproject)
target_include_directories(tst_sdkec PRIVATE ${PROJECT_SOURCE_DIR}/manager)
target_compile_definitions(tst_sdkec PRIVATE
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    RTSTUDIO_BUILD_DIR="${CMAKE_BINARY_DIR}"
    MANAGER_TEST_MODULE="${CMAKE_CURRENT_BINARY_DIR}/managermodules/ManagerTestModule.so")
add_dependencies(tst_sdkec rtmanager managertestmodule)
if(TARGET rtsdk_stage)
    add_dependencies(tst_sdkec rtsdk_stage)
endif()
set_tests_properties(tst_sdkec PROPERTIES LABELS sdk TIMEOUT 900)
