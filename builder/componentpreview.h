// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QRectF>
#include <QWidget>

namespace Builder {

/**
 * The live picture of the component being edited: its box with the name and every data, event
 * and service port drawn on the side its position names (LEFT/RIGHT/TOP/BOTTOM); EventPorts are
 * diamonds labelled with their events. It follows every
 * change of the model, so typing a port name shows up at once. A label that does not fit between
 * its port and the widget's edge is shortened with "…"; the port's tooltip gives it in full.
 */
class ComponentPreview : public QWidget
{
    Q_OBJECT

public:
    /// One port as drawn.
    struct Port
    {
        enum Kind { In, Out, Service, Event };
        Kind kind = In;
        QString name;
        QString type; ///< data type, the interface types of a service port, an EventPort's events
        QString side; ///< LEFT | RIGHT | TOP | BOTTOM (the drawn side)
        QRectF marker; ///< the port's marker in widget coordinates
        QString shownName; ///< the name as drawn (shortened when the widget is too narrow)
        QRectF nameRect; ///< where it is drawn
        QString shownType; ///< the type as drawn under the name of a LEFT/RIGHT port, or empty
        QRectF typeRect;
    };

    explicit ComponentPreview(ComponentModel *model, QWidget *parent = nullptr);

    /// The component box in widget coordinates.
    QRectF box() const { return m_box; }
    /// The ports as laid out for the current size.
    QList<Port> ports() const { return m_ports; }
    /// The name drawn in the box.
    QString title() const { return m_title; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    bool event(QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void relayout();
    void layoutSide(const QString &side, QList<Port *> ports);
    void placeLabels(Port &port) const;
    QFont typeFont() const;
    void paintPort(QPainter &painter, const Port &port) const;

    QPointer<ComponentModel> m_model;
    QRectF m_box;
    QSizeF m_extent; ///< box plus labels, for sizeHint()
    QList<Port> m_ports;
    QString m_title;
};

} // namespace Builder
