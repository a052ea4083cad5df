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
 * provider of their type) when the port connects. A provider's object exists only while its
 * component is active: calls at other times end in OBJECT_NOT_EXIST, as with OpenRTM-aist.
 */
class ServicePort : public PortBase
{
public:
    ServicePort(const std::string &name, PortableServer::POA_ptr poa);
    ~ServicePort() override;

    /// Offers @p servant under a reference fixed here; the object answers from the next
    /// activation of the component on. The port drops its reference to @p servant when released.
    void registerProvider(const std::string &instanceName, const std::string &typeName,
                          PortableServer::ServantBase *servant);
    /// Declares a required interface; returns the slot that receives the provider's reference.
    std::shared_ptr<ConsumerSlot> registerConsumer(const std::string &instanceName, const std::string &typeName);
    void activateInterfaces() override;
    void deactivateInterfaces() override;
    /// Deactivates the providers and drops the port's references to them.
    void releaseInterfaces() override;

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
        PortableServer::ObjectId id;
        std::string ior;
        bool active;
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
