// SPDX-License-Identifier: MIT
// A pull connection of an InPort: each read asks the OutPort side through a consumer.
#ifndef RTC_INPORTPULLCONNECTOR_H
#define RTC_INPORTPULLCONNECTOR_H

#include <rtm/DataPortStatus.h>
#include <rtm/InPortConnector.h>
#include <rtm/InPortProvider.h>
#include <rtm/PublisherBase.h>

#include <condition_variable>

namespace RTC {
class OutPortConsumer;

/// read() takes a sample from the OutPort side through @p consumer (owned by the connector).
class InPortPullConnector : public InPortConnector
{
public:
    InPortPullConnector(ConnectorInfo info, OutPortConsumer *consumer,
                        ConnectorListenersBase *listeners, CdrBufferBase *buffer = nullptr);
    ~InPortPullConnector() override;
    DataPortStatus read(ByteDataStreamBase *data) override;
    DataPortStatus disconnect() override;
    void activate() override { }
    void deactivate() override { }
    void unsubscribeInterface(const coil::Properties &prop) override;

protected:
    virtual CdrBufferBase *createBuffer(ConnectorInfo &info);
    void onConnect();
    void onDisconnect();

private:
    OutPortConsumer *m_consumer;
    bool m_deleteBuffer;
};
} // namespace RTC

#endif // RTC_INPORTPULLCONNECTOR_H
