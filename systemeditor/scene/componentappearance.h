// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QColor>
#include <QList>
#include <QRectF>
#include <QSet>
#include <QSizeF>
#include <QString>

namespace SystemEditor {

/// What the canvas needs to draw one component: plain data, taken from the system model.
struct ComponentAppearance
{
    QString instanceName;
    QString typeName; ///< the component type (the name part of its RTC id)
    QSizeF size {-1, -1}; ///< the saved size; non-positive parts mean "as the content needs"
    QColor bodyColor = QColor(255, 255, 238);
    QList<PortInfo> ports; ///< PortInfo::side already turned by the component's direction
    QSet<QString> connectedPorts; ///< names of ports with at least one connector
    /// The composite kind (`PeriodicECShared`, …) of a composite component; empty otherwise.
    /// A composite is drawn as a frame around its members with the exported ports on it.
    QString compositeType;

    bool isComposite() const { return !compositeType.isEmpty(); }

    /// The appearance of one component of `model`.
    static ComponentAppearance fromModel(const SystemModel &model, const QString &instanceName);

    bool operator==(const ComponentAppearance &other) const;
    bool operator!=(const ComponentAppearance &other) const { return !(*this == other); }
};

/// The colours of a component's text, readable on its body: dark on light fills, white on dark
/// ones (the black of a component that does not answer, the red of one in error).
struct BodyTextColours
{
    QColor title;
    QColor type;
    QColor portLabel;

    /// The colours for a body filled with @p body, the set that contrasts with it more.
    static BodyTextColours on(const QColor &body);
};

/// WCAG 2 contrast ratio of two colours (1 to 21), alpha ignored.
double contrastRatio(const QColor &a, const QColor &b);

/// Minimum sizes the text of a component needs; measured by the item with its fonts.
struct ComponentTextSizes
{
    qreal titleWidth = 0; ///< the widest of instance name and type name
    qreal titleHeight = 0; ///< both title lines
    qreal widestLabel = 0; ///< the widest port label
    qreal labelHeight = 0;
};

/// The placement of a component's parts in its item's coordinates (body at the origin).
struct ComponentGeometry
{
    QRectF body;
    QRectF title; ///< where instance and type names go: below the top ports' labels
    QList<QPointF> portCenters; ///< in the order of ComponentAppearance::ports, outside the body

    /// The smallest body the content fits in (ports spread evenly, titles and labels readable).
    static QSizeF minimumBodySize(const ComponentAppearance &component,
                                  const ComponentTextSizes &text);
    /**
     * Lays out a component: the body is the saved size, grown to minimumBodySize(), so resizing
     * never squeezes ports together; ports are spread evenly along their side.
     */
    static ComponentGeometry layout(const ComponentAppearance &component,
                                    const ComponentTextSizes &text);
};

/// Distance between neighbouring ports along a side.
inline constexpr qreal PortPitch = 24.0;

} // namespace SystemEditor
