// SPDX-License-Identifier: MIT
#include "liveports.h"

namespace Deploy {

namespace {

// `IDL:RTC/TimedLong:1.0` and `RTC::TimedLong` both become `RTC::TimedLong`.
QString canonicalType(QString type)
{
    if (type.startsWith(QLatin1String("IDL:"))) {
        type = type.mid(4);
        const int colon = type.lastIndexOf(QLatin1Char(':'));
        if (colon > 0)
            type.truncate(colon);
        type.replace(QLatin1Char('/'), QStringLiteral("::"));
    }
    return type.trimmed();
}

} // namespace

QString shortPortName(const QString &savedName, const QString &instanceName)
{
    const QString prefix = instanceName + QLatin1Char('.');
    return savedName.startsWith(prefix) ? savedName.mid(prefix.size()) : savedName;
}

const Corba::PortInfo *findPort(const std::vector<Corba::PortInfo> &ports, const QString &savedName,
                                const QString &instanceName)
{
    const QString shortName = shortPortName(savedName, instanceName);
    for (const Corba::PortInfo &port : ports) {
        if (port.name == savedName || port.shortName() == shortName)
            return &port;
    }
    return nullptr;
}

bool sameDataType(const QString &a, const QString &b)
{
    const QString left = canonicalType(a);
    const QString right = canonicalType(b);
    if (left == right)
        return true;
    // One side may omit the module (`TimedLong` vs `RTC::TimedLong`).
    return left.section(QStringLiteral("::"), -1) == right.section(QStringLiteral("::"), -1)
        && (!left.contains(QLatin1String("::")) || !right.contains(QLatin1String("::")));
}

const Corba::ConnectorInfo *findConnector(const Corba::PortInfo &port, const QString &connectorId)
{
    for (const Corba::ConnectorInfo &connector : port.connectors) {
        if (connector.id == connectorId)
            return &connector;
    }
    return nullptr;
}

} // namespace Deploy
