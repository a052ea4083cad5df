# SPDX-License-Identifier: MIT
# rtm: OpenRTM-aist's component API on the runtime.
set(SDK_RTM_HEADERS
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/BufferBase.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/BufferStatus.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/ByteData.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/ConfigAdmin.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/ConfigurationListener.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/ConnectorBase.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/ConnectorListener.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/CorbaConsumer.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/CorbaPort.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/DataFlowComponentBase.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/DataInPort.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/DataPortListeners.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/EventBase.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/EventPort.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/DataOutPort.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/Factory.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/FsmActionListener.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/InPort.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/InPortBase.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/Macho.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/Manager.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/ManagerActionListener.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/OutPort.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/OutPortBase.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/PortBase.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/RTC.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/RingBuffer.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/RTObject.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/StaticFSM.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/SystemLogger.h
    ${CMAKE_CURRENT_SOURCE_DIR}/include/rtm/Timestamp.h
)
set(SDK_RTM_SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/sdkinternal.h
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/sdkinternal.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/loggersink.h
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/logger.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/connectorlisteners.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/configadmin.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/ports.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/rtobject.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/fsmactions.h
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/fsmactions.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/manager.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/manageractions.h
    ${CMAKE_CURRENT_SOURCE_DIR}/rtm/manageractions.cpp
)
# The runtime headers the public headers build on, installed as <rtmruntime/…>.
set(SDK_RUNTIME_HEADERS
    configadmin.h dataport.h inport.h inportconnector.h outport.h outportconnector.h portbase.h
    properties.h ringbuffer.h rtobject.h serviceport.h)
