# SPDX-License-Identifier: MIT
# hrtm: the HRTM API OpenRTM-aist ships (hrtm::DataFlowComponent, ports, ComponentManager, statecharts)
# over the component API; installed as include/openrtm-2.1/hrtm/.
set(SDK_HRTM_HEADERS
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/component_manager.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/data_flow_component.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/defs.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/idls/BasicDataType.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/idls/ExtendedDataTypes.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/idls/HRTM.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/in_port.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/logger.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/out_port.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/properties.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/statechart.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/utils.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/hrtm/version.h
)
set(SDK_HRTM_SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/hrtm/component_manager.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/hrtm/data_flow_component.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/hrtm/properties.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/hrtm/statechart.cpp
)
