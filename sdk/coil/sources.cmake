# SPDX-License-Identifier: MIT
# coil: OpenRTM-aist's utility library (2.x API plus the 1.x parts published components still use).
set(SDK_COIL_HEADERS
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/config_coil.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Properties.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/stringutil.h
)
set(SDK_COIL_SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/Properties.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/stringutil.cpp
)
