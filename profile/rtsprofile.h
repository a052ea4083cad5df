// SPDX-License-Identifier: MIT
#pragma once

#include "rtscommon.h"
#include "rtscomponent.h"
#include "rtsconnector.h"
#include "rtsmessagesequence.h"

#include <QHash>

namespace Profile {

/// `rts:Groups @groupId` → `rts:Members+`.
struct RtsGroup
{
    QString groupId; ///< rtsprofile writes `groupID`; read both, written as the schema's groupId
    QList<RtsTargetComponent> members;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsGroup &other) const;
    bool operator!=(const RtsGroup &other) const { return !(*this == other); }
};

/// `rtsExt:Systems @path`: a nested sub-system file, relative to this one.
struct RtsSystemPath
{
    QString path;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsSystemPath &other) const;
    bool operator!=(const RtsSystemPath &other) const { return !(*this == other); }
};

/// The parts of a system id `RTSystem:vendor:name:version`.
struct RtsSystemId
{
    QString vendor;
    QString name;
    QString version;

    /// Splits an id; nothing when it does not have the form `RTSystem:v:n:ver`.
    static std::optional<RtsSystemId> parse(const QString &id);
    QString toString() const;
};

/**
 * An RTS Profile (system file, `rts:RtsProfile` + `rtsExt:rts_profile_ext`): the components of
 * an RT system, their connectors, groups, message sequences and the editor's layout.
 *
 * A plain value: editors refer to parts by stable ids (component instance name, port name,
 * connector id), never by pointer across edits. Numbers and enumerations are kept as the file's
 * text so that nothing is lost; validateRtsProfile() reports bad ones.
 */
struct RtsProfile
{
    /// The RTS Profile version this project writes.
    static inline const QString CurrentVersion = QStringLiteral("0.2");

    QString id; ///< `RTSystem:vendor:name:version`
    QString version; ///< RTS Profile format version, "0.2"
    std::optional<QString> abstract; ///< optional in the schema (rtsprofile wrongly requires it)
    QString creationDate; ///< xs:dateTime text
    QString updateDate; ///< xs:dateTime text
    std::optional<QString> comment; ///< rtsExt:comment

    QList<RtsComponent> components;
    QList<RtsGroup> groups;
    QList<RtsDataPortConnector> dataPortConnectors;
    QList<RtsServicePortConnector> servicePortConnectors;
    std::optional<RtsMessageSequence> startUp;
    std::optional<RtsMessageSequence> shutDown;
    std::optional<RtsMessageSequence> activation;
    std::optional<RtsMessageSequence> deactivation;
    std::optional<RtsMessageSequence> resetting;
    std::optional<RtsMessageSequence> initializing;
    std::optional<RtsMessageSequence> finalizing;
    QStringList versionUpLogs; ///< rtsExt:VersionUpLogs (legacy VersionUpLog)
    RtsProperties properties; ///< rtsExt:Properties
    QList<RtsSystemPath> systems; ///< rtsExt:Systems

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    /// A new empty system: id `RTSystem:vendor:name:version`, format version 0.2, dates now.
    static RtsProfile createNew(const QString &vendor, const QString &name, const QString &version);
    /// The current local time as xs:dateTime text with offset, e.g. `2024-05-01T10:20:30+09:00`.
    static QString currentDateTimeText();

    /// The vendor/name/version parts of `id`; nothing when `id` is malformed.
    std::optional<RtsSystemId> systemId() const;

    /// The component with this instance name, or null (linear; use componentIndex() in loops).
    const RtsComponent *component(const QString &instanceName) const;
    RtsComponent *component(const QString &instanceName);
    /// Instance name → index into `components` (the first one wins on duplicates).
    QHash<QString, qsizetype> componentIndex() const;

    /// The data-port or service-port connector with this id, or null.
    const RtsPortConnector *connector(const QString &connectorId) const;
    const RtsDataPortConnector *dataPortConnector(const QString &connectorId) const;
    const RtsServicePortConnector *servicePortConnector(const QString &connectorId) const;

    /// The message sequence block of one kind (StartUp … Finalizing).
    const std::optional<RtsMessageSequence> &sequence(RtsSequenceKind kind) const;
    std::optional<RtsMessageSequence> &sequence(RtsSequenceKind kind);

    bool operator==(const RtsProfile &other) const;
    bool operator!=(const RtsProfile &other) const { return !(*this == other); }
};

} // namespace Profile
