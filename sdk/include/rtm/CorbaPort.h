// SPDX-License-Identifier: MIT
// Service ports: provided interfaces (servants) and required ones (consumers).
#ifndef RTM_CORBAPORT_H
#define RTM_CORBAPORT_H

#include <rtm/CorbaConsumer.h>
#include <rtm/PortBase.h>

#include <rtmruntime/serviceport.h>

#include <array>
#include <compare>
#include <condition_variable>
#include <list>
#include <memory>
#include <string>
#include <vector>

namespace RTC
{
/**
 * A service port. Register provided interfaces (servants the component owns) and required ones
 * (CorbaConsumer members) in onInitialize(), then add the port with addPort(). Consumers receive
 * the provider's reference when the port connects and lose it when it disconnects.
 */
class CorbaPort : public ::Runtime::ServicePort
{
public:
    explicit CorbaPort(const char *name);
    ~CorbaPort() override;

    /**
     * Applies the port's properties: `connection_limit` caps the number of connections (a
     * connect beyond it is refused with PRECONDITION_NOT_MET); negative or unset is unlimited.
     */
    void init(coil::Properties &prop);

    /**
     * Offers @p provider (a servant the component owns, usually a member) as interface
     * @p instance_name of IDL type @p type_name; false if it cannot be activated.
     */
    template <class Servant>
    bool registerProvider(const char *instance_name, const char *type_name, Servant &provider)
    {
        return registerServant(instance_name, type_name, static_cast<PortableServer::ServantBase *>(&provider));
    }
    /// Declares a required interface that @p consumer will reach.
    bool registerConsumer(const char *instance_name, const char *type_name, CorbaConsumerBase &consumer);

protected:
    ReturnCode_t subscribeInterfaces(const ConnectorProfile &profile) override;
    void unsubscribeInterfaces(const ConnectorProfile &profile) override;

private:
    bool registerServant(const char *instance_name, const char *type_name, PortableServer::ServantBase *provider);

    struct ConsumerBinding
    {
        std::shared_ptr<::Runtime::ConsumerSlot> slot;
        CorbaConsumerBase *consumer;
    };
    void updateConsumers();

    std::vector<ConsumerBinding> m_consumers;
};
} // namespace RTC

#endif // RTM_CORBAPORT_H
