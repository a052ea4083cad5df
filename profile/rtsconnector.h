// SPDX-License-Identifier: MIT
#pragma once

#include "rtscommon.h"

namespace Profile {

/**
 * What data-port and service-port connectors share: the stable `connectorId`, the two ends and the
 * rtsExt extension (comment, visible, Properties).
 */
struct RtsPortConnector
{
    QString connectorId; ///< the stable key of the connector in the system
    QString name;
    RtsTargetPort source; ///< rts:sourceDataPort / rts:sourceServicePort
    RtsTargetPort target; ///< rts:targetDataPort / rts:targetServicePort
    std::optional<QString> comment; ///< rtsExt:comment
    std::optional<QString> visible; ///< rtsExt:visible
    RtsProperties properties; ///< rtsExt:Properties (dataport.*, BEND_POINT …)

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsPortConnector &other) const;
    bool operator!=(const RtsPortConnector &other) const { return !(*this == other); }
};

/// `rts:DataPortConnectors` (+ dataport_connector_ext).
struct RtsDataPortConnector : RtsPortConnector
{
    QString dataType; ///< e.g. RTC::TimedLong
    QString interfaceType; ///< e.g. corba_cdr
    QString dataflowType; ///< push|pull
    std::optional<QString> subscriptionType; ///< flush|new|periodic
    std::optional<QString> pushInterval; ///< Hz, raw text (xs:double)

    bool operator==(const RtsDataPortConnector &other) const;
    bool operator!=(const RtsDataPortConnector &other) const { return !(*this == other); }
};

/// `rts:ServicePortConnectors` (+ serviceport_connector_ext).
struct RtsServicePortConnector : RtsPortConnector
{
    std::optional<QString> transMethod;

    bool operator==(const RtsServicePortConnector &other) const;
    bool operator!=(const RtsServicePortConnector &other) const { return !(*this == other); }
};

} // namespace Profile
