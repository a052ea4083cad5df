// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QGraphicsPathItem>

namespace SystemEditor {

/**
 * One port drawn on the edge of its component (a child of the ComponentItem). Its shape says
 * what it is, its colour whether it is connected; while the user drags a new connector, legal
 * targets are highlighted and illegal ones dimmed.
 */
class PortItem : public QGraphicsPathItem
{
public:
    enum { Type = UserType + 2 };
    enum class Highlight { None, Legal, Illegal };

    PortItem(const QString &instanceName, const PortInfo &port, bool connected,
             QGraphicsItem *parent = nullptr);

    int type() const override { return Type; }
    QString instanceName() const { return m_instanceName; }
    const PortInfo &port() const { return m_port; }
    bool isConnected() const { return m_connected; }
    Highlight highlight() const { return m_highlight; }
    void setHighlight(Highlight highlight);

    /// Where connectors attach, in scene coordinates: the outer tip of the shape.
    QPointF connectionPoint() const;

    /// The tool tip text: kind, name, data type or interfaces.
    static QString toolTipFor(const PortInfo &port);

    QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option,
               QWidget *widget) override;

private:
    QString m_instanceName;
    PortInfo m_port;
    bool m_connected;
    Highlight m_highlight = Highlight::None;
};

} // namespace SystemEditor
