// SPDX-License-Identifier: MIT
// One connection of a data InPort.
#ifndef RTC_INPORTCONNECTOR_H
#define RTC_INPORTCONNECTOR_H

#include <rtm/BufferStatus.h>
#include <rtm/ByteData.h>
#include <rtm/ByteDataStreamBase.h>
#include <rtm/ConnectorBase.h>
#include <rtm/ConnectorListener.h>
#include <rtm/DirectOutPortBase.h>
#include <rtm/PortBase.h>

#include <condition_variable>
#include <string>

namespace RTC {
class OutPortBase;

/**
 * A connection of an InPort: where its samples wait (the buffer) and how they are taken
 * (read). The InPort makes one per connection; InPortBase::connectors() lists them.
 */
class InPortConnector : public ConnectorBase
{
public:
    /// @p buffer (may be null) stays its creator's.
    InPortConnector(ConnectorInfo &info, ConnectorListenersBase *listeners, CdrBufferBase *buffer);
    ~InPortConnector() override;

    const ConnectorInfo &profile() override;
    const char *id() override;
    const char *name() override;
    DataPortStatus disconnect() override = 0;
    CdrBufferBase *getBuffer() override;
    /// Takes the next sample of this connection into @p data.
    virtual DataPortStatus read(ByteDataStreamBase *data) = 0;
    virtual void setEndian(bool endian_type);
    /// The byte order of the connection's samples (`serializer.cdr.endian`, little by default).
    virtual bool isLittleEndian();
    /// Puts @p cdr into the connection's buffer, as if it had arrived.
    virtual BufferStatus write(ByteData &cdr);
    /// Drops what the connection subscribed to in the connector profile properties @p prop.
    virtual void unsubscribeInterface(const coil::Properties &prop);
    /**
     * Makes @p directOutPort (an OutPort of this process) the connection's direct sender:
     * getDirectData() then takes its latest value. False for null.
     */
    bool setOutPort(OutPortBase *directOutPort);
    /// Takes the direct sender's latest value into @p data; false without a sender of @p DataType.
    template <typename DataType>
    bool getDirectData(DataType &data)
    {
        DirectOutPortBase<DataType> *outport = dynamic_cast<DirectOutPortBase<DataType> *>(m_directOutPort);
        if (outport == nullptr)
            return false;
        outport->read(data);
        return true;
    }

protected:
    Logger rtclog;
    ConnectorInfo m_profile;
    ConnectorListenersBase *m_listeners;
    CdrBufferBase *m_buffer;
    bool m_littleEndian;
    std::string m_marshaling_type;
    /// A serializer of the connection's samples, for subclasses that make one (none by default).
    ByteDataStreamBase *m_cdr;
    DirectPortBase *m_directOutPort;
};
} // namespace RTC

#endif // RTC_INPORTCONNECTOR_H
