// SPDX-License-Identifier: MIT
#pragma once

#include "planlanes.h"

#include <QGraphicsRectItem>

namespace SystemEditor {

/**
 * A component in a lane of the Plan view: its instance and type names, a pin mark when the system
 * pins it, what gets installed for it, in red when a requirement of it is unmet. The user drags
 * it to another lane; the scene decides what a drop means.
 */
class PlanCardItem : public QGraphicsRectItem
{
public:
    static constexpr qreal Width = 200;
    static constexpr qreal Height = 40;

    PlanCardItem(const PlanCard &card, int lane);

    const PlanCard &card() const { return m_card; }
    /// The lane it was laid out in (index into the scene's lanes).
    int lane() const { return m_lane; }

    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option,
               QWidget *widget = nullptr) override;

private:
    QString toolTipText() const;
    void paintPin(QPainter *painter) const;

    PlanCard m_card;
    int m_lane;
};

} // namespace SystemEditor
