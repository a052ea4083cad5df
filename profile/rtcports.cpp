// SPDX-License-Identifier: MIT
#include "rtcports.h"

#include <tuple>

namespace Profile {

bool RtcDataPortDoc::operator==(const RtcDataPortDoc &other) const
{
    return std::tie(description, type, number, semantics, unit, occerrence, operation, extras)
        == std::tie(other.description, other.type, other.number, other.semantics, other.unit,
                    other.occerrence, other.operation, other.extras);
}

bool RtcEventDoc::operator==(const RtcEventDoc &other) const
{
    return std::tie(description, type, number, semantics, unit, operation, extras)
        == std::tie(other.description, other.type, other.number, other.semantics, other.unit,
                    other.operation, other.extras);
}

bool RtcEvent::operator==(const RtcEvent &other) const
{
    return std::tie(name, condition, source, target, type, doc, missing, extras)
        == std::tie(other.name, other.condition, other.source, other.target, other.type, other.doc,
                    other.missing, other.extras);
}

bool RtcDataPort::operator==(const RtcDataPort &other) const
{
    return std::tie(portType, name, type, idlFile, interfaceType, dataflowType, subscriptionType,
                    unit, constraint, events, doc, position, variableName, comment, properties,
                    missing, extras)
        == std::tie(other.portType, other.name, other.type, other.idlFile, other.interfaceType,
                    other.dataflowType, other.subscriptionType, other.unit, other.constraint,
                    other.events, other.doc, other.position, other.variableName, other.comment,
                    other.properties, other.missing, other.extras);
}

bool RtcServiceInterfaceDoc::operator==(const RtcServiceInterfaceDoc &other) const
{
    return std::tie(description, docArgument, docReturn, docException, docPreCondition,
                    docPostCondition, extras)
        == std::tie(other.description, other.docArgument, other.docReturn, other.docException,
                    other.docPreCondition, other.docPostCondition, other.extras);
}

bool RtcServiceInterface::operator==(const RtcServiceInterface &other) const
{
    return std::tie(name, direction, instanceName, idlFile, type, path, doc, variableName, comment,
                    properties, missing, extras)
        == std::tie(other.name, other.direction, other.instanceName, other.idlFile, other.type,
                    other.path, other.doc, other.variableName, other.comment, other.properties,
                    other.missing, other.extras);
}

bool RtcTransMethod::operator==(const RtcTransMethod &other) const
{
    return std::tie(kind, missing, extras) == std::tie(other.kind, other.missing, other.extras);
}

bool RtcServicePortDoc::operator==(const RtcServicePortDoc &other) const
{
    return std::tie(description, ifdescription, extras)
        == std::tie(other.description, other.ifdescription, other.extras);
}

bool RtcServicePort::operator==(const RtcServicePort &other) const
{
    return std::tie(name, interfaces, transMethods, doc, position, comment, properties, missing,
                    extras)
        == std::tie(other.name, other.interfaces, other.transMethods, other.doc, other.position,
                    other.comment, other.properties, other.missing, other.extras);
}

} // namespace Profile
