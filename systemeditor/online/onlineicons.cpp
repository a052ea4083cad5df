// SPDX-License-Identifier: MIT
#include "onlineicons.h"

#include <QCoreApplication>
#include <QHash>
#include <QPainter>
#include <QPixmap>

namespace SystemEditor::OnlineIcons {

using Corba::LifeCycleState;
using Corba::NodeType;

QColor stateColor(LifeCycleState state)
{
    switch (state) {
    case LifeCycleState::Created:
        return Qt::white;
    case LifeCycleState::Inactive:
        // A light blue keeps the canvas' black titles readable.
        return QColor(90, 140, 255);
    case LifeCycleState::Active:
        return QColor(0, 200, 0);
    case LifeCycleState::Error:
        return QColor(230, 0, 0);
    case LifeCycleState::Unknown:
        break;
    }
    return Qt::black;
}

namespace {

constexpr int iconSize = 16;

QPixmap canvas()
{
    QPixmap pixmap(iconSize, iconSize);
    pixmap.fill(Qt::transparent);
    return pixmap;
}

// A rounded block with a port on each side: the component glyph.
QIcon drawComponent(const QColor &fill)
{
    QPixmap pixmap = canvas();
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(Qt::darkGray, 1));
    p.setBrush(fill);
    p.drawRoundedRect(QRectF(3.5, 2.5, 9, 11), 2, 2);
    p.setBrush(Qt::darkGray);
    p.drawRect(QRectF(0.5, 6.5, 3, 3));
    p.drawRect(QRectF(12.5, 6.5, 3, 3));
    return QIcon(pixmap);
}

QIcon drawFolder(const QColor &fill)
{
    QPixmap pixmap = canvas();
    QPainter p(&pixmap);
    p.setPen(QPen(fill.darker(160), 1));
    p.setBrush(fill);
    p.drawRect(QRectF(1.5, 4.5, 13, 9));
    p.drawRect(QRectF(1.5, 2.5, 6, 2));
    return QIcon(pixmap);
}

QIcon drawShape(NodeType type)
{
    QPixmap pixmap = canvas();
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    switch (type) {
    case NodeType::Server:
        p.setPen(QPen(QColor(40, 40, 90), 1));
        p.setBrush(QColor(170, 180, 230));
        p.drawRect(QRectF(3.5, 1.5, 9, 13));
        p.drawLine(QPointF(5, 5), QPointF(11, 5));
        p.drawLine(QPointF(5, 8), QPointF(11, 8));
        break;
    case NodeType::Manager:
        p.setPen(QPen(QColor(90, 60, 0), 1));
        p.setBrush(QColor(240, 190, 80));
        p.drawEllipse(QRectF(2.5, 2.5, 11, 11));
        p.drawLine(QPointF(8, 5), QPointF(8, 11));
        p.drawLine(QPointF(5, 8), QPointF(11, 8));
        break;
    case NodeType::Zombie:
        p.setPen(QPen(QColor(160, 0, 0), 2));
        p.drawLine(QPointF(3, 3), QPointF(13, 13));
        p.drawLine(QPointF(13, 3), QPointF(3, 13));
        break;
    default:
        p.setPen(QPen(Qt::darkGray, 1));
        p.setBrush(Qt::lightGray);
        p.drawEllipse(QRectF(4.5, 4.5, 7, 7));
        break;
    }
    return QIcon(pixmap);
}

} // namespace

QIcon component(LifeCycleState state)
{
    static QHash<int, QIcon> cache;
    auto it = cache.find(int(state));
    if (it == cache.end())
        it = cache.insert(int(state), drawComponent(stateColor(state)));
    return *it;
}

QIcon node(NodeType type)
{
    static QHash<int, QIcon> cache;
    auto it = cache.find(int(type));
    if (it == cache.end()) {
        it = cache.insert(int(type),
                          type == NodeType::Context ? drawFolder(QColor(230, 200, 110))
                                                    : drawShape(type));
    }
    return *it;
}

QString stateLabel(Corba::LifeCycleState state)
{
    switch (state) {
    case Corba::LifeCycleState::Created:
        return QCoreApplication::translate("SystemEditor::OnlineIcons", "Created");
    case Corba::LifeCycleState::Inactive:
        return QCoreApplication::translate("SystemEditor::OnlineIcons", "Inactive");
    case Corba::LifeCycleState::Active:
        return QCoreApplication::translate("SystemEditor::OnlineIcons", "Active");
    case Corba::LifeCycleState::Error:
        return QCoreApplication::translate("SystemEditor::OnlineIcons", "Error");
    case Corba::LifeCycleState::Unknown:
        break;
    }
    return QCoreApplication::translate("SystemEditor::OnlineIcons", "Unknown");
}

QString nodeTypeLabel(Corba::NodeType type)
{
    static const char *const labels[] = {
        QT_TRANSLATE_NOOP("SystemEditor::OnlineIcons", "root"),
        QT_TRANSLATE_NOOP("SystemEditor::OnlineIcons", "server"),
        QT_TRANSLATE_NOOP("SystemEditor::OnlineIcons", "context"),
        QT_TRANSLATE_NOOP("SystemEditor::OnlineIcons", "component"),
        QT_TRANSLATE_NOOP("SystemEditor::OnlineIcons", "manager"),
        QT_TRANSLATE_NOOP("SystemEditor::OnlineIcons", "object"),
        QT_TRANSLATE_NOOP("SystemEditor::OnlineIcons", "zombie"),
    };
    const QString english = Corba::nodeTypeName(type);
    for (const char *label : labels) {
        if (english == QLatin1String(label))
            return QCoreApplication::translate("SystemEditor::OnlineIcons", label);
    }
    return english;
}

} // namespace SystemEditor::OnlineIcons
