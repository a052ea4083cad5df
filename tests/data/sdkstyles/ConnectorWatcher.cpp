// SPDX-License-Identifier: MIT
// Connector listeners reading the connector's properties the way many components do: copied into
// an SDO NVList and read with NVUtil and CORBA_SeqUtil. A connector's properties are the port's
// merged with the connector profile's `dataport.` keys, without that prefix.
#include "StyleProfile.h"

#include <rtm/CORBA_SeqUtil.h>
#include <rtm/ConnectorListener.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/NVUtil.h>
#include <rtm/idl/BasicDataTypeSkel.h>

namespace {
SDKSTYLES_SPEC(ConnectorWatcher);

struct IsNamed
{
    explicit IsNamed(const char *name) : m_name(name) {}
    bool operator()(const SDOPackage::NameValue &nv) const { return m_name == static_cast<const char *>(nv.name); }
    std::string m_name;
};

struct Counter
{
    Counter() : count(0) {}
    void operator()(const SDOPackage::NameValue &) { ++count; }
    int count;
};

class OnConnect : public RTC::ConnectorListener
{
public:
    ReturnCode operator()(RTC::ConnectorInfo &info) override
    {
        SDOPackage::NVList properties;
        NVUtil::copyFromProperties(properties, info.properties);
        const Counter counted = CORBA_SeqUtil::for_each(properties, Counter());
        const CORBA::Long at = CORBA_SeqUtil::find(properties, IsNamed("subscription_type"));
        std::cout << "ConnectorWatcher connect " << info.name << " subscription "
                  << NVUtil::toString(properties, "subscription_type") << " at " << (at >= 0 ? "found" : "none")
                  << " of " << counted.count << std::endl;
        return NO_CHANGE;
    }
};

class OnReceived : public RTC::ConnectorDataListenerT<RTC::TimedLong>
{
public:
    ReturnCode operator()(RTC::ConnectorInfo &info, RTC::TimedLong &data) override
    {
        std::cout << "ConnectorWatcher received " << data.data << " on " << info.id << std::endl;
        return NO_CHANGE;
    }
};

class ConnectorWatcher : public RTC::DataFlowComponentBase
{
public:
    explicit ConnectorWatcher(RTC::Manager *manager) : RTC::DataFlowComponentBase(manager), m_inIn("in", m_in) {}

    RTC::ReturnCode_t onInitialize() override
    {
        m_inIn.addConnectorListener(RTC::ConnectorListenerType::ON_CONNECT, new OnConnect());
        m_inIn.addConnectorDataListener(RTC::ConnectorDataListenerType::ON_RECEIVED, new OnReceived());
        addInPort("in", m_inIn);
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        while (m_inIn.isNew())
            m_inIn.read();
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_in;
    RTC::InPort<RTC::TimedLong> m_inIn;
};
} // namespace

extern "C" {
DLL_EXPORT void ConnectorWatcherInit(RTC::Manager *manager)
{
    registerStyle<ConnectorWatcher>(manager, ConnectorWatcher_spec);
}
}
