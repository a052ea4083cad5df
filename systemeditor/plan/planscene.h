// SPDX-License-Identifier: MIT
#pragma once

#include "planlanes.h"

#include <QGraphicsScene>
#include <QPointer>

class QMenu;

namespace SystemEditor {

class PlanCardItem;

/**
 * The lanes of the Plan view side by side, one column per node with its header (node, CPU load,
 * installs) and its components below. It only shows what showLanes() gives it; dropping a
 * component in another node's lane asks for a pin (pinRequested()), and the view answers with an
 * undoable command and new lanes. A drop anywhere else puts the component back. A card's context
 * menu pins it where it is or frees it.
 */
class PlanScene : public QGraphicsScene
{
    Q_OBJECT

public:
    static constexpr qreal LaneWidth = 224;
    static constexpr qreal HeaderHeight = 64;

    explicit PlanScene(QObject *parent = nullptr);

    void showLanes(const QList<PlanLane> &lanes);
    const QList<PlanLane> &lanes() const { return m_lanes; }
    /// The item of @p instanceName, or null.
    PlanCardItem *card(const QString &instanceName) const;
    /// The lane whose column holds @p scenePos, or -1.
    int laneAt(const QPointF &scenePos) const;
    /// Where the card of the component at @p row of lane @p lane is laid out.
    static QPointF cardPosition(int lane, int row);
    /**
     * The context menu of a component's card: pin it to the node of its lane, or free it (what
     * right-clicking the card shows). The caller owns it; null when there is no such card.
     */
    QMenu *cardMenu(const QString &instanceName);

signals:
    /// The user dropped @p instanceName in the lane of @p node, or chose to pin it there; an
    /// empty @p node: to free it.
    void pinRequested(const QString &instanceName, const QString &node);

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;
    void contextMenuEvent(QGraphicsSceneContextMenuEvent *event) override;

private:
    void addLane(const PlanLane &lane, int index, qreal height);
    QString laneTitle(const PlanLane &lane) const;

    QList<PlanLane> m_lanes;
    PlanCardItem *m_dragged = nullptr;
};

} // namespace SystemEditor
