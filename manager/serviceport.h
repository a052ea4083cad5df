// SPDX-License-Identifier: MIT
#pragma once

#include "portbase.h"

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace Runtime {

/// The far end of a required interface: an object reference filled in when the port connects.
class ConsumerSlot
{
public:
    /// The provider's reference; nil while unconnected.
    CORBA::Object_ptr object();
    void set(CORBA::Object_ptr object);

private:
    std::mutex m_mutex;
    CORBA::Object_var m_object;
};

/**
 * OpenRTM's CorbaPort: provided interfaces publish their IOR under `port.<type>.<instance>`;
 * required interfaces take the IOR published under the same key (or, failing that, the only
 * provider of their type) when the port connects.
 */
class ServicePort : public PortBase
{
public:
    ServicePort(const std::string &name, PortableServer::POA_ptr poa);
    ~ServicePort() override;

    /// Offers @p servant (activated here; the port drops its reference when destroyed).
    void registerProvider(const std::string &instanceName, const std::string &typeName,
                          PortableServer::ServantBase *servant);
    /// Declares a required interface; returns the slot that receives the provider's reference.
    std::shared_ptr<ConsumerSlot> registerConsumer(const std::string &instanceName, const std::string &typeName);
    /// Deactivates the providers and drops the port's references to them.
    void deactivateInterfaces() override;

protected:
    RTC::ReturnCode_t publishInterfaces(RTC::ConnectorProfile &profile) override;
    RTC::ReturnCode_t subscribeInterfaces(const RTC::ConnectorProfile &profile) override;
    void unsubscribeInterfaces(const RTC::ConnectorProfile &profile) override;

private:
    struct Provider
    {
        std::string instanceName;
        std::string typeName;
        PortableServer::ServantBase *servant;
        std::string ior;
    };
    struct Consumer
    {
        std::string instanceName;
        std::string typeName;
        std::shared_ptr<ConsumerSlot> slot;
        std::string connectorId;
    };

    PortableServer::POA_var m_poa;
    std::mutex m_mutex;
    std::vector<Provider> m_providers;
    std::vector<Consumer> m_consumers;
};

} // namespace Runtime
