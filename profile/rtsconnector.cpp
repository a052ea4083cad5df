// SPDX-License-Identifier: MIT
#include "rtsconnector.h"

#include <tuple>

namespace Profile {

bool RtsPortConnector::operator==(const RtsPortConnector &other) const
{
    return std::tie(connectorId, name, source, target, comment, visible, properties, extras,
                    yamlExtras)
        == std::tie(other.connectorId, other.name, other.source, other.target, other.comment,
                    other.visible, other.properties, other.extras, other.yamlExtras);
}

bool RtsDataPortConnector::operator==(const RtsDataPortConnector &other) const
{
    return RtsPortConnector::operator==(other)
        && std::tie(dataType, interfaceType, dataflowType, subscriptionType, pushInterval)
        == std::tie(other.dataType, other.interfaceType, other.dataflowType, other.subscriptionType,
                    other.pushInterval);
}

bool RtsServicePortConnector::operator==(const RtsServicePortConnector &other) const
{
    return RtsPortConnector::operator==(other) && transMethod == other.transMethod;
}

} // namespace Profile
