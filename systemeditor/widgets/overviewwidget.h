// SPDX-License-Identifier: MIT
#pragma once

#include <QPixmap>
#include <QWidget>

class QGraphicsView;

namespace SystemEditor {

class SystemScene;

/**
 * The minimap of a large diagram: the whole diagram scaled down with the part the view shows
 * framed; clicking or dragging in it moves the view there. It shows itself only while the
 * diagram does not fit the view.
 */
class OverviewWidget : public QWidget
{
    Q_OBJECT

public:
    OverviewWidget(SystemScene *scene, QGraphicsView *view, QWidget *parent = nullptr);

    /// Shows or hides the minimap depending on whether the diagram fits the view.
    void updateVisibility();
    /// The scene point a widget point stands for.
    QPointF sceneAt(const QPointF &widgetPos) const;
    /// The framed part, in widget coordinates.
    QRectF visibleFrame() const;

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;

private:
    QRectF diagramArea() const;
    QTransform sceneToWidget() const;
    const QPixmap &diagramPixmap(const QRectF &area, const QRect &target);

    SystemScene *m_scene;
    QGraphicsView *m_view;
    QPixmap m_map; ///< the scaled-down diagram, drawn again only when the scene changes
    QRectF m_mapArea;
    QRect m_mapTarget;
};

} // namespace SystemEditor
