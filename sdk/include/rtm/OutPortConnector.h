// SPDX-License-Identifier: MIT
// One connection of a data OutPort.
#ifndef RTC_OUTPORTCONNECTOR_H
#define RTC_OUTPORTCONNECTOR_H

#include <rtm/BufferStatus.h>
#include <rtm/ByteData.h>
#include <rtm/ByteDataStreamBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/DirectInPortBase.h>
#include <rtm/PortBase.h>
#include <rtm/SystemLogger.h>

#include <condition_variable>
#include <string>

namespace RTC {
class InPortBase;

/**
 * A connection of an OutPort: how a written sample reaches the other side (write). The
 * OutPort makes one per connection; OutPortBase::connectors() lists them.
 */
class OutPortConnector : public ConnectorBase
{
public:
    OutPortConnector(ConnectorInfo &info, ConnectorListenersBase *listeners);
    ~OutPortConnector() override;

    const ConnectorInfo &profile() override;
    const char *id() override;
    const char *name() override;
    DataPortStatus disconnect() override = 0;
    CdrBufferBase *getBuffer() override = 0;
    /// Sends (or keeps, for pull connections) the sample in @p data.
    virtual DataPortStatus write(ByteDataStreamBase *data) = 0;
    virtual void setEndian(bool endian_type);
    /// The byte order of the connection's samples (`serializer.cdr.endian`, little by default).
    virtual bool isLittleEndian();
    /// Takes a kept sample (pull connections); push connections keep none and answer
    /// PRECONDITION_NOT_MET.
    virtual BufferStatus read(ByteData &data);
    /// Drops what the connection subscribed to in the connector profile properties @p prop.
    virtual void unsubscribeInterface(const coil::Properties &prop);
    /// Makes @p directInPort (an InPort of this process) the connection's direct receiver; false for null.
    bool setInPort(InPortBase *directInPort);
    /// Marks the connection as one whose receiver takes the latest value itself (InPortConnector::getDirectData).
    virtual void setPullDirectMode();
    virtual bool pullDirectMode();

protected:
    Logger rtclog;
    ConnectorInfo m_profile;
    bool m_littleEndian;
    ConnectorListenersBase *m_listeners;
    std::string m_marshaling_type;
    /// A serializer of the connection's samples, for subclasses that make one (none by default).
    ByteDataStreamBase *m_cdr;
    InPortBase *m_directInPort;
    bool m_directMode;
};
} // namespace RTC

#endif // RTC_OUTPORTCONNECTOR_H
