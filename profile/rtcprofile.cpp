// SPDX-License-Identifier: MIT
#include "rtcprofile.h"

#include <QDateTime>

#include <tuple>

namespace Profile {

namespace {

struct ActionName
{
    RtcAction action;
    const char *element;
    const char *key;
};

constexpr std::array<ActionName, RtcActionCount> actionNames {{
    {RtcAction::OnInitialize, "OnInitialize", "onInitialize"},
    {RtcAction::OnFinalize, "OnFinalize", "onFinalize"},
    {RtcAction::OnStartup, "OnStartup", "onStartup"},
    {RtcAction::OnShutdown, "OnShutdown", "onShutdown"},
    {RtcAction::OnActivated, "OnActivated", "onActivated"},
    {RtcAction::OnDeactivated, "OnDeactivated", "onDeactivated"},
    {RtcAction::OnAborting, "OnAborting", "onAborting"},
    {RtcAction::OnError, "OnError", "onError"},
    {RtcAction::OnReset, "OnReset", "onReset"},
    {RtcAction::OnExecute, "OnExecute", "onExecute"},
    {RtcAction::OnStateUpdate, "OnStateUpdate", "onStateUpdate"},
    {RtcAction::OnRateChanged, "OnRateChanged", "onRateChanged"},
    {RtcAction::OnAction, "OnAction", "onAction"},
    {RtcAction::OnModeChanged, "OnModeChanged", "onModeChanged"},
}};

/// Now as OpenRTP writes dates: local time with milliseconds and the UTC offset.
QString nowAsDateTime()
{
    const QDateTime now = QDateTime::currentDateTime();
    return now.toOffsetFromUtc(now.offsetFromUtc()).toString(Qt::ISODateWithMs);
}

} // namespace

QString rtcActionElementName(RtcAction action)
{
    return QLatin1String(actionNames[std::size_t(action)].element);
}

QString rtcActionKey(RtcAction action)
{
    return QLatin1String(actionNames[std::size_t(action)].key);
}

const std::array<RtcAction, RtcActionCount> &rtcAllActions()
{
    static const std::array<RtcAction, RtcActionCount> all = [] {
        std::array<RtcAction, RtcActionCount> result {};
        for (std::size_t i = 0; i < result.size(); ++i)
            result[i] = actionNames[i].action;
        return result;
    }();
    return all;
}

bool RtcBasicDoc::operator==(const RtcBasicDoc &other) const
{
    return std::tie(description, inout, algorithm, creator, license, reference, extras)
        == std::tie(other.description, other.inout, other.algorithm, other.creator, other.license,
                    other.reference, other.extras);
}

std::optional<double> RtcBasicInfo::executionRateValue() const
{
    if (!executionRate)
        return std::nullopt;
    bool ok = false;
    const double value = executionRate->trimmed().toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

std::optional<qint64> RtcBasicInfo::maxInstancesValue() const
{
    if (!maxInstances)
        return std::nullopt;
    bool ok = false;
    const qint64 value = maxInstances->trimmed().toLongLong(&ok);
    return ok ? std::optional<qint64>(value) : std::nullopt;
}

bool RtcBasicInfo::operator==(const RtcBasicInfo &other) const
{
    return std::tie(name, componentType, activityType, componentKind, rtcType, category,
                    description, executionRate, executionType, maxInstances, vendor, version,
                    abstractText, hardwareProfile, creationDate, updateDate, doc)
        == std::tie(other.name, other.componentType, other.activityType, other.componentKind,
                    other.rtcType, other.category, other.description, other.executionRate,
                    other.executionType, other.maxInstances, other.vendor, other.version,
                    other.abstractText, other.hardwareProfile, other.creationDate, other.updateDate,
                    other.doc)
        && std::tie(versionUpLogs, properties, comment, saveProject, missing, extras)
        == std::tie(other.versionUpLogs, other.properties, other.comment, other.saveProject,
                    other.missing, other.extras);
}

bool RtcActionDoc::operator==(const RtcActionDoc &other) const
{
    return std::tie(description, preCondition, postCondition, extras)
        == std::tie(other.description, other.preCondition, other.postCondition, other.extras);
}

bool RtcActionStatus::isImplemented() const
{
    return parseBoolean(implemented).value_or(false);
}

void RtcActionStatus::setImplemented(bool value)
{
    implemented = booleanText(value);
    missing.removeAll(QStringLiteral("implemented"));
}

bool RtcActionStatus::operator==(const RtcActionStatus &other) const
{
    return std::tie(implemented, doc, missing, extras)
        == std::tie(other.implemented, other.doc, other.missing, other.extras);
}

bool RtcActions::isImplemented(RtcAction action) const
{
    const auto &entry = (*this)[action];
    return entry && entry->isImplemented();
}

void RtcActions::setImplemented(RtcAction action, bool value)
{
    auto &entry = (*this)[action];
    if (!entry)
        entry.emplace();
    entry->setImplemented(value);
}

bool RtcActions::operator==(const RtcActions &other) const
{
    return status == other.status && extras == other.extras;
}

bool RtcConfigurationDoc::operator==(const RtcConfigurationDoc &other) const
{
    return std::tie(dataname, defaultValue, description, unit, range, constraint, extras)
        == std::tie(other.dataname, other.defaultValue, other.description, other.unit, other.range,
                    other.constraint, other.extras);
}

std::optional<QString> RtcConfiguration::widget() const
{
    return rtcPropertyValue(properties, WidgetProperty);
}

bool RtcConfiguration::operator==(const RtcConfiguration &other) const
{
    return std::tie(name, type, defaultValue, unit, constraint, doc, variableName, comment,
                    properties, missing, extras)
        == std::tie(other.name, other.type, other.defaultValue, other.unit, other.constraint,
                    other.doc, other.variableName, other.comment, other.properties, other.missing,
                    other.extras);
}

bool RtcLibrary::operator==(const RtcLibrary &o) const
{
    return std::tie(name, version, other, missing, extras)
        == std::tie(o.name, o.version, o.other, o.missing, o.extras);
}

bool RtcTargetEnvironment::operator==(const RtcTargetEnvironment &o) const
{
    return std::tie(langVersion, os, other, cpuOther, osVersions, cpus, libraries, extras)
        == std::tie(o.langVersion, o.os, o.other, o.cpuOther, o.osVersions, o.cpus, o.libraries,
                    o.extras);
}

bool RtcLanguage::operator==(const RtcLanguage &other) const
{
    return std::tie(kind, targets, properties, missing, extras)
        == std::tie(other.kind, other.targets, other.properties, other.missing, other.extras);
}

bool RtcParameter::operator==(const RtcParameter &other) const
{
    return std::tie(name, defaultValue, missing, extras)
        == std::tie(other.name, other.defaultValue, other.missing, other.extras);
}

std::optional<RtcComponentId> RtcComponentId::parse(const QString &id)
{
    const QStringList parts = id.split(QLatin1Char(':'));
    if (parts.size() != 5 || parts.at(0) != QLatin1String("RTC"))
        return std::nullopt;
    for (const QString &part : parts) {
        if (part.isEmpty())
            return std::nullopt;
    }
    return RtcComponentId {parts.at(1), parts.at(2), parts.at(3), parts.at(4)};
}

QString RtcComponentId::toString() const
{
    return QStringList {QStringLiteral("RTC"), vendor, category, name, version}.join(
        QLatin1Char(':'));
}

RtcProfile RtcProfile::createDefault()
{
    RtcProfile profile;
    profile.version = CurrentVersion;
    RtcBasicInfo &info = profile.basicInfo;
    info.name = QStringLiteral("ModuleName");
    info.description = QStringLiteral("ModuleDescription");
    info.category = QStringLiteral("Category");
    info.version = QStringLiteral("1.0.0");
    info.vendor = QStringLiteral("VenderName");
    info.componentType = QStringLiteral("STATIC");
    info.activityType = QStringLiteral("PERIODIC");
    info.componentKind = QStringLiteral("DataFlowComponent");
    info.maxInstances = QStringLiteral("1");
    info.executionType = QStringLiteral("PeriodicExecutionContext");
    info.executionRate = QStringLiteral("1000.0");
    info.creationDate = nowAsDateTime();
    info.updateDate = info.creationDate;
    for (RtcAction action : rtcAllActions())
        profile.actions.setImplemented(action, action == RtcAction::OnInitialize);
    RtcLanguage language;
    language.kind = QStringLiteral("C++");
    profile.language = language;
    profile.id = profile.idFromBasicInfo();
    return profile;
}

QString RtcProfile::idFromBasicInfo() const
{
    return RtcComponentId {basicInfo.vendor, basicInfo.category, basicInfo.name, basicInfo.version}
        .toString();
}

const RtcDataPort *RtcProfile::dataPort(const QString &name) const
{
    for (const RtcDataPort &port : dataPorts) {
        if (port.name == name)
            return &port;
    }
    return nullptr;
}

const RtcServicePort *RtcProfile::servicePort(const QString &name) const
{
    for (const RtcServicePort &port : servicePorts) {
        if (port.name == name)
            return &port;
    }
    return nullptr;
}

const RtcConfiguration *RtcProfile::configuration(const QString &name) const
{
    for (const RtcConfiguration &configuration : configurations) {
        if (configuration.name == name)
            return &configuration;
    }
    return nullptr;
}

bool RtcProfile::operator==(const RtcProfile &other) const
{
    return std::tie(id, version, basicInfo, actions, configurations, hasConfigurationSet,
                    configurationSetExtras, dataPorts, servicePorts, parameters, language, missing,
                    extras)
        == std::tie(other.id, other.version, other.basicInfo, other.actions, other.configurations,
                    other.hasConfigurationSet, other.configurationSetExtras, other.dataPorts,
                    other.servicePorts, other.parameters, other.language, other.missing,
                    other.extras);
}

} // namespace Profile
