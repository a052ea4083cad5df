// SPDX-License-Identifier: MIT
// A push connection of an InPort: samples arrive through a provider into a buffer.
#ifndef RTC_INPORTPUSHCONNECTOR_H
#define RTC_INPORTPUSHCONNECTOR_H

#include <rtm/InPortConnector.h>
#include <rtm/InPortConsumer.h>
#include <rtm/PublisherBase.h>

#include <condition_variable>

namespace RTC {
class InPortProvider;

/**
 * Samples the other side puts through @p provider wait in the connection's buffer until
 * read() takes them. The connector owns the provider, and the buffer when it made it.
 */
class InPortPushConnector : public InPortConnector
{
public:
    /// Without @p buffer the connector makes a CdrRingBuffer with the `buffer.*` properties of @p
    /// info.
    InPortPushConnector(ConnectorInfo info, InPortProvider *provider,
                        ConnectorListenersBase *listeners, CdrBufferBase *buffer = nullptr);
    ~InPortPushConnector() override;
    DataPortStatus read(ByteDataStreamBase *data) override;
    DataPortStatus disconnect() override;
    void activate() override { }
    void deactivate() override { }

protected:
    virtual CdrBufferBase *createBuffer(ConnectorInfo &info);
    void onConnect();
    void onDisconnect();

private:
    InPortProvider *m_provider;
    bool m_deleteBuffer;
};
} // namespace RTC

#endif // RTC_INPORTPUSHCONNECTOR_H
