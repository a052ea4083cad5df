# SPDX-License-Identifier: MIT
# Static FSM components (rtm/Macho.h, rtm/StaticFSM.h, rtm/EventPort.h): the state machine
# semantics and an EventInPort in one process (tst_sdkfsm), the hand-written TrafficLight module
# in rtmanager driven through rtctl (tst_sdkfsmlive), the "any" data type in the System Editor's
# connection rules (tst_seconnectionany), and both built against a real OpenRTM-aist when a prefix
# is configured (tst_interopfsm, label interop).
set(SDK_FSM_DIR "${CMAKE_CURRENT_SOURCE_DIR}/sdkfsm")
set(SDK_TRAFFICLIGHT_DIR "${CMAKE_CURRENT_SOURCE_DIR}/sdkmodules/trafficlight")

rtstudio_add_test(tst_sdkfsm SOURCES tst_sdkfsm.cpp sdkfsm/lampmachine.h sdkfsm/lampids.cpp
    ${SDK_TRAFFICLIGHT_DIR}/TrafficLightFsm.h ${SDK_TRAFFICLIGHT_DIR}/TrafficLightFsm.cpp LIBS rtsdk)
target_include_directories(tst_sdkfsm PRIVATE ${SDK_FSM_DIR} ${PROJECT_SOURCE_DIR}/manager)
target_compile_definitions(tst_sdkfsm PRIVATE SDK_FSM_DIR="${SDK_FSM_DIR}")
set_tests_properties(tst_sdkfsm PROPERTIES LABELS sdk)

# The TrafficLight module as rtmanager loads it from its load path.
add_library(sdktrafficlight MODULE ${SDK_TRAFFICLIGHT_DIR}/TrafficLight.cpp ${SDK_TRAFFICLIGHT_DIR}/TrafficLightFsm.cpp)
target_link_libraries(sdktrafficlight PRIVATE rtsdk)
set_target_properties(sdktrafficlight PROPERTIES PREFIX "" OUTPUT_NAME TrafficLight AUTOMOC OFF
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/sdkfsmmodules)

add_library(rtstudio_sdkfsmdriver STATIC sdkfsm/trafficlightdriver.h sdkfsm/trafficlightdriver.cpp)
target_include_directories(rtstudio_sdkfsmdriver PUBLIC ${SDK_FSM_DIR})
target_link_libraries(rtstudio_sdkfsmdriver PUBLIC rtstudio_rtctlrunner rtcorba_stubs Qt6::Test)

rtstudio_add_test(tst_sdkfsmlive SOURCES tst_sdkfsmlive.cpp LIBS rtstudio_livetest rtstudio_sdkfsmdriver)
target_compile_definitions(tst_sdkfsmlive PRIVATE
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    SDK_TEST_MODULE_DIR="${CMAKE_CURRENT_BINARY_DIR}/sdkfsmmodules")
add_dependencies(tst_sdkfsmlive rtmanager rtctl sdktrafficlight)
set_tests_properties(tst_sdkfsmlive PROPERTIES LABELS sdk)

rtstudio_add_test(tst_seconnectionany SOURCES tst_seconnectionany.cpp LIBS rtsystemeditor)

rtstudio_add_test(tst_interopfsm SOURCES tst_interopfsm.cpp
    LIBS rtstudio_livetest rtstudio_sdkfsmdriver rtstudio_sdkproject)
target_compile_definitions(tst_interopfsm PRIVATE
    RTSTUDIO_OPENRTM_PREFIX="${RTSTUDIO_OPENRTM_PREFIX}"
    RTMANAGER_PATH="$<TARGET_FILE:rtmanager>"
    SDK_FSM_DIR="${SDK_FSM_DIR}"
    SDK_TRAFFICLIGHT_DIR="${SDK_TRAFFICLIGHT_DIR}")
add_dependencies(tst_interopfsm rtmanager rtctl)
set_tests_properties(tst_interopfsm PROPERTIES LABELS interop TIMEOUT 900)
