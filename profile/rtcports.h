// SPDX-License-Identifier: MIT
#pragma once

#include "rtccommon.h"
#include "rtcconstraint.h"

namespace Profile {

/// `rtcDoc:Doc` of a data port (`rtcDoc:doc_dataport`).
struct RtcDataPortDoc
{
    std::optional<QString> description;
    std::optional<QString> type;
    std::optional<QString> number;
    std::optional<QString> semantics;
    std::optional<QString> unit;
    std::optional<QString> occerrence; ///< [sic] the schema's spelling of "occurrence"
    std::optional<QString> operation;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcDataPortDoc &other) const;
    bool operator!=(const RtcDataPortDoc &other) const { return !(*this == other); }
};

/// `rtcDoc:Doc` of an FSM event (`rtcDoc:doc_eventport`).
struct RtcEventDoc
{
    std::optional<QString> description;
    std::optional<QString> type;
    std::optional<QString> number;
    std::optional<QString> semantics;
    std::optional<QString> unit;
    std::optional<QString> operation;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcEventDoc &other) const;
    bool operator!=(const RtcEventDoc &other) const { return !(*this == other); }
};

/// `rtc:Event` (+ `rtcDoc:event_doc`): an FSM transition carried by an EventPort.
struct RtcEvent
{
    QString name;
    std::optional<QString> condition;
    QString source; ///< source state
    QString target; ///< target state
    std::optional<QString> type;
    std::optional<RtcEventDoc> doc;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcEvent &other) const;
    bool operator!=(const RtcEvent &other) const { return !(*this == other); }
};

/// `rtc:DataPorts` (+ `rtcDoc:dataport_doc`, `rtcExt:dataport_ext`).
struct RtcDataPort
{
    QString portType; ///< DataInPort | DataOutPort | EventPort (see rtcPortType())
    QString name;
    QString type; ///< data type, e.g. `RTC::TimedLong`
    std::optional<QString> idlFile;
    std::optional<QString> interfaceType;
    std::optional<QString> dataflowType;
    /// Old files spell the attribute `subscriprionType`; read both, written as the schema's name.
    std::optional<QString> subscriptionType;
    std::optional<QString> unit;
    std::optional<RtcConstraint> constraint;
    QList<RtcEvent> events; ///< EventPort only
    std::optional<RtcDataPortDoc> doc;

    // rtcExt:dataport_ext
    QString position; ///< LEFT | RIGHT | TOP | BOTTOM (old files write lower case; read as upper)
    std::optional<QString> variableName; ///< old files: `varname`
    std::optional<QString> comment;
    RtcProperties properties;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    RtcPortType kind() const { return rtcPortType(portType); }

    bool operator==(const RtcDataPort &other) const;
    bool operator!=(const RtcDataPort &other) const { return !(*this == other); }
};

/// `rtcDoc:Doc` of a service interface (`rtcDoc:doc_serviceinterface`).
struct RtcServiceInterfaceDoc
{
    std::optional<QString> description;
    std::optional<QString> docArgument;
    std::optional<QString> docReturn;
    std::optional<QString> docException;
    std::optional<QString> docPreCondition;
    std::optional<QString> docPostCondition;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcServiceInterfaceDoc &other) const;
    bool operator!=(const RtcServiceInterfaceDoc &other) const { return !(*this == other); }
};

/// `rtc:ServiceInterface` (+ `rtcDoc:serviceinterface_doc`, `rtcExt:serviceinterface_ext`).
struct RtcServiceInterface
{
    QString name;
    QString direction; ///< Provided | Required (see rtcDirection())
    std::optional<QString> instanceName;
    std::optional<QString> idlFile;
    QString type; ///< IDL interface type, e.g. `SimpleService::MyService`
    std::optional<QString> path; ///< IDL search path (profile 0.2; still written by RTC Builder)
    std::optional<RtcServiceInterfaceDoc> doc;

    // rtcExt:serviceinterface_ext
    std::optional<QString> variableName; ///< old files: `rtc:varname`
    std::optional<QString> comment;
    RtcProperties properties;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    RtcDirection kind() const { return rtcDirection(direction); }

    bool operator==(const RtcServiceInterface &other) const;
    bool operator!=(const RtcServiceInterface &other) const { return !(*this == other); }
};

/// `rtc:TransMethods @kind` (e.g. CORBA).
struct RtcTransMethod
{
    QString kind;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcTransMethod &other) const;
    bool operator!=(const RtcTransMethod &other) const { return !(*this == other); }
};

/// `rtcDoc:Doc` of a service port (`rtcDoc:doc_serviceport`).
struct RtcServicePortDoc
{
    std::optional<QString> description;
    std::optional<QString> ifdescription;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcServicePortDoc &other) const;
    bool operator!=(const RtcServicePortDoc &other) const { return !(*this == other); }
};

/// `rtc:ServicePorts` (+ `rtcDoc:serviceport_doc`, `rtcExt:serviceport_ext`).
struct RtcServicePort
{
    QString name;
    QList<RtcServiceInterface> interfaces;
    QList<RtcTransMethod> transMethods;
    std::optional<RtcServicePortDoc> doc;

    // rtcExt:serviceport_ext
    QString position; ///< LEFT | RIGHT | TOP | BOTTOM
    std::optional<QString> comment;
    RtcProperties properties;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcServicePort &other) const;
    bool operator!=(const RtcServicePort &other) const { return !(*this == other); }
};

} // namespace Profile
