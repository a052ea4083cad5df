// SPDX-License-Identifier: MIT
#include "componentpreview.h"

#include <QPainter>
#include <QPainterPath>

namespace Builder {

namespace {

constexpr qreal Marker = 14;
constexpr qreal SidePitch = 34; ///< vertical distance between ports on LEFT/RIGHT
constexpr qreal TopPitch = 90; ///< horizontal distance between ports on TOP/BOTTOM

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
    for (const Profile::RtcDataPort &p : profile.dataPorts) {
        if (p.kind() == Profile::RtcPortType::Event) {
            m_ports.append(
                {Port::Event, p.name, eventsText(p), sideOf(p.position, Port::Event), {}});
            continue;
        }
        const Port::Kind kind = p.kind() == Profile::RtcPortType::DataOut ? Port::Out : Port::In;
        m_ports.append({kind, p.name, p.type, sideOf(p.position, kind), {}});
    }
    for (const Profile::RtcServicePort &p : profile.servicePorts) {
        QStringList types;
        for (const Profile::RtcServiceInterface &i : p.interfaces)
            types << i.type;
        m_ports.append({Port::Service,
                        p.name,
                        types.join(QStringLiteral(", ")),
                        sideOf(p.position, Port::Service),
                        {}});
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
    const auto labelWidth = [&](const QString &side) {
        qreal widest = 0;
        for (const Port *port : bySide.value(side))
            widest = qMax(widest,
                          qMax(metrics.horizontalAdvance(port->name),
                               metrics.horizontalAdvance(port->type) * 0.85));
        return widest > 0 ? widest + Marker + 8 : Marker;
    };
    const qreal left = labelWidth(QStringLiteral("LEFT"));
    const qreal right = labelWidth(QStringLiteral("RIGHT"));
    const qreal above = Marker + 4 + metrics.height();
    m_box = QRectF(0, 0, width, height);
    m_box.moveCenter(QRectF(rect()).center());
    const qreal spare = rect().width() - left - right - width;
    m_box.moveLeft(left + qMax<qreal>(0, spare / 2));
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
    }
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
    const QFontMetricsF metrics(painter.font());
    const QString label = port.name;
    const qreal w = metrics.horizontalAdvance(label);
    const qreal h = metrics.height();
    QRectF text;
    if (port.side == QLatin1String("LEFT"))
        text = QRectF(r.left() - 4 - w, r.center().y() - h, w, h);
    else if (port.side == QLatin1String("RIGHT"))
        text = QRectF(r.right() + 4, r.center().y() - h, w, h);
    else if (port.side == QLatin1String("TOP"))
        text = QRectF(r.center().x() - w / 2, r.top() - 2 - h, w, h);
    else
        text = QRectF(r.center().x() - w / 2, r.bottom() + 2, w, h);
    painter.setPen(palette().text().color());
    painter.drawText(text, Qt::AlignCenter, label);
    if (vertical(port.side) && !port.type.isEmpty()) {
        QFont small = painter.font();
        small.setPointSizeF(small.pointSizeF() * 0.85);
        painter.setFont(small);
        painter.setPen(QColor(100, 100, 100));
        const qreal tw = QFontMetricsF(small).horizontalAdvance(port.type);
        const qreal x = port.side == QLatin1String("LEFT") ? r.left() - 4 - tw : r.right() + 4;
        painter.drawText(QRectF(x, r.center().y(), tw, h), Qt::AlignCenter, port.type);
        painter.setFont(font());
    }
}

} // namespace Builder
