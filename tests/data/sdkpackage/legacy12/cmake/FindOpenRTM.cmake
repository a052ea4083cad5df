# SPDX-License-Identifier: MIT
# The kind of FindOpenRTM.cmake OpenRTM-aist 1.1/1.2-era projects carry: asks rtm-config (from
# OPENRTM_DIR/bin or the PATH) for the prefix, IDL compiler and libraries, pkg-config for openrtm-aist
# and libcoil, and reads the version out of rtm/version.h.
#
# Sets OPENRTM_FOUND, OPENRTM_DIR, OPENRTM_VERSION (+ _MAJOR, _MINOR, _PATCH), OPENRTM_INCLUDE_DIRS,
# OPENRTM_LIBRARY_DIRS, OPENRTM_LIBRARIES, OPENRTM_IDLC, OPENRTM_IDLFLAGS, OPENRTM_IDL_WRAPPER.

set(OPENRTM_FOUND FALSE)

if(OPENRTM_DIR)
  set(OPENRTM_CONFIG_EXECUTABLE ${OPENRTM_DIR}/bin/rtm-config)
else()
  find_program(OPENRTM_CONFIG_EXECUTABLE rtm-config)
endif()
if(NOT OPENRTM_CONFIG_EXECUTABLE OR NOT EXISTS ${OPENRTM_CONFIG_EXECUTABLE})
  message(FATAL_ERROR "rtm-config not found: put OpenRTM-aist's bin folder on the PATH or set OPENRTM_DIR")
endif()

macro(_openrtm_config variable option)
  execute_process(COMMAND ${OPENRTM_CONFIG_EXECUTABLE} ${option}
    OUTPUT_VARIABLE ${variable} RESULT_VARIABLE _openrtm_result OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT _openrtm_result EQUAL 0)
    message(FATAL_ERROR "rtm-config ${option} failed")
  endif()
endmacro()

_openrtm_config(OPENRTM_DIR --prefix)
_openrtm_config(OPENRTM_IDLC --idlc)
_openrtm_config(OPENRTM_IDLFLAGS --idlflags)
separate_arguments(OPENRTM_IDLFLAGS)
_openrtm_config(_openrtm_libs_l --libs-only-l)
_openrtm_config(_openrtm_libs_L --libs-only-L)
string(REGEX REPLACE "-l" ";" OPENRTM_LIBRARIES "${_openrtm_libs_l}")
string(REGEX REPLACE " ;" ";" OPENRTM_LIBRARIES "${OPENRTM_LIBRARIES}")
string(REGEX REPLACE "-L" ";" OPENRTM_LIBRARY_DIRS "${_openrtm_libs_L}")
string(REGEX REPLACE " ;" ";" OPENRTM_LIBRARY_DIRS "${OPENRTM_LIBRARY_DIRS}")
set(OPENRTM_IDL_WRAPPER ${OPENRTM_DIR}/bin/rtm-skelwrapper)

find_package(PkgConfig REQUIRED)
pkg_check_modules(OPENRTM_PC REQUIRED openrtm-aist)
pkg_check_modules(COIL_PC REQUIRED libcoil)
set(OPENRTM_INCLUDE_DIRS ${OPENRTM_PC_INCLUDE_DIRS} ${COIL_PC_INCLUDE_DIRS})

pkg_get_variable(_openrtm_includedir openrtm-aist rtm_includedir)
file(STRINGS ${_openrtm_includedir}/rtm/version.h _openrtm_version_line REGEX "version = \"")
if(_openrtm_version_line MATCHES "version = \"([0-9]+)\\.([0-9]+)\\.([0-9]+)")
  set(OPENRTM_VERSION_MAJOR ${CMAKE_MATCH_1})
  set(OPENRTM_VERSION_MINOR ${CMAKE_MATCH_2})
  set(OPENRTM_VERSION_PATCH ${CMAKE_MATCH_3})
  set(OPENRTM_VERSION ${CMAKE_MATCH_1}.${CMAKE_MATCH_2}.${CMAKE_MATCH_3})
  set(OPENRTM_FOUND TRUE)
else()
  message(FATAL_ERROR "No version in ${_openrtm_includedir}/rtm/version.h")
endif()
message(STATUS "OpenRTM-aist ${OPENRTM_VERSION} in ${OPENRTM_DIR}")
