// SPDX-License-Identifier: MIT
#include "dataport.h"

#include "outportconnector.h"

#include <stdexcept>

namespace Runtime {

DataPortBase::DataPortBase(const std::string &name, const std::string &portType,
                           const std::string &dataType)
    : PortBase(name)
    , m_dataType(dataType)
    , m_input(portType == "DataInPort")
{
    setProperty("port.port_type", portType);
    setProperty("dataport.data_type", dataType);
    setProperty("dataport.interface_type", "corba_cdr");
    setProperty("dataport.dataflow_type", "push,pull");
    // As OpenRTM-aist's ports: the subscription type is the sending side's; an InPort takes any.
    setProperty("dataport.subscription_type",
                m_input ? "Any" : "block,flush,new,nonblock,periodic");
    setProperty("dataport.marshaling_types", "cdr");
}

RTC::ReturnCode_t DataPortBase::admit(const RTC::ConnectorProfile &profile)
{
    const char *limitKey = m_input ? "fan_in" : "fan_out";
    const std::string connectorKey
        = std::string(m_input ? "dataport.inport." : "dataport.outport.") + limitKey;
    const Properties own = portProperties();
    const std::string text = own.contains(limitKey)
        ? own.value(limitKey)
        : nvToProperties(profile.properties).value(connectorKey);
    unsigned long limit = 100;
    try {
        if (!text.empty())
            limit = std::stoul(text);
    } catch (const std::exception &) {
        // An unreadable limit keeps OpenRTM's default.
    }
    if (connectionCount() >= limit)
        return RTC::PRECONDITION_NOT_MET;
    return PortBase::admit(profile);
}

std::string marshalingType(const Properties &p, const std::string &side)
{
    std::string type = p.value("dataport." + side + ".marshaling_type", p.value("dataport.marshaling_type", "cdr"));
    type.erase(0, type.find_first_not_of(" \t"));
    type.erase(type.find_last_not_of(" \t") + 1);
    return type.empty() ? std::string("cdr") : type;
}

std::string DataPortBase::checkProfile(const Properties &p, bool *pull) const
{
    const std::string interfaceType = p.value("dataport.interface_type", "corba_cdr");
    if (interfaceType != "corba_cdr")
        return "unsupported dataport.interface_type '" + interfaceType + "'";
    const std::string flow = p.value("dataport.dataflow_type", "push");
    if (flow != "push" && flow != "pull")
        return "unsupported dataport.dataflow_type '" + flow + "'";
    *pull = flow == "pull";
    OutPortPushConnector::Mode mode;
    if (!m_input && !*pull
        && !OutPortPushConnector::parseMode(p.value("dataport.subscription_type", "flush"), &mode))
        return "unsupported dataport.subscription_type '" + p.value("dataport.subscription_type") + "'";
    // OpenRTM's user serializers: an InPort's (`inport.marshaling_type=cdr:RTC/TimedShort:RTC/TimedDouble`)
    // may read another data type than its own, an OutPort's write its samples as another type.
    const std::string outportMarshaling = marshalingType(p, "outport");
    if (!m_input && outportMarshaling != "cdr" && !m_userSerializers)
        return "no serializer '" + outportMarshaling + "' for this OutPort (it writes plain cdr)";
    const std::string type = p.value("dataport.data_type");
    if (!type.empty() && !sameDataType(type, m_dataType) && marshalingType(p, "inport") == "cdr"
        && outportMarshaling == "cdr")
        return "data type '" + type + "' does not match '" + m_dataType + "'";
    return {};
}

} // namespace Runtime
