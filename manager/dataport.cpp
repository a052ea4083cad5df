// SPDX-License-Identifier: MIT
#include "dataport.h"

#include "outportconnector.h"

namespace Runtime {

DataPortBase::DataPortBase(const std::string &name, const std::string &portType, const std::string &dataType)
    : PortBase(name)
    , m_dataType(dataType)
{
    setProperty("port.port_type", portType);
    setProperty("dataport.data_type", dataType);
    setProperty("dataport.interface_type", "corba_cdr");
    setProperty("dataport.dataflow_type", "push,pull");
    setProperty("dataport.subscription_type", "flush,new,periodic");
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
    if (!*pull && !OutPortPushConnector::parseMode(p.value("dataport.subscription_type", "flush"), &mode))
        return "unsupported dataport.subscription_type '" + p.value("dataport.subscription_type") + "'";
    const std::string type = p.value("dataport.data_type");
    if (!type.empty() && !sameDataType(type, m_dataType))
        return "data type '" + type + "' does not match '" + m_dataType + "'";
    return {};
}

} // namespace Runtime
