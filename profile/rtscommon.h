// SPDX-License-Identifier: MIT
#pragma once

#include "xmlextras.h"

#include <QList>
#include <QString>

#include <optional>

namespace Profile {

/**
 * Mapping keys that the RTS YAML reader did not know, each kept with its value as YAML text, so
 * that the YAML writer can put them back. (Unknown XML content travels in XmlExtras instead.)
 */
struct RtsYamlExtras
{
    struct Entry
    {
        QString key;
        QString yaml; ///< the value, as a self-contained YAML document
        bool operator==(const Entry &other) const { return key == other.key && yaml == other.yaml; }
        bool operator!=(const Entry &other) const { return !(*this == other); }
    };

    QList<Entry> entries;

    bool isEmpty() const { return entries.isEmpty(); }
    bool operator==(const RtsYamlExtras &other) const { return entries == other.entries; }
    bool operator!=(const RtsYamlExtras &other) const { return !(*this == other); }
};

/// `rtsExt:Properties @name @value?` — a free key/value pair (IOR, COMPONENT_PATH_ID, dataport.*
/// …).
struct RtsProperty
{
    QString name;
    std::optional<QString> value;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsProperty &other) const;
    bool operator!=(const RtsProperty &other) const { return !(*this == other); }
};

using RtsProperties = QList<RtsProperty>;

/// The value of the first property called `name`, or nothing.
std::optional<QString> rtsPropertyValue(const RtsProperties &properties, const QString &name);
/// Sets (or adds) the property `name`.
void setRtsProperty(RtsProperties &properties, const QString &name, const QString &value);

/**
 * `rts:target_component` (+ `rtsExt:target_component_ext`): a reference to a component of the
 * system by its type id and instance name. Used by group members, composite participants and
 * execution-context participants.
 */
struct RtsTargetComponent
{
    QString componentId; ///< `RTC:vendor:category:name:version` of the referenced component
    QString instanceName; ///< the stable key of the referenced component in the system
    RtsProperties properties; ///< rtsExt:Properties (target_component_ext)

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsTargetComponent &other) const;
    bool operator!=(const RtsTargetComponent &other) const { return !(*this == other); }
};

/// `rts:target_port` (+ `rtsExt:target_port_ext`): one end of a connector.
struct RtsTargetPort : RtsTargetComponent
{
    QString portName; ///< as the component names it, often `Instance0.port`

    bool operator==(const RtsTargetPort &other) const;
    bool operator!=(const RtsTargetPort &other) const { return !(*this == other); }
};

/// `rts:target_executioncontext`: a component plus the id of one of its execution contexts.
struct RtsTargetExecutionContext : RtsTargetComponent
{
    QString id; ///< execution context id; may be non-numeric (`Comp1Ec1`)

    bool operator==(const RtsTargetExecutionContext &other) const;
    bool operator!=(const RtsTargetExecutionContext &other) const { return !(*this == other); }
};

} // namespace Profile
