# SPDX-License-Identifier: MIT
# package: how users' projects consume the SDK. The SDK presents itself as an OpenRTM-aist 2.1 prefix:
#
#   include/openrtm-2.1/rtm/      the component API, config_rtc.h, version.h
#   include/openrtm-2.1/rtm/idl/  OpenRTM's IDL, omniidl's <Name>.hh, wrapper <Name>Skel.h / <Name>Stub.h;
#                                 the extension IDL (camera, manipulator) too, where OpenRTM-aist puts it
#   include/openrtm-2.1/rtm/ext/  (empty; on OpenRTM-aist's include path, so kept)
#   include/openrtm-2.1/rtmruntime/  the runtime's headers (manager/*.h), which rtm/*.h include
#   include/openrtm-2.1/hrtm/     HRTM's API (hrtm/*.h, hrtm/idls/*.h), as OpenRTM-aist installs it
#   include/coil-2.1/coil/        coil (also as include/coil-2.0/coil/ for 2.0-era includes)
#   lib/librtstudio_rtm.so        the runtime, coil, the component API and the IDL stubs in one library
#   lib/librtmCamera2.so, librtmManipulator2.so (and the names without 2)
#                                 linker scripts naming librtstudio_rtm.so, which holds the extension
#                                 IDL's stubs: projects that link OpenRTM-aist's extension libraries link
#   lib/cmake/openrtm-2.1/        OpenRTMConfig.cmake, OpenRTMConfigVersion.cmake (find_package(OpenRTM))
#   lib/pkgconfig/                openrtm2.pc, openrtm-aist.pc (1.x name), libcoil.pc
#   bin/                          rtm2-config, rtm-config, rtm2-skelwrapper, rtm-skelwrapper
#   share/openrtm-2.1/            OPENRTM_DATA_DIR
#
# The prefix exists twice: staged in the build tree (CMAKE_BINARY_DIR is the prefix, so
# -DCMAKE_PREFIX_PATH=<build dir> works without installing) and installed by cmake --install
# (component "sdk"). Every file that names the prefix computes it from its own location, so one copy
# of each serves both.

set(RTSDK_OPENRTM_VERSION_MAJOR 2)
set(RTSDK_OPENRTM_VERSION_MINOR 1)
set(RTSDK_OPENRTM_VERSION_PATCH 0)
set(RTSDK_OPENRTM_VERSION "2.1.0")
set(RTSDK_OPENRTM_SHORT_VERSION 210)
set(RTSDK_RTM_DIR "openrtm-2.1")
set(RTSDK_COIL_DIR "coil-2.1")
set(RTSDK_LIBRARY_NAME rtstudio_rtm)
# Bare names only: OpenRTP's templates turn every "-l", "-L" and "-I" into a list separator.
set(RTSDK_ORB_LIBRARIES omniORB4 omniDynamic4 omnithread pthread)

set(rtsdk_package_dir "${CMAKE_CURRENT_LIST_DIR}")
get_target_property(rtsdk_runtime_headers_dir rtmanager_runtime SOURCE_DIR)
set(rtsdk_prefix "${CMAKE_BINARY_DIR}")
set(rtsdk_generated "${CMAKE_CURRENT_BINARY_DIR}/package/include")

string(REGEX MATCH "-[lLI]" rtsdk_bad_path "${rtsdk_prefix}")
if(rtsdk_bad_path)
    message(WARNING "The build directory ${rtsdk_prefix} contains \"${rtsdk_bad_path}\": OpenRTP-generated "
        "projects split OPENRTM_INCLUDE_DIRS at it, so they cannot use this build tree as their prefix.")
endif()

find_package(PkgConfig REQUIRED)
pkg_get_variable(RTSDK_OMNIORB_IDL_DIR omniORB4 idldir)
execute_process(COMMAND "${PKG_CONFIG_EXECUTABLE}" --modversion omniORB4
    OUTPUT_VARIABLE rtsdk_omniorb_version OUTPUT_STRIP_TRAILING_WHITESPACE)
# omniidl has no default include path; OpenRTM's SDOPackage.idl includes <orb.idl> from omniORB's.
set(RTSDK_IDLFLAGS_EXTRA "")
if(RTSDK_OMNIORB_IDL_DIR)
    set(RTSDK_IDLFLAGS_EXTRA " -I${RTSDK_OMNIORB_IDL_DIR}")
endif()

# --- Generated headers: rtm/config_rtc.h, rtm/version.h, rtm/idl/<Name>Skel.h and <Name>Stub.h.
# The library is built against them too, from this folder.
set(RTSDK_OMNIORB_VERSION_MACRO "")
if(rtsdk_omniorb_version MATCHES "^4\\.([0-9]+)")
    set(RTSDK_OMNIORB_VERSION_MACRO "#define RTM_OMNIORB_4${CMAKE_MATCH_1} 1")
endif()
set(RTSDK_VERSION "${PROJECT_VERSION}")
configure_file("${rtsdk_package_dir}/config_rtc.h.in" "${rtsdk_generated}/rtm/config_rtc.h" @ONLY)
configure_file("${rtsdk_package_dir}/version.h.in" "${rtsdk_generated}/rtm/version.h" @ONLY)

file(GLOB rtsdk_idl_files CONFIGURE_DEPENDS "${RTSTUDIO_IDL_DIR}/*.idl")
# OpenRTM-aist builds its extension IDL (libraries rtmCamera2, rtmManipulator2) with the core IDL of
# rtm/idl as dependencies, so their Skel headers include every core Skel header first; users of the
# extension types may rely on that.
set(rtsdk_core_idl BasicDataType DataPort DataPort_OpenRTM ExtendedDataTypes InterfaceDataTypes Manager
    OpenRTM RTC SDOPackage ExtendedFsmService SharedMemory)
set(rtsdk_extension_idl CameraCommonInterface ManipulatorCommonInterface_Common
    ManipulatorCommonInterface_DataTypes ManipulatorCommonInterface_Middle)
set(rtsdk_core_skel_includes "")
foreach(core IN LISTS rtsdk_core_idl)
    string(APPEND rtsdk_core_skel_includes "#include <rtm/idl/${core}Skel.h>\n")
endforeach()
set(rtsdk_idl_headers "")
foreach(idl IN LISTS rtsdk_idl_files)
    get_filename_component(RTSDK_IDL_NAME "${idl}" NAME_WE)
    foreach(RTSDK_WRAPPER_KIND Skel Stub)
        set(RTSDK_WRAPPER_DEPENDENCIES "")
        set(RTSDK_WRAPPER_UTILITY "")
        # As OpenRTM-aist's, the Skel wrapper brings the copyData() specialisations of the IDL's types.
        if(RTSDK_WRAPPER_KIND STREQUAL "Skel"
           AND EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/idl/${RTSDK_IDL_NAME}Util.h")
            set(RTSDK_WRAPPER_UTILITY "#include <rtm/idl/${RTSDK_IDL_NAME}Util.h>\n")
        endif()
        if(RTSDK_WRAPPER_KIND STREQUAL "Skel" AND RTSDK_IDL_NAME IN_LIST rtsdk_extension_idl)
            set(RTSDK_WRAPPER_DEPENDENCIES "${rtsdk_core_skel_includes}")
        endif()
        string(TOUPPER "RTM_IDL_${RTSDK_IDL_NAME}${RTSDK_WRAPPER_KIND}_H" RTSDK_WRAPPER_GUARD)
        configure_file("${rtsdk_package_dir}/idlwrapper.h.in"
            "${rtsdk_generated}/rtm/idl/${RTSDK_IDL_NAME}${RTSDK_WRAPPER_KIND}.h" @ONLY)
    endforeach()
    list(APPEND rtsdk_idl_headers "${CMAKE_BINARY_DIR}/corba/generated/${RTSDK_IDL_NAME}.hh")
endforeach()

target_include_directories(rtsdk PUBLIC
    $<BUILD_INTERFACE:${rtsdk_generated}>
    $<BUILD_INTERFACE:${rtsdk_generated}/rtm/idl>)
set_target_properties(rtsdk PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${rtsdk_prefix}/lib")

# --- Files that compute the prefix themselves: written once, staged and installed as they are.
set(RTSDK_OPENRTM_LIBRARIES_BARE "${RTSDK_LIBRARY_NAME};${RTSDK_ORB_LIBRARIES}")
list(TRANSFORM RTSDK_OPENRTM_LIBRARIES_BARE PREPEND "-l" OUTPUT_VARIABLE rtsdk_l_flags)
string(JOIN " " RTSDK_LIBS_L ${rtsdk_l_flags})
string(JOIN " " RTSDK_OPENRTM_LIBRARIES_SPACED ${RTSDK_OPENRTM_LIBRARIES_BARE})
# An SDK built with sanitizers (the asan preset) needs their runtimes first in every program that
# links it, so its exported link flags carry them; a normal build exports none.
string(REGEX MATCHALL "-fsanitize=[^ ]+" rtsdk_sanitize "${CMAKE_CXX_FLAGS}")
list(FILTER rtsdk_sanitize EXCLUDE REGEX "fuzzer")
set(RTSDK_LINK_ITEMS "")
set(RTSDK_LINK_FLAGS_SPACED "")
if(rtsdk_sanitize)
    string(JOIN " " rtsdk_sanitize_spaced ${rtsdk_sanitize})
    # With the libraries: 1.2-era projects take nothing but `rtm-config --libs-only-l`.
    string(APPEND RTSDK_LIBS_L " ${rtsdk_sanitize_spaced}")
    set(RTSDK_LINK_FLAGS_SPACED " ${rtsdk_sanitize_spaced}")
    list(JOIN rtsdk_sanitize ";" rtsdk_sanitize_items)
    set(RTSDK_LINK_ITEMS ";${rtsdk_sanitize_items}")
endif()
# The package test expects them too.
set(RTSDK_LINK_ITEMS "${RTSDK_LINK_ITEMS}" CACHE INTERNAL "Link flags the SDK exports besides its libraries")
set(RTSDK_LINK_FLAGS_SPACED "${RTSDK_LINK_FLAGS_SPACED}" CACHE INTERNAL "The same, space-separated")

set(rtsdk_cmake_dir "${rtsdk_prefix}/lib/cmake/${RTSDK_RTM_DIR}")
configure_file("${rtsdk_package_dir}/OpenRTMConfig.cmake.in"
    "${rtsdk_cmake_dir}/OpenRTMConfig.cmake" @ONLY)
include(CMakePackageConfigHelpers)
write_basic_package_version_file("${rtsdk_cmake_dir}/OpenRTMConfigVersion.cmake"
    VERSION ${RTSDK_OPENRTM_VERSION} COMPATIBILITY AnyNewerVersion)

set(rtsdk_pc_dir "${rtsdk_prefix}/lib/pkgconfig")
set(RTSDK_PC_NAME "OpenRTM-aist")
configure_file("${rtsdk_package_dir}/openrtm.pc.in" "${rtsdk_pc_dir}/openrtm2.pc" @ONLY)
configure_file("${rtsdk_package_dir}/openrtm.pc.in" "${rtsdk_pc_dir}/openrtm-aist.pc" @ONLY)
configure_file("${rtsdk_package_dir}/libcoil.pc.in" "${rtsdk_pc_dir}/libcoil.pc" @ONLY)

set(rtsdk_exec_permissions OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
    WORLD_READ WORLD_EXECUTE)
set(rtsdk_tools "")
foreach(tool rtm2-config rtm-config)
    configure_file("${rtsdk_package_dir}/rtm-config.in" "${rtsdk_prefix}/bin/${tool}"
        @ONLY FILE_PERMISSIONS ${rtsdk_exec_permissions})
    list(APPEND rtsdk_tools "${rtsdk_prefix}/bin/${tool}")
endforeach()
foreach(tool rtm2-skelwrapper rtm-skelwrapper)
    configure_file("${rtsdk_package_dir}/rtm-skelwrapper.py" "${rtsdk_prefix}/bin/${tool}"
        COPYONLY FILE_PERMISSIONS ${rtsdk_exec_permissions})
    list(APPEND rtsdk_tools "${rtsdk_prefix}/bin/${tool}")
endforeach()

# OpenRTM-aist's extension libraries by name. A linker script names a library relative to its own
# folder, so these follow the prefix wherever it is copied.
set(rtsdk_extension_libraries "")
foreach(extension rtmCamera2 rtmManipulator2 rtmCamera rtmManipulator)
    set(RTSDK_EXTENSION_LIBRARY ${extension})
    configure_file("${rtsdk_package_dir}/extensionlibrary.ld.in" "${rtsdk_prefix}/lib/lib${extension}.so" @ONLY)
    list(APPEND rtsdk_extension_libraries "${rtsdk_prefix}/lib/lib${extension}.so")
endforeach()

# --- The build-tree prefix: headers and omniidl output are copied at build time, so edits to the
# headers reach users' builds without re-running CMake.
file(MAKE_DIRECTORY "${rtsdk_prefix}/include/${RTSDK_RTM_DIR}/rtm/ext"
    "${rtsdk_prefix}/share/${RTSDK_RTM_DIR}")
add_custom_target(rtsdk_stage ALL
    COMMAND "${CMAKE_COMMAND}"
        "-DRTSDK_SOURCE_INCLUDE=${CMAKE_CURRENT_SOURCE_DIR}/include"
        "-DRTSDK_RUNTIME_HEADERS=${rtsdk_runtime_headers_dir}"
        "-DRTSDK_GENERATED_INCLUDE=${rtsdk_generated}"
        "-DRTSDK_IDL_DIR=${RTSTUDIO_IDL_DIR}"
        "-DRTSDK_OMNIIDL_DIR=${CMAKE_BINARY_DIR}/corba/generated"
        "-DRTSDK_PREFIX=${rtsdk_prefix}"
        "-DRTSDK_RTM_DIR=${RTSDK_RTM_DIR}"
        -P "${rtsdk_package_dir}/stage.cmake"
    COMMENT "Staging the SDK prefix in the build tree"
    VERBATIM)
add_dependencies(rtsdk_stage rtcorba_stubs)

# --- The installed prefix.
set(rtsdk_include_rtm "include/${RTSDK_RTM_DIR}/rtm")
install(TARGETS rtsdk LIBRARY DESTINATION lib COMPONENT sdk)
install(FILES ${rtsdk_extension_libraries} DESTINATION lib COMPONENT sdk)
install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/" "${rtsdk_generated}/rtm/"
    DESTINATION "${rtsdk_include_rtm}" COMPONENT sdk FILES_MATCHING PATTERN "*.h")
foreach(coil_dir coil-2.1 coil-2.0)
    install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/include/coil/"
        DESTINATION "include/${coil_dir}/coil" COMPONENT sdk FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES ${rtsdk_idl_files} ${rtsdk_idl_headers} DESTINATION "${rtsdk_include_rtm}/idl" COMPONENT sdk)
install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/" DESTINATION "include/${RTSDK_RTM_DIR}/hrtm"
    COMPONENT sdk FILES_MATCHING PATTERN "*.h")
install(DIRECTORY "${rtsdk_runtime_headers_dir}/" DESTINATION "include/${RTSDK_RTM_DIR}/rtmruntime"
    COMPONENT sdk FILES_MATCHING PATTERN "*.h" PATTERN "builtins" EXCLUDE)
install(DIRECTORY DESTINATION "${rtsdk_include_rtm}/ext" COMPONENT sdk)
install(DIRECTORY DESTINATION "share/${RTSDK_RTM_DIR}" COMPONENT sdk)
install(FILES "${rtsdk_cmake_dir}/OpenRTMConfig.cmake" "${rtsdk_cmake_dir}/OpenRTMConfigVersion.cmake"
    DESTINATION "lib/cmake/${RTSDK_RTM_DIR}" COMPONENT sdk)
install(FILES "${rtsdk_pc_dir}/openrtm2.pc" "${rtsdk_pc_dir}/openrtm-aist.pc" "${rtsdk_pc_dir}/libcoil.pc"
    DESTINATION lib/pkgconfig COMPONENT sdk)
install(PROGRAMS ${rtsdk_tools} DESTINATION bin COMPONENT sdk)
# rtmanager runs components on the SDK's library: installed, it finds it in <prefix>/lib wherever the prefix is.
# The build tree has the same layout (programs and lib/ one folder below its root), so rtmanager is built with
# that path too. Otherwise CMake pads the build tree's path with empty entries to make room for rewriting
# it on install, and the dynamic loader reads an empty entry as the working directory.
if(TARGET rtmanager)
    set_target_properties(rtmanager PROPERTIES INSTALL_RPATH "$ORIGIN/../lib" BUILD_WITH_INSTALL_RPATH ON)
endif()
