// SPDX-License-Identifier: MIT
#pragma once

#include "xmlextras.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace Profile {

/**
 * Bookkeeping shared by all RTC model structs: names of schema-required attributes or elements
 * (local names, e.g. "name", "BasicInfo") that the source file did not have.
 *
 * Readers fill it (and warn) so that writers can leave those parts out again while they are still
 * empty: a file that lacked them is written back without inventing values. Code that builds or
 * edits a model does not need to care; a value set later is always written.
 */
using RtcMissing = QStringList;

/// `rtcExt:Properties @name @value?` — a free key/value pair (e.g. `__widget__` → `slider.0.1`).
struct RtcProperty
{
    QString name;
    std::optional<QString> value;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcProperty &other) const;
    bool operator!=(const RtcProperty &other) const { return !(*this == other); }
};

using RtcProperties = QList<RtcProperty>;

/// The value of the first property called `name`, or nothing.
std::optional<QString> rtcPropertyValue(const RtcProperties &properties, const QString &name);
/// Sets (or adds) the property `name`.
void setRtcProperty(RtcProperties &properties, const QString &name, const QString &value);

// ---- Enumerations of the schema. The model keeps the file's text; these help to interpret it.

/// `rtc:componentType` values: STATIC, UNIQUE, COMMUTATIVE.
const QStringList &rtcComponentTypes();
/// `rtc:activityType` values: PERIODIC, SPORADIC, EVENTDRIVEN.
const QStringList &rtcActivityTypes();
/// `rtcExt:position` values: LEFT, RIGHT, TOP, BOTTOM.
const QStringList &rtcPositions();

/// `rtc:portType` of a data port.
enum class RtcPortType { DataIn, DataOut, Event, Unknown };
/// DataInPort / DataOutPort / EventPort → the enum; anything else → Unknown.
RtcPortType rtcPortType(const QString &text);
/// The schema text of a port type (empty for Unknown).
QString rtcPortTypeText(RtcPortType type);
/// DataInPort, DataOutPort, EventPort.
const QStringList &rtcPortTypes();

/// `rtc:direction` of a service interface.
enum class RtcDirection { Provided, Required, Unknown };
RtcDirection rtcDirection(const QString &text);
QString rtcDirectionText(RtcDirection direction);
/// Provided, Required.
const QStringList &rtcDirections();

} // namespace Profile
