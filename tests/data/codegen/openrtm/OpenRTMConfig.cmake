# SPDX-License-Identifier: MIT
# Test stand-in for OpenRTM-aist 2.x's OpenRTMConfig.cmake: defines the variables of the real
# file (same names and meanings) so that generated component projects can be configured where
# OpenRTM-aist is not installed. Point a generated project at it with -DOpenRTM_DIR=<this folder>.
#
# OPENRTM_FIXTURE_PREFIX (optional, cache) is the install prefix it describes; by default the
# folder of this file. The real file derives every path from its install prefix the same way.

set(OPENRTM_FIXTURE_PREFIX "${CMAKE_CURRENT_LIST_DIR}" CACHE PATH "Install prefix described by the OpenRTM test config")

message(STATUS "OpenRTMConfig.cmake found (RT Studio test fixture).")

# OpenRTM-aist version
set(OPENRTM_VERSION 2.0.2)
set(OPENRTM_VERSION_MAJOR 2)
set(OPENRTM_VERSION_MINOR 0)
set(OPENRTM_VERSION_PATCH 2)
set(OPENRTM_SHORT_VERSION 202)

# Basic compiler/linker options
set(OPENRTM_DIR "${OPENRTM_FIXTURE_PREFIX}")
set(OPENRTM_CFLAGS -Wall -fPIC -O2 -D__x86_64__ -D__linux__ -D__OSVERSION__=2 -D__OMNIORB4__ -D_REENTRANT)
set(OPENRTM_INCLUDE_DIRS
    ${OPENRTM_DIR}/include
    ${OPENRTM_DIR}/include/coil-2.0
    ${OPENRTM_DIR}/include/openrtm-2.0
    ${OPENRTM_DIR}/include/openrtm-2.0/rtm/ext)
set(OPENRTM_LDFLAGS -rdynamic)
set(OPENRTM_LIBRARY_DIRS ${OPENRTM_DIR}/lib)
set(OPENRTM_LIBRARIES RTC coil omniORB4 omnithread omniDynamic4 pthread dl)
set(OPENRTM_LIB_DIR ${OPENRTM_DIR}/lib/openrtm-2.0)
set(OPENRTM_DATA_DIR ${OPENRTM_DIR}/share/openrtm-2.0)
set(COIL_INCLUDE_DIR ${OPENRTM_DIR}/include/coil-2.0)

# OpenRTM-aist's CORBA related settings
set(OPENRTM_ORB omniORB)
set(OPENRTM_IDL_WRAPPER rtm-skelwrapper)
set(OPENRTM_IDL_WRAPPER_FLAGS --include-dir="" --skel-suffix=Skel)
set(OPENRTM_IDLC omniidl)
set(OPENRTM_IDLFLAGS -bcxx -Wba -nf -Wbshortcut)

# omniORB
set(OMNIORB_DIR /usr)
set(OMNIORB_CFLAGS -D__x86_64__ -D__linux__ -D__OSVERSION__=2)
set(OMNIORB_INCLUDE_DIRS /usr/include)
set(OMNIORB_LIBRARIES omniORB4 omnithread omniDynamic4)

set(OpenRTM_FOUND TRUE)
