# SPDX-License-Identifier: MIT
# coil: OpenRTM-aist's utility library (2.x API plus the 1.x parts published components still use).
set(SDK_COIL_HEADERS
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/config_coil.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Condition.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Guard.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Mutex.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/OS.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Properties.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Singleton.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/stringutil.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Task.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/Time.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/TimeMeasure.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/TimeValue.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/coil/UUID.h
)
set(SDK_COIL_SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/Properties.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/stringutil.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/Task.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/TimeMeasure.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/TimeValue.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coil/UUID.cpp
)
