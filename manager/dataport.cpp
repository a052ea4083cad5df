// SPDX-License-Identifier: MIT
#include "dataport.h"

#include "outportconnector.h"

#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

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

Properties DataPortBase::connectorProperties(const RTC::ConnectorProfile &profile) const
{
    Properties p = connectorDefaults();
    p.merge(nvToProperties(profile.properties));
    return p;
}

void DataPortBase::setCspChannel()
{
    m_cspChannel = true;
    setProperty("dataport.interface_type", "csp_channel");
    setProperty("dataport.dataflow_type", "duplex");
}

std::string DataPortBase::checkProfile(const Properties &p, Flow *flow) const
{
    const std::string interfaceType = p.value("dataport.interface_type", "corba_cdr");
    const std::string flowType = p.value("dataport.dataflow_type", "push");
    if (m_cspChannel) {
        if (interfaceType != "csp_channel" || flowType != "duplex")
            return "a CSP port takes dataport.interface_type csp_channel with dataflow_type duplex only (not "
                   + interfaceType + " with " + flowType + ")";
        *flow = Flow::Channel;
        return {};
    }
    if (interfaceType != "corba_cdr")
        return "interface type '" + interfaceType + "' is not available (RT Studio's data ports carry corba_cdr"
               + (interfaceType == "csp_channel" ? ", and csp_channel between CSP ports)" : " only)");
    if (flowType != "push" && flowType != "pull")
        return "unsupported dataport.dataflow_type '" + flowType + "'";
    *flow = flowType == "pull" ? Flow::Pull : Flow::Push;
    OutPortPushConnector::Mode mode;
    if (!m_input && *flow == Flow::Push
        && !OutPortPushConnector::parseMode(p.value("dataport.subscription_type", "flush"), &mode))
        return "unsupported dataport.subscription_type '" + p.value("dataport.subscription_type") + "'";
    // OpenRTM's user serializers: an InPort's (`inport.marshaling_type=cdr:RTC/TimedShort:RTC/TimedDouble`)
    // may read another data type than its own, an OutPort's write its samples as another type.
    const std::string outportMarshaling = marshalingType(p, "outport");
    const std::string inportMarshaling = marshalingType(p, "inport");
    const std::string &own = m_input ? inportMarshaling : outportMarshaling;
    if (own != "cdr" && !m_userSerializers)
        return "no serializer '" + own + (m_input ? "' for this InPort (it reads plain cdr)"
                                                   : "' for this OutPort (it writes plain cdr)");
    const std::string type = p.value("dataport.data_type");
    if (!type.empty() && !sameDataType(type, m_dataType) && inportMarshaling == "cdr"
        && outportMarshaling == "cdr")
        return "data type '" + type + "' does not match '" + m_dataType + "'";
    return {};
}

bool DataPortBase::fits(const RTC::ConnectorProfile &profile, const Properties &p, Flow *flow) const
{
    const std::string problem = checkProfile(p, flow);
    if (problem.empty())
        return true;
    refused(profile, problem);
    return false;
}

namespace {

/// Where a channel's connector profile bears the process mark of its first port.
constexpr const char *ChannelMarkKey = "dataport.csp_channel.process";

/// This process's mark on the channels it joins: its id and a random number (ids are reused).
const std::string &processMark()
{
    static const std::string mark = [] {
        std::random_device random;
        std::ostringstream text;
        text << getpid() << '-' << std::hex << random() << random();
        return text.str();
    }();
    return mark;
}

} // namespace

RTC::ReturnCode_t DataPortBase::connect(RTC::ConnectorProfile &connector_profile)
{
    SDOPackage::NVList &properties = connector_profile.properties;
    CORBA::ULong kept = 0;
    for (CORBA::ULong i = 0; i < properties.length(); ++i) {
        if (std::string(properties[i].name.in()) != ChannelMarkKey) {
            if (kept != i)
                properties[kept] = properties[i];
            ++kept;
        }
    }
    properties.length(kept);
    return PortBase::connect(connector_profile);
}

RTC::ReturnCode_t DataPortBase::joinChannel(RTC::ConnectorProfile &profile) const
{
    if (!nvToProperties(profile.properties).contains(ChannelMarkKey)) {
        nvSet(profile.properties, ChannelMarkKey, processMark());
        return RTC::RTC_OK;
    }
    return checkChannel(profile);
}

RTC::ReturnCode_t DataPortBase::checkChannel(const RTC::ConnectorProfile &profile) const
{
    if (nvToProperties(profile.properties).value(ChannelMarkKey) == processMark())
        return RTC::RTC_OK;
    refused(profile, "a CSP channel joins ports of one process, and the other port is in another");
    return RTC::BAD_PARAMETER;
}

void DataPortBase::refused(const RTC::ConnectorProfile &profile, const std::string &problem) const
{
    std::cerr << programName() << ": port " << getName() << ": connector '" << profile.name.in()
              << "' refused: " << problem << std::endl;
}

} // namespace Runtime
