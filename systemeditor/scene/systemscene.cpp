// SPDX-License-Identifier: MIT
#include "systemscene.h"

#include "componentappearance.h"
#include "instancecommands.h"
#include "componentitem.h"
#include "connectorcommands.h"
#include "connectoritem.h"
#include "portitem.h"

#include <QPainter>

#include <cmath>

namespace SystemEditor {

SystemScene::SystemScene(SystemModel *model, QUndoStack *undoStack, QObject *parent)
    : QGraphicsScene(parent)
    , m_model(model)
    , m_undoStack(undoStack)
{
    connect(model, &SystemModel::componentAdded, this, &SystemScene::addComponentItem);
    connect(model, &SystemModel::componentAboutToBeRemoved, this,
            &SystemScene::removeComponentItem);
    connect(model, &SystemModel::componentChanged, this, &SystemScene::refreshComponent);
    connect(model, &SystemModel::componentRenamed, this, &SystemScene::renameComponentItem);
    connect(model, &SystemModel::connectorAdded, this, &SystemScene::addConnectorItem);
    connect(model, &SystemModel::connectorAboutToBeRemoved, this,
            &SystemScene::removeConnectorItem);
    connect(model, &SystemModel::connectorRemoved, this, &SystemScene::connectorRemoved);
    connect(model, &SystemModel::connectorChanged, this, &SystemScene::refreshConnector);
    connect(model, &SystemModel::reset, this, &SystemScene::rebuild);
    rebuild();
}

SystemScene::~SystemScene()
{
    // Items go before the maps that their signals would consult.
    for (ComponentItem *item : std::as_const(m_components))
        item->disconnect(this);
    for (ConnectorItem *item : std::as_const(m_connectors))
        item->disconnect(this);
    // Deleting a selected item announces a selection change; nobody may look at half-deleted
    // items through this scene any more.
    blockSignals(true);
    m_components.clear();
    m_connectors.clear();
    clear();
}

ComponentItem *SystemScene::componentItem(const QString &instanceName) const
{
    return m_components.value(instanceName);
}

ConnectorItem *SystemScene::connectorItem(const QString &connectorId) const
{
    return m_connectors.value(connectorId);
}

PortItem *SystemScene::portItem(const ConnectorEnd &end) const
{
    const ComponentItem *component = m_components.value(end.instanceName);
    return component ? component->portItem(end.portName) : nullptr;
}

QStringList SystemScene::selectedComponents() const
{
    QStringList names;
    for (const QString &name : m_model->componentIds()) {
        if (const ComponentItem *item = m_components.value(name); item && item->isSelected())
            names.append(name);
    }
    return names;
}

QStringList SystemScene::selectedConnectors() const
{
    QStringList ids;
    for (const QString &id : m_model->connectorIds()) {
        if (const ConnectorItem *item = m_connectors.value(id); item && item->isSelected())
            ids.append(id);
    }
    return ids;
}

void SystemScene::selectComponents(const QStringList &instanceNames)
{
    clearSelection();
    for (const QString &name : instanceNames) {
        if (ComponentItem *item = m_components.value(name))
            item->setSelected(true);
    }
}

void SystemScene::setGridVisible(bool visible)
{
    m_gridVisible = visible;
    update();
}

void SystemScene::setSnapToGrid(bool snap)
{
    m_snapToGrid = snap;
    for (ComponentItem *item : std::as_const(m_components))
        item->setSnapGrid(snap ? GridSize : 0);
}

QRectF SystemScene::diagramRect() const
{
    QRectF rect;
    for (const ComponentItem *item : m_components)
        rect |= item->sceneBoundingRect();
    for (const ConnectorItem *item : m_connectors)
        rect |= item->sceneBoundingRect();
    return rect.adjusted(-20, -20, 20, 20);
}

void SystemScene::rebuild()
{
    clearSelection();
    for (const QString &id : m_connectors.keys())
        removeConnectorItem(id);
    for (const QString &name : m_components.keys())
        removeComponentItem(name);
    // The model holds every connector already, so components get their final look when added;
    // adding connectors must then not refresh their ends (which would reattach every connector of
    // both, quadratic in a large system).
    m_rebuilding = true;
    for (const QString &name : m_model->componentIds())
        addComponentItem(name);
    for (const QString &id : m_model->connectorIds())
        addConnectorItem(id);
    m_rebuilding = false;
}

void SystemScene::addComponentItem(const QString &instanceName)
{
    if (m_components.contains(instanceName))
        return;
    auto *item = new ComponentItem(appearanceOf(instanceName));
    // The model's position is exact; snapping applies to what the user drags only.
    item->setPos(m_model->layout(instanceName).position);
    item->setSnapGrid(m_snapToGrid ? GridSize : 0);
    m_components.insert(instanceName, item);
    addItem(item);
    connect(item, &ComponentItem::xChanged, this, [this, item] {
        rerouteConnectors(item->instanceName());
    });
    connect(item, &ComponentItem::yChanged, this, [this, item] {
        rerouteConnectors(item->instanceName());
    });
    connect(item, &ComponentItem::geometryChanged, this, [this, item] {
        reattachConnectors(item->instanceName());
    });
    connect(item, &ComponentItem::resizeRequested, this,
            [this](const QString &name, const QSizeF &size) {
                push(new ResizeComponentCommand(m_model, name, size));
            });
}

void SystemScene::removeComponentItem(const QString &instanceName)
{
    ComponentItem *item = m_components.take(instanceName);
    if (!item)
        return;
    item->disconnect(this);
    for (ConnectorItem *connector : std::as_const(m_connectors)) {
        const ConnectorInfo &info = connector->info();
        if (info.source.instanceName == instanceName || info.target.instanceName == instanceName)
            connector->setPorts(nullptr, nullptr);
    }
    if (m_dragSource && m_dragSource->parentItem() == item)
        clearHighlights();
    delete item;
}

void SystemScene::refreshComponent(const QString &instanceName)
{
    ComponentItem *item = m_components.value(instanceName);
    if (!item)
        return;
    item->setAppearance(appearanceOf(instanceName));
    const qreal grid = m_snapToGrid ? GridSize : 0;
    item->setSnapGrid(0);
    item->setPos(m_model->layout(instanceName).position);
    item->setSnapGrid(grid);
    reattachConnectors(instanceName);
}

ComponentAppearance SystemScene::appearanceOf(const QString &instanceName) const
{
    ComponentAppearance appearance = ComponentAppearance::fromModel(*m_model, instanceName);
    const auto colour = m_bodyColors.constFind(instanceName);
    if (colour != m_bodyColors.constEnd())
        appearance.bodyColor = *colour;
    return appearance;
}

void SystemScene::setBodyColor(const QString &instanceName, const QColor &colour)
{
    m_bodyColors.insert(instanceName, colour);
    ComponentItem *item = m_components.value(instanceName);
    if (item && item->appearance().bodyColor != colour)
        item->setAppearance(appearanceOf(instanceName));
}

void SystemScene::renameComponentItem(const QString &oldName, const QString &newName)
{
    if (m_bodyColors.contains(oldName))
        m_bodyColors.insert(newName, m_bodyColors.take(oldName));
    if (ComponentItem *item = m_components.take(oldName))
        m_components.insert(newName, item);
    // Connector ends name the component; take them from the model again before its ports are
    // rebuilt, so that reattaching finds the connectors by the new name (with the old one they
    // kept pointing at the deleted ports).
    for (const QString &id : m_model->connectorsOf(newName))
        refreshConnector(id);
    refreshComponent(newName);
}

void SystemScene::addConnectorItem(const QString &connectorId)
{
    const std::optional<ConnectorInfo> info = m_model->connector(connectorId);
    if (!info || m_connectors.contains(connectorId))
        return;
    auto *item = new ConnectorItem(*info);
    m_connectors.insert(connectorId, item);
    addItem(item);
    connect(item, &ConnectorItem::bendPointsRequested, this,
            [this](const QString &id, const QList<QPointF> &points) {
                push(new SetBendPointsCommand(m_model, id, points));
            });
    connect(item, &ConnectorItem::editRequested, this, &SystemScene::connectorEditRequested);
    // The ends are now connected: their colour changes (which also attaches this item).
    if (!m_rebuilding) {
        refreshComponent(info->source.instanceName);
        refreshComponent(info->target.instanceName);
    }
    item->setPorts(portItem(info->source), portItem(info->target));
}

void SystemScene::removeConnectorItem(const QString &connectorId)
{
    ConnectorItem *item = m_connectors.take(connectorId);
    if (!item)
        return;
    m_removedConnectors.insert(connectorId, item->info());
    item->disconnect(this);
    delete item;
}

void SystemScene::connectorRemoved(const QString &connectorId)
{
    const std::optional<ConnectorInfo> info = m_removedConnectors.take(connectorId);
    if (!info)
        return;
    refreshComponent(info->source.instanceName);
    refreshComponent(info->target.instanceName);
}

void SystemScene::refreshConnector(const QString &connectorId)
{
    ConnectorItem *item = m_connectors.value(connectorId);
    const std::optional<ConnectorInfo> info = m_model->connector(connectorId);
    if (!item || !info)
        return;
    item->setInfo(*info);
    item->setPorts(portItem(info->source), portItem(info->target));
}

void SystemScene::reattachConnectors(const QString &instanceName)
{
    for (ConnectorItem *item : std::as_const(m_connectors)) {
        const ConnectorInfo &info = item->info();
        if (info.source.instanceName == instanceName || info.target.instanceName == instanceName)
            item->setPorts(portItem(info.source), portItem(info.target));
    }
}

void SystemScene::rerouteConnectors(const QString &instanceName)
{
    for (ConnectorItem *item : std::as_const(m_connectors)) {
        const ConnectorInfo &info = item->info();
        if (info.source.instanceName == instanceName || info.target.instanceName == instanceName)
            item->updateRoute();
    }
}

void SystemScene::drawBackground(QPainter *painter, const QRectF &rect)
{
    painter->fillRect(rect, Qt::white);
    // Zoomed far out the dots would be a grey blur that costs much to draw.
    if (!m_gridVisible || rect.width() * rect.height() > 4e6)
        return;
    painter->setPen(QPen(QColor(200, 205, 215), 0));
    const qreal left = std::floor(rect.left() / GridSize) * GridSize;
    const qreal top = std::floor(rect.top() / GridSize) * GridSize;
    QList<QPointF> dots;
    for (qreal x = left; x < rect.right(); x += GridSize) {
        for (qreal y = top; y < rect.bottom(); y += GridSize)
            dots.append(QPointF(x, y));
    }
    painter->drawPoints(dots.constData(), int(dots.size()));
}

} // namespace SystemEditor
