// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/BufferStatus.h>
#include <rtm/ByteData.h>
#include <rtm/ByteDataStreamBase.h>
#include <rtm/CdrBufferBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/DataPortStatus.h>

namespace RTC::Sdk {

DataPortStatus toDataPortStatus(BufferStatus status);
/// Calls the data listeners of @p type (when @p listeners is a port's ConnectorListeners).
void notifyData(ConnectorListenersBase *listeners, ConnectorDataListenerType type,
                const ConnectorInfo &info, const ByteData &data, bool littleEndian);
void notify(ConnectorListenersBase *listeners, ConnectorListenerType type,
            const ConnectorInfo &info);
/// The bytes a stream holds.
ByteData bytesOf(const ByteDataStreamBase &stream);
/// `serializer.cdr.endian` of a connection (little unless it says big).
bool littleEndianOf(const ConnectorInfo &info);
/// A CdrRingBuffer with the connection's `buffer.*` and `<side>.buffer.*` properties.
CdrBufferBase *newRingBuffer(ConnectorInfo &info, const char *side);
SDOPackage::NVList toNVList(const coil::Properties &prop);
/**
 * Logs that interface type @p interfaceType is not available (RT Studio's data ports carry
 * corba_cdr only) when @p operation is asked of @p what.
 */
void logUnavailable(const char *what, const char *interfaceType, const char *operation);

} // namespace RTC::Sdk
