// SPDX-License-Identifier: MIT
#include "planscene.h"

#include "plancarditem.h"

#include <QGraphicsSceneContextMenuEvent>
#include <QGraphicsSceneMouseEvent>
#include <QGraphicsSimpleTextItem>
#include <QMenu>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace SystemEditor {

namespace {

constexpr qreal Gap = 8;

} // namespace

PlanScene::PlanScene(QObject *parent)
    : QGraphicsScene(parent)
{ }

QPointF PlanScene::cardPosition(int lane, int row)
{
    return {lane * LaneWidth + (LaneWidth - PlanCardItem::Width) / 2,
            HeaderHeight + Gap + row * (PlanCardItem::Height + Gap)};
}

void PlanScene::showLanes(const QList<PlanLane> &lanes)
{
    m_dragged = nullptr;
    clear();
    m_lanes = lanes;
    qsizetype rows = 1;
    for (const PlanLane &lane : lanes)
        rows = std::max(rows, lane.cards.size());
    const qreal height = cardPosition(0, int(rows)).y() + Gap;
    for (int l = 0; l < lanes.size(); ++l)
        addLane(lanes.at(l), l, height);
    setSceneRect(0, 0, std::max<qsizetype>(1, lanes.size()) * LaneWidth, height);
}

QString PlanScene::laneTitle(const PlanLane &lane) const
{
    if (lane.node.isEmpty())
        return tr("Not placed");
    QString title = tr("%1\nCPU load %2 per CPU").arg(lane.node).arg(lane.load, 0, 'f', 2);
    if (!lane.installs.isEmpty())
        title += tr("\nInstalls: %1").arg(lane.installs.join(QStringLiteral(", ")));
    return title;
}

void PlanScene::addLane(const PlanLane &lane, int index, qreal height)
{
    const QRectF column(index * LaneWidth + 2, 0, LaneWidth - 4, height);
    auto *background = addRect(column, QPen(QColor(190, 198, 210)),
                               lane.node.isEmpty() ? QColor(252, 236, 236) : QColor(246, 248, 251));
    background->setZValue(-2);
    auto *header = addRect(QRectF(column.topLeft(), QSizeF(column.width(), HeaderHeight)),
                           Qt::NoPen, QColor(222, 229, 240));
    header->setZValue(-1);
    auto *title = addSimpleText(laneTitle(lane));
    title->setPos(column.left() + 8, 6);
    QFont font = title->font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    title->setFont(font);
    for (int row = 0; row < lane.cards.size(); ++row) {
        auto *item = new PlanCardItem(lane.cards.at(row), index);
        item->setPos(cardPosition(index, row));
        addItem(item);
    }
}

PlanCardItem *PlanScene::card(const QString &instanceName) const
{
    for (QGraphicsItem *item : items()) {
        auto *card = dynamic_cast<PlanCardItem *>(item);
        if (card && card->card().instanceName == instanceName)
            return card;
    }
    return nullptr;
}

int PlanScene::laneAt(const QPointF &scenePos) const
{
    const int lane = int(std::floor(scenePos.x() / LaneWidth));
    return scenePos.x() >= 0 && lane < m_lanes.size() ? lane : -1;
}

void PlanScene::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    QGraphicsScene::mousePressEvent(event);
    m_dragged = nullptr;
    for (QGraphicsItem *item : items(event->scenePos())) {
        if (auto *card = dynamic_cast<PlanCardItem *>(item)) {
            m_dragged = card;
            break;
        }
    }
}

void PlanScene::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    QGraphicsScene::mouseReleaseEvent(event);
    PlanCardItem *dragged = std::exchange(m_dragged, nullptr);
    if (!dragged)
        return;
    const int lane = laneAt(event->scenePos());
    const bool toNode = lane >= 0 && lane != dragged->lane() && !m_lanes.at(lane).node.isEmpty();
    if (!toNode) {
        // Back to where it was: only a drop on another node means something.
        const QList<PlanCard> &cards = m_lanes.at(dragged->lane()).cards;
        const auto it = std::find_if(cards.cbegin(), cards.cend(), [&](const PlanCard &c) {
            return c.instanceName == dragged->card().instanceName;
        });
        dragged->setPos(cardPosition(dragged->lane(), int(it - cards.cbegin())));
        return;
    }
    // The answer rebuilds the scene, dragged item included: let this event finish first.
    const QString instance = dragged->card().instanceName;
    const QString node = m_lanes.at(lane).node;
    QTimer::singleShot(0, this, [this, instance, node] { emit pinRequested(instance, node); });
}

QMenu *PlanScene::cardMenu(const QString &instanceName)
{
    const PlanCardItem *item = card(instanceName);
    if (!item)
        return nullptr;
    const QString node = m_lanes.at(item->lane()).node;
    auto *menu = new QMenu;
    QAction *pin = menu->addAction(tr("Pin to %1").arg(node));
    pin->setObjectName(QStringLiteral("planPinHere"));
    pin->setEnabled(!node.isEmpty() && !item->card().pinned);
    connect(pin, &QAction::triggered, this,
            [this, instanceName, node] { emit pinRequested(instanceName, node); });
    QAction *free = menu->addAction(tr("Free (Let the Planner Choose)"));
    free->setObjectName(QStringLiteral("planFree"));
    free->setEnabled(item->card().pinned);
    connect(free, &QAction::triggered, this,
            [this, instanceName] { emit pinRequested(instanceName, QString()); });
    return menu;
}

void PlanScene::contextMenuEvent(QGraphicsSceneContextMenuEvent *event)
{
    for (QGraphicsItem *item : items(event->scenePos())) {
        if (auto *card = dynamic_cast<PlanCardItem *>(item)) {
            const std::unique_ptr<QMenu> menu(cardMenu(card->card().instanceName));
            menu->exec(event->screenPos());
            return;
        }
    }
}

} // namespace SystemEditor
