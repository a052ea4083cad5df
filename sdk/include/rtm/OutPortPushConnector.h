// SPDX-License-Identifier: MIT
// A push connection of an OutPort: a publisher sends each sample through a consumer.
#ifndef RTC_OUTPORTPUSHCONNECTOR_H
#define RTC_OUTPORTPUSHCONNECTOR_H

#include <rtm/InPortConsumer.h>
#include <rtm/OutPortConnector.h>
#include <rtm/PublisherBase.h>

#include <condition_variable>

namespace RTC {
class ConnectorListeners;

/**
 * write() hands samples to the publisher `subscription_type` names (flush: the default, new,
 * periodic), which sends them through @p consumer. The connector owns the consumer and the
 * publisher, and the buffer when it made it.
 */
class OutPortPushConnector : public OutPortConnector
{
public:
    OutPortPushConnector(ConnectorInfo info, InPortConsumer *consumer,
                         ConnectorListenersBase *listeners, CdrBufferBase *buffer = nullptr);
    ~OutPortPushConnector() override;
    DataPortStatus write(RTC::ByteDataStreamBase *data) override;
    DataPortStatus disconnect() override;
    void activate() override;
    void deactivate() override;
    CdrBufferBase *getBuffer() override;
    void unsubscribeInterface(const coil::Properties &prop) override;

protected:
    /// The publisher for the `subscription_type` of @p profile; null for an unknown type.
    virtual PublisherBase *createPublisher(ConnectorInfo &info);
    virtual CdrBufferBase *createBuffer(ConnectorInfo &info);
    void onConnect();
    void onDisconnect();

private:
    InPortConsumer *m_consumer;
    PublisherBase *m_publisher;
    CdrBufferBase *m_buffer;
    bool m_deleteBuffer;
};
} // namespace RTC

#endif // RTC_OUTPORTPUSHCONNECTOR_H
