// SPDX-License-Identifier: MIT
#pragma once

#include "rtscommon.h"

#include <QStringList>

namespace Profile {

/// `rts:DataPorts` / `rts:ServicePorts` (+ dataport_ext / serviceport_ext): a port shown in the
/// system.
struct RtsPort
{
    QString name; ///< the stable key of the port within its component
    std::optional<QString> comment; ///< rtsExt:comment
    std::optional<QString>
        visible; ///< rtsExt:visible, `true`/`false` (other text kept for validation)
    RtsProperties properties; ///< rtsExt:Properties

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsPort &other) const;
    bool operator!=(const RtsPort &other) const { return !(*this == other); }
};

/// `rts:ConfigurationData @name @data?`: one parameter value of a configuration set.
struct RtsConfigurationData
{
    QString name;
    std::optional<QString> data;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsConfigurationData &other) const;
    bool operator!=(const RtsConfigurationData &other) const { return !(*this == other); }
};

/// `rts:ConfigurationSets @id`: a named set of configuration values.
struct RtsConfigurationSet
{
    QString id;
    QList<RtsConfigurationData> data;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsConfigurationSet &other) const;
    bool operator!=(const RtsConfigurationSet &other) const { return !(*this == other); }
};

/// `rts:ExecutionContexts` (+ execution_context_ext) `@id @kind @rate?`.
struct RtsExecutionContext
{
    QString id; ///< may be non-numeric (`Comp1Ec1`)
    QString kind; ///< e.g. PeriodicExecutionContext
    std::optional<QString> rate; ///< Hz, raw text (xs:double)
    QList<RtsTargetComponent> participants; ///< rts:Participants
    RtsProperties properties; ///< rtsExt:Properties

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    /// The rate as a number, when present and well-formed.
    std::optional<double> rateValue() const;

    bool operator==(const RtsExecutionContext &other) const;
    bool operator!=(const RtsExecutionContext &other) const { return !(*this == other); }
};

/// `rts:Participants` → `rts:Participant`: a member of a composite component.
struct RtsParticipant
{
    RtsTargetComponent participant;

    XmlExtras extras; ///< of the rts:Participants wrapper
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsParticipant &other) const;
    bool operator!=(const RtsParticipant &other) const { return !(*this == other); }
};

/// `rtsExt:Location @x @y @height @width @direction`: where the editor draws the component.
struct RtsLocation
{
    QString x;
    QString y;
    QString height; ///< -1 = default size
    QString width; ///< -1 = default size
    QString direction; ///< UP|DOWN|LEFT|RIGHT (read case-insensitively and stored upper case)

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    static std::optional<int> toInt(const QString &text);
    /// The four directions of the schema, in its order.
    static QStringList directions();

    bool operator==(const RtsLocation &other) const;
    bool operator!=(const RtsLocation &other) const { return !(*this == other); }
};

/// The parts of a component type id `RTC:vendor:category:name:version`.
struct RtsComponentTypeId
{
    QString vendor;
    QString category;
    QString name;
    QString version;

    /// Splits an id; nothing when it does not have the form `RTC:v:c:n:ver`.
    static std::optional<RtsComponentTypeId> parse(const QString &id);
    QString toString() const;
};

/**
 * `rts:Components` (+ `rtsExt:component_ext`): one RT-Component instance of the system.
 * `instanceName` is its stable key; ports are keyed by name within it.
 */
struct RtsComponent
{
    QString id; ///< `RTC:vendor:category:name:version`
    QString pathUri; ///< naming-service path or file URI
    QString instanceName;
    std::optional<QString> activeConfigurationSet;
    std::optional<QString> compositeType; ///< one of compositeTypes(); raw text otherwise
    QString isRequired = QStringLiteral("true"); ///< `true`/`false` (legacy `1`/`0` normalised)
    std::optional<QString> comment; ///< rtsExt:comment
    std::optional<QString> visible; ///< rtsExt:visible

    QList<RtsPort> dataPorts;
    QList<RtsPort> servicePorts;
    QList<RtsConfigurationSet> configurationSets;
    QList<RtsExecutionContext> executionContexts;
    QList<RtsParticipant> participants; ///< members when this is a composite
    std::optional<RtsLocation> layout; ///< rtsExt:Location
    RtsProperties properties; ///< rtsExt:Properties (IOR, COMPONENT_PATH_ID …)

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    /// None, PeriodicECShared, PeriodicStateShared, Grouping, FsmECShared, FsmStateShared.
    static QStringList compositeTypes();

    const RtsPort *dataPort(const QString &name) const;
    const RtsPort *servicePort(const QString &name) const;
    /// True when a data or service port of that name is listed.
    bool hasPort(const QString &name) const;
    const RtsExecutionContext *executionContext(const QString &id) const;
    bool isRequiredValue() const;

    bool operator==(const RtsComponent &other) const;
    bool operator!=(const RtsComponent &other) const { return !(*this == other); }
};

} // namespace Profile
