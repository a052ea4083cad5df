// SPDX-License-Identifier: MIT
#include "overviewwidget.h"

#include "systemscene.h"

#include <QGraphicsView>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>

namespace SystemEditor {

OverviewWidget::OverviewWidget(SystemScene *scene, QGraphicsView *view, QWidget *parent)
    : QWidget(parent)
    , m_scene(scene)
    , m_view(view)
{
    setObjectName(QStringLiteral("overview"));
    setFixedSize(200, 140);
    setCursor(Qt::PointingHandCursor);
    setToolTip(tr("Overview: click to show that part of the diagram"));
    connect(scene, &QGraphicsScene::changed, this, [this] {
        m_map = QPixmap();
        updateVisibility();
        update();
    });
    for (QScrollBar *bar : {view->horizontalScrollBar(), view->verticalScrollBar()}) {
        connect(bar, &QScrollBar::valueChanged, this, qOverload<>(&QWidget::update));
        connect(bar, &QScrollBar::rangeChanged, this, &OverviewWidget::updateVisibility);
    }
}

QRectF OverviewWidget::diagramArea() const
{
    // The visible part is included, so that the frame never leaves the map.
    return m_scene->diagramRect().united(m_view->mapToScene(m_view->viewport()->rect())
                                             .boundingRect());
}

QTransform OverviewWidget::sceneToWidget() const
{
    const QRectF area = diagramArea();
    if (area.isEmpty())
        return {};
    const QRectF inner = QRectF(rect()).adjusted(4, 4, -4, -4);
    const qreal scale = std::min(inner.width() / area.width(), inner.height() / area.height());
    return QTransform::fromTranslate(-area.left(), -area.top())
        * QTransform::fromScale(scale, scale)
        * QTransform::fromTranslate(inner.left(), inner.top());
}

void OverviewWidget::updateVisibility()
{
    const QRectF shown = m_view->mapToScene(m_view->viewport()->rect()).boundingRect();
    const QRectF diagram = m_scene->diagramRect();
    setVisible(!diagram.isEmpty() && !shown.contains(diagram));
    if (isVisible())
        raise();
}

QPointF OverviewWidget::sceneAt(const QPointF &widgetPos) const
{
    return sceneToWidget().inverted().map(widgetPos);
}

QRectF OverviewWidget::visibleFrame() const
{
    return sceneToWidget().mapRect(m_view->mapToScene(m_view->viewport()->rect()).boundingRect());
}

void OverviewWidget::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.fillRect(rect(), QColor(245, 246, 248));
    painter.setPen(QColor(150, 150, 150));
    painter.drawRect(rect().adjusted(0, 0, -1, -1));
    const QRectF area = diagramArea();
    if (area.isEmpty())
        return;
    const QTransform transform = sceneToWidget();
    const QRect target = transform.mapRect(area).toAlignedRect();
    painter.drawPixmap(target.topLeft(), diagramPixmap(area, target));
    painter.setPen(QPen(QColor(30, 110, 230), 1.5));
    painter.setBrush(QColor(30, 110, 230, 30));
    painter.drawRect(visibleFrame());
}

const QPixmap &OverviewWidget::diagramPixmap(const QRectF &area, const QRect &target)
{
    // Scrolling repaints the frame only; rendering a thousand components on every scroll step
    // would make panning a large diagram slow.
    if (!m_map.isNull() && area == m_mapArea && target == m_mapTarget)
        return m_map;
    const qreal ratio = devicePixelRatioF();
    m_map = QPixmap(target.size() * ratio);
    m_map.setDevicePixelRatio(ratio);
    m_map.fill(Qt::transparent);
    QPainter painter(&m_map);
    painter.setRenderHint(QPainter::Antialiasing);
    m_scene->render(&painter, QRectF(QPointF(0, 0), QSizeF(target.size())), area);
    m_mapArea = area;
    m_mapTarget = target;
    return m_map;
}

void OverviewWidget::mousePressEvent(QMouseEvent *event)
{
    m_view->centerOn(sceneAt(event->position()));
    update();
}

void OverviewWidget::mouseMoveEvent(QMouseEvent *event)
{
    if (event->buttons() & Qt::LeftButton) {
        m_view->centerOn(sceneAt(event->position()));
        update();
    }
}

} // namespace SystemEditor
