// SPDX-License-Identifier: MIT
// A pull connection of an OutPort: samples wait in a buffer until the InPort side takes them.
#ifndef RTC_OUTPORTPULLCONNECTOR_H
#define RTC_OUTPORTPULLCONNECTOR_H

#include <rtm/ConnectorListener.h>
#include <rtm/OutPortConnector.h>

#include <condition_variable>

namespace RTC {
class OutPortProvider;

/// write() keeps samples in the buffer, which @p provider (owned) serves to the InPort side.
class OutPortPullConnector : public OutPortConnector
{
public:
    OutPortPullConnector(ConnectorInfo info, OutPortProvider *provider,
                         ConnectorListenersBase *listeners, CdrBufferBase *buffer = nullptr);
    ~OutPortPullConnector() override;
    DataPortStatus write(ByteDataStreamBase *data) override;
    BufferStatus read(ByteData &data) override;
    DataPortStatus disconnect() override;
    CdrBufferBase *getBuffer() override;
    void activate() override { }
    void deactivate() override { }
    /// A CdrRingBuffer with the `buffer.*` properties of @p info.
    static CdrBufferBase *createBuffer(ConnectorInfo &info);
    void onConnect();
    void onDisconnect();

private:
    OutPortProvider *m_provider;
    CdrBufferBase *m_buffer;
    bool m_deleteBuffer;
};
} // namespace RTC

#endif // RTC_OUTPORTPULLCONNECTOR_H
