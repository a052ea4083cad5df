// SPDX-License-Identifier: MIT
#include "componentpreview.h"

#include <QHelpEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

namespace Builder {

namespace {

constexpr qreal Marker = 14;
constexpr qreal SidePitch = 34; ///< vertical distance between ports on LEFT/RIGHT
constexpr qreal TopPitch = 90; ///< horizontal distance between ports on TOP/BOTTOM
constexpr qreal LabelGap = 4; ///< between a marker and its label
constexpr qreal EdgeMargin = 2; ///< kept free along the widget's edges

QString sideOf(const QString &position, ComponentPreview::Port::Kind kind)
{
    const QString upper = position.toUpper();
    if (Profile::rtcPositions().contains(upper))
        return upper;
    return kind == ComponentPreview::Port::Out ? QStringLiteral("RIGHT") : QStringLiteral("LEFT");
}

/// "e1, e2" or "no events": what an EventPort shows under its name (each event once, although
/// several transitions may share it).
QString eventsText(const Profile::RtcDataPort &port)
{
    QStringList names;
    for (const Profile::RtcEvent &event : port.events) {
        if (!names.contains(event.name))
            names << event.name;
    }
    return names.isEmpty() ? ComponentPreview::tr("no events") : names.join(QStringLiteral(", "));
}

bool vertical(const QString &side)
{
    return side == QLatin1String("LEFT") || side == QLatin1String("RIGHT");
}

} // namespace

ComponentPreview::ComponentPreview(ComponentModel *model, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
{
    setObjectName(QStringLiteral("componentPreview"));
    connect(model, &ComponentModel::changed, this, [this] {
        relayout();
        updateGeometry();
        update();
    });
    relayout();
}

QSize ComponentPreview::sizeHint() const
{
    return QSize(qMax(360, int(m_extent.width()) + 16), qMax(320, int(m_extent.height()) + 16));
}

QSize ComponentPreview::minimumSizeHint() const
{
    return {220, 180};
}

void ComponentPreview::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    relayout();
}

void ComponentPreview::relayout()
{
    m_ports.clear();
    if (!m_model)
        return;
    const Profile::RtcProfile &profile = m_model->profile();
    m_title = profile.basicInfo.name;
    const auto add = [this](Port::Kind kind, const QString &name, const QString &type, const QString &position) {
        Port port;
        port.kind = kind;
        port.name = name;
        port.type = type;
        port.side = sideOf(position, kind);
        m_ports.append(port);
    };
    for (const Profile::RtcDataPort &p : profile.dataPorts) {
        if (p.kind() == Profile::RtcPortType::Event)
            add(Port::Event, p.name, eventsText(p), p.position);
        else
            add(p.kind() == Profile::RtcPortType::DataOut ? Port::Out : Port::In, p.name, p.type, p.position);
    }
    for (const Profile::RtcServicePort &p : profile.servicePorts) {
        QStringList types;
        for (const Profile::RtcServiceInterface &i : p.interfaces)
            types << i.type;
        add(Port::Service, p.name, types.join(QStringLiteral(", ")), p.position);
    }
    QHash<QString, QList<Port *>> bySide;
    for (Port &port : m_ports)
        bySide[port.side].append(&port);
    const qreal width = qMax<qreal>(140,
                                    TopPitch
                                        * qMax(bySide.value(QStringLiteral("TOP")).size(),
                                               bySide.value(QStringLiteral("BOTTOM")).size()));
    const qreal height = qMax<qreal>(90,
                                     SidePitch
                                         * qMax(bySide.value(QStringLiteral("LEFT")).size(),
                                                bySide.value(QStringLiteral("RIGHT")).size()));
    // Labels sit outside the box: keep room for the widest on each side, then centre.
    const QFontMetricsF metrics(font());
    const QFontMetricsF typeMetrics(typeFont());
    const auto labelWidth = [&](const QString &side) {
        qreal widest = 0;
        for (const Port *port : bySide.value(side))
            widest = qMax(widest,
                          qMax(metrics.horizontalAdvance(port->name), typeMetrics.horizontalAdvance(port->type)));
        return widest > 0 ? widest + Marker + LabelGap + 2 * EdgeMargin : Marker;
    };
    const qreal left = labelWidth(QStringLiteral("LEFT"));
    const qreal right = labelWidth(QStringLiteral("RIGHT"));
    const qreal above = Marker + 4 + metrics.height();
    m_box = QRectF(0, 0, width, height);
    m_box.moveCenter(QRectF(rect()).center());
    const qreal spare = rect().width() - left - right - width;
    // Too narrow for every label: a side that needs less than half of the room left by the box
    // keeps what it needs, the other gets the rest, and the labels are shortened to fit.
    const qreal room = rect().width() - width;
    qreal leftRoom = left + spare / 2;
    if (spare < 0)
        leftRoom = left <= room / 2 ? left : right <= room / 2 ? room - right : room / 2;
    m_box.moveLeft(qMax(Marker, leftRoom));
    m_box.moveTop(qMax(above, m_box.top()));
    m_extent = QSizeF(left + width + right, 2 * above + height);
    for (const QString &side : Profile::rtcPositions())
        layoutSide(side, bySide.value(side));
}

void ComponentPreview::layoutSide(const QString &side, QList<Port *> ports)
{
    const int count = int(ports.size());
    for (int i = 0; i < count; ++i) {
        // Spread the ports evenly along the side, centred on it.
        const qreal t = (i + 1.0) / (count + 1.0);
        QPointF centre;
        if (side == QLatin1String("LEFT"))
            centre = {m_box.left() - Marker / 2, m_box.top() + t * m_box.height()};
        else if (side == QLatin1String("RIGHT"))
            centre = {m_box.right() + Marker / 2, m_box.top() + t * m_box.height()};
        else if (side == QLatin1String("TOP"))
            centre = {m_box.left() + t * m_box.width(), m_box.top() - Marker / 2};
        else
            centre = {m_box.left() + t * m_box.width(), m_box.bottom() + Marker / 2};
        QRectF marker(0, 0, Marker, Marker);
        marker.moveCenter(centre);
        ports[i]->marker = marker;
        placeLabels(*ports[i]);
    }
}

QFont ComponentPreview::typeFont() const
{
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    return small;
}

void ComponentPreview::placeLabels(Port &port) const
{
    const QRectF &r = port.marker;
    const QFontMetricsF metrics(font());
    const qreal h = metrics.height();
    // The room between the marker and the widget's edge on the label's side.
    qreal room = width() - 2 * EdgeMargin;
    if (port.side == QLatin1String("LEFT"))
        room = r.left() - LabelGap - EdgeMargin;
    else if (port.side == QLatin1String("RIGHT"))
        room = width() - EdgeMargin - r.right() - LabelGap;
    room = qMax<qreal>(0, room);
    port.shownName = metrics.elidedText(port.name, Qt::ElideRight, room);
    const qreal w = metrics.horizontalAdvance(port.shownName);
    if (port.side == QLatin1String("LEFT"))
        port.nameRect = QRectF(r.left() - LabelGap - w, r.center().y() - h, w, h);
    else if (port.side == QLatin1String("RIGHT"))
        port.nameRect = QRectF(r.right() + LabelGap, r.center().y() - h, w, h);
    else if (port.side == QLatin1String("TOP"))
        port.nameRect = QRectF(r.center().x() - w / 2, r.top() - 2 - h, w, h);
    else
        port.nameRect = QRectF(r.center().x() - w / 2, r.bottom() + 2, w, h);
    if (!vertical(port.side)) {
        port.nameRect.moveRight(qMin(port.nameRect.right(), width() - EdgeMargin));
        port.nameRect.moveLeft(qMax(port.nameRect.left(), EdgeMargin));
    }
    port.shownType.clear();
    port.typeRect = QRectF();
    if (!vertical(port.side) || port.type.isEmpty())
        return;
    const QFontMetricsF small(typeFont());
    port.shownType = small.elidedText(port.type, Qt::ElideRight, room);
    const qreal tw = small.horizontalAdvance(port.shownType);
    const qreal x = port.side == QLatin1String("LEFT") ? r.left() - LabelGap - tw : r.right() + LabelGap;
    port.typeRect = QRectF(x, r.center().y(), tw, h);
}

bool ComponentPreview::event(QEvent *event)
{
    if (event->type() != QEvent::ToolTip)
        return QWidget::event(event);
    const QPoint at = static_cast<QHelpEvent *>(event)->pos();
    for (const Port &port : std::as_const(m_ports)) {
        if (port.marker.adjusted(-2, -2, 2, 2).contains(at) || port.nameRect.contains(at)
            || port.typeRect.contains(at)) {
            QToolTip::showText(static_cast<QHelpEvent *>(event)->globalPos(),
                               port.type.isEmpty() ? port.name : port.name + QLatin1Char('\n') + port.type,
                               this);
            return true;
        }
    }
    QToolTip::hideText();
    event->ignore();
    return true;
}

void ComponentPreview::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    painter.setPen(QPen(QColor(40, 70, 120), 1.5));
    painter.setBrush(QColor(214, 228, 247));
    painter.drawRoundedRect(m_box, 4, 4);
    QFont bold = font();
    bold.setBold(true);
    painter.setFont(bold);
    painter.setPen(palette().text().color());
    painter.drawText(m_box.adjusted(4, 4, -4, -4), Qt::AlignCenter | Qt::TextWordWrap,
                     m_title.isEmpty() ? tr("(unnamed)") : m_title);
    painter.setFont(font());
    for (const Port &port : std::as_const(m_ports))
        paintPort(painter, port);
}

void ComponentPreview::paintPort(QPainter &painter, const Port &port) const
{
    const QRectF &r = port.marker;
    painter.setPen(QPen(QColor(40, 40, 40), 1));
    if (port.kind == Port::Service) {
        painter.setBrush(QColor(250, 210, 120));
        painter.drawRect(r);
    } else if (port.kind == Port::Event) {
        const QPolygonF diamond(
            {QPointF(r.center().x(), r.top()), QPointF(r.right(), r.center().y()),
             QPointF(r.center().x(), r.bottom()), QPointF(r.left(), r.center().y())});
        painter.setBrush(QColor(196, 160, 230));
        painter.drawPolygon(diamond);
    } else {
        // Triangles point into the box for InPorts and out of it for OutPorts.
        const bool in = port.kind == Port::In;
        QPointF tip;
        QPointF a;
        QPointF b;
        if (vertical(port.side)) {
            const bool right = (port.side == QLatin1String("LEFT")) == in;
            tip = right ? QPointF(r.right(), r.center().y()) : QPointF(r.left(), r.center().y());
            a = right ? r.topLeft() : r.topRight();
            b = right ? r.bottomLeft() : r.bottomRight();
        } else {
            const bool down = (port.side == QLatin1String("TOP")) == in;
            tip = down ? QPointF(r.center().x(), r.bottom()) : QPointF(r.center().x(), r.top());
            a = down ? r.topLeft() : r.bottomLeft();
            b = down ? r.topRight() : r.bottomRight();
        }
        QPainterPath path;
        path.moveTo(a);
        path.lineTo(tip);
        path.lineTo(b);
        path.closeSubpath();
        painter.setBrush(in ? QColor(120, 170, 230) : QColor(130, 200, 140));
        painter.drawPath(path);
    }
    painter.setPen(palette().text().color());
    painter.drawText(port.nameRect, Qt::AlignCenter, port.shownName);
    if (!port.shownType.isEmpty()) {
        painter.setFont(typeFont());
        painter.setPen(QColor(100, 100, 100));
        painter.drawText(port.typeRect, Qt::AlignCenter, port.shownType);
        painter.setFont(font());
    }
}

} // namespace Builder
