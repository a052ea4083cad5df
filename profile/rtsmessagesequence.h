// SPDX-License-Identifier: MIT
#pragma once

#include "rtscommon.h"

#include <QStringList>

namespace Profile {

/// `rts:WaitTime @waitTime?`: wait before sending the action (ms, raw text).
struct RtsWaitTime
{
    std::optional<QString> waitTime;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsWaitTime &other) const;
    bool operator!=(const RtsWaitTime &other) const { return !(*this == other); }
};

/// `rts:Preceding @timeout? @sendingTiming?`: send after the preceding components are done.
struct RtsPreceding
{
    std::optional<QString> timeout; ///< ms, raw text
    std::optional<QString> sendingTiming; ///< one of sendingTimings(); raw text otherwise
    QList<RtsTargetExecutionContext> precedingComponents;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    /// SYNC, ASYNC, NO_SYNC and rtsprofile's default NOT_SYNC.
    static QStringList sendingTimings();

    bool operator==(const RtsPreceding &other) const;
    bool operator!=(const RtsPreceding &other) const { return !(*this == other); }
};

/**
 * `rts:targets` (+ `rtsExt:condition_ext`): one step of a message sequence: which execution
 * context gets the action, in which order, after what. The schema demands exactly one of
 * WaitTime/Preceding; files without either are kept as they are (the validator reports them).
 */
struct RtsCondition
{
    QString sequence; ///< order, raw text (xs:integer)
    RtsTargetExecutionContext targetComponent;
    std::optional<RtsWaitTime> waitTime;
    std::optional<RtsPreceding> preceding;
    RtsProperties properties; ///< rtsExt:Properties

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsCondition &other) const;
    bool operator!=(const RtsCondition &other) const { return !(*this == other); }
};

/// The seven message-sequence blocks of a system, in schema order.
enum class RtsSequenceKind {
    StartUp,
    ShutDown,
    Activation,
    Deactivation,
    Resetting,
    Initializing,
    Finalizing
};

/// All kinds, in schema order (for loops).
QList<RtsSequenceKind> rtsSequenceKinds();
/// The XML element name (`StartUp`, `ShutDown`, … `Finalizing`).
QString rtsSequenceElementName(RtsSequenceKind kind);
/// The rtsprofile YAML key (`startUp`, `shutDown`, … `finalizing`).
QString rtsSequenceYamlKey(RtsSequenceKind kind);

/// `rts:StartUp`, `rts:ShutDown`, …: the ordered conditions of one action.
struct RtsMessageSequence
{
    QList<RtsCondition> targets;

    XmlExtras extras;
    RtsYamlExtras yamlExtras;
    SourceLocation location;

    bool operator==(const RtsMessageSequence &other) const;
    bool operator!=(const RtsMessageSequence &other) const { return !(*this == other); }
};

} // namespace Profile
