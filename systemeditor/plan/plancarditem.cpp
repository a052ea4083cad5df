// SPDX-License-Identifier: MIT
#include "plancarditem.h"

#include <QCoreApplication>
#include <QCursor>
#include <QPainter>

namespace SystemEditor {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SystemEditor::PlanCardItem)
};

const QColor UnmetColour(200, 30, 30);

} // namespace

PlanCardItem::PlanCardItem(const PlanCard &card, int lane)
    : QGraphicsRectItem(0, 0, Width, Height)
    , m_card(card)
    , m_lane(lane)
{
    setFlags(ItemIsMovable | ItemIsSelectable);
    setCursor(Qt::OpenHandCursor);
    setToolTip(toolTipText());
    setData(0, card.instanceName);
}

QString PlanCardItem::toolTipText() const
{
    QStringList lines {QStringLiteral("%1 (%2)").arg(m_card.instanceName, m_card.typeName)};
    lines << (m_card.process.isEmpty() ? Text::tr("Runs in a process of its own")
                                       : Text::tr("Shares process %1").arg(m_card.process));
    if (!m_card.installPackage.isEmpty())
        lines << Text::tr("Installs %1 here").arg(m_card.installPackage);
    lines << (m_card.pinned ? Text::tr("Pinned here: drag it to another node to move the pin")
                            : Text::tr("Free: drag it to a node to pin it there"));
    lines << m_card.unmet;
    return lines.join(QLatin1Char('\n'));
}

void PlanCardItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const bool unmet = !m_card.unmet.isEmpty();
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(unmet ? UnmetColour : QColor(90, 110, 140), isSelected() ? 2.5 : 1.2));
    painter->setBrush(unmet ? QColor(255, 228, 228) : QColor(236, 242, 250));
    painter->drawRoundedRect(rect().adjusted(1, 1, -1, -1), 5, 5);
    QFont font = painter->font();
    font.setBold(true);
    painter->setFont(font);
    painter->setPen(unmet ? UnmetColour : QColor(20, 20, 20));
    painter->drawText(rect().adjusted(8, 3, -24, -Height / 2), Qt::AlignLeft | Qt::AlignVCenter,
                      m_card.instanceName);
    if (m_card.pinned)
        paintPin(painter);
    font.setBold(false);
    painter->setFont(font);
    painter->setPen(QColor(70, 70, 70));
    painter->setBrush(Qt::NoBrush);
    QString detail = m_card.typeName;
    if (!m_card.process.isEmpty())
        detail += QStringLiteral(" · ") + m_card.process;
    if (!m_card.installPackage.isEmpty())
        detail += QStringLiteral(" · +") + m_card.installPackage;
    painter->drawText(rect().adjusted(8, Height / 2 - 2, -8, -3), Qt::AlignLeft | Qt::AlignVCenter,
                      painter->fontMetrics().elidedText(detail, Qt::ElideRight, int(Width - 16)));
}

/// A drawing pin in the top right corner: the system keeps the component on this node.
void PlanCardItem::paintPin(QPainter *painter) const
{
    const QPointF head(Width - 14, 11);
    painter->setPen(QPen(QColor(60, 60, 60), 1.5));
    painter->drawLine(head, head + QPointF(0, 11));
    painter->setPen(QPen(QColor(120, 20, 20), 1));
    painter->setBrush(QColor(215, 50, 50));
    painter->drawEllipse(head, 5, 5);
}

} // namespace SystemEditor
