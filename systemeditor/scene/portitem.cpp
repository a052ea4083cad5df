// SPDX-License-Identifier: MIT
#include "portitem.h"

#include "portgeometry.h"

#include <QCoreApplication>
#include <QPainter>

namespace SystemEditor {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SystemEditor::PortItem)
};

QString kindText(PortKind kind)
{
    switch (kind) {
    case PortKind::DataIn:
        return Text::tr("InPort");
    case PortKind::DataOut:
        return Text::tr("OutPort");
    case PortKind::Service:
        return Text::tr("Service port");
    case PortKind::Unknown:
        break;
    }
    return Text::tr("Port (no RTC profile)");
}

QString interfaceLine(const InterfaceInfo &interface)
{
    const QString polarity = interface.polarity == Profile::RtcDirection::Required
        ? Text::tr("required")
        : Text::tr("provided");
    return QStringLiteral("%1 %2 : %3").arg(polarity, interface.name, interface.type);
}

} // namespace

PortItem::PortItem(const QString &instanceName, const PortInfo &port, bool connected,
                   QGraphicsItem *parent)
    : QGraphicsPathItem(portShape(port.kind, port.side), parent)
    , m_instanceName(instanceName)
    , m_port(port)
    , m_connected(connected)
{
    setToolTip(toolTipFor(port));
    setAcceptHoverEvents(true);
    setBrush(portColor(port.kind, connected));
    setPen(QPen(QColor(40, 40, 40), 1));
}

void PortItem::setHighlight(Highlight highlight)
{
    if (m_highlight == highlight)
        return;
    m_highlight = highlight;
    update();
}

QPointF PortItem::connectionPoint() const
{
    return mapToScene(outwardNormal(m_port.side) * PortHalfSize);
}

QString PortItem::toolTipFor(const PortInfo &port)
{
    QStringList lines {QStringLiteral("%1: %2").arg(kindText(port.kind), port.profileName)};
    if (port.isDataPort() && !port.dataType.isEmpty())
        lines << Text::tr("Data type: %1").arg(port.dataType);
    for (const InterfaceInfo &interface : port.interfaces)
        lines << interfaceLine(interface);
    return lines.join(QLatin1Char('\n'));
}

QRectF PortItem::boundingRect() const
{
    // Room for the highlight halo.
    const qreal halo = PortHalfSize + 6;
    return QGraphicsPathItem::boundingRect().united(QRectF(-halo, -halo, 2 * halo, 2 * halo));
}

void PortItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget)
{
    QGraphicsPathItem::paint(painter, option, widget);
    if (m_highlight == Highlight::None)
        return;
    // A halo says "you may drop here"; a grey veil says "not this one".
    painter->setRenderHint(QPainter::Antialiasing);
    if (m_highlight == Highlight::Legal) {
        painter->setPen(QPen(QColor(255, 140, 0), 3));
        painter->setBrush(Qt::NoBrush);
        painter->drawEllipse(QPointF(0, 0), PortHalfSize + 4, PortHalfSize + 4);
    } else {
        painter->setPen(Qt::NoPen);
        painter->setBrush(QColor(128, 128, 128, 170));
        painter->drawPath(path());
    }
}

} // namespace SystemEditor
