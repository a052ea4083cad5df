// SPDX-License-Identifier: MIT
#pragma once

#include "rtcprofile.h"
#include "rtscomponent.h"

#include <QPointF>
#include <QSizeF>

namespace SystemEditor {

class SystemModel;

/// The width of a component's body when the file gives none (the canvas draws it so).
constexpr qreal DefaultComponentWidth = 80;
/// Vertical room per port on a side, and the body's minimum height.
constexpr qreal PortSpacing = 20;
constexpr qreal MinimumComponentHeight = 60;

/**
 * A new system entry for an instance of the component `rtc` describes, as the offline editor
 * creates it when a profile is dropped from the repository: type id, `pathUri` (the RTC.xml it
 * came from), ports named `<instance>.<port>`, a `default` configuration set holding the
 * parameters' default values (active), `isRequired` true and a Location at `position`.
 */
Profile::RtsComponent componentFromRtcProfile(const Profile::RtcProfile &rtc,
                                              const QString &instanceName,
                                              const QString &pathUri, const QPointF &position);

/// The type name used for instance names: the RTC profile's name, else the id's name part,
/// else "Component".
QString componentTypeName(const Profile::RtsComponent &component,
                          const Profile::RtcProfile *rtc);

/**
 * The size the component is drawn with: the Location's width/height when positive, else the
 * default width and a height that fits the ports of its fullest side.
 */
QSizeF componentSize(const SystemModel &model, const QString &instanceName);

} // namespace SystemEditor
