# SPDX-License-Identifier: MIT
# The client and deployment libraries for other programs (the deployment paper's "embed to
# applications", rtctree's role for rtshell): one shared library with the profile readers, the RTC
# tree, component and manager proxies, port taps, the deployment engine (restore, start, stop,
# teardown, cryo, drift, the local runtime), component packages and their repositories
# (packages/) and the deployment planner (planner/); their headers under include/rtstudio; and a CMake package:
#
#   find_package(RTStudioClient REQUIRED)
#   target_link_libraries(MyTool PRIVATE RTStudio::Client)
#
# omniORB and yaml-cpp stay inside the library (no header of the API names them); programs
# using it need Qt 6 Core. resources/examples/client is a program built against the installed package.

add_library(rtstudio_client SHARED)
set_target_properties(rtstudio_client PROPERTIES OUTPUT_NAME rtstudio_client LINKER_LANGUAGE CXX
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR})
# Every object of the static libraries, and what they link.
target_sources(rtstudio_client PRIVATE client.cpp)
target_link_libraries(rtstudio_client PRIVATE
    -Wl,--whole-archive $<TARGET_FILE:rtdeploy> $<TARGET_FILE:rtcorba> $<TARGET_FILE:rtpackages>
    $<TARGET_FILE:rtpackageinstall>
    $<TARGET_FILE:rtplanner> $<TARGET_FILE:rtprofile>
    -Wl,--no-whole-archive
    rtcorba_stubs rtcorba_tls rtcorba_guard yaml-cpp rtstudio_omniorb PkgConfig::Z3 Qt6::Network Qt6::Core)
add_dependencies(rtstudio_client rtdeploy rtcorba rtpackages rtpackageinstall rtplanner rtprofile)

set(rtstudio_client_headers "")
foreach(dir profile corba corba/deployment packages packages/install planner)
    file(GLOB headers CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/${dir}/*.h")
    list(APPEND rtstudio_client_headers ${headers})
endforeach()
# The omniORB, yaml-cpp and Z3 side stays inside.
list(FILTER rtstudio_client_headers EXCLUDE REGEX "/(corbacall|rtcconversion|placementsolver|[a-z]+internal|[a-z]+_p)\\.h$")

include(CMakePackageConfigHelpers)
set(rtstudio_client_config_dir "${CMAKE_CURRENT_BINARY_DIR}/client")
configure_file(client/RTStudioClientConfig.cmake.in "${rtstudio_client_config_dir}/RTStudioClientConfig.cmake" @ONLY)
write_basic_package_version_file("${rtstudio_client_config_dir}/RTStudioClientConfigVersion.cmake"
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)

install(TARGETS rtstudio_client LIBRARY DESTINATION lib)
install(FILES ${rtstudio_client_headers} DESTINATION include/rtstudio)
install(FILES "${rtstudio_client_config_dir}/RTStudioClientConfig.cmake"
              "${rtstudio_client_config_dir}/RTStudioClientConfigVersion.cmake"
        DESTINATION lib/cmake/RTStudioClient)
