// SPDX-License-Identifier: MIT
#include "systemview.h"

#include "componentitem.h"
#include "instancecommands.h"
#include "connectionrules.h"
#include "serviceconnectordialog.h"
#include "systemscene.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QScrollBar>
#include <QToolTip>
#include <QUndoStack>
#include <QWheelEvent>

#include <cmath>

namespace SystemEditor {

namespace {

constexpr qreal ZoomStep = 1.25;

std::optional<ConnectorSettings> askWithDialog(QWidget *parent, const ConnectorSettings &proposed,
                                               const ConnectorDialog::Choices &choices)
{
    ConnectorDialog dialog(proposed, choices, parent);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return dialog.settings();
}

std::optional<ServiceConnectorSettings> askServiceWithDialog(
    QWidget *parent, const ServiceConnectorSettings &proposed, const ServicePortSide &source,
    const ServicePortSide &target)
{
    ServiceConnectorDialog dialog(proposed, source, target, parent);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return dialog.settings();
}

/// `Instance0.port` → `port`.
QString shortName(const std::optional<PortInfo> &port, const QString &fallback)
{
    return port ? port->profileName : fallback.section(QLatin1Char('.'), -1);
}

} // namespace

SystemView::SystemView(SystemScene *scene, QWidget *parent)
    : QGraphicsView(scene, parent)
    , m_scene(scene)
{
    setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
    // The dotted grid is drawn once per view size and scrolled with the contents.
    setCacheMode(CacheBackground);
    setDragMode(RubberBandDrag);
    setRubberBandSelectionMode(Qt::IntersectsItemShape);
    setTransformationAnchor(AnchorUnderMouse);
    setResizeAnchor(AnchorViewCenter);
    setAcceptDrops(true);
    setFocusPolicy(Qt::StrongFocus);
    m_connectorEditor = [this](const ConnectorSettings &proposed,
                               const ConnectorDialog::Choices &choices) {
        return askWithDialog(this, proposed, choices);
    };
    m_serviceConnectorEditor = [this](const ServiceConnectorSettings &proposed,
                                      const ServicePortSide &source,
                                      const ServicePortSide &target) {
        return askServiceWithDialog(this, proposed, source, target);
    };
    connect(scene, &SystemScene::connectRequested, this, &SystemView::requestConnection);
    connect(scene, &SystemScene::connectionRefused, this, &SystemView::showRefusal);
    connect(scene, &SystemScene::connectorEditRequested, this, &SystemView::editConnector);
    connect(scene, &SystemScene::statusMessage, this, &SystemView::statusMessage);
    connect(scene, &QGraphicsScene::changed, this, &SystemView::growSceneRect);
    growSceneRect();
}

void SystemView::growSceneRect()
{
    // Room around the diagram to pan into and drop on; it only grows, so that the view does not
    // jump while something is dragged.
    const QRectF wanted = m_scene->diagramRect().adjusted(-800, -600, 800, 600);
    if (!sceneRect().contains(wanted))
        setSceneRect(sceneRect().united(wanted));
}

qreal SystemView::zoomFactor() const
{
    return transform().m11();
}

void SystemView::setZoomFactor(qreal factor)
{
    factor = std::clamp(factor, MinimumZoom, MaximumZoom);
    if (qFuzzyCompare(factor, zoomFactor()))
        return;
    setTransform(QTransform::fromScale(factor, factor));
    emit zoomChanged(factor);
}

void SystemView::zoomIn()
{
    setZoomFactor(zoomFactor() * ZoomStep);
}

void SystemView::zoomOut()
{
    setZoomFactor(zoomFactor() / ZoomStep);
}

void SystemView::resetZoom()
{
    setZoomFactor(1.0);
}

void SystemView::fitToDiagram()
{
    const QRectF diagram = m_scene->diagramRect();
    if (diagram.isEmpty())
        return;
    growSceneRect();
    const QRectF viewport = this->viewport()->rect();
    const qreal factor = std::min(viewport.width() / diagram.width(),
                                  viewport.height() / diagram.height());
    setZoomFactor(std::min(factor, 1.0));
    centerOn(diagram.center());
}

bool SystemView::findComponent(const QString &text)
{
    const QString needle = text.trimmed();
    if (needle.isEmpty())
        return false;
    for (const QString &name : m_scene->model()->componentIds()) {
        if (!name.contains(needle, Qt::CaseInsensitive))
            continue;
        m_scene->selectComponents({name});
        ComponentItem *item = m_scene->componentItem(name);
        growSceneRect();
        centerOn(item);
        item->setFocus();
        return true;
    }
    emit statusMessage(tr("No component matches \"%1\".").arg(needle));
    return false;
}

void SystemView::requestConnection(const ConnectionCheck &check)
{
    if (check.kind == ConnectorKind::Service) {
        requestServiceConnection(check);
        return;
    }
    const std::optional<PortInfo> out = m_scene->model()->port(check.source.instanceName,
                                                              check.source.portName);
    const std::optional<PortInfo> in = m_scene->model()->port(check.target.instanceName,
                                                             check.target.portName);
    const QString dataType = out && !out->dataType.isEmpty() ? out->dataType
                                                             : (in ? in->dataType : QString());
    const ConnectorDialog::Choices choices = choicesFor(check);
    ConnectorSettings proposed = ConnectorSettings::defaults(
        out ? out->profileName : check.source.portName, in ? in->profileName : check.target.portName,
        dataType);
    if (!choices.interfaceTypes.contains(proposed.interfaceType))
        proposed.interfaceType = choices.interfaceTypes.value(0);
    if (!choices.dataflowTypes.contains(proposed.dataflowType))
        proposed.dataflowType = choices.dataflowTypes.value(0);
    if (!choices.subscriptionTypes.contains(proposed.subscriptionType))
        proposed.subscriptionType = choices.subscriptionTypes.value(0);
    if (const std::optional<ConnectorSettings> settings = m_connectorEditor(proposed, choices))
        m_scene->connectPorts(check, *settings);
}

void SystemView::requestServiceConnection(const ConnectionCheck &check)
{
    const ServicePortSide source = serviceSide(check.source);
    const ServicePortSide target = serviceSide(check.target);
    ServiceConnectorSettings proposed;
    proposed.name = source.portName + QLatin1Char('_') + target.portName;
    if (const std::optional<ServiceConnectorSettings> settings
        = m_serviceConnectorEditor(proposed, source, target))
        m_scene->connectServicePorts(check, *settings);
}

ServicePortSide SystemView::serviceSide(const ConnectorEnd &end) const
{
    const std::optional<PortInfo> port = m_scene->model()->port(end.instanceName, end.portName);
    return {end.instanceName, shortName(port, end.portName),
            port ? port->interfaces : QList<InterfaceInfo>()};
}

void SystemView::editServiceConnector(const QString &connectorId)
{
    const Profile::RtsServicePortConnector *connector
        = m_scene->model()->serviceConnector(connectorId);
    if (!connector)
        return;
    const ServiceConnectorSettings current = ServiceConnectorSettings::fromConnector(*connector);
    const std::optional<ServiceConnectorSettings> settings = m_serviceConnectorEditor(
        current, serviceSide({connector->source.instanceName, connector->source.portName}),
        serviceSide({connector->target.instanceName, connector->target.portName}));
    if (settings && *settings != current)
        m_scene->editServiceConnector(connectorId, *settings);
}

void SystemView::editConnector(const QString &connectorId)
{
    const Profile::RtsDataPortConnector *connector = m_scene->model()->dataConnector(connectorId);
    if (!connector) {
        editServiceConnector(connectorId);
        return;
    }
    const ConnectorSettings current
        = ConnectorSettings::fromConnector(*connector, m_scene->model());
    // The same choices as when it was made: what both ports offer.
    ConnectionCheck ends;
    ends.source = {connector->source.instanceName, connector->source.portName};
    ends.target = {connector->target.instanceName, connector->target.portName};
    const std::optional<ConnectorSettings> settings
        = m_connectorEditor(current, choicesFor(ends));
    if (settings && *settings != current)
        m_scene->editConnector(connectorId, *settings);
}

void SystemView::showRefusal(const QString &reason)
{
    QToolTip::showText(QCursor::pos(), reason, this);
    emit statusMessage(reason);
}

void SystemView::wheelEvent(QWheelEvent *event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    const int steps = event->angleDelta().y() / 120;
    if (steps != 0)
        setZoomFactor(zoomFactor() * std::pow(ZoomStep, steps));
    event->accept();
}

void SystemView::keyPressEvent(QKeyEvent *event)
{
    if (m_renameEditor) {
        QGraphicsView::keyPressEvent(event);
        return;
    }
    const qreal step = event->modifiers() & Qt::ShiftModifier ? 1 : SystemScene::GridSize;
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoomIn();
        return;
    case Qt::Key_Minus:
        zoomOut();
        return;
    case Qt::Key_0:
        resetZoom();
        return;
    case Qt::Key_Left:
        nudgeSelection({-step, 0});
        return;
    case Qt::Key_Right:
        nudgeSelection({step, 0});
        return;
    case Qt::Key_Up:
        nudgeSelection({0, -step});
        return;
    case Qt::Key_Down:
        nudgeSelection({0, step});
        return;
    case Qt::Key_Space:
        if (!event->isAutoRepeat()) {
            m_spaceHeld = true;
            viewport()->setCursor(Qt::OpenHandCursor);
        }
        return;
    default:
        break;
    }
    QGraphicsView::keyPressEvent(event);
}

void SystemView::keyReleaseEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
        m_spaceHeld = false;
        viewport()->unsetCursor();
        return;
    }
    QGraphicsView::keyReleaseEvent(event);
}

void SystemView::nudgeSelection(const QPointF &delta)
{
    QHash<QString, QPointF> positions;
    for (const QString &name : m_scene->selectedComponents())
        positions.insert(name, m_scene->model()->layout(name).position + delta);
    if (!positions.isEmpty() && m_scene->undoStack())
        m_scene->undoStack()->push(new MoveComponentsCommand(m_scene->model(), positions));
}

void SystemView::mousePressEvent(QMouseEvent *event)
{
    const bool pan = event->button() == Qt::MiddleButton
        || (event->button() == Qt::LeftButton && m_spaceHeld);
    if (!pan) {
        QGraphicsView::mousePressEvent(event);
        return;
    }
    m_panning = true;
    m_panStart = event->position().toPoint();
    viewport()->setCursor(Qt::ClosedHandCursor);
    event->accept();
}

void SystemView::mouseMoveEvent(QMouseEvent *event)
{
    if (!m_panning) {
        QGraphicsView::mouseMoveEvent(event);
        return;
    }
    const QPoint delta = event->position().toPoint() - m_panStart;
    m_panStart = event->position().toPoint();
    horizontalScrollBar()->setValue(horizontalScrollBar()->value() - delta.x());
    verticalScrollBar()->setValue(verticalScrollBar()->value() - delta.y());
    event->accept();
}

void SystemView::mouseReleaseEvent(QMouseEvent *event)
{
    if (!m_panning) {
        QGraphicsView::mouseReleaseEvent(event);
        return;
    }
    m_panning = false;
    if (m_spaceHeld)
        viewport()->setCursor(Qt::OpenHandCursor);
    else
        viewport()->unsetCursor();
    event->accept();
}

} // namespace SystemEditor
