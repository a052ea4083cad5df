// SPDX-License-Identifier: MIT
#include "propertiespanel.h"

#include "componentfactory.h"
#include "configurationseteditor.h"
#include "systemmodel.h"
#include "systemscene.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStackedWidget>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

enum Page { NothingPage, ComponentPage, ConnectorPage };

QTableWidget *twoColumnTable(const QString &objectName, const QStringList &headers)
{
    auto *table = new QTableWidget(0, 2);
    table->setObjectName(objectName);
    table->setHorizontalHeaderLabels(headers);
    table->horizontalHeader()->setStretchLastSection(true);
    table->verticalHeader()->hide();
    return table;
}

QTableWidgetItem *readOnlyItem(const QString &text)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

} // namespace

PropertiesPanel::PropertiesPanel(SystemModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_pages(new QStackedWidget)
{
    auto *nothing = new QLabel(tr("Select a component or a connector to see its properties."));
    nothing->setWordWrap(true);
    nothing->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_pages->insertWidget(NothingPage, nothing);
    m_pages->insertWidget(ComponentPage, buildComponentPage());
    m_pages->insertWidget(ConnectorPage, buildConnectorPage());
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_pages);
    connect(model, &SystemModel::componentChanged, this, [this](const QString &name) {
        if (name == m_component)
            refresh();
    });
    connect(model, &SystemModel::componentRenamed, this,
            [this](const QString &oldName, const QString &newName) {
                if (oldName == m_component)
                    showComponent(newName);
            });
    connect(model, &SystemModel::componentRemoved, this, [this](const QString &name) {
        if (name == m_component)
            showNothing();
    });
    connect(model, &SystemModel::connectorChanged, this, [this](const QString &id) {
        if (id == m_connector)
            refresh();
    });
    connect(model, &SystemModel::connectorRemoved, this, [this](const QString &id) {
        if (id == m_connector)
            showNothing();
    });
    connect(model, &SystemModel::reset, this, &PropertiesPanel::showNothing);
}

QLabel *PropertiesPanel::addField(QFormLayout *form, const QString &name, const QString &label)
{
    auto *field = new QLabel;
    field->setObjectName(name);
    field->setTextInteractionFlags(Qt::TextSelectableByMouse);
    field->setWordWrap(true);
    form->addRow(label, field);
    return field;
}

QLabel *PropertiesPanel::field(const QString &name) const
{
    return findChild<QLabel *>(name);
}

QWidget *PropertiesPanel::buildComponentPage()
{
    auto *page = new QWidget;
    auto *form = new QFormLayout;
    addField(form, QStringLiteral("instanceName"), tr("Instance name:"));
    addField(form, QStringLiteral("typeName"), tr("Type name:"));
    addField(form, QStringLiteral("componentId"), tr("Id:"));
    addField(form, QStringLiteral("pathUri"), tr("Path URI:"));
    m_configuration = new ConfigurationSetEditor(m_model, m_undoStack);
    auto *layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("<b>Configuration sets</b>")));
    layout->addWidget(m_configuration, 1);
    return page;
}

QWidget *PropertiesPanel::buildConnectorPage()
{
    auto *page = new QWidget;
    auto *form = new QFormLayout;
    addField(form, QStringLiteral("connectorName"), tr("Name:"));
    addField(form, QStringLiteral("connectorKind"), tr("Kind:"));
    addField(form, QStringLiteral("connectorSource"), tr("Source:"));
    addField(form, QStringLiteral("connectorTarget"), tr("Target:"));
    addField(form, QStringLiteral("connectorId"), tr("Id:"));
    m_connectorProperties
        = twoColumnTable(QStringLiteral("connectorProperties"), {tr("Property"), tr("Value")});
    m_connectorProperties->setEditTriggers(QAbstractItemView::NoEditTriggers);
    auto *layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(form);
    auto *edit = new QPushButton(tr("Edit Connector…"));
    edit->setObjectName(QStringLiteral("editConnector"));
    connect(edit, &QPushButton::clicked, this, [this] {
        if (!m_connector.isEmpty())
            emit editConnectorRequested(m_connector);
    });
    layout->addWidget(m_connectorProperties, 1);
    layout->addWidget(edit, 0, Qt::AlignRight);
    return page;
}

void PropertiesPanel::followScene(SystemScene *scene)
{
    m_scene = scene;
    connect(scene, &QGraphicsScene::selectionChanged, this, &PropertiesPanel::followSelection);
    followSelection();
}

void PropertiesPanel::followSelection()
{
    if (!m_scene)
        return;
    const QStringList components = m_scene->selectedComponents();
    const QStringList connectors = m_scene->selectedConnectors();
    if (components.size() == 1 && connectors.isEmpty())
        showComponent(components.first());
    else if (connectors.size() == 1 && components.isEmpty())
        showConnector(connectors.first());
    else
        showNothing();
}

void PropertiesPanel::showComponent(const QString &instanceName)
{
    m_component = instanceName;
    m_connector.clear();
    refresh();
}

void PropertiesPanel::showConnector(const QString &connectorId)
{
    m_component.clear();
    m_connector = connectorId;
    refresh();
}

void PropertiesPanel::showNothing()
{
    m_component.clear();
    m_connector.clear();
    refresh();
}

void PropertiesPanel::refresh()
{
    if (m_model && m_model->component(m_component)) {
        fillComponent();
        m_pages->setCurrentIndex(ComponentPage);
    } else if (m_model && m_model->connector(m_connector)) {
        fillConnector();
        m_pages->setCurrentIndex(ConnectorPage);
    } else {
        m_pages->setCurrentIndex(NothingPage);
    }
}

void PropertiesPanel::fillComponent()
{
    const Profile::RtsComponent &c = *m_model->component(m_component);
    field(QStringLiteral("instanceName"))->setText(c.instanceName);
    field(QStringLiteral("typeName"))->setText(
        componentTypeName(c, m_model->rtcProfile(m_component)));
    field(QStringLiteral("componentId"))->setText(c.id);
    field(QStringLiteral("pathUri"))->setText(c.pathUri);
    m_configuration->setComponent(m_component);
}

QString PropertiesPanel::shownSet() const
{
    return m_configuration->shownSet();
}

void PropertiesPanel::setShownSet(const QString &setId)
{
    m_configuration->setShownSet(setId);
}

QComboBox *PropertiesPanel::setCombo() const
{
    return m_configuration->setCombo();
}

bool PropertiesPanel::setValue(const QString &parameter, const QString &value)
{
    return m_configuration->setValue(parameter, value);
}

void PropertiesPanel::activateShownSet()
{
    m_configuration->activateShownSet();
}

void PropertiesPanel::addSetCopy()
{
    m_configuration->addSetCopy();
}

void PropertiesPanel::deleteShownSet()
{
    m_configuration->deleteShownSet();
}

void PropertiesPanel::fillConnector()
{
    const std::optional<ConnectorInfo> info = m_model->connector(m_connector);
    const Profile::RtsPortConnector *record = m_model->dataConnector(m_connector);
    if (!record)
        record = m_model->serviceConnector(m_connector);
    field(QStringLiteral("connectorName"))->setText(info->name);
    field(QStringLiteral("connectorKind"))->setText(
        info->kind == ConnectorKind::Data ? tr("Data port connector")
                                          : tr("Service port connector"));
    field(QStringLiteral("connectorSource"))->setText(info->source.portName);
    field(QStringLiteral("connectorTarget"))->setText(info->target.portName);
    field(QStringLiteral("connectorId"))->setText(info->id);
    m_connectorProperties->setRowCount(0);
    if (const Profile::RtsDataPortConnector *data = m_model->dataConnector(m_connector)) {
        const QList<QPair<QString, QString>> attributes {
            {tr("data type"), data->dataType},
            {tr("interface type"), data->interfaceType},
            {tr("dataflow type"), data->dataflowType},
            {tr("subscription type"), data->subscriptionType.value_or(QString())},
            {tr("push interval"), data->pushInterval.value_or(QString())}};
        for (const auto &[name, value] : attributes) {
            if (value.isEmpty())
                continue;
            const int row = m_connectorProperties->rowCount();
            m_connectorProperties->insertRow(row);
            m_connectorProperties->setItem(row, 0, readOnlyItem(name));
            m_connectorProperties->setItem(row, 1, readOnlyItem(value));
        }
    }
    for (const Profile::RtsProperty &property : record->properties) {
        const int row = m_connectorProperties->rowCount();
        m_connectorProperties->insertRow(row);
        m_connectorProperties->setItem(row, 0, readOnlyItem(property.name));
        m_connectorProperties->setItem(row, 1, readOnlyItem(property.value.value_or(QString())));
    }
}

} // namespace SystemEditor
