// SPDX-License-Identifier: MIT
#include "connectorsettings.h"

#include "systemmodel.h"

#include <QSet>

#include <algorithm>

#include <tuple>

namespace SystemEditor {

using namespace Profile;

namespace {

const QString DataTypeKey = QStringLiteral("dataport.data_type");
const QString InterfaceTypeKey = QStringLiteral("dataport.interface_type");
const QString DataflowTypeKey = QStringLiteral("dataport.dataflow_type");
const QString SubscriptionTypeKey = QStringLiteral("dataport.subscription_type");
const QString PushRateKey = QStringLiteral("dataport.push_rate");
const QString PushPolicyKey = QStringLiteral("dataport.publisher.push_policy");
const QString SkipCountKey = QStringLiteral("dataport.publisher.skip_count");
const QString TimestampPolicyKey = QStringLiteral("dataport.timestamp_policy");
const QString OutMarshalingKey = QStringLiteral("dataport.outport.marshaling_type");
const QString InMarshalingKey = QStringLiteral("dataport.inport.marshaling_type");

QString bufferKey(const QString &side, const char *suffix)
{
    return QStringLiteral("dataport.%1.buffer.%2").arg(side, QLatin1String(suffix));
}

const char *const BufferSuffixes[] = {"length", "write.full_policy", "write.timeout",
                                      "read.empty_policy", "read.timeout"};

QString *bufferField(BufferSettings &buffer, int index)
{
    QString *fields[] = {&buffer.length, &buffer.fullPolicy, &buffer.writeTimeout,
                         &buffer.emptyPolicy, &buffer.readTimeout};
    return fields[index];
}

QString property(const RtsProperties &properties, const QString &key)
{
    return rtsPropertyValue(properties, key).value_or(QString());
}

/// Sets `key` to `value`, or removes it when `value` is empty.
void putProperty(RtsProperties &properties, const QString &key, const QString &value)
{
    if (value.isEmpty())
        properties.removeIf([&key](const RtsProperty &p) { return p.name == key; });
    else
        setRtsProperty(properties, key, value);
}

void readBuffer(const RtsProperties &properties, const QString &side, BufferSettings &buffer)
{
    for (int i = 0; i < 5; ++i)
        *bufferField(buffer, i) = property(properties, bufferKey(side, BufferSuffixes[i]));
}

void writeBuffer(RtsProperties &properties, const QString &side, BufferSettings buffer)
{
    for (int i = 0; i < 5; ++i)
        putProperty(properties, bufferKey(side, BufferSuffixes[i]), *bufferField(buffer, i));
}

bool isPositiveInteger(const QString &text)
{
    bool ok = false;
    const qlonglong value = text.toLongLong(&ok);
    return ok && value > 0;
}

bool isNonNegativeNumber(const QString &text)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok && value >= 0;
}

QString shortPortName(const QString &portName)
{
    const int dot = portName.lastIndexOf(QLatin1Char('.'));
    return dot < 0 ? portName : portName.mid(dot + 1);
}

} // namespace

bool BufferSettings::operator==(const BufferSettings &other) const
{
    return std::tie(length, fullPolicy, writeTimeout, emptyPolicy, readTimeout)
        == std::tie(other.length, other.fullPolicy, other.writeTimeout, other.emptyPolicy,
                    other.readTimeout);
}

ConnectorSettings ConnectorSettings::defaults(const QString &outPort, const QString &inPort,
                                              const QString &dataType)
{
    ConnectorSettings s;
    s.name = shortPortName(outPort) + QLatin1Char('_') + shortPortName(inPort);
    s.dataType = dataType;
    s.interfaceType = QStringLiteral("corba_cdr");
    s.dataflowType = QStringLiteral("push");
    s.subscriptionType = QStringLiteral("flush");
    s.pushRate = QStringLiteral("1000.0");
    s.pushPolicy = QStringLiteral("all");
    s.skipCount = QStringLiteral("0");
    s.timestampPolicy = QStringLiteral("on_write");
    return s;
}

void reverseConnectorEnds(RtsPortConnector &connector)
{
    std::swap(connector.source, connector.target);
    const QString bends = property(connector.properties, SystemModel::BendPointProperty);
    if (std::optional<QList<QPointF>> points = bendPointsFromText(bends);
        points && !bends.isEmpty()) {
        std::reverse(points->begin(), points->end());
        setRtsProperty(connector.properties, SystemModel::BendPointProperty,
                       bendPointsToText(*points));
    }
}

ConnectDirection ConnectorSettings::directionOf(const RtsDataPortConnector &connector,
                                               const SystemModel *model)
{
    if (!model)
        return ConnectDirection::OutToIn;
    const auto kindOf = [model](const RtsTargetPort &end) {
        const std::optional<PortInfo> port = model->port(end.instanceName, end.portName);
        return port ? port->kind : PortKind::Unknown;
    };
    // Either end tells: a port of unknown kind leaves the decision to the other one.
    const bool reversed = kindOf(connector.source) == PortKind::DataIn
        || kindOf(connector.target) == PortKind::DataOut;
    return reversed ? ConnectDirection::InToOut : ConnectDirection::OutToIn;
}

QString ConnectorSettings::directionText(ConnectDirection direction)
{
    return direction == ConnectDirection::OutToIn
        ? tr("OutPort \u2192 InPort (the OutPort connects)")
        : tr("InPort \u2192 OutPort (the InPort connects)");
}

ConnectorSettings ConnectorSettings::fromConnector(const RtsDataPortConnector &connector,
                                                   const SystemModel *model)
{
    const RtsProperties &p = connector.properties;
    ConnectorSettings s;
    s.name = connector.name;
    s.dataType = connector.dataType.isEmpty() ? property(p, DataTypeKey) : connector.dataType;
    s.interfaceType =
        connector.interfaceType.isEmpty() ? property(p, InterfaceTypeKey) : connector.interfaceType;
    s.dataflowType =
        connector.dataflowType.isEmpty() ? property(p, DataflowTypeKey) : connector.dataflowType;
    s.subscriptionType = connector.subscriptionType.value_or(property(p, SubscriptionTypeKey));
    s.pushRate = connector.pushInterval.value_or(property(p, PushRateKey));
    s.pushPolicy = property(p, PushPolicyKey);
    s.skipCount = property(p, SkipCountKey);
    s.timestampPolicy = property(p, TimestampPolicyKey);
    s.connectDirection = directionOf(connector, model);
    s.marshalingType = property(p, OutMarshalingKey);
    if (s.marshalingType.isEmpty())
        s.marshalingType = property(p, InMarshalingKey);
    readBuffer(p, QStringLiteral("outport"), s.outBuffer);
    readBuffer(p, QStringLiteral("inport"), s.inBuffer);
    const QStringList standard = standardKeys();
    for (const RtsProperty &prop : p) {
        if (!standard.contains(prop.name) && prop.name != SystemModel::BendPointProperty)
            s.freeProperties.append({prop.name, prop.value.value_or(QString())});
    }
    return s;
}

void ConnectorSettings::applyTo(RtsDataPortConnector &connector, const SystemModel *model) const
{
    if (directionOf(connector, model) != connectDirection)
        reverseConnectorEnds(connector);
    connector.name = name;
    connector.dataType = dataType;
    connector.interfaceType = interfaceType;
    connector.dataflowType = dataflowType;
    const QString subscription = isSubscriptionTypeEnabled() ? subscriptionType : QString();
    const QString rate = isPushRateEnabled() ? pushRate : QString();
    connector.subscriptionType =
        subscription.isEmpty() ? std::nullopt : std::optional<QString>(subscription);
    connector.pushInterval = rate.isEmpty() ? std::nullopt : std::optional<QString>(rate);

    RtsProperties &p = connector.properties;
    putProperty(p, DataTypeKey, dataType);
    putProperty(p, InterfaceTypeKey, interfaceType);
    putProperty(p, DataflowTypeKey, dataflowType);
    putProperty(p, SubscriptionTypeKey, subscription);
    putProperty(p, PushRateKey, rate);
    putProperty(p, PushPolicyKey, isPushPolicyEnabled() ? pushPolicy : QString());
    putProperty(p, SkipCountKey, isSkipCountEnabled() ? skipCount : QString());
    putProperty(p, TimestampPolicyKey, timestampPolicy);
    putProperty(p, OutMarshalingKey, marshalingType);
    putProperty(p, InMarshalingKey, marshalingType);
    writeBuffer(p, QStringLiteral("outport"), outBuffer);
    writeBuffer(p, QStringLiteral("inport"), inBuffer);

    // Free properties replace the old free ones; an unchanged one keeps its record (and extras).
    const QStringList standard = standardKeys();
    QSet<QString> freeNames;
    for (const auto &entry : freeProperties)
        freeNames.insert(entry.first);
    p.removeIf([&](const RtsProperty &prop) {
        return !standard.contains(prop.name) && prop.name != SystemModel::BendPointProperty
            && !freeNames.contains(prop.name);
    });
    for (const auto &entry : freeProperties)
        setRtsProperty(p, entry.first, entry.second);
}

bool ConnectorSettings::isSubscriptionTypeEnabled() const
{
    return dataflowType == QLatin1String("push");
}

bool ConnectorSettings::isPushRateEnabled() const
{
    return isSubscriptionTypeEnabled() && subscriptionType == QLatin1String("periodic");
}

bool ConnectorSettings::isPushPolicyEnabled() const
{
    return isSubscriptionTypeEnabled()
        && (subscriptionType == QLatin1String("new")
            || subscriptionType == QLatin1String("periodic"));
}

bool ConnectorSettings::isSkipCountEnabled() const
{
    return isPushPolicyEnabled() && pushPolicy == QLatin1String("skip");
}

QStringList ConnectorSettings::validate() const
{
    QStringList problems;
    if (name.trimmed().isEmpty())
        problems << tr("The connector name is empty.");
    else if (name.size() > MaxNameLength)
        problems << tr("The connector name is longer than %1 characters.").arg(MaxNameLength);
    if (interfaceType.isEmpty())
        problems << tr("Choose an interface type.");
    if (!dataflowTypes().contains(dataflowType))
        problems << tr("Choose a dataflow type (push, pull or duplex).");
    if (isSubscriptionTypeEnabled() && !subscriptionTypes().contains(subscriptionType))
        problems << tr("Choose a subscription type (flush, new or periodic).");
    bool ok = false;
    if (isPushRateEnabled() && !(pushRate.toDouble(&ok) > 0 && ok))
        problems << tr("The push rate must be a number greater than 0.");
    if (isPushPolicyEnabled() && !pushPolicies().contains(pushPolicy))
        problems << tr("Choose a push policy (all, fifo, skip or new).");
    if (isSkipCountEnabled() && !(skipCount.toInt(&ok) >= 0 && ok))
        problems << tr("The skip count must be an integer of 0 or more.");
    if (!timestampPolicy.isEmpty() && !timestampPolicies().contains(timestampPolicy))
        problems << tr("Unknown timestamp policy \"%1\".").arg(timestampPolicy);
    const auto checkBuffer = [&](const BufferSettings &b, const QString &side) {
        if (!b.length.isEmpty() && !isPositiveInteger(b.length))
            problems << tr("The %1 buffer length must be an integer greater than 0.").arg(side);
        if (!b.fullPolicy.isEmpty() && !fullPolicies().contains(b.fullPolicy))
            problems << tr("Unknown %1 buffer full policy \"%2\".").arg(side, b.fullPolicy);
        if (!b.emptyPolicy.isEmpty() && !emptyPolicies().contains(b.emptyPolicy))
            problems << tr("Unknown %1 buffer empty policy \"%2\".").arg(side, b.emptyPolicy);
        if (!b.writeTimeout.isEmpty() && !isNonNegativeNumber(b.writeTimeout))
            problems << tr("The %1 buffer write timeout must be a number of 0 or more.").arg(side);
        if (!b.readTimeout.isEmpty() && !isNonNegativeNumber(b.readTimeout))
            problems << tr("The %1 buffer read timeout must be a number of 0 or more.").arg(side);
    };
    checkBuffer(outBuffer, tr("OutPort"));
    checkBuffer(inBuffer, tr("InPort"));
    QSet<QString> seen;
    for (const auto &entry : freeProperties) {
        if (entry.first.trimmed().isEmpty())
            problems << tr("A property has no name.");
        else if (seen.contains(entry.first))
            problems << tr("The property \"%1\" is listed twice.").arg(entry.first);
        else if (standardKeys().contains(entry.first))
            problems << tr("The property \"%1\" is set by a field of this dialog.").arg(entry.first);
        seen.insert(entry.first);
    }
    return problems;
}

QStringList ConnectorSettings::standardKeys()
{
    QStringList keys {DataTypeKey,  InterfaceTypeKey, DataflowTypeKey,    SubscriptionTypeKey,
                      PushRateKey,  PushPolicyKey,    SkipCountKey,       TimestampPolicyKey,
                      OutMarshalingKey, InMarshalingKey};
    for (const char *side : {"outport", "inport"}) {
        for (const char *suffix : BufferSuffixes)
            keys << bufferKey(QLatin1String(side), suffix);
    }
    return keys;
}

QStringList ConnectorSettings::interfaceTypes()
{
    return {QStringLiteral("corba_cdr"), QStringLiteral("shared_memory"),
            QStringLiteral("direct")};
}

QStringList ConnectorSettings::dataflowTypes()
{
    return {QStringLiteral("push"), QStringLiteral("pull"), QStringLiteral("duplex")};
}

QStringList ConnectorSettings::subscriptionTypes()
{
    return {QStringLiteral("flush"), QStringLiteral("new"), QStringLiteral("periodic")};
}

QStringList ConnectorSettings::pushPolicies()
{
    return {QStringLiteral("all"), QStringLiteral("fifo"), QStringLiteral("skip"),
            QStringLiteral("new")};
}

QStringList ConnectorSettings::timestampPolicies()
{
    return {QStringLiteral("on_write"), QStringLiteral("on_send"), QStringLiteral("on_received"),
            QStringLiteral("on_read")};
}

QStringList ConnectorSettings::fullPolicies()
{
    // The reference's offline list misspells overwrite ("overerite"); offer the real value.
    return {QStringLiteral("overwrite"), QStringLiteral("do_nothing"), QStringLiteral("block")};
}

QStringList ConnectorSettings::emptyPolicies()
{
    return {QStringLiteral("readback"), QStringLiteral("do_nothing"), QStringLiteral("block")};
}

bool ConnectorSettings::operator==(const ConnectorSettings &other) const
{
    return std::tie(name, dataType, interfaceType, marshalingType, dataflowType, subscriptionType,
                    pushRate, pushPolicy, skipCount, timestampPolicy, connectDirection, outBuffer,
                    inBuffer, freeProperties)
        == std::tie(other.name, other.dataType, other.interfaceType, other.marshalingType,
                    other.dataflowType, other.subscriptionType, other.pushRate, other.pushPolicy,
                    other.skipCount, other.timestampPolicy, other.connectDirection,
                    other.outBuffer, other.inBuffer, other.freeProperties);
}

} // namespace SystemEditor
