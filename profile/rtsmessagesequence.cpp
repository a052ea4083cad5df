// SPDX-License-Identifier: MIT
#include "rtsmessagesequence.h"

#include <tuple>

namespace Profile {

bool RtsWaitTime::operator==(const RtsWaitTime &other) const
{
    return std::tie(waitTime, extras, yamlExtras)
        == std::tie(other.waitTime, other.extras, other.yamlExtras);
}

QStringList RtsPreceding::sendingTimings()
{
    return {QStringLiteral("SYNC"), QStringLiteral("ASYNC"), QStringLiteral("NO_SYNC"),
            QStringLiteral("NOT_SYNC")};
}

bool RtsPreceding::operator==(const RtsPreceding &other) const
{
    return std::tie(timeout, sendingTiming, precedingComponents, extras, yamlExtras)
        == std::tie(other.timeout, other.sendingTiming, other.precedingComponents, other.extras,
                    other.yamlExtras);
}

bool RtsCondition::operator==(const RtsCondition &other) const
{
    return std::tie(sequence, targetComponent, waitTime, preceding, properties, extras, yamlExtras)
        == std::tie(other.sequence, other.targetComponent, other.waitTime, other.preceding,
                    other.properties, other.extras, other.yamlExtras);
}

QList<RtsSequenceKind> rtsSequenceKinds()
{
    return {RtsSequenceKind::StartUp,    RtsSequenceKind::ShutDown,
            RtsSequenceKind::Activation, RtsSequenceKind::Deactivation,
            RtsSequenceKind::Resetting,  RtsSequenceKind::Initializing,
            RtsSequenceKind::Finalizing};
}

QString rtsSequenceElementName(RtsSequenceKind kind)
{
    switch (kind) {
    case RtsSequenceKind::StartUp:
        return QStringLiteral("StartUp");
    case RtsSequenceKind::ShutDown:
        return QStringLiteral("ShutDown");
    case RtsSequenceKind::Activation:
        return QStringLiteral("Activation");
    case RtsSequenceKind::Deactivation:
        return QStringLiteral("Deactivation");
    case RtsSequenceKind::Resetting:
        return QStringLiteral("Resetting");
    case RtsSequenceKind::Initializing:
        return QStringLiteral("Initializing");
    case RtsSequenceKind::Finalizing:
        return QStringLiteral("Finalizing");
    }
    return {};
}

QString rtsSequenceYamlKey(RtsSequenceKind kind)
{
    // rtsprofile's keys are the element names with a lower-case first letter.
    QString key = rtsSequenceElementName(kind);
    key[0] = key.at(0).toLower();
    return key;
}

bool RtsMessageSequence::operator==(const RtsMessageSequence &other) const
{
    return std::tie(targets, extras, yamlExtras)
        == std::tie(other.targets, other.extras, other.yamlExtras);
}

} // namespace Profile
