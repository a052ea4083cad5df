// SPDX-License-Identifier: MIT
#pragma once

#include "planlanes.h"

#include <QGraphicsScene>
#include <QPointer>

namespace SystemEditor {

class PlanCardItem;

/**
 * The lanes of the Plan view side by side, one column per node with its header (node, CPU load,
 * installs) and its components below. It only shows what showLanes() gives it; dropping a
 * component in another node's lane asks for a pin (pinRequested()), and the view answers with an
 * undoable command and new lanes. A drop anywhere else puts the component back.
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

signals:
    /// The user dropped @p instanceName in the lane of @p node.
    void pinRequested(const QString &instanceName, const QString &node);

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;

private:
    void addLane(const PlanLane &lane, int index, qreal height);
    QString laneTitle(const PlanLane &lane) const;

    QList<PlanLane> m_lanes;
    PlanCardItem *m_dragged = nullptr;
};

} // namespace SystemEditor
